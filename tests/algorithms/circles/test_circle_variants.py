"""Bresenham's circle, the polar circle and the midpoint circle as printed,
against oracles written here from the definitions (integers only)."""
from math import isqrt

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import circles as exact
from tests.support import record
from tests.support.curve_oracles import cell_meets_circle, chebyshev_gaps, printed_c


def offsets(trace, centre=(0, 0)):
    return [(x - centre[0], y - centre[1]) for x, y in trace.written_pixels().tolist()]


def residual(x, y, r):
    return x * x + y * y - r * r


def nearest_octant(r):
    """Per column of the octant, the y whose |x^2 + y^2 - R^2| is least."""
    pixels, x = [], 0
    while True:
        s = isqrt(r * r - x * x) if x <= r else 0
        y = min((s, s + 1), key=lambda v: abs(residual(x, v, r)))
        if x > y:
            return pixels
        pixels.append((x, y))
        x += 1


# ------------------------------------------------------ Bresenham circle
def test_bresenham_picks_the_candidate_with_the_smaller_residual():
    for r in range(0, 200):
        pixels = offsets(record("circle-bresenham", ((0, 0),), {"radius": r}))
        assert len(pixels) == len(set(pixels)), r
        assert set(pixels) == exact.eight_way(nearest_octant(r)), r
        # And the same pixels as the midpoint circle: with h^2 = R^2 - x^2 whole,
        # |F(y)| < |F(y - 1)| is (y - 1/2)^2 + 1/4 < h^2, and the midpoint's test
        # (y - 1/2)^2 < h^2 can only differ if h^2 - (y - 1/2)^2 = k - 1/4 lay in
        # (0, 1/4] for a whole k: never.
        assert set(pixels) == exact.midpoint_circle(r), r


@settings(max_examples=30)
@given(st.integers(1, 300), st.tuples(st.integers(-40, 40), st.integers(-40, 40)))
def test_bresenham_decision_is_the_sum_of_the_candidates_residuals(r, centre):
    trace = record("circle-bresenham", (centre,), {"radius": r}, (8, 8))
    for i in range(1, len(trace)):
        step = trace.step(i)
        if not step.branch:
            continue
        x, y = (int(step.values["x"]) - 1,
                int(step.values["y"]) + (step.branch == "SE"))  # the pixel before the move
        d = residual(x + 1, y, r) + residual(x + 1, y - 1, r)
        assert step.values["d"] == d and d % 2 == 1
        assert step.branch == ("E" if d < 0 else "SE")


# ------------------------------------------------------ polar circle
@pytest.mark.parametrize("r, dt", [(1, "auto"), (7, "auto"), (40, "auto"), (10, 0.3),
                                   (10, 0.02), (25, 1.0)])
def test_polar_pixels_lie_on_the_circle_and_gaps_are_counted(r, dt):
    trace = record("circle-polar", ((3, 4),), {"radius": r, "dt": dt})
    pixels = offsets(trace, (3, 4))
    step = 1 / r if dt == "auto" else dt
    assert len(pixels) == int(np.ceil(2 * np.pi / step))
    assert all(cell_meets_circle(p, r) for p in pixels)
    final = trace.final_variables()
    assert final["gaps"] == chebyshev_gaps(pixels)
    assert final["duplicates"] == len(pixels) - len(set(pixels))
    if dt == "auto":
        assert final["gaps"] == 0  # a step of 1/R moves less than a pixel
    if (r, dt) == (10, 0.3):
        assert final["gaps"] > 0  # 3 px a step
    if (r, dt) == (10, 0.02):
        assert final["duplicates"] > 0


def test_polar_refuses_a_zero_step():
    from algorithms.core.registry import InputError, get
    with pytest.raises(InputError):
        get("circle-polar").resolve({"dt": 0.0})


# ------------------------------------------- midpoint circle as printed
def test_printed_reproduces_the_printed_code_and_counts_what_it_gets_wrong():
    wrong_radii = 0
    for r in range(0, 120):
        trace = record("circle-midpoint-printed", ((0, 0),), {"radius": r})
        drawn = printed_c(r)
        assert offsets(trace) == drawn, r
        final = trace.final_variables()
        right = exact.midpoint_circle(r)
        assert final["off_circle"] == len(set(drawn) - right)
        assert final["missing"] == len(right - set(drawn))
        assert final["duplicates"] == len(drawn) - len(set(drawn))
        wrong_radii += final["off_circle"] > 0
    # The lost 5 matters once the loop takes an SE step and then a test more.
    assert wrong_radii > 100


def test_printed_goes_wrong_outside_the_circle():
    final = record("circle-midpoint-printed", ((0, 0),), {"radius": 20}).final_variables()
    drawn = set(printed_c(20))
    wrong = drawn - exact.midpoint_circle(20)
    # The arc stays outside: every wrong pixel is farther out than the circle.
    assert wrong and all(residual(x, y, 20) > 0 for x, y in wrong)
    first = min(abs(x) for x, y in wrong if abs(x) <= abs(y))
    assert final["first_wrong_column"] == first


def test_bresenham_circle_candidates_are_e_and_se_of_the_pixel_decided_from():
    """The eight mirrors are plotted between the pixel decided from and the
    decision, yet the candidates are E and SE of that pixel (x - 1, y or
    y + 1 before the step, from the step's own x and y) and hold the pixel
    the step plots."""
    xc, yc, radius = 15, 11, 9
    trace = record("circle-bresenham", [(xc, yc)], {"radius": radius})
    checked = 0
    for i in range(len(trace)):
        step = trace.step(i)
        if step.branch not in ("E", "SE"):
            continue
        x, y = int(step.values["x"]), int(step.values["y"])
        before = (xc + x - 1, yc + y + (1 if step.branch == "SE" else 0))
        assert trace.candidates_at(i) == [(before[0] + 1, before[1]),
                                          (before[0] + 1, before[1] - 1)], i
        assert tuple(step.pixel) in trace.candidates_at(i)
        checked += 1
    assert checked >= 5


def test_the_summary_slides_slips_are_flagged_with_what_they_would_do():
    from fractions import Fraction

    from algorithms.core import registry
    spec = registry.get("circle-midpoint-printed")
    text = " ".join(line.text for line in spec.code(((10, 10),), spec.resolve({"radius": 8})))
    assert "F(0, R)" in text and "y_{i-1}" in text
    for r in range(1, 30):
        def f(x, y):
            return x * x + y * y - r * r
        # d0 = F(0, R) is 0, so the first test d < 0 fails and the step goes SE ...
        assert f(0, r) == 0 and not f(0, r) < 0
        # ... while the first midpoint, F(1, R - 1/2), is 5/4 - R.
        assert f(1, Fraction(2 * r - 1, 2)) == Fraction(5, 4) - r
