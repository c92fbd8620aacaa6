"""The two-region midpoint ellipse against exact checks.

How close to the ideal ellipse: for every pixel the ellipse crosses the
pixel's column or its row less than one pixel away (exact, with Fractions).
Most pixels are within half a pixel; the classic algorithm goes past that
near the switch between the regions and at the ends of thin ellipses,
where one step per column (region 1) or per row (region 2) cannot follow
the curve; at rx = 1, ry = 4096 the top pixel (1, ry - 1) is 0.98 from
the curve along its row. With rx == ry the algorithm gives exactly the
midpoint circle's pixels, so those are within half a pixel.
"""
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import circles as exact
from algorithms.core.registry import InputError, get
from tests.support.trace_oracle import slow_replay
from tests.support import record

HALF, ONE = Fraction(1, 2), Fraction(1)


def ellipse(rx, ry, centre=(0, 0), grid=(8, 8)):
    return record("ellipse-midpoint", (centre,), {"rx": rx, "ry": ry}, grid)


def offsets(trace, centre=(0, 0)):
    return [(x - centre[0], y - centre[1]) for x, y in trace.written_pixels().tolist()]


def is_unbroken(pixels) -> bool:
    """The quadrant x, y >= 0 in drawing order steps between 8-neighbours only.

    With 4-way symmetry and both ends on the axes that closes the curve. (A
    flat ellipse, ry = 1, ends in a one-pixel-thick tip along y = 0, so
    "every pixel has two neighbours" would be too strict.)
    """
    arc = [(x, y) for x, y in pixels if x >= 0 and y >= 0]
    return (arc[0][0] == 0 and arc[-1][1] == 0 and
            all(max(abs(a[0] - b[0]), abs(a[1] - b[1])) == 1 for a, b in zip(arc, arc[1:])))


def check_ellipse(rx, ry, centre=(0, 0)):
    pixels = offsets(ellipse(rx, ry, centre), centre)
    assert len(pixels) == len(set(pixels)), "a pixel is plotted twice"
    assert exact.four_way(pixels) == set(pixels), "not 4-way symmetric"
    if rx == 0 or ry == 0:
        assert set(pixels) == exact.ellipse_segment(rx, ry)
        return pixels
    assert all(exact.ellipse_axis_distance_below(rx, ry, x, y, ONE) for x, y in pixels)
    assert is_unbroken(pixels)
    return pixels


def test_every_small_ellipse():
    for rx in range(0, 25):
        for ry in range(0, 25):
            check_ellipse(rx, ry)


@settings(max_examples=80)
@given(st.integers(0, 400), st.integers(0, 400),
       st.tuples(st.integers(-30, 30), st.integers(-30, 30)))
def test_random_ellipses(rx, ry, centre):
    check_ellipse(rx, ry, centre)


def test_thin_ellipses_stay_within_one_pixel():
    for rx, ry in [(1, 4096), (4096, 1), (2, 3000), (3000, 2), (1, 60), (5, 700)]:
        check_ellipse(rx, ry)


def test_most_pixels_are_within_half_a_pixel():
    for rx, ry in [(8, 6), (20, 13), (37, 50), (100, 90)]:
        pixels = offsets(ellipse(rx, ry))
        near = sum(exact.ellipse_axis_distance_below(rx, ry, x, y, HALF) for x, y in pixels)
        assert near >= 0.9 * len(pixels)


def test_equals_the_midpoint_circle_when_rx_equals_ry():
    # Region 1 runs while x < y, as the circle's loop does, makes the same
    # choices (d is R^2 times the circle's F) and region 2 picks the
    # nearest pixel of each row, the mirror image of the circle's columns.
    for r in range(0, 301):
        assert set(offsets(ellipse(r, r))) == exact.midpoint_circle(r), r


def test_degenerate_ellipses():
    assert offsets(ellipse(0, 0)) == [(0, 0)]
    assert set(offsets(ellipse(0, 5))) == {(0, y) for y in range(-5, 6)}
    assert set(offsets(ellipse(7, 0))) == {(x, 0) for x in range(-7, 8)}


def test_worked_example_rx8_ry6():
    # The classic worked example: region 1 decisions (d / 4 is F at the
    # midpoint) -332, -224, -44, 208, -108, 288, 244; region 2: -23, 361, 297.
    trace = ellipse(8, 6)
    decisions = [(trace.step(i).branch, trace.step(i).pixel, trace.step(i).values["d"] / 4)
                 for i in range(len(trace)) if trace.step(i).branch]
    assert decisions == [
        ("E", (1, 6), -332), ("E", (2, 6), -224), ("E", (3, 6), -44), ("SE", (4, 5), 208),
        ("E", (5, 5), -108), ("SE", (6, 4), 288), ("SE", (7, 3), 244),
        ("SW", (8, 2), -23), ("S", (8, 1), 361), ("S", (8, 0), 297)]


@pytest.mark.parametrize("rx, ry", [(8, 6), (13, 31), (40, 9), (1, 12), (12, 1)])
def test_decisions_are_f_at_the_midpoints_and_candidates_follow_the_region(rx, ry):
    trace = ellipse(rx, ry, centre=(4, 5))
    for i in range(1, len(trace)):
        step = trace.step(i)
        if not step.branch:
            continue
        before = trace.step(i - 1).pixel  # the loop test, on the current pixel
        x, y = before[0] - 4, before[1] - 5
        d = step.values["d"]
        candidates = trace.state_at(i).candidates
        if step.branch in ("E", "SE"):
            assert d == 4 * exact.ellipse_value(rx, ry, x + 1, y - HALF)
            assert candidates == [(before[0] + 1, before[1]), (before[0] + 1, before[1] - 1)]
        else:
            assert d == 4 * exact.ellipse_value(rx, ry, x + HALF, y - 1)
            assert candidates == [(before[0], before[1] - 1), (before[0] + 1, before[1] - 1)]
        assert step.pixel in candidates


def test_options_are_checked():
    with pytest.raises(InputError):
        ellipse(-1, 3)
    with pytest.raises(InputError):
        ellipse(3, 5000)


def test_state_at_equals_slow_replay(small_keyframes):
    small_keyframes(4)
    trace = ellipse(11, 6, centre=(12, 7), grid=(25, 15))
    for i in range(len(trace)):
        state = trace.state_at(i)
        replay = slow_replay(trace, i)
        assert np.array_equal(state.raster.counts, replay.counts)


def test_panel_rows_for_every_step():
    spec = get("ellipse-midpoint")
    trace = spec.record(((8, 8),), {"rx": 7, "ry": 3}, grid=(17, 17))
    for i in range(len(trace)):
        assert all(isinstance(b, str) for _, b in spec.panel_rows(trace, i))
