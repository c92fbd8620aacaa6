"""The exact coverage reference: how much of every pixel square a shape covers.

Pixel (i, j) is the unit square [i, i+1] x [j, j+1] (y up). For a shape the
coverage of the pixel is the area of the square that the shape covers, a
number in 0..1 (the square has area 1). Antialiasing methods estimate it;
this module computes it, for

* triangles (3k points): the union of the k triangles (``union=True``), or
  the sum of their areas (``union=False``: overlaps count twice);
* polygons of one or more contours, under a fill rule:

  - ``evenodd``: a point is covered when a ray from it crosses the
    contours an odd number of times (the default, as the polygon fill);
  - ``nonzero``: covered when its winding number is not zero;
  - ``signed``: no rule at all, the integral of the winding number over
    the square. It is negative where the contours run clockwise and
    counts doubly wound parts twice; for a simple counter-clockwise
    polygon it equals the other two.

  A self-intersecting contour is therefore well defined: the parts it
  winds around an odd number of times (evenodd), or at all (nonzero);
* a line's rectangle: the segment P Q widened by ``width`` / 2 on each
  side (``caps="butt"``) and, with ``caps="square"``, lengthened by
  ``width`` / 2 at each end.

Two independent computations.

Float64, vectorised over the grid (``exact=False``): the signed area of
edge method. By Green's theorem the integral of the winding number w over
a square S equals a sum over the directed edges of

    - integral along the edge of  clamp(y - j, 0, 1) * [i <= x <= i+1] dx,

so every edge is cut at the pixel columns into pieces and each piece adds
-dx * (its mean of clamp(y - j, 0, 1)) to the pixels of its column: the
mean of a clamped linear function in closed form for the rows the piece
crosses, and the full -dx for every row below it (a running sum down each
column). Every addition is a number of size at most 1, so the result is
accurate to a few units in the last place of 1. A pixel no edge passes
through is wholly inside or wholly outside the shape; its value is rounded
to the integer it must be, so such pixels are exactly 0 or 1.
For ``evenodd`` and ``nonzero`` the region is first cut into trapezoids
(horizontal slabs between all vertex heights and edge crossings; in each
slab the edges keep their left-to-right order and the rule picks the gaps
between them), whose edges then go through the same method. A single
triangle, or a contour whose edges do not cross, skips that step.

Fractions (``exact=True``): every coordinate becomes a fractions.Fraction
(floats convert exactly), trapezoids are cut with exact intersection
points, and each piece is clipped against each pixel square by
Sutherland-Hodgman (columns first, then rows) and measured by the shoelace
formula. Clipping any closed polygon against a convex square keeps the
integral of its winding number, so ``signed`` clips the contours as they
are. The result is an object array of Fractions.

The corners of a line's rectangle are irrational in general: both paths
compute them in float64, and from there on the exact path is exact.

``grid`` is (W, H) for the pixels [0, W) x [0, H), or a window
(x0, y0, x1, y1) of pixel indices; the result has shape (rows, columns) of
the window, row 0 at the bottom.
"""
from __future__ import annotations

import math
from fractions import Fraction
import numpy as np

RULES = ("evenodd", "nonzero", "signed")
CAPS = ("butt", "square")


# ================================================================ inputs
def window_of(grid) -> tuple[int, int, int, int]:
    if len(grid) == 2:
        return (0, 0, int(grid[0]), int(grid[1]))
    x0, y0, x1, y1 = (int(v) for v in grid)
    if x1 < x0 or y1 < y0:
        raise ValueError(f"window {grid} is empty the wrong way round")
    return (x0, y0, x1, y1)


def _contours(polygon) -> list[list[tuple]]:
    """A polygon as a list of contours: one list of points, or a list of lists."""
    polygon = list(polygon)
    if polygon and len(polygon[0]) == 2 and not isinstance(polygon[0][0], (list, tuple)):
        return [[tuple(p) for p in polygon]]
    return [[tuple(p) for p in contour] for contour in polygon]


def _triangles(points) -> list[list[tuple]]:
    points = [tuple(p) for p in points]
    if len(points) % 3:
        raise ValueError(f"triangles take 3k points, not {len(points)}")
    return [points[k:k + 3] for k in range(0, len(points), 3)]


def twice_signed_area(contour) -> object:
    """Twice the signed area (shoelace): positive for counter-clockwise contours."""
    total = 0
    n = len(contour)
    for k in range(n):
        (x0, y0), (x1, y1) = contour[k], contour[(k + 1) % n]
        total += x0 * y1 - x1 * y0
    return total


