"""The fastest exact triangle fill: spans written straight into a canvas.

``fill_canvas`` finds each row's run of a triangle exactly as the span
kernel does (per edge, A i + R > 0 bounds the column i by one floor
division) but, instead of building arrays of spans and pixels, a compiled
loop writes every run into the caller's canvas as it finds it. Triangles
whose edge terms do not fit int64 take the span kernel's Python-integer
path and are written from its spans, so the result stays exact at any size.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from algorithms.core.compiled import compiled
from algorithms.core.raster import canvas_for
from algorithms.core.registry import InputError

from .kernels import _spans_python, oriented, snap_array

RULES = {"top-left": 0, "inclusive": 1, "strict": 2}


def fill_canvas(points, grid, canvas=None, value=None, rule: str = "top-left",
                subpixel_bits: int = 8, cull: bool = False) -> np.ndarray:
    """Fill k triangles (3k points, pixel units, y up) into a (H, W) canvas; returns it.

    Pixel (x, y) is ``canvas[y, x]``. With ``value`` None every covered
    pixel is counted (+1 per triangle, the coverage counts of ``fill``);
    otherwise covered pixels are set to ``value``. ``canvas`` defaults to
    int32 zeros; a given one is written in place (any integer or float
    dtype, e.g. a uint8 picture).
    """
    if rule not in RULES:
        raise InputError(f"unknown fill rule {rule!r}; choose one of {', '.join(RULES)}")
    canvas = canvas_for(grid, canvas)
    scale = 1 << subpixel_bits
    snapped = snap_array(points, scale)
    if len(snapped) % 3:
        raise InputError(f"triangles take 3 points each, got {len(snapped)}")
    add = value is None
    fill_value = canvas.dtype.type(1 if add else value)
    beyond = np.zeros(len(snapped) // 3, np.bool_)
    _fill_rows(snapped.reshape(-1, 3, 2), scale, RULES[rule], cull, _largest_int64_reach(scale),
               canvas, fill_value, add, beyond)
    if beyond.any():  # too large for int64: the span kernel's Python integers
        far = np.asarray(points, np.float64).reshape(-1, 3, 2)[beyond]
        tris, _ = oriented(far, {"subpixel_bits": subpixel_bits, "cull": cull})
        for tri in tris:
            _, y, x0, x1 = _spans_python(tri, 0, scale, rule, (0, 0, *grid))
            for row, start, end in zip(y.tolist(), x0.tolist(), x1.tolist()):
                canvas[row, start:end] = canvas[row, start:end] + fill_value if add else fill_value
    return canvas


@functools.lru_cache(maxsize=None)
def _largest_int64_reach(scale: int) -> int:
    """The largest distance m (1/scale px) from a triangle's first pixel that keeps its
    edge terms in int64: 12 m^2 + 32 scale m + 64 < 2^63, as kernels._fits_int64 asks."""
    m = math.isqrt(2 ** 63 // 12)
    while 12 * m * m + 32 * scale * m + 64 >= 2 ** 63:
        m -= 1
    return m


@compiled
def _fill_rows(tris, scale, rule, cull, reach, canvas, value, add, beyond):
    """Every triangle's rows, clipped to the canvas, written as runs (see kernels._spans_numpy).

    Degenerate triangles are dropped, clockwise ones turned (or culled); a
    triangle reaching farther than ``reach`` from its first pixel is only
    marked in ``beyond``.
    """
    height, width = canvas.shape
    X = np.empty(3, np.int64)
    Y = np.empty(3, np.int64)
    A = np.empty(3, np.int64)
    B = np.empty(3, np.int64)
    C = np.empty(3, np.int64)
    for t in range(tris.shape[0]):
        # Coordinates relative to the first vertex's pixel keep the products small.
        ox = tris[t, 0, 0] // scale
        oy = tris[t, 0, 1] // scale
        far = False
        for k in range(3):
            X[k] = tris[t, k, 0] - ox * scale
            Y[k] = tris[t, k, 1] - oy * scale
            far |= abs(X[k]) > reach or abs(Y[k]) > reach
        if far:
            beyond[t] = True
            continue
        area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0])
        if area == 0 or (cull and area < 0):
            continue
        if area < 0:  # clockwise: turn it counter-clockwise
            X[1], X[2], Y[1], Y[2] = X[2], X[1], Y[2], Y[1]
        for k in range(3):  # edge k runs from P_(k+1) to P_(k+2)
            i, j = (k + 1) % 3, (k + 2) % 3
            A[k] = -2 * scale * (Y[j] - Y[i])
            B[k] = 2 * scale * (X[j] - X[i])
            C[k] = scale * (X[j] - X[i]) - scale * (Y[j] - Y[i]) + 2 * (X[i] * Y[j] - Y[i] * X[j])
            if rule == 1 or (rule == 0 and (A[k] > 0 or (A[k] == 0 and B[k] > 0))):
                C[k] += 1  # the rule keeps centres exactly on this edge
        i_lo = max(-((scale - 2 * X.min()) // (2 * scale)), -ox)
        i_hi = min((2 * X.max() - scale) // (2 * scale), width - 1 - ox)
        j_lo = max(-((scale - 2 * Y.min()) // (2 * scale)), -oy)
        j_hi = min((2 * Y.max() - scale) // (2 * scale), height - 1 - oy)
        for j in range(j_lo, j_hi + 1):
            lo, hi = i_lo, i_hi
            for k in range(3):
                a, r = A[k], B[k] * j + C[k]  # the test is a i + r > 0
                if a > 0:
                    lo = max(lo, (-r) // a + 1)
                elif a < 0:
                    hi = min(hi, -((-r) // (-a)) - 1)
                elif r <= 0:
                    hi = lo - 1
            if hi < lo:
                continue
            row = canvas[j + oy]
            if add:
                for i in range(lo + ox, hi + ox + 1):
                    row[i] += value
            else:
                row[lo + ox:hi + ox + 1] = value
