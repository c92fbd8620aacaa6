"""Many polygons in one call: the scan-line fill, compiled, straight into a canvas.

``scanline_fill_many`` gives every polygon exactly the pixels of
``scanline_pixels`` (clipped to the grid) without a Python step per
polygon or per row. numpy snaps every vertex and sets up every edge at
once; a compiled loop then walks each polygon's rows with an active edge
list, finds each crossing's first covered column by one exact integer
division (the kernel's: ceil of (x - 1/2 px), x being a rational with
denominator 256 dy) and writes the runs the fill rule fills. Snapped
coordinates stay within 2^28, so every product fits int64.
"""
from __future__ import annotations

import numpy as np

from algorithms.core.compiled import compiled
from algorithms.core.raster import canvas_for
from algorithms.core.registry import InputError

from .common import HALF_PIXEL, MAX_COORDINATE, ONE
from .scanline import sample_of, scanline_pixels

RULES = {"evenodd": 0, "nonzero": 1}


def scanline_fill_many(polygons, grid, canvas=None, value=None, options=None) -> np.ndarray:
    """Fill many polygons into a (H, W) canvas (pixel (x, y) at ``canvas[y, x]``); returns it.

    ``polygons`` is a list of polygons, each a list of contours of (x, y)
    points (as ``scanline_pixels`` takes them), or an array (n, k, 2): n
    polygons of one contour with k corners each. With ``value`` None each
    polygon adds 1 to the pixels it covers (coverage counts); otherwise they
    are set to ``value``. ``canvas`` defaults to int32 zeros. ``options``
    are the scan-line fill's (fill_rule, arithmetic, edge_x); float
    arithmetic takes the per-polygon kernel, one polygon at a time.
    """
    options = dict(options or {})
    rule = options.get("fill_rule", "evenodd")
    if rule not in RULES:
        raise InputError(f"unknown fill rule {rule!r}; choose evenodd or nonzero")
    canvas = canvas_for(grid, canvas)
    add = value is None
    fill_value = canvas.dtype.type(1 if add else value)
    if options.get("arithmetic", "exact") != "exact":
        return _one_at_a_time(polygons, options, canvas, fill_value, add)
    vertices, following, first_vertex = _vertices_of(polygons)
    edges = _edge_setup(vertices, following, first_vertex, sample_of(options))
    _fill_polygons(*edges, RULES[rule], canvas, fill_value, add)
    return canvas


def _one_at_a_time(polygons, options, canvas, value, add):
    """Float arithmetic steps x row by row, as the generator does: the per-polygon kernel."""
    height, width = canvas.shape
    for polygon in polygons:
        contours = [polygon] if isinstance(polygon, np.ndarray) else polygon
        pixels = scanline_pixels([[tuple(p) for p in c] for c in contours], options)
        inside = pixels[(pixels[:, 0] >= 0) & (pixels[:, 0] < width)
                        & (pixels[:, 1] >= 0) & (pixels[:, 1] < height)]
        if add:
            canvas[inside[:, 1], inside[:, 0]] += value
        else:
            canvas[inside[:, 1], inside[:, 0]] = value
    return canvas


def _vertices_of(polygons):
    """Snapped vertices (V, 2), the index of each one's successor on its contour,
    and where each polygon's vertices begin (n + 1 offsets)."""
    if isinstance(polygons, np.ndarray) and polygons.ndim == 3:
        n, k = polygons.shape[:2]
        if k == 0:
            polygons = [[] for _ in range(n)]
            return _vertices_of(polygons)
        following = np.arange(1, n * k + 1, dtype=np.int64)
        following[k - 1::k] -= k
        return (_snapped(polygons.reshape(-1, 2)), following,
                np.arange(0, n * k + 1, k, dtype=np.int64))
    flat, following, first_vertex = [], [], [0]
    for polygon in polygons:
        for contour in polygon:
            size = len(contour)
            flat.extend(contour)
            following.extend(range(len(following) + 1, len(following) + size))
            following.append(len(following) - size + 1)
        first_vertex.append(len(flat))
    return (_snapped(np.array(flat, np.float64).reshape(-1, 2)),
            np.array(following, np.int64), np.array(first_vertex, np.int64))


def _snapped(points) -> np.ndarray:
    """Vertices in 1/256 px, rounded half to even as common.snap does."""
    if points.size and not np.all(np.abs(points) <= MAX_COORDINATE):
        raise InputError(f"polygon coordinates must lie within +-{MAX_COORDINATE} px")
    return np.rint(points * ONE).astype(np.int64)


