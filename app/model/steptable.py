"""The table of every step of a run: one row per step, as a lecture's
worked example lists them.

A row holds the step number, the pseudo-code line run (number and text), the
pixel it names (or the run a Span writes), the branch taken, every named
variable as the variables panel shows it at that step, and the latest
snapshot of each table (edge table, active edge table, ...). The command
line prints it (``run --steps``), the Steps dock shows it, worksheets leave
columns of it blank. ``numbers`` (app/model/notation.py) is how its text
shows fractions; with "exact" the text shows the exact values where the run
has them (app/model/exact.py), and the JSON form keeps its fields and adds
the exact values as "p/q" strings (app/model/step_output.py). The text
reads as people read numbers (five significant figures, colours as
#rrggbb: app/model/notation.py); the JSON form keeps every digit.

Rows are made on demand: a million-step run does not build a million rows
to show twenty. Every ``CHECKPOINT`` steps the table keeps the variables set
so far, so any row costs at most that many records to replay. Nothing here
imports Qt.
"""
from __future__ import annotations

import bisect
import csv
from dataclasses import dataclass
from fractions import Fraction

from algorithms.core.steps import Span, Table, Vars

from app.model.escape import csv_row
from app.model.exact import EXACT_NAMES, exact_values
from app.model.notation import checked_numbers, colour, colour_names, fraction
from app.model.tables import cell_text

CHECKPOINT = 4096  # steps between saved variable states


@dataclass(frozen=True)
class Column:
    """One column: the key of its cells in a row, and its heading."""

    key: str
    title: str
    kind: str = "fixed"  # "fixed", "variable", "table" or (JSON only) "exact"


FIXED_COLUMNS = (
    Column("step", "step"),
    Column("line", "line"),
    Column("code", "pseudo-code"),
    Column("pixel", "pixel"),
    Column("choice", "choice"),
)


class StepTable:
    """The rows of one trace's steps, made on demand (see the module text)."""

    def __init__(self, trace, numbers: str = "decimal"):
        self.trace = trace
        self.numbers = checked_numbers(numbers)
        self.colours = colour_names(trace.start)  # values that read as #rrggbb
        self.constants = dict(trace.start.constants)
        if self.numbers == "exact":
            self.constants.update(implied(trace))
        names = list(trace.value_names)
        self._checkpoints: list[tuple[int, dict]] = [(-1, {})]
        state: dict = {}
        next_checkpoint = CHECKPOINT
        for index, record in trace.records_of(Vars):
            while index >= next_checkpoint:
                self._checkpoints.append((next_checkpoint - 1, dict(state)))
                next_checkpoint += CHECKPOINT
            state.update(record.values)
            names.extend(name for name in record.values if name not in names)
        self._checkpoint_steps = [step for step, _ in self._checkpoints]
        self._tables = _table_steps(trace)
        self.columns = FIXED_COLUMNS + tuple(
            Column(name, name, "variable") for name in names) + tuple(
            Column(name, name, "table") for name in self._tables)

    def __len__(self) -> int:
        return len(self.trace)

    @property
    def keys(self) -> list[str]:
        return [column.key for column in self.columns]

    def row(self, i: int) -> dict:
        """Step i's cells by column key; a variable not known yet is absent."""
        if not 0 <= i < len(self.trace):
            raise IndexError(f"step {i} is outside 0..{len(self.trace) - 1}")
        step = self.trace.step(i)
        code = self.trace.code[step.line]
        cells = {"step": i, "line": step.line + 1, "code": code.text,
                 "pixel": _pixel(step), "choice": code.branch or None}
        cells.update(self._variables(i))
        cells.update(step.values)
        for name, steps in self._tables.items():
            at = bisect.bisect_right(steps, i)
            if at:
                cells[name] = self.trace.record_at(steps[at - 1])
        return cells

    def rows(self, lo: int = 0, hi: int | None = None):
        """The rows of steps lo .. hi - 1, one after another."""
        hi = len(self.trace) if hi is None else min(hi, len(self.trace))
        for i in range(max(lo, 0), hi):
            yield self.row(i)

    def text_row(self, i: int) -> list[str]:
        """Step i's cells as text, in column order ("" where nothing is known)."""
        cells = self.row(i)
        cells.update(self.exact_cells(i, cells))
        return [self._text(column.key, cells.get(column.key)) for column in self.columns]

    def _text(self, key: str, value) -> str:
        if key in self.colours and colour(value) is not None:
            return colour(value)
        return cell_to_text(value, self.numbers)

    def exact_cells(self, i: int, cells: dict | None = None) -> dict:
        """With "exact": step i's values that have an exact form, as
        Fractions (app/model/exact.py); else {}."""
        if self.numbers != "exact":
            return {}
        cells = self.row(i) if cells is None else cells
        return {name: value for name, value in exact_values(self.trace, i, cells).items()
                if name in cells}

    def exact_columns(self) -> tuple[Column, ...]:
        """With "exact": a column "<name>_exact" for each variable that can
        have an exact form (its p/q text, null at steps where it has none),
        for the JSON form; else none."""
        if self.numbers != "exact":
            return ()
        return tuple(Column(c.key, f"{c.key}_exact", "exact") for c in self.columns
                     if c.kind == "variable" and c.key in EXACT_NAMES)

    def _variables(self, i: int) -> dict:
        """The Vars values set at or before step i."""
        at = bisect.bisect_right(self._checkpoint_steps, i) - 1
        since, saved = self._checkpoints[at]
        values = dict(saved)
        for _, record in self.trace.records_of(Vars, lo=since + 1, hi=i + 1):
            values.update(record.values)
        return values


