"""DDA, basic incremental and explicit form against exact rational values.

Each of these computes a real minor coordinate in floating point and rounds
it. Away from a rounding boundary the float error (far below 1e-9 here) can
never change the pixel, because an exact value y0 + dy*k/dx lies at least
1/(2|dx|) from the next boundary. Exactly on a boundary it decides:

* DDA adds dy/dx step by step; the sum can land on either side of an exact
  half (seven additions of 1/14 fall just short of 1/2), so either
  neighbour is accepted there.
* The incremental and explicit forms multiply a float m by x and add b;
  m*x + b can miss an exact whole number (floor's boundary) or an exact
  half (round's boundary) by one unit in the last place, to either side.
"""
import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import lines as exact
from tests.support.linecases import NAMED_CASES, pixels_of, segments, trace_of


def accepted(value: Fraction, rounding: str) -> set[int]:
    """The pixel coordinates a correct float evaluation may give for an exact value."""
    if rounding == "floor":
        v = exact.floor_exact(value)
        return {v - 1, v} if exact.is_integer(value) else {v}
    v = exact.round_half_up_exact(value)
    return {v - 1, v} if exact.is_half(value) else {v}


def exact_steps(p, q):
    """The exact point after k of n equal steps from P to Q, for k = 0..n."""
    n = max(abs(q[0] - p[0]), abs(q[1] - p[1]))
    if n == 0:
        return [(Fraction(p[0]), Fraction(p[1]))]
    return [(p[0] + Fraction((q[0] - p[0]) * k, n), p[1] + Fraction((q[1] - p[1]) * k, n))
            for k in range(n + 1)]


# ---------------------------------------------------------------------- DDA
@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_dda_named_cases_are_exact(p, q):
    pixels = pixels_of("line-dda", p, q)
    assert pixels[0] == p and pixels[-1] == q
    for pixel, (x, y) in zip(pixels, exact_steps(p, q), strict=True):
        assert pixel[0] in accepted(x, "round") and pixel[1] in accepted(y, "round")


@settings(max_examples=150)
@given(segments(600))
def test_dda_float64_rounds_exactly_except_at_halves(pq):
    p, q = pq
    pixels = pixels_of("line-dda", p, q, {"dtype": "float64"})
    assert pixels[0] == p and pixels[-1] == q
    for pixel, (x, y) in zip(pixels, exact_steps(p, q), strict=True):
        assert pixel[0] in accepted(x, "round")
        assert pixel[1] in accepted(y, "round")


def test_dda_at_an_exact_half_can_round_down():
    # y after 7 steps of 1/14 is exactly 1/2, which rounds up; the float
    # sum lands just below 1/2 and DDA rounds down.
    value = Fraction(1 * 7, 14)
    assert exact.is_half(value) and exact.round_half_up_exact(value) == 1
    assert pixels_of("line-dda", (0, 0), (14, 1))[7] == (7, 0)


def test_float32_dda_drifts_on_a_long_shallow_line():
    p, q = (0, 0), (4000, 1234)
    k = 1094
    value = exact.y_at(p, q, k)  # 337.491, not a tie: the right pixel is 337
    assert not exact.is_half(value) and exact.round_half_up_exact(value) == 337
    assert pixels_of("line-dda", p, q, {"dtype": "float64"})[k] == (k, 337)
    assert pixels_of("line-dda", p, q, {"dtype": "float32"})[k] == (k, 338)
    # And it is not a lone case: count the columns float32 gets wrong.
    wrong = [i for i, pixel in enumerate(pixels_of("line-dda", p, q, {"dtype": "float32"}))
             if pixel[1] not in accepted(exact.y_at(p, q, i), "round")]
    assert len(wrong) > 10