def counter_clockwise(contour) -> list:
    return list(contour) if twice_signed_area(contour) >= 0 else list(contour)[::-1]


def segment_rectangle(p, q, width: float, caps: str = "butt") -> list[tuple[float, float]]:
    """The four corners (counter-clockwise, float64) of a segment's rectangle.

    A segment of zero length has a square of side ``width`` with square
    caps and nothing (a degenerate rectangle) with butt caps.
    """
    if caps not in CAPS:
        raise ValueError(f"caps must be one of {CAPS}, not {caps!r}")
    (px, py), (qx, qy) = (float(p[0]), float(p[1])), (float(q[0]), float(q[1]))
    dx, dy = qx - px, qy - py
    length = math.hypot(dx, dy)
    half = width / 2.0
    if length == 0:
        if caps == "butt":
            return [(px, py)] * 4
        ux, uy = 1.0, 0.0
    else:
        ux, uy = dx / length, dy / length
    nx, ny = -uy * half, ux * half  # to the left of P -> Q
    if caps == "square":
        px, py, qx, qy = px - ux * half, py - uy * half, qx + ux * half, qy + uy * half
    return [(px - nx, py - ny), (qx - nx, qy - ny), (qx + nx, qy + ny), (px + nx, py + ny)]


# ===================================================== the public calls
def polygon_coverage(polygon, grid, rule: str = "evenodd", exact: bool = False,
                     columns=None) -> np.ndarray:
    """Coverage of every pixel of the grid by a polygon (one contour or a list of them).

    ``columns`` (first, end) of the window, counted from its left: only those
    columns are computed, each exactly as the whole window computes it.
    """
    if rule not in RULES:
        raise ValueError(f"rule must be one of {RULES}, not {rule!r}")
    contours = [c for c in _contours(polygon) if len(c) >= 3]
    window = window_of(grid)
    if exact:
        contours = [[(Fraction(x), Fraction(y)) for x, y in c] for c in contours]
        if rule == "signed":
            whole = _clip_coverage(contours, window)
        else:
            whole = _clip_coverage(trapezoids(contours, rule), window)
        return whole if columns is None else whole[:, columns[0]:columns[1]]
    if rule == "signed" or not contours:
        return _float_coverage(contours, window, columns=columns)
    if len(contours) == 1 and not _self_crossing(contours[0]):
        # One simple contour: the region is where w = +1 or -1 everywhere.
        return _float_coverage([counter_clockwise(contours[0])], window, touched_by=contours,
                               columns=columns)
    return _float_coverage(trapezoids(contours, rule), window, touched_by=contours,
                           columns=columns)


def triangle_coverage(points, grid, union: bool = True, exact: bool = False) -> np.ndarray:
    """Coverage by k triangles (3k points): of their union, or the sum of their areas."""
    tris = [counter_clockwise(t) for t in _triangles(points)]
    tris = [t for t in tris if twice_signed_area(t) != 0]
    if len(tris) <= 1 or not union:
        return polygon_coverage(tris, grid, "signed", exact)
    return polygon_coverage(tris, grid, "nonzero", exact)


def segment_coverage(p, q, width: float, grid, caps: str = "butt",
                     exact: bool = False, columns=None) -> np.ndarray:
    """Coverage by the rectangle of segment P Q and the given width."""
    return polygon_coverage([segment_rectangle(p, q, width, caps)], grid, "signed", exact,
                            columns)


def region_area(polygon, rule: str = "evenodd", exact: bool = False):
    """The whole area the coverage of the polygon adds up to (no grid)."""
    contours = [c for c in _contours(polygon) if len(c) >= 3]
    if exact:
        contours = [[(Fraction(x), Fraction(y)) for x, y in c] for c in contours]
    if rule == "signed":
        pieces = contours
    else:
        pieces = trapezoids(contours, rule)
    total = sum((twice_signed_area(piece) for piece in pieces), Fraction(0) if exact else 0.0)
    return total / 2


