"""The window's grid picture, patched cell by cell while the person steps.

Composing a 4096 x 4096 grid touches 16 million cells; a step writes a
handful. ``StepImages`` keeps the last picture and, when the next step on
show is of the same run and a few steps away, recolours only the cells the
steps in between wrote (``Trace.written``), with the same colouring as
``compose`` (``cell_colors``, ``coverage_colors``). Anything else (another
run, palette or mode, a long jump) composes the whole picture afresh.
``changed`` then says which cells the last call recoloured, so that the
window repaints only that rectangle of the grid.
"""
from __future__ import annotations

import numpy as np

from app.render.compose import cell_colors, compose, coverage_colors

# Beyond this many steps a jump recomposes: the written cells of a long
# stretch can be as many as the grid's.
MOST_STEPS = 4096


class StepImages:
    """The (H, W, 4) uint8 picture of a run's step, as ``compose`` makes it."""

    def __init__(self):
        self._key = None
        self._index = -1
        self._image: np.ndarray | None = None
        #: Cells recoloured by the last ``image`` call, as (x0, y0, x1, y1)
        #: with x1, y1 exclusive (empty when x0 == x1), or None when the
        #: picture was composed afresh (it is then a new array).
        self.changed: tuple[int, int, int, int] | None = None

    def image(self, trace, state, palette, coverage: bool = False) -> np.ndarray:
        """The picture of ``state`` (a FrameState of ``trace``); the array
        returned is the one patched next time, so show it, do not keep it."""
        raster = state.raster
        # The run and palette themselves are kept (not their ids, which a
        # new object may take once they are gone).
        key = (trace, palette, bool(coverage), raster.counts.shape,
               bool(getattr(raster, "replaces", False)), raster.colors is None)
        near = abs(state.index - self._index) <= MOST_STEPS
        if not self._same(key) or not near or self._image is None:
            self._image = compose(raster, None, palette, coverage=coverage)
            self.changed = None
        elif state.index != self._index:
            self.changed = self._patch(trace, state, palette, coverage)
        else:
            self.changed = (0, 0, 0, 0)
        self._key, self._index = key, state.index
        return self._image

    def _same(self, key) -> bool:
        return (self._key is not None and key[0] is self._key[0] and key[1] is self._key[1]
                and key[2:] == self._key[2:])

    def _patch(self, trace, state, palette, coverage: bool) -> tuple[int, int, int, int]:
        lo, hi = sorted((self._index, state.index))
        pixels = trace.written(lo + 1, hi + 1).pixels
        raster = state.raster
        height, width = raster.counts.shape
        x, y = pixels[:, 0], pixels[:, 1]
        inside = (x >= 0) & (x < width) & (y >= 0) & (y < height)
        flat = np.unique(y[inside] * width + x[inside])
        counts = raster.counts.reshape(-1)[flat]
        if coverage:
            colours = coverage_colors(counts, palette)
        else:
            colors = None if raster.colors is None else raster.colors.reshape(-1)[flat]
            colours = cell_colors(counts, colors, getattr(raster, "replaces", False), palette)
        self._image.view(np.uint32).reshape(-1)[flat] = colours
        if not len(flat):
            return (0, 0, 0, 0)
        rows, columns = np.divmod(flat, width)
        return (int(columns.min()), int(rows[0]), int(columns.max()) + 1, int(rows[-1]) + 1)
