"""The step table written out a block of rows at a time, for `run --steps`.

``steptable.aligned_text`` builds every row at once, which a million-step
run cannot afford; here the column widths are measured in a first pass and
the rows written in a second, so memory stays at one block of rows.
"""
from __future__ import annotations

from app.model.steptable import StepTable, cell_to_json

BLOCK = 4096  # rows made and written at a time


def json_row(table: StepTable, i: int) -> list:
    """Step i's cells as JSON values, in column order (null where unknown)."""
    cells = table.row(i)
    return [cell_to_json(cells.get(key)) for key in table.keys]


def json_columns(table: StepTable) -> list[dict]:
    """The columns for a JSON reader: key, heading and kind."""
    return [{"key": c.key, "title": c.title, "kind": c.kind} for c in table.columns]


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
            groups[column.kind][column.key] = cell_to_json(cells[column.key])
    step["variables"], step["tables"] = variables, tables
    return step
