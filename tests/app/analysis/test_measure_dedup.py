"""line_errors' sort-based deduplication against a set-based count in exact integers."""
from fractions import Fraction

import numpy as np
import pytest

from app.analysis.measure_curves import differing_pixels, distinct_pixels, line_errors


def oracle(p, q, pixels):
    """missed, extra and duplicates by sets: a column's nearest pixels are
    those whose distance across is at most 1/2 from the ideal line."""
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    steep = abs(dy) > abs(dx)
    n, m = (dy, dx) if steep else (dx, dy)
    sign = 1 if n >= 0 else -1
    distinct = set(map(tuple, pixels))
    hit = set()
    for x, y in distinct:
        along, across = (y - y0, x - x0) if steep else (x - x0, y - y0)
        u = along * sign
        if not 0 <= u <= abs(n):
            continue
        ideal = Fraction(m * u, abs(n)) if n else Fraction(0)
        if abs(across - ideal) <= Fraction(1, 2):  # midway: either pixel is nearest
            hit.add(u)
    return abs(n) + 1 - len(hit), len(distinct) - len(hit), len(pixels) - len(distinct)


@pytest.mark.parametrize("seed", range(6))
def test_counts_equal_a_set_based_oracle(seed):
    rng = np.random.default_rng(seed)
    p = tuple(rng.integers(-10, 10, 2).tolist())
    q = tuple((np.array(p) + rng.integers(-25, 26, 2)).tolist())
    pixels = np.array(p) + rng.integers(-3, 28, (60, 2)) * np.sign(np.array(q) - p + 0.5)
    pixels = np.concatenate([pixels, pixels[:7]]).astype(np.int64)  # duplicates
    got = line_errors(p, q, pixels)
    missed, extra, duplicates = oracle(p, q, pixels)
    assert (got["missed"], got["extra"], got["duplicates"]) == (missed, extra, duplicates)


def test_distinct_pixels_are_the_set_of_rows():
    rng = np.random.default_rng(3)
    pixels = rng.integers(-(1 << 20), 1 << 20, (500, 2))
    pixels = np.concatenate([pixels, pixels[::3]])
    got = distinct_pixels(pixels)
    assert sorted(map(tuple, got.tolist())) == sorted(set(map(tuple, pixels.tolist())))
    assert len(distinct_pixels(np.zeros((0, 2), np.int64))) == 0


def test_asymmetry_counts_pixels_of_one_direction_only():
    from app.analysis.measure_curves import asymmetry

    rng = np.random.default_rng(5)
    for _ in range(5):
        a = rng.integers(0, 12, (40, 2))
        b = rng.integers(0, 12, (30, 2))
        expected = len(set(map(tuple, a.tolist())) ^ set(map(tuple, b.tolist())))
        assert asymmetry(a, b) == expected
    assert asymmetry(np.zeros((0, 2), np.int64), a) == len(set(map(tuple, a.tolist())))


@pytest.mark.parametrize("seed", range(4))
def test_gaps_deviation_and_differing_against_plain_loops(seed):
    rng = np.random.default_rng(100 + seed)
    p = tuple(rng.integers(-20, 20, 2).tolist())
    q = p if seed == 0 else tuple((np.array(p) + rng.integers(-40, 41, 2)).tolist())
    pixels = np.array(p) + rng.integers(-3, 4, (50, 2)).cumsum(axis=0) // 2
    pixels = np.concatenate([pixels, pixels[-1:], pixels[:3]]).astype(np.int64)
    got = line_errors(p, q, pixels)
    plots = [tuple(v) for v in pixels.tolist()]
    gaps = sum(1 for a, b in zip(plots, plots[1:])
               if a != b and max(abs(b[0] - a[0]), abs(b[1] - a[1])) > 1)
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    if dx == dy == 0:
        worst = max(((x - x0) ** 2 + (y - y0) ** 2) ** 0.5 for x, y in plots)
    else:  # squared distances compared exactly, one square root at the end
        worst = max(Fraction((dx * (y - y0) - dy * (x - x0)) ** 2, dx * dx + dy * dy)
                    for x, y in plots) ** 0.5
    assert got["gaps"] == gaps
    assert got["max_deviation"] == pytest.approx(float(worst), rel=1e-12)
    assert differing_pixels(p, q, pixels) == got["differing"] == got["missed"] + got["extra"]
