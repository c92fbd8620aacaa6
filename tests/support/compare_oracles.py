"""Oracles for the compare-mode tests, written from the textbook definitions
with integers and Fractions (never the algorithm generators)."""
from collections import Counter
from fractions import Fraction

FLOAT32_BITS, FLOAT64_BITS = 24, 53
HALF = Fraction(1, 2)


def round_to_float(value: Fraction, bits: int) -> Fraction:
    """The IEEE binary float of ``bits`` significand bits nearest to
    ``value`` (ties to even), as a Fraction. No subnormals or overflow:
    the values here are modest."""
    if value == 0:
        return Fraction(0)
    sign = -1 if value < 0 else 1
    size = abs(value)
    exponent = size.numerator.bit_length() - size.denominator.bit_length()
    while Fraction(2) ** exponent > size:
        exponent -= 1
    while Fraction(2) ** (exponent + 1) <= size:
        exponent += 1
    scale = Fraction(2) ** (bits - 1 - exponent)
    scaled = size * scale
    whole, rest = divmod(scaled.numerator, scaled.denominator)
    rest = Fraction(rest, scaled.denominator)
    if rest > HALF or (rest == HALF and whole % 2 == 1):
        whole += 1
    return sign * whole / scale


def round_half_up(value: Fraction) -> int:
    """floor(v + 1/2), exactly."""
    shifted = value + HALF
    return shifted.numerator // shifted.denominator


def dda_pixels(p, q, bits: int) -> list:
    """The DDA: x_inc, y_inc = d / steps in the float type; x and y start at
    P and add them once per step, each sum rounded to the float type; every
    position is plotted at (round(x), round(y)), halves up."""
    (x0, y0), (x1, y1) = p, q
    steps = max(abs(x1 - x0), abs(y1 - y0))
    x_inc = round_to_float(Fraction(x1 - x0, steps), bits)
    y_inc = round_to_float(Fraction(y1 - y0, steps), bits)
    x, y = Fraction(x0), Fraction(y0)
    pixels = [(x0, y0)]
    for _ in range(steps):
        x = round_to_float(x + x_inc, bits)
        y = round_to_float(y + y_inc, bits)
        pixels.append((round_half_up(x), round_half_up(y)))
    return pixels


def diff_counts(pixels_a, pixels_b, width: int, height: int) -> dict:
    """Counts of cells only in A, only in B, in both, and in both but
    written a different number of times (runs without values), from the
    pixel lists the two runs emit (clipped to the grid)."""
    def inside(pixels):
        return Counter((x, y) for x, y in pixels if 0 <= x < width and 0 <= y < height)
    a, b = inside(pixels_a), inside(pixels_b)
    both = set(a) & set(b)
    return {"only A": len(set(a) - set(b)), "only B": len(set(b) - set(a)),
            "both": len(both), "both, different value": sum(a[c] != b[c] for c in both)}
