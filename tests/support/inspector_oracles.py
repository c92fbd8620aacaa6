"""The pixel inspector's scene and oracles: exact fractions from the vertices."""
from fractions import Fraction

import pytest

GRID = (16, 14)
# Not on the 1/256 grid: the run snaps them (DESIGN.md: nearest multiple of
# 1/256 px, halves to even) and the oracle must do the same.
TRIANGLE = [(2.3, 1.1), (12.7, 3.2), (5.5, 10.9)]


def snapped(points, bits=8):
    scale = 1 << bits
    # round() of a Fraction rounds halves to even, as the run does.
    return [tuple(Fraction(round(Fraction(v) * scale), scale) for v in point) for point in points]


def edge_values(vertices, pixel):
    """e_k at the pixel centre: twice the signed area of (P_k+1, P_k+2, centre)."""
    px, py = Fraction(2 * pixel[0] + 1, 2), Fraction(2 * pixel[1] + 1, 2)
    values = []
    for k in range(3):
        (xi, yi), (xj, yj) = vertices[(k + 1) % 3], vertices[(k + 2) % 3]
        values.append((xj - xi) * (py - yi) - (yj - yi) * (px - xi))
    return values


def weight(text):
    """A weight as the inspector prints it: exact, or 10 digits and an ellipsis."""
    return text.rstrip("\u2026"), text.endswith("\u2026")


def assert_weight(text, exact):
    digits, rounded = weight(text)
    if rounded:
        assert float(digits) == pytest.approx(float(exact), rel=1e-9, abs=1e-12)
    else:
        assert Fraction(digits) == exact
