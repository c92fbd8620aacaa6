"""The framebuffer state a trace replays into."""
from __future__ import annotations

import numpy as np

MAX_GRID = 4096
NO_COLOR = -1  # stored in the colour buffer where no value was written


class Raster:
    """Pixels of a W x H grid, row 0 at y = 0.

    ``counts`` says how often each pixel was written (duplicates show as
    counts above one); ``colors`` holds the last packed 0xRRGGBB value
    written, and exists only when the run writes values. ``depth`` holds the
    last depth written (NaN where none was), and exists only when the run
    keeps a depth buffer (``Start.depth_value``).
    """

    depth = None  # set by __init__; a class default keeps hand-made rasters valid
    replaces = False  # Start.replaces of the run: writing again is not overdraw

    def __init__(self, width: int, height: int, with_colors: bool = False,
                 with_depth: bool = False):
        check_grid(width, height)
        self.width = width
        self.height = height
        self.counts = np.zeros((height, width), dtype=np.int32)
        self.colors = np.full((height, width), NO_COLOR, np.int64) if with_colors else None
        self.depth = np.full((height, width), np.nan) if with_depth else None

    def copy(self) -> "Raster":
        other = Raster.__new__(Raster)
        other.width, other.height = self.width, self.height
        other.counts = self.counts.copy()
        other.colors = None if self.colors is None else self.colors.copy()
        other.depth = None if self.depth is None else self.depth.copy()
        other.replaces = self.replaces
        return other

    def inside(self, x: int, y: int) -> bool:
        return 0 <= x < self.width and 0 <= y < self.height

    def write(self, x: int, y: int, value=None, depth=None) -> None:
        """Write one pixel; pixels outside the grid are clipped."""
        if not self.inside(x, y):
            return
        self.counts[y, x] += 1
        if self.colors is not None and value is not None and value == value:  # NaN: no colour
            self.colors[y, x] = int(value)
        if self.depth is not None and depth is not None and depth == depth:  # NaN: no depth
            self.depth[y, x] = float(depth)

    def write_many(self, flat: np.ndarray, values: np.ndarray | None = None,
                   depths: np.ndarray | None = None) -> None:
        """Write pixels given as flat indices y * W + x, in order.

        Negative indices stand for pixels outside the grid and are skipped;
        a NaN value writes no colour, a NaN depth no depth.
        """
        keep = flat >= 0
        flat = flat[keep]
        if flat.size == 0:
            return
        _add_counts(self.counts.reshape(-1), flat)
        if self.colors is not None and values is not None:
            values = values[keep]
            valued = ~np.isnan(values)
            _write_last(self.colors.reshape(-1), flat[valued], values[valued])
        if self.depth is not None and depths is not None:
            depths = depths[keep]
            valued = ~np.isnan(depths)
            _write_last(self.depth.reshape(-1), flat[valued], depths[valued])

    def written(self) -> np.ndarray:
        """Boolean mask of pixels written at least once."""
        return self.counts > 0

    def bytes(self) -> int:
        extra = 0 if self.colors is None else self.colors.nbytes
        extra += 0 if self.depth is None else self.depth.nbytes
        return self.counts.nbytes + extra


def _add_counts(counts: np.ndarray, flat: np.ndarray) -> None:
    """counts[flat] += 1 for every entry, repeats included."""
    low, high = int(flat.min()), int(flat.max())
    if high - low < 16 * flat.size:
        # The writes of a few steps lie close together: counting them over
        # their range is many times faster than np.add.at's per-entry loop.
        counts[low:high + 1] += np.bincount(flat - low).astype(counts.dtype, copy=False)
    else:
        np.add.at(counts, flat, 1)


def _write_last(target: np.ndarray, flat: np.ndarray, values: np.ndarray) -> None:
    # Where a pixel is written more than once the last write must win;
    # np.unique on the reversed order finds each pixel's last write.
    reversed_flat = flat[::-1]
    pixels, first = np.unique(reversed_flat, return_index=True)
    target[pixels] = values[::-1][first].astype(target.dtype)


def check_grid(width: int, height: int) -> None:
    if not (1 <= width <= MAX_GRID and 1 <= height <= MAX_GRID):
        raise ValueError(
            f"grid {width}x{height} is outside 1x1 .. {MAX_GRID}x{MAX_GRID}")


def canvas_for(grid, canvas):
    """The picture a batched fill writes into: ``canvas`` as given, checked
    against the grid, or int32 zeros (coverage counts) when it is None."""
    width, height = grid
    if canvas is None:
        return np.zeros((height, width), np.int32)
    if canvas.shape != (height, width):
        raise ValueError(f"the canvas is {canvas.shape}, the grid needs {(height, width)}")
    return canvas
