"""Exact oracles for triangles: integers and fractions.Fraction, never floats.

They are written from the definitions, not from the algorithms in
triangles.py, so that tests can hold every traversal to them:

* A vertex given as a real number is snapped to the nearest multiple of
  1/2^bits (ties to even), exactly.
* A pixel (i, j) is covered when its centre (i + 1/2, j + 1/2) lies in the
  triangle under the fill rule:

  - ``inclusive``: in the closed triangle (boundary included);
  - ``strict``: in the open triangle (boundary excluded);
  - ``top-left``: the centre, nudged right by a tiny epsilon and up by
    epsilon squared, lies in the open triangle. A centre strictly inside
    stays inside, one strictly outside stays outside, and one on the
    boundary goes in exactly when the triangle lies to the right of that
    edge, or above it where the edge is horizontal: left edges and bottom
    horizontal edges are kept (y up). The nudge is a real (tiny, rational)
    displacement here, chosen small enough from the coordinates'
    denominators that no sign other than a zero can change.

  None of this depends on the winding order. A triangle of zero area covers
  nothing.
* The interior of a union of triangles is decided by looking at the
  directions around the point (see ``in_union_interior``).
"""
from __future__ import annotations

from fractions import Fraction
import functools
from math import lcm
from typing import Iterable, Sequence

RULES = ("top-left", "inclusive", "strict")


# ------------------------------------------------------------ snapping
def snap(value, bits: int) -> Fraction:
    """The nearest multiple of 1 / 2^bits, halves to even."""
    scale = 1 << bits
    return Fraction(round(Fraction(value) * scale), scale)


def snap_triangle(triangle, bits: int) -> tuple:
    return tuple((snap(x, bits), snap(y, bits)) for x, y in triangle)


def centre(i: int, j: int) -> tuple[Fraction, Fraction]:
    return Fraction(2 * i + 1, 2), Fraction(2 * j + 1, 2)


# ------------------------------------------------------------ geometry
def cross(o, p, q):
    """(p - o) x (q - o): positive when q lies to the left of o -> p."""
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])


def twice_area(triangle):
    """Twice the signed area: positive for counter-clockwise (y up)."""
    return cross(*triangle)


def counter_clockwise(triangle) -> tuple:
    p0, p1, p2 = triangle
    return (p0, p2, p1) if twice_area(triangle) < 0 else (p0, p1, p2)


def sides(triangle, point) -> list:
    """For a counter-clockwise triangle: how far left of each directed edge the point lies."""
    return [cross(triangle[k], triangle[(k + 1) % 3], point) for k in range(3)]


def _nudge(triangle, point) -> Fraction:
    """A displacement small enough to flip only zero signs of the sides."""
    coords = [c for p in triangle for c in p] + list(point)
    fractions = [Fraction(c) for c in coords]
    denominator = lcm(*(f.denominator for f in fractions))
    reach = int(max(abs(f) for f in fractions)) + 2
    # Every non-zero side is at least 1/denominator^2 in size and every
    # coordinate difference at least 1/denominator; epsilon must stay far
    # below both once multiplied by edge lengths up to 2 * reach.
    bound = 16 * denominator * denominator * reach * reach
    return Fraction(1, 1 << bound.bit_length())


def covers(triangle, point, rule: str) -> bool:
    """Does the (snapped) triangle cover the point under the fill rule?"""
    if rule not in RULES:
        raise ValueError(f"unknown fill rule {rule!r}")
    if twice_area(triangle) == 0:
        return False
    triangle = counter_clockwise(triangle)
    if rule == "inclusive":
        return all(s >= 0 for s in sides(triangle, point))
    if rule == "strict":
        return all(s > 0 for s in sides(triangle, point))
    eps = _nudge(triangle, point)
    moved = (point[0] + eps, point[1] + eps * eps)
    return all(s > 0 for s in sides(triangle, moved))


def triangles_of(points) -> list[tuple]:
    points = list(points)
    return [tuple(points[k:k + 3]) for k in range(0, len(points), 3)]


def coverage(points, bits: int, rule: str, window, cull: bool = False) -> dict:
    """Per pixel of the window (x0, y0, x1, y1), how many triangles cover it.

    ``points`` are real vertices, three per triangle. With ``cull``,
    clockwise triangles draw nothing. Pixels covered by none are left out.
    """
    counts: dict = {}
    for triangle in triangles_of(points):
        snapped = snap_triangle(triangle, bits)
        area = twice_area(snapped)
        if area == 0 or (cull and area < 0):
            continue
        for i, j in _pixels_near(snapped, window):
            if covers(snapped, centre(i, j), rule):
                counts[(i, j)] = counts.get((i, j), 0) + 1
    return counts


def _pixels_near(triangle, window):
    """Pixels of the window whose centres lie in the triangle's closed bounding box."""
    x0, y0, x1, y1 = window
    xs = [p[0] for p in triangle]
    ys = [p[1] for p in triangle]
    # centre i + 1/2 >= min x  <=>  i >= ceil(min x - 1/2)
    i_lo, i_hi = max(x0, _ceil(min(xs) - Fraction(1, 2))), min(x1 - 1, _floor(max(xs) - Fraction(1, 2)))
    j_lo, j_hi = max(y0, _ceil(min(ys) - Fraction(1, 2))), min(y1 - 1, _floor(max(ys) - Fraction(1, 2)))
    return [(i, j) for j in range(j_lo, j_hi + 1) for i in range(i_lo, i_hi + 1)]


