"""Patterns drawn inside grid cells, so that colour is never the only cue.

A picture of one pixel per cell has no room for a pattern, so ``stamp``
enlarges it to ``scale`` x ``scale`` image pixels per cell and cuts each
cell's pattern into it in a mark colour (the ground the picture sits on).
The compare diff marks its classes this way (app/model/colours.py
DIFF_PATTERNS) and the coverage-error map hatches the cells with too little
coverage; the window shows the enlarged picture over the grid, and a file
gets the same array, so both show the same marks.

Images are (H, W, 4) uint8 with row 0 at y = 0, the bottom row of the
picture, so "stripes /" rise to the right as seen.
"""
from __future__ import annotations

import numpy as np

# Cells smaller than this many image pixels cannot hold a readable pattern.
MIN_SCALE = 4
MAX_SCALE = 8
# Enlarged pictures stay below this many image pixels a side.
MAX_SIDE = 2048


def pattern_scale(width: int, height: int) -> int:
    """Image pixels per cell for a grid of this size: MIN_SCALE .. MAX_SCALE,
    or 1 (no pattern) when the grid is too large for patterns to fit."""
    scale = min(MAX_SCALE, MAX_SIDE // max(width, height, 1))
    return scale if scale >= MIN_SCALE else 1


def mask(name: str, scale: int) -> np.ndarray:
    """(scale, scale) bool: the image pixels of one cell the pattern marks."""
    y, x = np.mgrid[0:scale, 0:scale]
    period = max(scale // 2, 3)  # at 2, "/" and "\\" would mark the same pixels
    if name == "plain":
        return np.zeros((scale, scale), bool)
    if name == "stripes /":
        return (x - y) % period == 0
    if name == "stripes \\":
        return (x + y) % period == 0
    if name == "cross":
        return (x == y) | (x + y == scale - 1)
    raise ValueError(f"no pattern called {name!r}")


def stamp(image: np.ndarray, kinds: np.ndarray, names, mark: tuple, scale: int) -> np.ndarray:
    """``image`` (one pixel per cell) enlarged ``scale`` times, with the
    pattern ``names[k]`` cut in colour ``mark`` (r, g, b) into every cell
    whose ``kinds`` value is k (a negative kind gets no pattern)."""
    big = np.repeat(np.repeat(image, scale, axis=0), scale, axis=1)
    if scale < MIN_SCALE:
        return big
    height, width = kinds.shape
    for k, name in enumerate(names):
        cells = np.repeat(np.repeat(kinds == k, scale, axis=0), scale, axis=1)
        marked = cells & np.tile(mask(name, scale), (height, width))
        big[marked, :3] = mark
    return big
