"""Many segments in one numpy call: the kernels for large workloads.

A registered kernel draws one primitive per call, and for small primitives
the cost of the call outweighs the drawing (ten thousand short lines spend
most of their time entering numpy). These functions take all primitives
at once and give the same pixels as the per-primitive kernels, in the same
order, primitive after primitive, with the index of the primitive of each
pixel.
"""
from __future__ import annotations

import numpy as np



def octants(starts, ends):
    """Each segment starts[k] -> ends[k] mapped into the first octant:
    (starts as (m, 2) int64, steep, x step, y step, dx, dy), where dx is the
    extent along the major axis and dy across it, both >= 0."""
    p = np.asarray(starts, np.int64).reshape(-1, 2)
    q = np.asarray(ends, np.int64).reshape(-1, 2)
    ddx, ddy = q[:, 0] - p[:, 0], q[:, 1] - p[:, 1]
    steep = np.abs(ddy) > np.abs(ddx)
    sx, sy = np.where(ddx >= 0, 1, -1), np.where(ddy >= 0, 1, -1)
    dx = np.where(steep, np.abs(ddy), np.abs(ddx))
    dy = np.where(steep, np.abs(ddx), np.abs(ddy))
    return p, steep, sx, sy, dx, dy


def bresenham_lines(starts, ends, symmetric: bool = False):
    """Bresenham's pixels of the segments starts[k] -> ends[k] (integer
    (m, 2) arrays): ((n, 2) pixels, (n,) segment index), as
    ``lines.bresenham_pixels`` gives them one segment at a time."""
    p, steep, sx, sy, dx, dy = octants(starts, ends)
    # Octant's unit steps: along the major axis and across it.
    major_x, major_y = np.where(steep, 0, sx), np.where(steep, sy, 0)
    minor_x, minor_y = np.where(steep, sx, 0), np.where(steep, 0, sy)
    # The textbook's tie goes to E; `symmetric` rounds the minor coordinate down.
    ties_to_e = np.logical_or(not symmetric, minor_x + minor_y > 0)
    segment = np.repeat(np.arange(len(p)), dx + 1)
    first = np.cumsum(dx + 1) - (dx + 1)
    u = np.arange(len(segment), dtype=np.int64) - first[segment]
    n, m = dx[segment], dy[segment]
    twice = np.maximum(2 * n, 1)  # a point (dx = 0) has u = 0 and v = 0
    v = np.where(ties_to_e[segment], -((n - 2 * m * u) // twice), (2 * m * u + n) // twice)
    x = p[segment, 0] + u * major_x[segment] + v * minor_x[segment]
    y = p[segment, 1] + u * major_y[segment] + v * minor_y[segment]
    return np.stack([x, y], axis=1), segment
