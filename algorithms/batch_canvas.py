"""Batched kernels that write straight into a canvas.

``batch.py`` gives the pixels of many primitives as one array, and a caller
that only wants a picture then scatters them into its canvas with a second
fancy index. Here the pixels go into the canvas at once, by flat index, and
the index arrays of the per-primitive form are never made: for a thousand
small circles that halves the time.
"""
from __future__ import annotations

import numpy as np

from .batch import midpoint_circles
from .circles import midpoint_circle_pixels


def draw_midpoint_circles(canvas: np.ndarray, centres, radius: int, value=1) -> np.ndarray:
    """Set the midpoint circle of ``radius`` around each integer centre to
    ``value`` in ``canvas`` (indexed [y, x], any trailing channel axis);
    pixels off the canvas are left out. The same pixels as
    ``batch.midpoint_circles``; returns the canvas."""
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
