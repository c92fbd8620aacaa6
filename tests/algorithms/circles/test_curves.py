"""The circle by distance (real centre), Wu's circle and the Bezier curve as N
lines, against oracles written here in exact arithmetic."""
from fractions import Fraction
from math import isqrt

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.support import record
from tests.support.curve_oracles import de_casteljau, outline_oracle, polyline_oracle


def written(trace):
    return [tuple(p) for p in trace.written_pixels().tolist()]


# ------------------------------------------------ circle by distance
def disk_oracle(centre, r, grid):
    """Pixels of the whole grid whose centres are within r, in Fractions."""
    cx, cy, r = (Fraction(v) for v in (*centre, r))
    half = Fraction(1, 2)
    return {(i, j) for i in range(-2, grid[0] + 2) for j in range(-2, grid[1] + 2)
            if (i + half - cx) ** 2 + (j + half - cy) ** 2 <= r * r}


@settings(max_examples=40)
@given(st.floats(4, 12), st.floats(4, 12), st.floats(0, 4.5),
       st.sampled_from(["disk", "outline"]))
def test_distance_circle_is_the_exact_disk(cx, cy, r, shape):
    trace = record("circle-distance", ((cx, cy),), {"radius": r, "shape": shape}, (17, 17))
    pixels = written(trace)
    disk = disk_oracle((cx, cy), r, (17, 17))
    assert len(pixels) == len(set(pixels))
    assert set(pixels) == (disk if shape == "disk" else outline_oracle(disk))


@pytest.mark.parametrize("centre, r", [((8.5, 8.5), 3), ((8.5, 8.5), 0), ((8, 8), 0.5),
                                       ((8.25, 8.75), 1.25)])
def test_distance_circle_centres_exactly_on_the_circle_count_as_inside(centre, r):
    # (8.5, 8.5) radius 3: the centres 3 px straight out lie exactly on the circle.
    pixels = set(written(record("circle-distance", (centre,), {"radius": r}, (17, 17))))
    assert pixels == disk_oracle(centre, r, (17, 17))


def test_integer_pixel_centre_matches_the_integer_rule():
    # A centre on a pixel centre and a whole radius: the same disk as the offsets
    # with x^2 + y^2 <= R^2.
    pixels = set(written(record("circle-distance", ((10.5, 10.5),), {"radius": 7}, (21, 21))))
    assert pixels == {(10 + x, 10 + y) for x in range(-7, 8) for y in range(-7, 8)
                      if x * x + y * y <= 49}


# ------------------------------------------------------- Wu's circle
@pytest.mark.parametrize("r", [1, 2, 5, 13, 40, 100])
def test_wu_circle_shares_each_column_between_the_two_nearest_centres(r):
    trace = record("circle-wu", ((0, 0),), {"radius": r})
    plotted = trace.writes()
    xs, ys = trace.written_pixels().T
    intensity = trace.series("intensity")[plotted]
    h2 = {}
    for x, y, a in zip(xs.tolist(), ys.tolist(), intensity.tolist()):
        if abs(x) > abs(y):
            continue  # a mirror across the diagonal; its own column is checked
        x, y = abs(x), abs(y)
        n = r * r - x * x
        floor_h = isqrt(n)
        assert y in (floor_h, floor_h + 1)
        # Intensity of the far pixel is f = h - floor(h); within 1e-12 of exact.
        f = a if y == floor_h + 1 else 1 - a
        h = floor_h + f
        assert abs(h * h - n) < 1e-9 * max(n, 1)
        h2.setdefault(x, set()).add((y, round(a, 12)))
    # Every column of the octant (x <= h) has its pixels; the two add up to 1.
    for x in range(0, r + 1):
        if x * x > r * r - x * x:
            assert x not in h2
            continue
        pairs = h2[x]
        assert abs(sum(a for _, a in pairs) - 1) < 1e-9 or len(pairs) == 1


def test_wu_circle_values_are_coverages_and_grey_ink():
    trace = record("circle-wu", ((10, 10),), {"radius": 6}, (21, 21))
    values = trace.pixel_values()
    assert np.all((values > 0) & (values <= 1))


# ------------------------------------------------ Bezier as N lines
CONTROL = st.tuples(st.integers(-20, 40), st.integers(-20, 40))


@settings(max_examples=40)
@given(st.tuples(CONTROL, CONTROL, CONTROL, CONTROL), st.integers(1, 24))
def test_bezier_is_the_polyline_through_the_rounded_curve_points(points, n):
    trace = record("curve-bezier", points, {"segments": n}, (8, 8))
    corners, pixels = polyline_oracle(points, n)
    assert written(trace) == pixels
    assert corners[0] == points[0] and corners[-1] == points[3]


def test_more_segments_follow_the_curve_closer():
    points = ((1, 1), (4, 20), (25, 20), (30, 2))

    def worst(n):
        # The farthest any drawn pixel centre lies from the curve, over a fine
        # sampling of the curve (exact points, float distances).
        curve = [tuple(map(float, de_casteljau(points, Fraction(k, 400)))) for k in range(401)]
        curve = np.array(curve)
        pixels = np.array(written(record("curve-bezier", points, {"segments": n})), float)
        return np.sqrt(((pixels[:, None, :] - curve[None]) ** 2).sum(-1)).min(1).max()

    assert worst(3) > 1.5 > worst(16) and worst(16) <= 1.0
