"""The step table written out a block of rows at a time, for `run --steps`.

``steptable.aligned_text`` builds every row at once, which a million-step
run cannot afford; here the column widths are measured in a first pass and
the rows written in a second, so memory stays at one block of rows.

With the table's ``numbers`` "exact", the JSON forms keep every field as it
is and add the exact values as "p/q" strings: a "<name>_exact" column per
variable that can have one, and "<column>_exact" in a table's rows.
"""
from __future__ import annotations

from app.model.notation import fraction
from app.model.steptable import StepTable, cell_to_json

BLOCK = 4096  # rows made and written at a time


def json_row(table: StepTable, i: int) -> list:
    """Step i's cells as JSON values, in column order (null where unknown)."""
    cells = table.row(i)
    row = [cell_to_json(cells.get(key), table.numbers) for key in table.keys]
    extra = table.exact_columns()
    if extra:
        exact = table.exact_cells(i, cells)
        row += [fraction(exact[c.key]) if c.key in exact else None for c in extra]
    return row


def json_columns(table: StepTable) -> list[dict]:
    """The columns for a JSON reader: key, heading and kind."""
    return [{"key": c.key if c.kind != "exact" else c.title, "title": c.title, "kind": c.kind}
            for c in table.columns + table.exact_columns()]


def write_aligned(table: StepTable, stream) -> int:
    """The table as plain text, columns padded to line up; the row count."""
    heading = [column.title for column in table.columns]
    widths = [len(title) for title in heading]
    for lo in range(0, len(table), BLOCK):
        for i in range(lo, min(lo + BLOCK, len(table))):
            widths = [max(w, len(text)) for w, text in zip(widths, table.text_row(i))]
    stream.write(_line(heading, widths))
    for lo in range(0, len(table), BLOCK):
        stream.write("".join(_line(table.text_row(i), widths)
                             for i in range(lo, min(lo + BLOCK, len(table)))))
    return len(table)


def _line(cells: list[str], widths: list[int]) -> str:
    return "  ".join(text.ljust(width) for text, width in zip(cells, widths)).rstrip() + "\n"


def json_step(table: StepTable, i: int) -> dict:
    """Step i as one dict of the cells `run --steps --json` gives: the fixed
    columns (step, line, code, pixel, choice) by key, then the variables and
    the tables known at that step under "variables" and "tables"."""
    cells = table.row(i)
    step, variables, tables = {}, {}, {}
    groups = {"fixed": step, "variable": variables, "table": tables}
    for column in table.columns:
        if column.key in cells:  # a variable not set yet is left out
            groups[column.kind][column.key] = cell_to_json(cells[column.key], table.numbers)
    for column in table.exact_columns():
        value = table.exact_cells(i, cells).get(column.key)
        if value is not None:
            variables[column.title] = fraction(value)
    step["variables"], step["tables"] = variables, tables
    return step