@compiled
def _edge_setup(vertices, following, first_vertex, sample):
    """Every polygon's edges that meet a scan line, each polygon's sorted by first row.

    Per edge: first row, the row after its last, the numerator of the first
    covered column at the first row, its step per row, the denominator, and
    whether it runs up (as scanline._crossing_columns has them); and where
    each polygon's edges begin.
    """
    total = len(vertices)
    first, stop = np.empty(total, np.int64), np.empty(total, np.int64)
    numerator, step = np.empty(total, np.int64), np.empty(total, np.int64)
    denominator, up = np.empty(total, np.int64), np.empty(total, np.bool_)
    first_edge = np.zeros(len(first_vertex), np.int64)
    m = 0
    for p in range(len(first_vertex) - 1):
        for v in range(first_vertex[p], first_vertex[p + 1]):
            w = following[v]
            rising = vertices[w, 1] > vertices[v, 1]
            low, high = (v, w) if rising else (w, v)
            first[m] = -((sample - vertices[low, 1]) // ONE)
            stop[m] = -((sample - vertices[high, 1]) // ONE)
            if stop[m] <= first[m]:
                continue  # horizontal, or between two scan lines
            dx, dy = vertices[high, 0] - vertices[low, 0], vertices[high, 1] - vertices[low, 1]
            rise = ONE * first[m] + sample - vertices[low, 1]
            numerator[m] = rise * dx + (vertices[low, 0] - HALF_PIXEL) * dy
            step[m], denominator[m], up[m] = ONE * dx, ONE * dy, rising
            m += 1
        first_edge[p + 1] = m
        start = first_edge[p]
        # Shell sort (Knuth's gaps) in place: insertion sort for the usual few
        # edges, and no O(k^2) for a polygon of thousands; numba compiles
        # np.argsort far more slowly than this loop.
        columns = (first, stop, numerator, step, denominator)
        gap = 1
        while gap < (m - start) // 3:
            gap = 3 * gap + 1
        while gap > 0:
            for a in range(start + gap, m):
                b = a
                while b - gap >= start and first[b - gap] > first[b]:
                    for column in columns:
                        column[b - gap], column[b] = column[b], column[b - gap]
                    up[b - gap], up[b] = up[b], up[b - gap]
                    b -= gap
            gap //= 3
    return first_edge, first[:m], stop[:m], numerator[:m], step[:m], denominator[:m], up[:m]


@compiled
def _fill_polygons(first_edge, first, stop, numerator, step, denominator, up, nonzero,
                   canvas, value, add):
    """Each polygon's rows with an active edge list; the runs its fill rule fills."""
    height, width = canvas.shape
    most = np.max(first_edge[1:] - first_edge[:-1]) if len(first_edge) > 1 else 0
    active = np.empty(most, np.int64)
    keys = np.empty(most, np.int64)  # 2 * column + (1 if the edge runs up)
    for p in range(len(first_edge) - 1):
        e0, e1 = first_edge[p], first_edge[p + 1]
        if e1 == e0:
            continue
        row, following, live = max(first[e0], 0), e0, 0
        end = min(stop[e0:e1].max(), height)
        while row < end:
            while following < e1 and first[following] <= row:  # edges reaching this row
                active[live] = following
                live += 1
                following += 1
            kept = 0
            for a in range(live):  # the edges that ended below this row leave
                if stop[active[a]] > row:
                    active[kept] = active[a]
                    kept += 1
            live = kept
            # Crossings sorted by insertion, the edges moving with their keys: the
            # AET then stays in last row's order, nearly sorted, so this is ~O(live).
            for a in range(live):
                e = active[a]
                n = numerator[e] + (row - first[e]) * step[e]
                key = 2 * -((-n) // denominator[e]) + up[e]
                b = a
                while b > 0 and keys[b - 1] > key:
                    keys[b], active[b] = keys[b - 1], active[b - 1]
                    b -= 1
                keys[b], active[b] = key, e
            winding, left, line = 0, 0, canvas[row]
            for a in range(live):
                before = winding
                winding = (winding + 2 * (keys[a] & 1) - 1) if nonzero else 1 - winding
                column = min(max(keys[a] >> 1, 0), width)  # a run is clipped to the grid
                if before == 0:
                    left = column
                elif winding == 0:
                    if add:
                        for i in range(left, column):
                            line[i] += value
                    else:  # a slice becomes one memset
                        line[left:column] = value
            row += 1
