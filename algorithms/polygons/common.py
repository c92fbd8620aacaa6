"""What every polygon algorithm shares: snapping to the 1/256 px grid, the
pixel-centre tests of the fill rule, and exact cross products."""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms.core.registry import InputError, Inputs

NAN = math.nan
SUBPIXEL_BITS = 8
ONE = 1 << SUBPIXEL_BITS  # one pixel in snapped units
HALF_PIXEL = ONE // 2
HALF = Fraction(1, 2)
# Keeps every product of the fast kernel inside int64 (see _crossing_columns).
MAX_COORDINATE = 1 << 20

POLYGON = Inputs(3, integer=False, contours=True)
FLOATS = {"float64": np.float64, "float32": np.float32}


def snap(value: float) -> int:
    """A coordinate in 1/256 px, rounded to nearest (halves to even)."""
    return round(value * ONE)


def snap_contours(points) -> list[list[tuple[int, int]]]:
    """Every contour with its vertices on the 1/256 grid."""
    contours = []
    for contour in points:
        for x, y in contour:
            if abs(x) > MAX_COORDINATE or abs(y) > MAX_COORDINATE:
                raise InputError(f"polygon coordinates must lie within +-{MAX_COORDINATE} px, "
                                 f"got ({x:g}, {y:g})")
        contours.append([(snap(x), snap(y)) for x, y in contour])
    return contours


def first_index(v: int) -> int:
    """The first pixel index (row or column) whose centre is at or beyond v (snapped units)."""
    return -((HALF_PIXEL - v) // ONE)


def first_column(x) -> int:
    """The leftmost pixel whose centre is at or right of x (in pixels)."""
    if isinstance(x, (int, Fraction)):
        return math.ceil(x - HALF)
    # Float arithmetic: the same test done in float64, as the fast kernel does.
    return math.ceil(float(x) - 0.5)


def pixel_of(vertex) -> tuple[int, int]:
    """The pixel whose square holds a snapped vertex."""
    return vertex[0] // ONE, vertex[1] // ONE


def as_pixels(value: int) -> Fraction:
    return Fraction(value, ONE)


def edge_label(contours, contour: int, index: int) -> str:
    after = (index + 1) % len(contours[contour])
    if len(contours) > 1:
        return f"C{contour + 1}.P{index + 1}P{after + 1}"
    return f"P{index + 1}P{after + 1}"


class WholeAndError(Fraction):
    """An exact x kept as the integer edge walk keeps it: a whole part and an
    error term e over dy (0 <= e < dy). Adding a WholeAndError step (1/m as a
    whole q and a remainder r) does x += q; e += r; if e >= dy: x += 1, e -= dy,
    which is Bresenham's carry. It is a Fraction, so it compares and rounds
    exactly like the exact x it stands for."""

    __slots__ = ("whole", "error", "over")

    def __new__(cls, whole: int, error: int, over: int):
        value = super().__new__(cls, whole * over + error, over)
        value.whole, value.error, value.over = whole, error, over
        return value

    @classmethod
    def of(cls, value: Fraction, over: int) -> "WholeAndError":
        """``value`` (a multiple of 1/over) as a whole part and an error term."""
        whole, error = divmod(value.numerator * (over // value.denominator), over)
        return cls(whole, error, over)

    def __add__(self, step):
        if not isinstance(step, WholeAndError):
            return Fraction(self) + step
        whole, error = self.whole + step.whole, self.error + step.error
        if error >= self.over:
            whole, error = whole + 1, error - self.over
        return WholeAndError(whole, error, self.over)


def table_number(value):
    """A table cell: exact fractions stay exact, floats become plain floats; an
    integer walk's x shows as (whole, error/dy)."""
    if isinstance(value, WholeAndError):
        return (value.whole, f"{value.error}/{value.over}")
    if isinstance(value, (int, Fraction)):
        return value.numerator if isinstance(value, Fraction) and value.denominator == 1 else value
    return float(value)


def cross(o, a, b) -> int:
    """(a - o) x (b - o): positive when o -> a -> b turns left."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def signed_area2(contour) -> int:
    """Twice the signed area (snapped units): positive counter-clockwise."""
    return sum(contour[k - 1][0] * contour[k][1] - contour[k][0] * contour[k - 1][1]
               for k in range(len(contour)))


def without_repeats(contour):
    """The vertices with repeated neighbours (and a repeated first/last) merged."""
    kept = []
    for vertex in contour:
        if not kept or kept[-1] != vertex:
            kept.append(vertex)
    while len(kept) > 1 and kept[0] == kept[-1]:
        kept.pop()
    return kept


def single_contour(points, name: str, alternative: str):
    if len(points) != 1:
        raise InputError(f"{name} fills one contour, got {len(points)}; {alternative}")