# ============================================== float: signed edge areas
def _float_coverage(contours, window, touched_by=None, columns=None) -> np.ndarray:
    """Integral of the winding number of the contours over every pixel of the window.

    ``touched_by``: the contours whose edges decide which pixels can be
    partly covered (the original polygon when ``contours`` are its
    trapezoids, whose internal cuts cross pixels without bounding the
    region); every other pixel is rounded to its whole number.
    """
    x0, y0, x1, y1 = window
    # The edges keep the whole window's origin whatever columns are asked
    # for, so each column's sums are the same numbers in the same order.
    first, width = (0, x1 - x0) if columns is None else columns
    height = y1 - y0
    if width <= first or height == 0:
        return np.zeros((height, max(width - first, 0)))
    ax, ay, bx, by = _edge_arrays(contours, x0, y0)
    values, touched = _edge_sums(ax, ay, bx, by, width, height, first)
    if touched_by is not None:
        touched = _touched(*_edge_arrays(touched_by, x0, y0), width, height, first)
    untouched = ~touched
    values[untouched] = np.rint(values[untouched])
    return values


def _edge_arrays(contours, x0, y0):
    starts, ends = [], []
    for contour in contours:
        n = len(contour)
        for k in range(n):
            starts.append(contour[k])
            ends.append(contour[(k + 1) % n])
    if not starts:
        empty = np.zeros(0)
        return empty, empty, empty, empty
    a = np.array(starts, dtype=np.float64).reshape(-1, 2)
    b = np.array(ends, dtype=np.float64).reshape(-1, 2)
    return a[:, 0] - x0, a[:, 1] - y0, b[:, 0] - x0, b[:, 1] - y0


def _pieces(ax, ay, bx, by, width, first=0):
    """Every non-vertical edge cut at the pixel columns of [first, width).

    Returns (column, signed dx, y at the left end, y at the right end) per piece.
    """
    dx = bx - ax
    keep = dx != 0
    ax, ay, bx, by, dx = ax[keep], ay[keep], bx[keep], by[keep], dx[keep]
    lo_x, hi_x = np.minimum(ax, bx), np.maximum(ax, bx)
    start = np.maximum(np.floor(lo_x), first).astype(np.int64)
    last = np.minimum(np.ceil(hi_x) - 1, width - 1).astype(np.int64)
    counts = np.maximum(last - start + 1, 0)
    edge = np.repeat(np.arange(len(ax)), counts)
    starts = np.cumsum(counts) - counts
    column = np.repeat(start, counts) + (np.arange(int(counts.sum())) - np.repeat(starts, counts))
    left = np.maximum(lo_x[edge], column)
    right = np.minimum(hi_x[edge], column + 1)
    y_left = _y_at(ax[edge], ay[edge], bx[edge], by[edge], left)
    y_right = _y_at(ax[edge], ay[edge], bx[edge], by[edge], right)
    signed_dx = np.where(dx[edge] > 0, right - left, left - right)
    return column, signed_dx, y_left, y_right


def _y_at(ax, ay, bx, by, x):
    # Endpoints keep their own y exactly; inside, y = ay + t (by - ay) with t in 0..1.
    t = (x - ax) / (bx - ax)
    y = ay + t * (by - ay)
    return np.where(x == ax, ay, np.where(x == bx, by, y))


def mean_clamp(s0, s1):
    """The mean of clamp(s, 0, 1) over s running linearly from s0 to s1 (arrays)."""
    lo, hi = np.minimum(s0, s1), np.maximum(s0, s1)
    a, b = np.clip(lo, 0.0, 1.0), np.clip(hi, 0.0, 1.0)
    integral = (b - a) * (a + b) / 2 + (np.maximum(hi, 1.0) - np.maximum(lo, 1.0))
    span = hi - lo
    with np.errstate(divide="ignore", invalid="ignore"):
        mean = integral / span
    return np.where(span > 0, mean, a)


def _edge_sums(ax, ay, bx, by, end, height, left=0):
    """(values, touched) of the window's columns left .. end: the signed
    edge-area sums per pixel."""
    column, dx, y_left, y_right = _pieces(ax, ay, bx, by, end, left)
    column = column - left
    width = end - left
    lo = np.minimum(y_left, y_right)
    hi = np.maximum(y_left, y_right)
    row_lo = np.floor(lo).astype(np.int64)
    row_hi = np.ceil(hi).astype(np.int64) - 1
    # Rows below a piece: -dx each, summed from the top of each column down.
    below = np.minimum(row_lo, height)
    has_rows = below >= 1
    # (bincount answers int64 for no input at all: hence the astype)
    marks = np.bincount(below[has_rows] * width + column[has_rows], weights=-dx[has_rows],
                        minlength=(height + 1) * width).astype(np.float64)
    marks = marks.reshape(height + 1, width)
    from_top = np.cumsum(marks[::-1], axis=0)[::-1]  # from_top[k] = sum of marks[k:]
    values = from_top[1:].copy()
    # Rows the piece crosses: -dx times its mean clamp there.
    first = np.maximum(row_lo, 0)
    last = np.minimum(row_hi, height - 1)
    counts = np.maximum(last - first + 1, 0)
    piece = np.repeat(np.arange(len(column)), counts)
    starts = np.cumsum(counts) - counts
    row = np.repeat(first, counts) + (np.arange(int(counts.sum())) - np.repeat(starts, counts))
    part = -dx[piece] * mean_clamp(y_left[piece] - row, y_right[piece] - row)
    flat = row * width + column[piece]
    values += np.bincount(flat, weights=part, minlength=height * width).astype(
        np.float64).reshape(height, width)
    touched = np.zeros(height * width, bool)
    touched[flat] = True
    touched = touched.reshape(height, width) | _vertical_touches(ax, ay, bx, by, end, height,
                                                                 left)
    return values, touched


