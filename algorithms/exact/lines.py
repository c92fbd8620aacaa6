"""Exact oracles for lines: integers and fractions.Fraction, never floats.

These are written from the definitions, not from the algorithms in
lines.py, so tests and the speed/error report can hold the algorithms to
them. Points are integer pixel coordinates; since pixel (i, j) and the
endpoints are both offset by 1/2, pixel (i, j) stands for the point (i, j)
of the ideal segment's plane.
"""
from __future__ import annotations

from fractions import Fraction
from math import gcd
from typing import Iterable, Sequence

TIE_RULES = ("down", "up", "toward-P")
HALF = Fraction(1, 2)


# ------------------------------------------------------- exact line values
def x_is_major(p, q) -> bool:
    """The major axis is the longer extent; x wins at 45 degrees and for a point."""
    return abs(q[0] - p[0]) >= abs(q[1] - p[1])


def line_value(p, q, major: int) -> Fraction:
    """The ideal line's minor coordinate at a major coordinate, exactly.

    For an x-major segment this is y = y0 + dy * (x - x0) / dx; for a
    y-major one, x = x0 + dx * (y - y0) / dy.
    """
    (x0, y0), (x1, y1) = p, q
    if x_is_major(p, q):
        if x1 == x0:
            return Fraction(y0)
        return y0 + Fraction((y1 - y0) * (major - x0), x1 - x0)
    return x0 + Fraction((x1 - x0) * (major - y0), y1 - y0)


def y_at(p, q, x: int) -> Fraction:
    """y = y0 + dy * (x - x0) / dx, exactly (dx must not be zero)."""
    (x0, y0), (x1, y1) = p, q
    if x1 == x0:
        raise ValueError("y is not a function of x on a vertical segment")
    return y0 + Fraction((y1 - y0) * (x - x0), x1 - x0)


def x_at(p, q, y: int) -> Fraction:
    """x = x0 + dx * (y - y0) / dy, exactly (dy must not be zero)."""
    return y_at((p[1], p[0]), (q[1], q[0]), y)


def floor_exact(value: Fraction) -> int:
    return value.numerator // value.denominator


def round_half_up_exact(value: Fraction) -> int:
    """floor(v + 1/2): the nearest integer, halves rounded up."""
    return floor_exact(value + HALF)


def is_half(value: Fraction) -> bool:
    """Is v exactly half-way between two integers (a tie for rounding)?"""
    return value.denominator == 2


def is_integer(value: Fraction) -> bool:
    """Is v an integer (a boundary for floor)?"""
    return value.denominator == 1


# ------------------------------------------------ the nearest-pixel line
def nearest_minor(value: Fraction, tie: str, toward: int) -> int:
    """The integer nearest to v; at a tie, by the rule.

    ``tie`` is 'down' (the smaller integer), 'up' (the larger) or
    'toward-P' (the one nearer ``toward``, P's minor coordinate).
    """
    if tie not in TIE_RULES:
        raise ValueError(f"unknown tie rule {tie!r}; use one of {', '.join(TIE_RULES)}")
    if not is_half(value):
        return round_half_up_exact(value)
    below, above = floor_exact(value), floor_exact(value) + 1
    if tie == "down":
        return below
    if tie == "up":
        return above
    return below if toward <= below else above


def nearest_pixel_line(p, q, tie: str = "down") -> list[tuple[int, int]]:
    """One pixel per major-axis column, P to Q: the pixel nearest the ideal line.

    Within a column the nearest pixel in the minor direction is also the
    nearest in perpendicular distance, since both scale by the same factor.
    """
    major_is_x = x_is_major(p, q)
    a0, a1 = (p[0], q[0]) if major_is_x else (p[1], q[1])
    toward = p[1] if major_is_x else p[0]
    step = 1 if a1 >= a0 else -1
    pixels = []
    for a in range(a0, a1 + step, step):
        b = nearest_minor(line_value(p, q, a), tie, toward)
        pixels.append((a, b) if major_is_x else (b, a))
    return pixels


def tie_columns(p, q) -> list[int]:
    """Major coordinates where the ideal line is exactly half-way between two pixels."""
    major_is_x = x_is_major(p, q)
    a0, a1 = (p[0], q[0]) if major_is_x else (p[1], q[1])
    step = 1 if a1 >= a0 else -1
    return [a for a in range(a0, a1 + step, step) if is_half(line_value(p, q, a))]


