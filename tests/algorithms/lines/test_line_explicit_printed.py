"""line-explicit-printed: the slide titled Bresenham, which is the explicit
form split into cases, against the listing ported here in C's integers."""
from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings

from algorithms.exact import lines as exact
from tests.support.linecases import NAMED_CASES, pixels_of, segments, trace_of

NAME = "line-explicit-printed"


def c_div(a, b):
    """C's int / int: the exact quotient with its fraction dropped (toward zero)."""
    return int(Fraction(a, b))


def printed_slide(x0, y0, x1, y1):
    """The listing as printed; c and b make the line pass through P."""
    out = []
    rise = y1 - y0
    run = x1 - x0
    if run > 0:
        if rise > 0:
            if run > rise:
                c = y0 - c_div(rise, run) * x0
                for x in range(x0, x1):
                    out.append((x, c_div(rise, run) * x + c))
            else:
                b = x0 - c_div(run, rise) * y0
                for y in range(y0, y1):
                    out.append((c_div(run, rise) * y + b, y))
        else:
            if run > -rise:
                c = y0 - c_div(rise, run) * x0
                for x in range(x0, x1):
                    out.append((x, c_div(rise, run) * x + c))
            else:
                b = x0 - c_div(run, rise) * y0
                for y in range(y0, y1):
                    out.append((c_div(run, rise) * y + b, y))
    # run <= 0: the slide's "&c."; nothing is drawn.
    return out


@settings(max_examples=300, deadline=None)
@given(segments())
def test_the_listing_as_printed_on_random_segments(segment):
    p, q = segment
    assert pixels_of(NAME, p, q) == printed_slide(*p, *q)


@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_the_listing_as_printed_on_the_hard_cases(p, q):
    assert pixels_of(NAME, p, q) == printed_slide(*p, *q)


@settings(max_examples=200, deadline=None)
@given(segments())
def test_a_shallow_line_comes_out_flat_on_ps_row_without_q(segment):
    (x0, y0), (x1, y1) = segment
    if not 0 <= abs(y1 - y0) < x1 - x0:
        return
    pixels = pixels_of(NAME, (x0, y0), (x1, y1))
    assert pixels == [(x, y0) for x in range(x0, x1)]
    assert (x1, y1) not in pixels


@pytest.mark.parametrize("p, q", [((0, 9), (2, 1)), ((3, 20), (4, 2)), ((0, 5), (5, 0))])
def test_a_falling_steep_line_draws_nothing(p, q):
    assert pixels_of(NAME, p, q) == []
    assert trace_of(NAME, p, q).final_variables()["branch"] == "steep_down"


@pytest.mark.parametrize("p, q", [((0, 0), (9, 9)), ((2, 3), (12, 13))])
def test_only_a_rising_diagonal_comes_out_right_but_for_q(p, q):
    nearest = exact.nearest_pixel_line(p, q, "up")
    assert pixels_of(NAME, p, q) == [tuple(c) for c in nearest[:-1]]


def test_the_counts_against_the_corrected_form():
    p, q = (0, 0), (10, 7)
    final = trace_of(NAME, p, q).final_variables()
    nearest = {tuple(c) for c in exact.nearest_pixel_line(p, q, "up")}
    drawn = {(x, 0) for x in range(10)}
    assert final["Q_plotted"] == "no"
    assert final["off_corrected"] == len(drawn - nearest) == 9
    assert final["missing"] == len(nearest - drawn) == 10