def _vertical_touches(ax, ay, bx, by, end, height, first=0):
    """Pixels of columns first .. end whose inside a vertical edge passes
    through (it adds no area there)."""
    touched = np.zeros((height, end - first), bool)
    vertical = (ax == bx) & (np.floor(ax) != ax) & (ay != by)
    for x, ya, yb in zip(ax[vertical], ay[vertical], by[vertical]):
        column = int(math.floor(x)) - first
        if 0 <= column < end - first:
            lo, hi = max(int(math.floor(min(ya, yb))), 0), min(int(math.ceil(max(ya, yb))), height)
            touched[lo:hi, column] = True
    return touched


def _touched(ax, ay, bx, by, end, height, first=0):
    return _edge_sums(ax, ay, bx, by, end, height, first)[1]


# ================================================== exact: clip and measure
def _clip_half(poly, axis: int, bound, keep_above: bool) -> list:
    """Sutherland-Hodgman against the half-plane coordinate[axis] >= bound (or <=)."""
    out = []
    n = len(poly)
    for k in range(n):
        p, q = poly[k], poly[(k + 1) % n]
        p_in = p[axis] >= bound if keep_above else p[axis] <= bound
        q_in = q[axis] >= bound if keep_above else q[axis] <= bound
        if p_in:
            out.append(p)
        if p_in != q_in:
            t = (bound - p[axis]) / (q[axis] - p[axis])
            point = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
            point[axis] = bound  # exactly on the clip line
            out.append(tuple(point))
    return out


def _clip_coverage(polygons, window) -> np.ndarray:
    """Exact (Fraction) signed area of every polygon within every pixel, summed."""
    x0, y0, x1, y1 = window
    result = np.empty((y1 - y0, x1 - x0), dtype=object)
    for index in np.ndindex(result.shape):
        result[index] = Fraction(0)
    for poly in polygons:
        if len(poly) < 3:
            continue
        xs = [p[0] for p in poly]
        ys = [p[1] for p in poly]
        c_lo, c_hi = max(math.floor(min(xs)), x0), min(math.ceil(max(xs)), x1)
        r_lo, r_hi = max(math.floor(min(ys)), y0), min(math.ceil(max(ys)), y1)
        for i in range(c_lo, c_hi):
            strip = _clip_half(_clip_half(poly, 0, i, True), 0, i + 1, False)
            if len(strip) < 3:
                continue
            for j in range(r_lo, r_hi):
                cell = _clip_half(_clip_half(strip, 1, j, True), 1, j + 1, False)
                if len(cell) >= 3:
                    result[j - y0, i - x0] += Fraction(twice_signed_area(cell)) / 2
    return result


# ======================================================== trapezoids
def _self_crossing(contour) -> bool:
    """Do two non-adjacent edges of the contour meet, or adjacent ones overlap?"""
    n = len(contour)
    edges = [(contour[k], contour[(k + 1) % n]) for k in range(n)]
    for a in range(n):
        for b in range(a + 1, n):
            adjacent = b == a + 1 or (a == 0 and b == n - 1)
            p, q = edges[a]
            r, s = edges[b]
            if adjacent:
                # Sharing one vertex: they only overlap when folding back on each other.
                shared, other_a, other_b = (q, p, s) if b == a + 1 else (p, q, r)
                if n > 3 and _cross(shared, other_a, other_b) == 0 and \
                        _dot(shared, other_a, other_b) > 0:
                    return True
                continue
            if _segments_meet(p, q, r, s):
                return True
    return False


def _cross(o, p, q):
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])


