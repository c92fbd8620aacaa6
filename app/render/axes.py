"""Coordinate axes beside an exported grid: ticks at the cell boundaries,
which are the integer coordinates (pixel i is [i, i+1)), labelled often
enough to read and never crowded; in both origins. When a cell is large
enough to hold its number, the labels name the cells instead, each at
its cell's centre i + 1/2 between two boundary ticks."""
from __future__ import annotations

import numpy as np
from PIL import Image, ImageDraw

STEPS = (1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000)


def label_step(scale: int, widest: int) -> int:
    """The smallest of 1, 2, 5, 10, ... cells between labels that leaves
    room for the widest label and a gap."""
    for step in STEPS:
        if step * scale >= widest + 6:
            return step
    return STEPS[-1]


class Axes:
    """The axis strips of one export, drawn once as palette indices.

    ``left`` and ``bottom`` are the strips' sizes in pixels; ``strip(…)``
    gives the left strip (next to the grid, as tall as the grid plus the
    bottom strip) and the bottom strip (under the grid).
    """

    def __init__(self, renderer, face, tick: int):
        self.r = renderer
        self.face = face
        width, height = renderer.trace.width, renderer.trace.height
        self.tick = tick
        widest = max(face.width(str(width)), face.width(str(height)))
        self.left = widest + 2 * tick + 2
        self.bottom = face.ascent + face.descent + 2 * tick
        self.scale = renderer.settings.scale
        self.step_x = label_step(self.scale, widest)
        self.step_y = label_step(self.scale, face.ascent + face.descent)
        # Cells numbered at their centres when every number fits in its
        # cell; both axes alike, never cell numbers on one and boundaries
        # on the other.
        self.cells_x = self.cells_y = self.scale >= max(
            face.width(str(max(width, height) - 1)) + 6, face.ascent + face.descent + 2)

    def label_at(self, k: int, count: int, cells: bool, step: int) -> float | None:
        """Where along the axis, in cells, boundary k's label goes: at k
        (every ``step``-th boundary), or at the centre k + 1/2 of cell k
        when cells are labelled; None for no label."""
        if cells:
            return k + 0.5 if k < count else None
        return float(k) if k % step == 0 else None

    def ticks(self, count: int) -> list[int]:
        """The integer coordinates 0 .. count (every cell boundary)."""
        return list(range(count + 1))

    def draw(self) -> tuple[np.ndarray, np.ndarray]:
        """(left strip, bottom strip) as palette indices."""
        r, theme = self.r, self.r.theme
        gw, gh = r.grid_size
        left = Image.new("RGBA", (self.left, gh + self.bottom), theme.palette.outside)
        bottom = Image.new("RGBA", (gw, self.bottom), theme.palette.outside)
        self.paint(ImageDraw.Draw(left), ImageDraw.Draw(bottom))
        colours = r.colours
        return colours.indices(np.asarray(left)), colours.indices(np.asarray(bottom))

    def paint(self, ld, bd) -> None:
        """The ticks and labels onto the left strip's ``ld`` and the bottom
        strip's ``bd`` (Pillow's, or a vector frame's: app/render/vector.py)."""
        r, theme = self.r, self.r.theme
        gw, gh = r.grid_size
        half_height = (self.face.ascent + self.face.descent) // 2
        for k in self.ticks(r.trace.width):
            x = min(gw - 1, k * self.scale)
            at = self.label_at(k, r.trace.width, self.cells_x, self.step_x)
            long = self.cells_x or k % self.step_x == 0
            bd.line((x, 0, x, self.tick * (2 if long else 1) - 1), fill=theme.muted)
            if at is None:
                continue
            x = at * self.scale
            half = self.face.width(str(k)) // 2 + 1
            # A label that would not fit whole is left out, not pushed
            # onto its neighbour.
            if (x - half >= 0 or k == 0) and x + half <= gw:
                bd.text((max(x, half), 2 * self.tick), str(k), font=self.face.face,
                        fill=theme.text, anchor="mt")
        for k in self.ticks(r.trace.height):
            y = min(gh - 1, self._row(k))
            at = self.label_at(k, r.trace.height, self.cells_y, self.step_y)
            long = self.cells_y or k % self.step_y == 0
            ld.line((self.left - self.tick * (2 if long else 1), y, self.left - 1, y),
                    fill=theme.muted)
            if at is None:
                continue
            y = self._row(at)
            if y - half_height >= 0 and y + half_height <= gh + self.bottom:
                ld.text((self.left - 2 * self.tick - 2, y), str(k), font=self.face.face,
                        fill=theme.text, anchor="rm")

    def _row(self, value: float) -> float:
        """The image row of coordinate y = ``value`` in the scene's origin."""
        scaled = value * self.scale
        return scaled if self.r.y_down else self.r.grid_size[1] - scaled