# -------------------------------------------------------- basic incremental
def check_incremental(p, q, rounding):
    pixels = pixels_of("line-incremental", p, q, {"rounding": rounding})
    major_is_x = exact.x_is_major(p, q)
    a0, a1 = (p[0], q[0]) if major_is_x else (p[1], q[1])
    step = 1 if a1 >= a0 else -1
    assert len(pixels) == abs(a1 - a0) + 1
    assert pixels[0] == p and pixels[-1] == q
    for a, pixel in zip(range(a0, a1, step), pixels):  # the loop; Q is plotted as given
        major, minor = (pixel[0], pixel[1]) if major_is_x else (pixel[1], pixel[0])
        assert major == a
        assert minor in accepted(exact.line_value(p, q, a), rounding)


@pytest.mark.parametrize("rounding", ["floor", "round"])
@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_incremental_named_cases(p, q, rounding):
    check_incremental(p, q, rounding)


@settings(max_examples=150)
@given(segments(600), st.sampled_from(["floor", "round"]))
def test_incremental_matches_its_formula_exactly(pq, rounding):
    check_incremental(*pq, rounding)


def test_incremental_plots_q_as_given():
    # The formula at Q itself would give floor((1/49) * 49) = floor(0.999...) = 0.
    assert math.floor((1 / 49) * 49 + 0) == 0
    assert pixels_of("line-incremental", (0, 0), (49, 1), {"rounding": "floor"})[-1] == (49, 1)


def test_incremental_floor_loses_a_whole_number_to_float_m():
    # y at x = 49 on (0,0)-(98,2) is exactly 1, but the float m = 2/98
    # times 49 is 0.999..., so floor plots the pixel below.
    assert exact.y_at((0, 0), (98, 2), 49) == 1
    assert pixels_of("line-incremental", (0, 0), (98, 2), {"rounding": "floor"})[49] == (49, 0)
    assert pixels_of("line-incremental", (0, 0), (98, 2), {"rounding": "round"})[49] == (49, 1)


def test_incremental_floor_is_not_the_nearest_pixel():
    # floor(2 * 4/5) = 1 where round gives 2: floor biases the line downwards.
    assert pixels_of("line-incremental", (0, 0), (5, 4), {"rounding": "floor"})[2] == (2, 1)
    assert pixels_of("line-incremental", (0, 0), (5, 4), {"rounding": "round"})[2] == (2, 2)


# ------------------------------------------------------------ explicit form
def check_explicit(p, q):
    pixels = pixels_of("line-explicit", p, q)
    major_is_x = exact.x_is_major(p, q)
    a0, a1 = (p[0], q[0]) if major_is_x else (p[1], q[1])
    step = 1 if a1 >= a0 else -1
    assert pixels[0] == p and pixels[-1] == q
    for a, pixel in zip(range(a0, a1 + step, step), pixels, strict=True):
        major, minor = (pixel[0], pixel[1]) if major_is_x else (pixel[1], pixel[0])
        assert major == a
        assert minor in accepted(exact.line_value(p, q, a), "round")


@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_explicit_named_cases(p, q):
    check_explicit(p, q)


@settings(max_examples=150)
@given(segments(600))
def test_explicit_matches_its_formula_exactly(pq):
    check_explicit(*pq)


@pytest.mark.parametrize("p, q, case, direction", [
    ((0, 0), (7, 3), "x major", "ascending"), ((7, 3), (0, 0), "x major", "descending"),
    ((0, 0), (3, 7), "y major", "ascending"), ((3, 7), (0, 0), "y major", "descending"),
    ((0, 0), (-7, 3), "x major", "descending"), ((0, 0), (3, -7), "y major", "descending"),
    ((2, 2), (2, 2), "x major", "ascending"), ((0, 0), (5, -5), "x major", "ascending"),
])
def test_explicit_steps_through_its_case_split(p, q, case, direction):
    trace = trace_of("line-explicit", p, q)
    branches = [trace.step(i).branch for i in range(len(trace)) if trace.step(i).branch]
    assert branches == [case, direction]