def _dot(o, p, q):
    return (p[0] - o[0]) * (q[0] - o[0]) + (p[1] - o[1]) * (q[1] - o[1])


def _segments_meet(p, q, r, s) -> bool:
    d1, d2 = _cross(r, s, p), _cross(r, s, q)
    d3, d4 = _cross(p, q, r), _cross(p, q, s)
    if ((d1 > 0 > d2) or (d1 < 0 < d2)) and ((d3 > 0 > d4) or (d3 < 0 < d4)):
        return True

    def on(a, b, c):  # c on segment a b, given collinear
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and \
            min(a[1], b[1]) <= c[1] <= max(a[1], b[1])
    return ((d1 == 0 and on(r, s, p)) or (d2 == 0 and on(r, s, q))
            or (d3 == 0 and on(p, q, r)) or (d4 == 0 and on(p, q, s)))


def trapezoids(contours, rule: str) -> list[list[tuple]]:
    """The region the rule fills, as counter-clockwise trapezoids with horizontal sides.

    Works in whatever arithmetic the coordinates use: Fractions give exact
    trapezoids, floats trapezoids with rounded crossing heights.
    """
    if rule not in ("evenodd", "nonzero"):
        raise ValueError(f"trapezoids need the rule evenodd or nonzero, not {rule!r}")
    edges = []
    for contour in contours:
        n = len(contour)
        for k in range(n):
            (ax, ay), (bx, by) = contour[k], contour[(k + 1) % n]
            if ay != by:
                # Stored bottom to top; a downward edge adds +1 to the winding
                # number of the points to its right (counter-clockwise: inside).
                if ay < by:
                    edges.append((ax, ay, bx, by, -1))
                else:
                    edges.append((bx, by, ax, ay, +1))
    if not edges:
        return []
    exact = isinstance(edges[0][0], Fraction)
    heights = {e[1] for e in edges} | {e[3] for e in edges}
    for a in range(len(edges)):
        for b in range(a + 1, len(edges)):
            y = _crossing_height(edges[a], edges[b], exact)
            if y is not None:
                heights.add(y)
    heights = sorted(heights)
    pieces = []
    for ya, yb in zip(heights, heights[1:]):
        if not yb > ya:
            continue
        active = []
        for e in edges:
            if e[1] <= ya and e[3] >= yb:
                xa, xb = _x_at(e, ya), _x_at(e, yb)
                active.append((xa + xb, xa, xb, e[4]))
        active.sort(key=lambda item: item[0])
        winding = 0
        for left, right in zip(active, active[1:]):
            winding += left[3]
            inside = winding % 2 == 1 if rule == "evenodd" else winding != 0
            if inside:
                pieces.append([(left[1], ya), (right[1], ya), (right[2], yb), (left[2], yb)])
    return pieces


def _x_at(edge, y):
    ax, ay, bx, by, _ = edge
    if y == ay:
        return ax
    if y == by:
        return bx
    return ax + (bx - ax) * ((y - ay) / (by - ay))


def _crossing_height(e, f, exact: bool):
    """The height where two edges (stored bottom to top) cross, if they do inside both."""
    lo, hi = max(e[1], f[1]), min(e[3], f[3])
    if not hi > lo:
        return None
    # x difference at the two ends of the shared height range
    d_lo = _x_at(e, lo) - _x_at(f, lo)
    d_hi = _x_at(e, hi) - _x_at(f, hi)
    if d_lo == 0 or d_hi == 0 or (d_lo > 0) == (d_hi > 0):
        return None
    y = lo + (hi - lo) * (d_lo / (d_lo - d_hi))
    if not exact:
        y = min(max(y, lo), hi)
    return y


# ============================================================ helpers
def as_float(coverage: np.ndarray) -> np.ndarray:
    """An exact (Fraction) coverage array as float64."""
    return np.vectorize(float, otypes=[np.float64])(coverage) if coverage.dtype == object \
        else coverage


def pixel_area_bounds(polygon) -> tuple[int, int, int, int]:
    """The window (x0, y0, x1, y1) of pixels a polygon's bounding box touches."""
    points = [p for c in _contours(polygon) for p in c]
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return (math.floor(min(xs)), math.floor(min(ys)), math.ceil(max(xs)), math.ceil(max(ys)))


__all__ = ["RULES", "CAPS", "polygon_coverage", "triangle_coverage", "segment_coverage",
           "segment_rectangle", "region_area", "trapezoids", "twice_signed_area",
           "counter_clockwise", "mean_clamp", "as_float", "pixel_area_bounds", "window_of"]
