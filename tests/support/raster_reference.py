"""Exact point-in-triangle tests in whole numbers, for references that test many
points (not a test module).

algorithms/exact/triangles.py defines the top-left rule by a nudge: the
point moved right by a tiny epsilon and up by epsilon squared must lie in
the open triangle. For a counter-clockwise triangle and its edge a -> b,
the moved point's side is side + (a_y - b_y) epsilon + (b_x - a_x)
epsilon^2, so its sign is that of the first non-zero entry of
(side, a_y - b_y, b_x - a_x): the same rule as a comparison of whole
numbers, thousands of times faster than building the nudge per point.
tests/algorithms/test_visibility_reference.py holds it to the exact
module on the catalogue's triangles.
"""
from __future__ import annotations

from fractions import Fraction


def snap(value, scale: int) -> int:
    """value * scale rounded to a whole number, halves to even, exactly."""
    return round(Fraction(value) * scale)


def counter_clockwise(tri):
    (x0, y0), (x1, y1), (x2, y2) = tri
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    return (tri[0], tri[2], tri[1]) if area < 0 else tuple(tri)


def twice_area(tri):
    (x0, y0), (x1, y1), (x2, y2) = tri
    return (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)


def inside(tri, x, y, rule: str = "top-left") -> bool:
    """Is (x, y) in the counter-clockwise triangle ``tri`` (same whole-number units)?"""
    for k in range(3):
        (ax, ay), (bx, by) = tri[k], tri[(k + 1) % 3]
        side = (bx - ax) * (y - ay) - (by - ay) * (x - ax)
        if rule == "inclusive":
            if side < 0:
                return False
        elif rule == "strict":
            if side <= 0:
                return False
        elif (side, ay - by, bx - ax) <= (0, 0, 0):
            return False
    return True


def triangle_pixels(triangle, grid, rule: str = "top-left", bits: int = 8) -> set:
    """The pixels of the grid whose centres the triangle (real vertices, snapped
    to 1/2^bits px) covers under the rule; empty for a triangle of no area."""
    scale = 1 << bits
    # Units of 1/2^(bits + 1) px: vertices are even, centres (2i + 1) 2^bits.
    tri = counter_clockwise([(2 * snap(x, scale), 2 * snap(y, scale)) for x, y in triangle])
    if twice_area(tri) == 0:
        return set()
    xs, ys = [p[0] for p in tri], [p[1] for p in tri]
    step = 2 * scale
    i_lo, i_hi = max(0, -((scale - min(xs)) // step)), min(grid[0] - 1, (max(xs) - scale) // step)
    j_lo, j_hi = max(0, -((scale - min(ys)) // step)), min(grid[1] - 1, (max(ys) - scale) // step)
    return {(i, j) for j in range(j_lo, j_hi + 1) for i in range(i_lo, i_hi + 1)
            if inside(tri, (2 * i + 1) * scale, (2 * j + 1) * scale, rule)}