def _floor(value: Fraction) -> int:
    return value.numerator // value.denominator


def _ceil(value: Fraction) -> int:
    return -((-value.numerator) // value.denominator)


# ------------------------------------------------- the union's interior
def _half(v) -> int:
    """0 for directions in [0, pi), 1 for [pi, 2 pi)."""
    return 0 if (v[1] > 0 or (v[1] == 0 and v[0] > 0)) else 1


def _sorted_by_angle(vectors: list) -> list:
    def compare(a, b):
        ha, hb = _half(a), _half(b)
        if ha != hb:
            return ha - hb
        c = a[0] * b[1] - a[1] * b[0]
        return -1 if c > 0 else (1 if c < 0 else 0)

    ordered = sorted(vectors, key=functools.cmp_to_key(compare))
    unique = []
    for v in ordered:
        if not unique or compare(unique[-1], v) != 0:
            unique.append(v)
    return unique


def _between(u, v):
    """A direction strictly inside the counter-clockwise arc from u to v."""
    c = u[0] * v[1] - u[1] * v[0]
    if c > 0:
        return (u[0] + v[0], u[1] + v[1])
    if c < 0:
        return (-(u[0] + v[0]), -(u[1] + v[1]))
    if u[0] * v[0] + u[1] * v[1] < 0:  # opposite: a half-turn
        return (-u[1], u[0])
    return (-u[0], -u[1])  # the same direction: the whole turn but one ray


def in_union_interior(triangles: Iterable[Sequence], point) -> bool:
    """Is the point inside the interior of the union of the (closed) triangles?

    Exact for integer or Fraction coordinates. A point strictly inside one
    triangle is. Otherwise every triangle that holds the point on its
    boundary covers a closed wedge of directions around it (a half-turn on
    an edge, the corner's angle at a vertex); the point is interior exactly
    when these wedges cover every direction. Between two neighbouring wedge
    sides no side lies, so testing one direction per gap decides it.
    """
    wedges = []
    for triangle in triangles:
        if twice_area(triangle) == 0:
            continue
        triangle = counter_clockwise(triangle)
        s = sides(triangle, point)
        if min(s) < 0:
            continue
        if min(s) > 0:
            return True
        wedges.append((triangle, s))
    if not wedges:
        return False
    directions = []
    for triangle, s in wedges:
        for k in range(3):
            if s[k] == 0:
                p, q = triangle[k], triangle[(k + 1) % 3]
                d = (q[0] - p[0], q[1] - p[1])
                directions += [d, (-d[0], -d[1])]
    directions = _sorted_by_angle(directions)
    for n, u in enumerate(directions):
        probe = _between(u, directions[(n + 1) % len(directions)])
        if not any(_wedge_holds(triangle, s, probe) for triangle, s in wedges):
            return False
    return True


def _wedge_holds(triangle, s, d) -> bool:
    """Does a ray from the point in direction d start inside the triangle?

    Only edges through the point matter; the others are strictly positive.
    """
    for k in range(3):
        if s[k] == 0:
            p, q = triangle[k], triangle[(k + 1) % 3]
            if (q[0] - p[0]) * d[1] - (q[1] - p[1]) * d[0] <= 0:
                return False
    return True


def union_interior(points, bits: int, window, cull: bool = False) -> set:
    """Pixels of the window whose centres lie in the interior of the drawn triangles' union.

    Only triangles whose bounding box holds a centre can matter to it.
    """
    drawn = []
    for triangle in triangles_of(points):
        snapped = snap_triangle(triangle, bits)
        area = twice_area(snapped)
        if area == 0 or (cull and area < 0):
            continue
        drawn.append(snapped)
    near: dict = {}
    for triangle in drawn:
        for pixel in _pixels_near(triangle, window):
            near.setdefault(pixel, []).append(triangle)
    return {pixel for pixel, triangles in near.items()
            if in_union_interior(triangles, centre(*pixel))}


def overlaps_and_cracks(counts: dict, interior: set) -> tuple[int, int]:
    """(pixels covered more than once, interior centres covered by none)."""
    overlaps = sum(1 for c in counts.values() if c > 1)
    cracks = sum(1 for pixel in interior if counts.get(pixel, 0) == 0)
    return overlaps, cracks


# ---------------------------------------------------- interpolation
def barycentric(triangle, point) -> tuple[Fraction, Fraction, Fraction]:
    """(alpha, beta, gamma) with point = alpha P0 + beta P1 + gamma P2, by Cramer's rule."""
    (x0, y0), (x1, y1), (x2, y2) = [(Fraction(x), Fraction(y)) for x, y in triangle]
    x, y = Fraction(point[0]), Fraction(point[1])
    det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    if det == 0:
        raise ValueError("a degenerate triangle has no barycentric coordinates")
    beta = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / det
    gamma = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / det
    return 1 - beta - gamma, beta, gamma


def affine(weights, values) -> Fraction:
    return sum((Fraction(w) * Fraction(v) for w, v in zip(weights, values)), Fraction(0))


def perspective_correct(weights, values, w) -> Fraction:
    """The attribute at a point of the projected triangle, undoing the projection.

    Screen-space weights are weights of the projected points; the point in
    space has weights proportional to weight_k / w_k.
    """
    inverse = [Fraction(1) / Fraction(wk) for wk in w]
    total = sum(Fraction(a) * iw for a, iw in zip(weights, inverse))
    return sum(Fraction(a) * iw * Fraction(v) for a, iw, v in zip(weights, inverse, values)) / total
