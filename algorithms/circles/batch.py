"""Many midpoint circles in one numpy call: the kernels for large workloads.

``midpoint_circles`` gives the pixels of many circles as one array, as
``algorithms/lines/batch.py`` does for segments. A caller that only wants a
picture would then scatter them into its canvas with a second fancy index;
``draw_midpoint_circles`` puts them into the canvas at once, by flat index,
and the index arrays of the per-circle form are never made: for a thousand
small circles that halves the time.
"""
from __future__ import annotations

import numpy as np

from algorithms.circles.midpoint import midpoint_circle_pixels


def midpoint_circles(centres, radius: int):
    """The midpoint circle of ``radius`` around each integer centre:
    ((n, 2) pixels, (n,) circle index), as ``midpoint_circle_pixels``
    gives them one circle at a time (the pixels of a circle around (0, 0),
    moved)."""
    centres = np.asarray(centres, np.int64).reshape(-1, 2)
    offsets = midpoint_circle_pixels([(0, 0)], {"radius": int(radius)})
    pixels = centres[:, None, :] + offsets[None, :, :]
    return pixels.reshape(-1, 2), np.repeat(np.arange(len(centres)), len(offsets))


def draw_midpoint_circles(canvas: np.ndarray, centres, radius: int, value=1) -> np.ndarray:
    """Set the midpoint circle of ``radius`` around each integer centre to
    ``value`` in ``canvas`` (indexed [y, x], any trailing channel axis);
    pixels off the canvas are left out. The same pixels as
    ``midpoint_circles``; returns the canvas."""
    centres = np.asarray(centres, np.int64).reshape(-1, 2)
    radius = int(radius)
    height, width = canvas.shape[:2]
    whole = ((centres[:, 0] >= radius) & (centres[:, 0] < width - radius)
             & (centres[:, 1] >= radius) & (centres[:, 1] < height - radius))
    if not canvas.flags.c_contiguous:
        whole[:] = False  # no flat view to write through: every circle takes the slow path
    if whole.any():
        offsets = midpoint_circle_pixels([(0, 0)], {"radius": radius})
        # A circle wholly on the canvas needs no clipping: its flat indices
        # are its centre's plus the offsets'.
        starts = centres[whole, 1] * width + centres[whole, 0]
        steps = offsets[:, 1] * width + offsets[:, 0]
        flat = canvas.reshape(height * width, *canvas.shape[2:])
        flat[(starts[:, None] + steps[None, :]).ravel()] = value
    if not whole.all():
        pixels, _ = midpoint_circles(centres[~whole], radius)
        x, y = pixels[:, 0], pixels[:, 1]
        on = (x >= 0) & (x < width) & (y >= 0) & (y < height)
        canvas[y[on], x[on]] = value
    return canvas
