"""The pixel difference of a submission's first failing case, as a picture
for a grader: a PNG (as a data URI, for PrairieLearn) or an inline SVG (for
CodeRunner's feedback HTML). Grey: pixels both the reference and the
student give; blue: pixels only the reference gives (missing); red: pixels
only the student gives (extra). y grows upward, as on RasterLab's grid.
"""
from __future__ import annotations

import base64
import io
from dataclasses import dataclass

COLOURS = {"both": (158, 158, 158), "missing": (31, 119, 180), "extra": (214, 39, 40)}
LEGEND = "grey: both; blue: expected only (missing); red: yours only (extra)"
MAX_CELLS = 128  # a side of the picture, in pixels of the grid: the rest is cut off
PNG_SIDE = 512   # the largest side of the PNG, in its own pixels


@dataclass(frozen=True)
class Difference:
    """The case's name and the pixels the reference and the student gave."""

    name: str
    expected: frozenset
    got: frozenset

    def cells(self) -> tuple[dict, tuple]:
        """{(column, row): kind} within the picture's window, and its (columns, rows)."""
        union = self.expected | self.got
        if not union:
            return {}, (1, 1)
        x0, y0 = min(x for x, _ in union), min(y for _, y in union)
        columns = min(MAX_CELLS, max(x for x, _ in union) - x0 + 1)
        rows = min(MAX_CELLS, max(y for _, y in union) - y0 + 1)
        cells = {}
        for x, y in union:
            column, row = x - x0, rows - 1 - (y - y0)  # y up
            if 0 <= column < columns and 0 <= row < rows:
                cells[column, row] = ("both" if (x, y) in self.expected and (x, y) in self.got
                                      else "missing" if (x, y) in self.expected else "extra")
        return cells, (columns, rows)


def difference(graded, plan) -> Difference | None:
    """The first failing case that ran, as a Difference (None: none failed)."""
    for case, (_, _, expected) in zip(graded.cases, plan.cases):
        if not case.passed and not case.skipped:
            return Difference(case.name, _pixels(expected), _pixels(case.result.outcome.steps))
    return None


def _pixels(steps) -> frozenset:
    return frozenset((int(step[0]), int(step[1])) for step in steps)


def png_data_uri(diff: Difference) -> str:
    """The difference as a PNG, as a ``data:image/png;base64,...`` URI."""
    from PIL import Image, ImageDraw
    cells, (columns, rows) = diff.cells()
    size = max(1, min(8, PNG_SIDE // max(columns, rows)))
    image = Image.new("RGB", (columns * size, rows * size), (255, 255, 255))
    draw = ImageDraw.Draw(image)
    for (column, row), kind in cells.items():
        draw.rectangle([column * size, row * size, (column + 1) * size - 1, (row + 1) * size - 1],
                       fill=COLOURS[kind])
    out = io.BytesIO()
    image.save(out, format="PNG", optimize=True)
    return "data:image/png;base64," + base64.b64encode(out.getvalue()).decode("ascii")


def svg(diff: Difference, cell: int = 8) -> str:
    """The difference as an inline SVG element (numbers and fixed names only)."""
    cells, (columns, rows) = diff.cells()
    fill = {kind: "#%02x%02x%02x" % rgb for kind, rgb in COLOURS.items()}
    rects = "".join(f'<rect x="{column * cell}" y="{row * cell}" width="{cell}" '
                    f'height="{cell}" fill="{fill[kind]}"/>'
                    for (column, row), kind in sorted(cells.items()))
    width, height = columns * cell, rows * cell
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" role="img">'
            f'<rect width="{width}" height="{height}" fill="#ffffff"/>{rects}</svg>')
