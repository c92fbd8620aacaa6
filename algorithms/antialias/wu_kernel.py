"""Xiaolin Wu's lines in numpy: the generator's pixels and intensities at once.

In column u of a segment mapped into the first octant (``Octant``), the
generator's error term is e = u dy mod dx and its row v = u dy div dx; the
near pixel (u, v) takes (dx - e) / dx and the far one (u, v + 1) takes
e / dx, written only when that is above 0 (the line passes through the
near pixel's centre otherwise). Both are computed for every column of every
segment at once, in the generator's order (near, then far, column after
column) and with its float operations, so the intensities agree to the
last bit. The extents are below 2^31 (the inputs' bound), so u dy fits in
int64.
"""
from __future__ import annotations

import numpy as np

from algorithms.lines.batch import octants
from algorithms.core.compiled import compiled


def wu_pixels(points, options) -> tuple[np.ndarray, np.ndarray]:
    """The kernel of ``line-wu``: ((n, 2) pixels, (n,) intensities), as the
    generator writes them."""
    p, q = points
    pixels, intensity, _ = wu_lines([p], [q], options.get("endpoints", "full"))
    return pixels, intensity


def wu_lines(starts, ends, endpoints: str = "full"):
    """Wu's lines starts[k] -> ends[k] (integer (m, 2) arrays): ((n, 2) pixels,
    (n,) intensities, (n,) segment index), segment after segment, each as
    ``wu_pixels`` gives it. ``endpoints`` "gap" halves the two end columns."""
    p, steep, sx, sy, dx, dy = octants(starts, ends)
    major = np.stack([np.where(steep, 0, sx), np.where(steep, sy, 0)], axis=1)
    minor = np.stack([np.where(steep, sx, 0), np.where(steep, 0, sy)], axis=1)
    segment = np.repeat(np.arange(len(p)), dx + 1)
    first = np.cumsum(dx + 1) - (dx + 1)
    u = np.arange(len(segment), dtype=np.int64) - first[segment]
    n, m = dx[segment], dy[segment]
    safe = np.maximum(n, 1)  # a point (dx = 0): u = 0, e = 0, v = 0
    e, v = (u * m) % safe, (u * m) // safe
    scale = np.ones(len(u))
    if endpoints == "gap":
        scale[(u == 0) | (u == n)] = 0.5
    # The generator's own operations: (dx - e) / dx * scale and e / dx * scale.
    near = (n - e) / safe * scale
    near[n == 0] = 1.0  # a point is one whole pixel, whatever the endpoints
    far = e / safe * scale
    base = p[segment] + u[:, None] * major[segment] + v[:, None] * minor[segment]
    pixels = np.stack([base, base + minor[segment]], axis=1)  # (columns, near/far, 2)
    intensity = np.stack([near, far], axis=1)
    keep = np.stack([np.ones(len(u), bool), e > 0], axis=1)
    return (pixels[keep], intensity[keep],
            np.broadcast_to(segment[:, None], keep.shape)[keep])


def draw_wu_lines(canvas: np.ndarray, starts, ends, endpoints: str = "full",
                  level: float = 255.0) -> np.ndarray:
    """Write level x intensity of Wu's lines starts[k] -> ends[k] into the 2-D
    ``canvas`` (indexed [y, x]; the value cast as numpy casts it), the pixels
    ``wu_lines`` gives in its order, those off the canvas left out. A
    compiled loop: for many short lines the numpy form spends its time on
    the temporary arrays. Returns the canvas."""
    p = np.ascontiguousarray(np.asarray(starts, np.int64).reshape(-1, 2))
    q = np.ascontiguousarray(np.asarray(ends, np.int64).reshape(-1, 2))
    _draw_wu(canvas, p, q, endpoints == "gap", float(level))
    return canvas


@compiled
def _draw_wu(canvas, starts, ends, gap, level):  # pragma: no cover - compiled
    height, width = canvas.shape
    for k in range(len(starts)):
        x0, y0 = starts[k, 0], starts[k, 1]
        ddx, ddy = ends[k, 0] - x0, ends[k, 1] - y0
        sx = 1 if ddx >= 0 else -1
        sy = 1 if ddy >= 0 else -1
        if abs(ddy) > abs(ddx):  # steep: y is the major axis
            dx, dy, mx, my, nx, ny = abs(ddy), abs(ddx), 0, sy, sx, 0
        else:
            dx, dy, mx, my, nx, ny = abs(ddx), abs(ddy), sx, 0, 0, sy
        if dx == 0:
            if 0 <= x0 < width and 0 <= y0 < height:
                canvas[y0, x0] = level
            continue
        e = v = 0
        for u in range(dx + 1):
            scale = 0.5 if gap and (u == 0 or u == dx) else 1.0
            x, y = x0 + u * mx + v * nx, y0 + u * my + v * ny
            if 0 <= x < width and 0 <= y < height:
                canvas[y, x] = (dx - e) / dx * scale * level
            if e > 0 and 0 <= x + nx < width and 0 <= y + ny < height:
                canvas[y + ny, x + nx] = e / dx * scale * level
            e += dy
            if e >= dx:
                e -= dx
                v += 1
