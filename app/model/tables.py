"""Which table snapshots belong to a step, and what changed in them.

An algorithm may yield ``Table`` records (a scan-line fill's edge table and
active edge table, a triangle's edge equations). At step i the tables panel
shows, for each table name, the latest snapshot taken at or before step i,
with the rows that are new or changed since that table's snapshot before
it. Nothing here imports Qt.
"""
from __future__ import annotations

import bisect
from dataclasses import dataclass, field
from fractions import Fraction

from algorithms.core.steps import Table

from app.model.notation import checked_numbers, fraction, number

# A fraction is shown as a decimal when that decimal is exact and this short.
MAX_DECIMALS = 6


@dataclass(frozen=True)
class ShownTable:
    """One table as the panel shows it.

    ``rows`` hold the text of each cell, in the order the algorithm gave
    them. ``changed_rows`` are rows that are new or differ from the previous
    snapshot of the same table; ``changed_cells`` (row, column) the cells
    that differ within a row that was there before. ``step`` is the step the
    snapshot was taken at; ``fresh`` says it was taken at the step on show.
    """

    name: str
    columns: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    step: int
    fresh: bool = False
    changed_rows: frozenset = field(default_factory=frozenset)
    changed_cells: frozenset = field(default_factory=frozenset)
    tooltips: dict = field(default_factory=dict)  # (row, column) -> longer text


class TableIndex:
    """The Table records of one trace, by name, for lookup at any step."""

    def __init__(self, trace, numbers: str = "decimal"):
        self.trace = trace
        self.numbers = checked_numbers(numbers)  # app/model/notation.py: decimal or exact
        self.names: list[str] = []  # in the order the tables first appear
        self._steps: dict[str, list[int]] = {}
        # Formatted snapshots by (record step, fresh): playing a long run
        # formats each snapshot once, and the panel skips what it shows.
        self._cache: dict[tuple[int, bool], ShownTable] = {}
        if trace is None:
            return
        for index, record in trace.records_of(Table):
            if record.name not in self._steps:
                self.names.append(record.name)
                self._steps[record.name] = []
            self._steps[record.name].append(index)

    def __bool__(self) -> bool:
        return bool(self.names)

    def at(self, index: int) -> list[ShownTable]:
        """Each table as of step ``index``, in order of first appearance."""
        shown = []
        for name in self.names:
            steps = self._steps[name]
            k = bisect.bisect_right(steps, index) - 1
            if k < 0:
                continue
            key = (steps[k], steps[k] == index)
            if key not in self._cache:
                record = self.trace.record_at(steps[k])
                before = self.trace.record_at(steps[k - 1]) if k > 0 else None
                self._cache[key] = _shown(record, before, *key, self.numbers)
            shown.append(self._cache[key])
        return shown


def _shown(record: Table, before: Table | None, step: int, fresh: bool,
           numbers: str = "decimal") -> ShownTable:
    rows = tuple(tuple(cell_text(v, numbers) for v in row) for row in record.rows)
    tips = {(r, c): cell_tip(v, numbers) for r, row in enumerate(record.rows)
            for c, v in enumerate(row) if cell_tip(v, numbers) != rows[r][c]}
    changed_rows, changed_cells = changes(record, before)
    return ShownTable(record.name, tuple(record.columns), rows, step, fresh,
                      frozenset(changed_rows), frozenset(changed_cells), tips)


def changes(record: Table, before: Table | None) -> tuple[set[int], set[tuple[int, int]]]:
    """Rows of ``record`` that are new or changed since ``before``, and the
    cells that changed in rows that were there before.

    Rows are matched by a key column: the first column whose values are
    distinct in both snapshots and the same in both headers (an edge's
    name, say). Without one, a row counts as changed when no equal row was
    there before. The first snapshot of a table has nothing to compare with
    and marks nothing.
    """
    if before is None:
        return set(), set()
    key = _key_column(record, before)
    if key is None or tuple(before.columns) != tuple(record.columns):
        old = list(before.rows)
        changed = set()
        for r, row in enumerate(record.rows):
            if row in old:
                old.remove(row)
            else:
                changed.add(r)
        return changed, set()
    old = {row[key]: row for row in before.rows}
    rows, cells = set(), set()
    for r, row in enumerate(record.rows):
        previous = old.get(row[key])
        if previous is None:
            rows.add(r)
            continue
        differ = {(r, c) for c, (a, b) in enumerate(zip(row, previous)) if a != b}
        if differ:
            rows.add(r)
            cells |= differ
    return rows, cells


def _key_column(record: Table, before: Table) -> int | None:
    for c, name in enumerate(record.columns):
        if c >= len(before.columns) or before.columns[c] != name:
            continue
        now = [row[c] for row in record.rows]
        then = [row[c] for row in before.rows]
        if all(isinstance(v, str) for v in now + then) and len(set(now)) == len(now) \
                and len(set(then)) == len(then):
            return c
    return None


def cell_text(value, numbers: str = "decimal") -> str:
    """Short text for a cell.

    With ``numbers`` "decimal", a fraction whose decimal is exact and short
    reads as that decimal (37/16 -> 2.3125); any other as a rounded decimal
    marked as such (296/15 -> ~19.733), the exact fraction being in the
    cell's tooltip. With "exact", every fraction reads as p/q (-5/2).
    A float reads to five significant figures (``notation.number``: the
    drift of a near tie stays visible).
    """
    if isinstance(value, Fraction):
        if value.denominator == 1 or numbers == "exact":
            return fraction(value)
        decimal = _exact_decimal(value)
        if decimal is not None:
            return decimal
        return f"\u2248{float(value):.5g}"
    if isinstance(value, tuple):
        return "(" + ", ".join(cell_text(v, numbers) for v in value) + ")"
    return number(value)


def cell_tip(value, numbers: str = "decimal") -> str:
    """The exact value and its decimal, for a tooltip."""
    if isinstance(value, Fraction) and value.denominator != 1:
        return f"{fraction(value)} = {float(value)!r}"
    return cell_text(value, numbers)


def _exact_decimal(value: Fraction) -> str | None:
    scaled = value * 10 ** MAX_DECIMALS
    if scaled.denominator != 1:
        return None
    sign = "-" if scaled < 0 else ""
    digits = str(abs(scaled.numerator)).rjust(MAX_DECIMALS + 1, "0")
    whole, frac = digits[:-MAX_DECIMALS], digits[-MAX_DECIMALS:].rstrip("0")
    return f"{sign}{whole}.{frac}" if frac else f"{sign}{whole}"