def has_ties(p, q) -> bool:
    """A tie exists exactly when the major extent over gcd(dx, dy) is even.

    With g = gcd and dx' = dx/g, dy' = dy/g coprime, dy * u / dx has
    fraction 1/2 for some whole u only when dx' is even (then dy' is odd).
    """
    major = max(abs(q[0] - p[0]), abs(q[1] - p[1]))
    minor = min(abs(q[0] - p[0]), abs(q[1] - p[1]))
    if major == 0:
        return False
    return (major // gcd(major, minor)) % 2 == 0


# --------------------------------------------- distances to the segment
def _cross(p, q, point) -> int:
    return (q[0] - p[0]) * (point[1] - p[1]) - (q[1] - p[1]) * (point[0] - p[0])


def segment_distance_sq(p, q, point) -> Fraction:
    """Squared distance from a point to the segment PQ (not the infinite line)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    wx, wy = point[0] - p[0], point[1] - p[1]
    length_sq = dx * dx + dy * dy
    along = wx * dx + wy * dy
    if along <= 0:  # nearest point is P (this also covers P == Q)
        return Fraction(wx * wx + wy * wy)
    if along >= length_sq:  # nearest point is Q
        ux, uy = point[0] - q[0], point[1] - q[1]
        return Fraction(ux * ux + uy * uy)
    return Fraction(_cross(p, q, point) ** 2, length_sq)


def within_half(p, q, point) -> bool:
    """Is the point at distance < 1/2 from the segment? Integers only."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    wx, wy = point[0] - p[0], point[1] - p[1]
    length_sq = dx * dx + dy * dy
    along = wx * dx + wy * dy
    if along <= 0:
        return 4 * (wx * wx + wy * wy) < 1
    if along >= length_sq:
        ux, uy = point[0] - q[0], point[1] - q[1]
        return 4 * (ux * ux + uy * uy) < 1
    return 4 * _cross(p, q, point) ** 2 < length_sq


def implicit_pixels(p, q) -> set[tuple[int, int]]:
    """Every pixel whose centre lies at distance < 1/2 from the segment."""
    return {(x, y)
            for x in range(min(p[0], q[0]), max(p[0], q[0]) + 1)
            for y in range(min(p[1], q[1]), max(p[1], q[1]) + 1)
            if within_half(p, q, (x, y))}


def projection(p, q, point) -> Fraction:
    """Where the point projects onto PQ, as t in [0, 1] (0 for a point segment)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    length_sq = dx * dx + dy * dy
    if length_sq == 0:
        return Fraction(0)
    t = Fraction((point[0] - p[0]) * dx + (point[1] - p[1]) * dy, length_sq)
    return min(max(t, Fraction(0)), Fraction(1))


# ----------------------------------------- measures for the error report
def deviation_sq(p, q, pixel) -> Fraction:
    """Squared perpendicular distance of a pixel from the ideal (infinite) line.

    For a point segment, the squared distance to P.
    """
    dx, dy = q[0] - p[0], q[1] - p[1]
    length_sq = dx * dx + dy * dy
    if length_sq == 0:
        return Fraction((pixel[0] - p[0]) ** 2 + (pixel[1] - p[1]) ** 2)
    return Fraction(_cross(p, q, pixel) ** 2, length_sq)


def deviation(p, q, pixel) -> float:
    """Perpendicular distance of a pixel from the ideal line, in pixels."""
    return float(deviation_sq(p, q, pixel)) ** 0.5


def max_deviation_sq(p, q, pixels: Iterable) -> Fraction:
    return max((deviation_sq(p, q, pixel) for pixel in pixels), default=Fraction(0))


def are_8_neighbours(a, b) -> bool:
    """Distinct pixels sharing an edge or a corner."""
    return a != b and max(abs(a[0] - b[0]), abs(a[1] - b[1])) == 1


def gap_count(pixels: Sequence) -> int:
    """Jumps between consecutive distinct plotted pixels that are not 8-neighbours.

    Repeats of the previous pixel are skipped first; each jump counts once,
    however many pixels it skips.
    """
    gaps = 0
    previous = None
    for pixel in map(tuple, pixels):
        if previous is not None and pixel != previous and not are_8_neighbours(previous, pixel):
            gaps += 1
        previous = pixel
    return gaps


def duplicate_count(pixels: Sequence) -> int:
    """Plots of a pixel that was already plotted, just before or any time earlier."""
    seen = set()
    duplicates = 0
    for pixel in map(tuple, pixels):
        if pixel in seen:
            duplicates += 1
        seen.add(pixel)
    return duplicates


def is_8_connected(pixels: Iterable) -> bool:
    """Does the set of pixels form one 8-connected piece?"""
    remaining = set(map(tuple, pixels))
    if not remaining:
        return True
    stack = [remaining.pop()]
    while stack:
        x, y = stack.pop()
        for ox in (-1, 0, 1):
            for oy in (-1, 0, 1):
                neighbour = (x + ox, y + oy)
                if neighbour in remaining:
                    remaining.remove(neighbour)
                    stack.append(neighbour)
    return not remaining
