"""Exact oracles for circles and ellipses: integers and Fractions only.

Written from the definitions, not from the loops in circles.py, so tests and
reports can hold those algorithms to them. All coordinates are offsets from
an integer centre; since the centre pixel and every other pixel have their
sample points at half-integers, offset (x, y) is the point (x, y) of the
ideal curve's plane.

The midpoint circle, derived. In the octant from (0, R) clockwise to the
diagonal, the loop holds one pixel per column x. Its decision for column x
is the sign of F(x, y - 1/2), with F(x, y) = x^2 + y^2 - R^2 and y the
previous column's pixel: negative (the midpoint is inside) keeps y, else y
drops by one. Multiplied by 4, F(x, y - 1/2) = 4x^2 + (2y - 1)^2 - 4R^2:
an odd number, never 0, so there are no ties. Since the arc falls by less
than one pixel per column in this octant, the choice is always the one y
whose cell [y - 1/2, y + 1/2] holds the circle's height h = sqrt(R^2 - x^2):

    (2y - 1)^2 < 4 (R^2 - x^2) < (2y + 1)^2,

that is y = round(h); with s = isqrt(4 (R^2 - x^2)), y = (s + 1) // 2. The
octant's columns are x = 0, 1, ... while x <= y; the other seven octants
are mirror images.
"""
from __future__ import annotations

from fractions import Fraction
from math import isqrt


# ------------------------------------------------------------------ circles
def midpoint_height(r: int, x: int) -> int:
    """The y the midpoint test picks in column x (0 <= x <= r): round(sqrt(r^2 - x^2))."""
    return (isqrt(4 * (r * r - x * x)) + 1) // 2


def midpoint_octant(r: int) -> list[tuple[int, int]]:
    """The midpoint circle's pixels from (0, r) to the diagonal, column by column."""
    pixels = []
    x = 0
    while x <= r:
        y = midpoint_height(r, x)
        if x > y:
            break
        pixels.append((x, y))
        x += 1
    return pixels


def eight_way(pixels) -> set[tuple[int, int]]:
    """All images of the pixels under the 8 symmetries of the square grid."""
    return {image for x, y in pixels
            for image in ((x, y), (y, x), (y, -x), (x, -y), (-x, -y), (-y, -x), (-y, x), (-x, y))}


def four_way(pixels) -> set[tuple[int, int]]:
    return {image for x, y in pixels for image in ((x, y), (x, -y), (-x, y), (-x, -y))}


def midpoint_circle(r: int) -> set[tuple[int, int]]:
    return eight_way(midpoint_octant(r))


def sqrt_height(r: int, x: int) -> int:
    """floor(sqrt(r^2 - x^2)), the 4- and 8-way algorithms' y, exactly."""
    return isqrt(r * r - x * x)


def sqrt4_circle(r: int) -> set[tuple[int, int]]:
    return four_way([(x, sqrt_height(r, x)) for x in range(r + 1)])


def sqrt4_gap_columns(r: int) -> list[tuple[int, int]]:
    """(x, skipped) for each column x where the 4-way arc jumps.

    The arc of the first quadrant steps from column x - 1 to column x; it
    leaves a gap when y drops by two or more, skipping drop - 1 pixels. Such
    a drop needs the ideal arc to fall by more than one pixel over the
    column, which happens only past 45 degrees (2 x^2 > r^2).
    """
    jumps = []
    for x in range(1, r + 1):
        drop = sqrt_height(r, x - 1) - sqrt_height(r, x)
        if drop >= 2:
            jumps.append((x, drop - 1))
    return jumps


def sqrt8_circle(r: int) -> set[tuple[int, int]]:
    """The 8-way algorithm's pixels: the columns with x < y, then x == y."""
    octant = [(0, r)]
    x = 1
    while x <= r and x < sqrt_height(r, x):
        octant.append((x, sqrt_height(r, x)))
        x += 1
    if x <= r and x == sqrt_height(r, x):
        octant.append((x, x))
    return eight_way(octant)


# ----------------------------------------------------------------- ellipses
def ellipse_value(rx: int, ry: int, x, y) -> Fraction:
    """F(x, y) = ry^2 x^2 + rx^2 y^2 - rx^2 ry^2: negative inside, exactly."""
    x, y = Fraction(x), Fraction(y)
    return ry * ry * x * x + rx * rx * y * y - rx * rx * ry * ry


def ellipse_axis_distance_below(rx: int, ry: int, x: int, y: int, limit: Fraction) -> bool:
    """Does the ellipse cross the pixel's column or row within ``limit`` of it?

    True when the ideal ellipse (rx, ry > 0) passes through the vertical
    segment from (x, y - limit) to (x, y + limit), or through the horizontal
    one from (x - limit, y) to (x + limit, y), limit excluded. By symmetry
    the quadrant x, y >= 0 is enough, where F grows with |x| and with |y|.
    """
    x, y = abs(x), abs(y)

    def crosses(f, at):
        # f grows strictly for t >= 0: is f(t) = 0 for some t >= 0, |t - at| < limit?
        low, high = Fraction(at) - limit, Fraction(at) + limit
        if low < 0:
            return f(0) <= 0 < f(high)
        return f(low) < 0 < f(high)

    column = crosses(lambda t: ellipse_value(rx, ry, x, t), y)
    row = crosses(lambda t: ellipse_value(rx, ry, t, y), x)
    return column or row


def ellipse_segment(rx: int, ry: int) -> set[tuple[int, int]]:
    """A degenerate ellipse: the segment along an axis (one pixel when both are 0)."""
    if rx == 0:
        return {(0, y) for y in range(-ry, ry + 1)}
    return {(x, 0) for x in range(-rx, rx + 1)}