def _table_steps(trace) -> dict[str, list[int]]:
    """{table name: steps of its snapshots}, names in order of first appearance."""
    steps: dict[str, list[int]] = {}
    for index, record in trace.records_of(Table):
        steps.setdefault(record.name, []).append(index)
    return steps


def _pixel(step):
    """The pixel a step names, or (x_start, x_end - 1, y) for a Span's run."""
    if isinstance(step.record, Span):
        return ("span", step.record.x_start, step.record.x_end - 1, step.record.y)
    return step.pixel


def implied(trace) -> dict:
    """Exact values a run implies without recording them (Bresenham's m)."""
    return {name: value for name, value in exact_values(trace, 0).items()
            if name not in trace.start.constants and name not in trace.value_names}


def cell_to_text(value, numbers: str = "decimal") -> str:
    """A cell as plain text: tables as rows in brackets, runs as x0..x1."""
    if value is None:
        return ""
    if isinstance(value, Table):
        rows = ("[" + " ".join(f"{c}={cell_text(v, numbers)}" for c, v in zip(value.columns, row))
                + "]" for row in value.rows)
        return " ".join(rows) or "(empty)"
    if isinstance(value, tuple) and value and value[0] == "span":
        _, x0, x1, y = value
        return f"({x0}..{x1}, {y})"
    return cell_text(value, numbers)


def cell_to_json(value, numbers: str = "decimal"):
    """A cell as a JSON value: numbers stay numbers, tables become lists of
    rows. With ``numbers`` "exact" a table row gains "<column>_exact": "p/q"
    beside each cell that holds a fraction; every other field stays as it is."""
    if isinstance(value, Table):
        return [_json_table_row(value.columns, row, numbers) for row in value.rows]
    if isinstance(value, tuple) and value and value[0] == "span":
        _, x0, x1, y = value
        return {"x_start": x0, "x_end": x1, "y": y}
    if isinstance(value, tuple):
        return [cell_to_json(v) for v in value]
    if isinstance(value, float) and value.is_integer() and abs(value) < 2 ** 53:
        return int(value)  # lean values are stored as floats; counters read as integers
    if isinstance(value, (bool, int, float, str)) or value is None:
        return value
    return cell_text(value)  # fractions and anything else: their exact text


def _json_table_row(columns, row, numbers: str) -> dict:
    shown = dict(zip(columns, (cell_to_json(v) for v in row)))
    if numbers == "exact":
        shown.update((f"{c}_exact", fraction(v)) for c, v in zip(columns, row)
                     if isinstance(v, Fraction) and v.denominator != 1)
    return shown


def write_csv(table: StepTable, stream, lo: int = 0, hi: int | None = None) -> int:
    """Write the heading and rows lo .. hi - 1 as CSV to a text stream (text
    cells guarded against spreadsheet formulas: ``escape.csv_row``); the row count."""
    writer = csv.writer(stream, lineterminator="\n")
    writer.writerow(csv_row(column.title for column in table.columns))
    hi = len(table) if hi is None else min(hi, len(table))
    for i in range(max(lo, 0), hi):
        writer.writerow(csv_row(table.text_row(i)))
    return max(hi - max(lo, 0), 0)


def aligned_text(table: StepTable, lo: int = 0, hi: int | None = None) -> str:
    """Rows lo .. hi - 1 as a plain table with columns padded to line up."""
    hi = len(table) if hi is None else min(hi, len(table))
    body = [table.text_row(i) for i in range(max(lo, 0), hi)]
    heading = [column.title for column in table.columns]
    widths = [max([len(heading[c])] + [len(row[c]) for row in body])
              for c in range(len(heading))]
    lines = ["  ".join(text.ljust(width) for text, width in zip(row, widths)).rstrip()
             for row in [heading] + body]
    return "\n".join(lines)
