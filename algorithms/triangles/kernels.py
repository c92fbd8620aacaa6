"""Fast kernels: the covered pixels of many triangles at once, without a frame per pixel.

Per row and edge the test A i + R > 0 bounds the column i by one floor
division, so a triangle's row is one run (span) found without testing a
pixel; numpy does every row of every triangle at once in int64 where the
terms fit, Python integers beyond. The traversals' generators must give the
same pixels (tests prove it).
"""
from __future__ import annotations

import numpy as np

from algorithms.core.registry import InputError

from .edges import (MAX_COORDINATE, MAX_KERNEL_PIXELS, Edges, Triangle, floor_div, offset_of,
                    prepare, window_of)

def snap_array(points, scale: int) -> np.ndarray:
    """(n, 2) int64 vertex coordinates in 1/scale px (|x| <= 1e15 px keeps them below 2^58)."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    if pts.size and not np.all(np.abs(pts) <= MAX_COORDINATE):
        raise InputError(f"a coordinate is beyond +-{MAX_COORDINATE:g} px")
    return np.rint(pts * scale).astype(np.int64)  # exact scaling; rint is half-to-even


def oriented(points, options):
    """Snapped triangles, counter-clockwise, degenerate and culled ones dropped.

    Returns (vertices (T, 3, 2) int64, input triangle numbers).
    """
    scale = 1 << options.get("subpixel_bits", 8)
    ox, oy = offset_of(options)
    tris = snap_array(points, scale).reshape(-1, 3, 2) + np.array([ox, oy], np.int64) * scale
    d1 = tris[:, 1] - tris[:, 0]
    d2 = tris[:, 2] - tris[:, 0]
    if tris.size and np.abs(tris).max() >= 1 << 30:
        # the area products could overflow; only Python integers are safe
        area = np.array([int(a[0]) * int(b[1]) - int(b[0]) * int(a[1]) for a, b in zip(d1, d2)],
                        dtype=object)
        sign = np.array([(a > 0) - (a < 0) for a in area], dtype=np.int64)
    else:
        sign = np.sign(d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1])
    keep = sign != 0
    if options.get("cull", False):
        keep &= sign > 0
    numbers = np.flatnonzero(keep)
    tris = tris[keep].copy()
    cw = sign[keep] < 0
    tris[cw, 1], tris[cw, 2] = tris[cw, 2].copy(), tris[cw, 1].copy()
    return tris, numbers


def span_arrays(tris, scale: int, rule: str, window=None, top_down=False):
    """Covered runs of counter-clockwise triangles, vertices in 1/scale px.

    ``tris`` is an int64 array (T, 3, 2) or a list of vertex triples of
    Python integers. Returns (triangle, y, x_start, x_end) int64 arrays,
    x_end excluded, one entry per non-empty row, ordered by triangle and
    then by row (upwards, or downwards with ``top_down``). Per row and
    edge, A i + R > 0 with R = B j + C (+1 where the rule keeps ties) bounds
    i by one floor division, so no pixel is tested. Triangles too large for
    int64 go through the same steps in Python integers.
    """
    if len(tris) == 0:
        empty = np.zeros(0, np.int64)
        return empty, empty, empty, empty
    if isinstance(tris, np.ndarray):
        fits = _fits_int64_array(tris, scale)
        small, big = np.flatnonzero(fits), np.flatnonzero(~fits)
        arrays = tris if len(big) == 0 else tris[small]
    else:
        fits = [_fits_int64(t, scale) for t in tris]
        small = np.flatnonzero(fits)
        big = np.flatnonzero(~np.array(fits, bool))
        arrays = np.array([tris[n] for n in small], dtype=np.int64).reshape(-1, 3, 2)
    parts = [_spans_numpy(arrays, small, scale, rule, window)] if len(small) else []
    parts += [_spans_python(tris[n], n, scale, rule, window) for n in big]
    t, y, x0, x1 = (np.concatenate([p[k] for p in parts]) for k in range(4))
    if len(big) or top_down:
        order = np.lexsort((-y if top_down else y, t))
        t, y, x0, x1 = t[order], y[order], x0[order], x1[order]
    return t, y, x0, x1


def _fits_int64(tri, scale) -> bool:
    """Do the edge terms of this triangle, relative to its first vertex's pixel, fit int64?"""
    xs = [int(p[0]) for p in tri]
    ys = [int(p[1]) for p in tri]
    ox, oy = (xs[0] // scale) * scale, (ys[0] // scale) * scale
    m = max(max(abs(v - ox) for v in xs), max(abs(v - oy) for v in ys))
    return 12 * m * m + 32 * scale * m + 64 < 2 ** 63


def _fits_int64_array(tris, scale) -> np.ndarray:
    # The same bound in float64, with room to spare for its rounding.
    f = tris.astype(np.float64)
    origin = np.floor(f[:, 0:1, :] / scale) * scale
    d = np.abs(f - origin).reshape(-1, 6)
    m = d[:, 0]
    for column in range(1, 6):
        m = np.maximum(m, d[:, column])
    return 12 * m * m + 32 * scale * m + 64 < 0.9 * 2.0 ** 63


def _edge_terms(X, Y, scale, rule):
    """A, B, C (relative to the first vertex's pixel) and the tie bias, per edge: (T, 3) each."""
    Xi, Yi = np.roll(X, -1, axis=1), np.roll(Y, -1, axis=1)   # P_(k+1)
    Xj, Yj = np.roll(X, -2, axis=1), np.roll(Y, -2, axis=1)   # P_(k+2)
    A = -2 * scale * (Yj - Yi)
    B = 2 * scale * (Xj - Xi)
    C = scale * (Xj - Xi) - scale * (Yj - Yi) + 2 * (Xi * Yj - Yi * Xj)
    if rule == "inclusive":
        bias = np.ones_like(A)
    elif rule == "strict":
        bias = np.zeros_like(A)
    else:
        bias = ((A > 0) | ((A == 0) & (B > 0))).astype(A.dtype)
    return A, B, C, bias


def _spans_numpy(tris, numbers, scale, rule, window):
    X, Y = tris[:, :, 0], tris[:, :, 1]
    ox, oy = X[:, 0] // scale, Y[:, 0] // scale
    X = X - (ox * scale)[:, None]
    Y = Y - (oy * scale)[:, None]
    A, B, C, bias = _edge_terms(X, Y, scale, rule)
    x_min = np.minimum(np.minimum(X[:, 0], X[:, 1]), X[:, 2])
    x_max = np.maximum(np.maximum(X[:, 0], X[:, 1]), X[:, 2])
    y_min = np.minimum(np.minimum(Y[:, 0], Y[:, 1]), Y[:, 2])
    y_max = np.maximum(np.maximum(Y[:, 0], Y[:, 1]), Y[:, 2])
    i_lo = -((scale - 2 * x_min) // (2 * scale))
    i_hi = (2 * x_max - scale) // (2 * scale)
    j_lo = -((scale - 2 * y_min) // (2 * scale))
    j_hi = (2 * y_max - scale) // (2 * scale)
    if window is not None:
        wx0, wy0, wx1, wy1 = window
        i_lo, i_hi = np.maximum(i_lo, wx0 - ox), np.minimum(i_hi, wx1 - 1 - ox)
        j_lo, j_hi = np.maximum(j_lo, wy0 - oy), np.minimum(j_hi, wy1 - 1 - oy)
    rows = np.maximum(j_hi - j_lo + 1, 0)
    total = int(rows.sum())
    if total > MAX_KERNEL_PIXELS:
        raise InputError("the triangles span too many rows; give a grid to clip them")
    which = np.repeat(np.arange(len(tris)), rows)
    first = np.cumsum(rows) - rows
    j = np.repeat(j_lo - first, rows) + np.arange(total)
    lo, hi = i_lo[which], i_hi[which]
    empty = np.zeros(total, bool)
    for k in range(3):  # one edge at a time: short reductions are slow in numpy
        a = A[:, k][which]
        r = B[:, k][which] * j + (C[:, k] + bias[:, k])[which]  # the test is A i + r > 0
        q = np.floor_divide(-r, np.where(a == 0, 1, np.abs(a)))
        np.maximum(lo, np.where(a > 0, q + 1, lo), out=lo)
        np.minimum(hi, np.where(a < 0, -q - 1, hi), out=hi)
        empty |= (a == 0) & (r <= 0)
    keep = (hi >= lo) & ~empty
    w = which[keep]
    return (np.asarray(numbers, np.int64)[w], j[keep] + oy[w], lo[keep] + ox[w],
            hi[keep] + 1 + ox[w])


def _spans_python(tri, number, scale, rule, window):
    """The same bounds as _spans_numpy, one row at a time in Python integers."""
    vertices = [(int(x), int(y)) for x, y in tri]
    t = Triangle(number, vertices, (0, 1, 2), scale, rule)
    i_lo, i_hi, j_lo, j_hi = t.box()
    if window is not None:
        wx0, wy0, wx1, wy1 = window
        i_lo, i_hi, j_lo, j_hi = max(i_lo, wx0), min(i_hi, wx1 - 1), max(j_lo, wy0), min(j_hi, wy1 - 1)
    if j_hi - j_lo + 1 > MAX_KERNEL_PIXELS:
        raise InputError("the triangles span too many rows; give a grid to clip them")
    out = ([], [], [], [])
    for j in range(j_lo, j_hi + 1):
        lo, hi = i_lo, i_hi
        for k in range(3):
            a = t.A[k]
            r = t.B[k] * j + t.C[k] + (1 if t.include[k] else 0)
            if a > 0:
                lo = max(lo, floor_div(-r, a) + 1)
            elif a < 0:
                hi = min(hi, -floor_div(-r, -a) - 1)
            elif r <= 0:
                hi = lo - 1
        if hi >= lo:
            for column, value in zip(out, (number, j, lo, hi + 1)):
                column.append(value)
    return tuple(np.array(c, dtype=np.int64) for c in out)


def span_mask(tris, scale, rule, window) -> np.ndarray:
    """Boolean (rows, columns) of the window: centres covered by any of ``tris``."""
    x0, y0, x1, y1 = window
    mask = np.zeros((y1 - y0, x1 - x0), bool)
    _, y, s, e = span_arrays(list(tris), scale, rule, window)
    for row, start, end in zip(y - y0, s - x0, e - x0):
        mask[row, start:end] = True
    return mask


def pixels_from_spans(y, x_start, x_end) -> np.ndarray:
    """(n, 2) pixels of the runs, in order."""
    keep = x_end > x_start
    y, x_start, x_end = y[keep], x_start[keep], x_end[keep]
    lengths = x_end - x_start
    total = int(lengths.sum())
    if total > MAX_KERNEL_PIXELS:
        raise InputError("too many pixels; give a grid to clip the triangles")
    out = np.empty((total, 2), np.int64)
    if total == 0:
        return out
    # x climbs by one along a run and jumps at the start of the next: a cumsum of steps.
    step = np.ones(total, np.int64)
    step[np.cumsum(lengths) - lengths] = x_start - np.concatenate(([0], x_end[:-1] - 1))
    np.cumsum(step, out=out[:, 0])
    out[:, 1] = np.repeat(y, lengths)
    return out


def counts_from_spans(y, x_start, x_end, width: int, height: int) -> np.ndarray:
    """Coverage counts (height, width) int32 of runs, clipped to the grid."""
    keep = (y >= 0) & (y < height)
    y, s, e = y[keep], np.clip(x_start[keep], 0, width), np.clip(x_end[keep], 0, width)
    counts = np.zeros((height, width), np.int32)
    if len(y) <= 4096:  # few, long runs: one slice each
        for row, start, end in zip(y.tolist(), s.tolist(), e.tolist()):
            counts[row, start:end] += 1
        return counts
    lengths = e - s
    long = lengths >= 32
    if long.any():
        # Long runs: +1 where each starts, -1 where it ends, summed along the rows.
        stride = width + 1
        marks = np.bincount(y[long] * stride + s[long], minlength=height * stride)
        marks -= np.bincount(y[long] * stride + e[long], minlength=height * stride)
        counts += np.cumsum(marks.reshape(height, stride), axis=1)[:, :width].astype(np.int32)
    y, s, lengths = y[~long], s[~long], lengths[~long]
    # Short runs: every pixel's flat index, counted by bincount, in chunks
    # of at most 2^24 pixels so memory stays bounded.
    ends = np.cumsum(lengths)
    flat_counts = counts.reshape(-1)
    lo = 0
    while lo < len(y):
        hi = int(np.searchsorted(ends, ends[lo] - lengths[lo] + (1 << 24), side="right"))
        hi = max(hi, lo + 1)
        part = lengths[lo:hi]
        first = np.cumsum(part) - part
        flat = np.repeat(y[lo:hi] * width + s[lo:hi] - first, part) + np.arange(int(part.sum()))
        flat_counts += np.bincount(flat, minlength=width * height).astype(np.int32)
        lo = hi
    return counts


def fill(points, grid, rule: str = "top-left", subpixel_bits: int = 8, cull: bool = False):
    """Coverage counts of k triangles (3k points) on a W x H grid, exact: the fast path."""
    options = {"subpixel_bits": subpixel_bits, "cull": cull}
    width, height = grid
    tris, _ = oriented(points, options)
    _, y, s, e = span_arrays(tris, 1 << subpixel_bits, rule, (0, 0, width, height))
    return counts_from_spans(y, s, e, width, height)


def kernel_pixels(points, options, grid=None, top_down=False) -> np.ndarray:
    """Fast kernel (precision fixed): covered pixels, per triangle, row by row, left to right."""
    offset = offset_of(options)
    window = None if grid is None else window_of(grid, (), offset)
    scale = 1 << options.get("subpixel_bits", 8)
    rule = options.get("fill_rule", "top-left")
    tris, _ = oriented(points, options)
    _, y, s, e = span_arrays(tris, scale, rule, window, top_down)
    return pixels_from_spans(y, s, e) - np.array(offset, np.int64)


def _float_box_pixels(points, options, grid, whole):
    """Dense float evaluation of a*x + b*y + c, as triangle-scan / triangle-bbox do it."""
    full = dict(options)
    setups = prepare(points, full)
    offset = offset_of(full)
    window = window_of(grid, setups, offset)
    t = np.float64 if options["precision"] == "float64" else np.float32
    out = []
    for setup in setups:
        if setup.tri is None:
            continue
        edges = Edges(setup.tri, options["precision"])
        if whole:
            i_lo, j_lo, i_hi, j_hi = window[0], window[1], window[2] - 1, window[3] - 1
        else:
            x0, y0, x1, y1 = window
            b = setup.tri.box()
            i_lo, i_hi, j_lo, j_hi = max(b[0], x0), min(b[1], x1 - 1), max(b[2], y0), min(b[3], y1 - 1)
        if i_lo > i_hi or j_lo > j_hi:
            continue
        xs = (np.arange(i_lo, i_hi + 1, dtype=np.float64) + 0.5).astype(t)[None, :]
        ys = (np.arange(j_lo, j_hi + 1, dtype=np.float64) + 0.5).astype(t)[:, None]
        ok = np.ones((len(ys), xs.shape[1]), bool)
        for k in range(3):
            a, b, c = t(edges.a[k]), t(edges.b[k]), t(edges.c[k])
            e = (a * xs + b * ys) + c
            e = edges.sign * e
            ok &= (e > 0) | ((e == 0) & edges.include[k])
        rows, cols = np.nonzero(ok)
        out.append(np.stack([cols + i_lo - offset[0], rows + j_lo - offset[1]], axis=1))
    return np.concatenate(out).astype(np.int64) if out else np.zeros((0, 2), np.int64)
