"""Bresenham against the exact nearest-pixel line.

The textbook loop chooses E when d <= 0. Mapped back from octant 1, a tie
(the ideal line exactly half-way between two pixels of a column) therefore
goes to the pixel on P's side of the minor axis: the exact oracle's
'toward-P' rule. With `symmetric`, ties round the minor coordinate down,
whichever end the run starts from.
"""
import itertools

import pytest
from hypothesis import given, settings

from algorithms.exact import lines as exact
from tests.support.linecases import NAMED_CASES, pixels_of, segments, trace_of

TEXTBOOK = {}
SYMMETRIC = {"symmetric": True}


def check_shape(p, q, pixels):
    """Count, ends, one pixel per major column, 8-connected without gaps."""
    major = 0 if exact.x_is_major(p, q) else 1
    assert len(pixels) == max(abs(q[0] - p[0]), abs(q[1] - p[1])) + 1
    assert pixels[0] == p and pixels[-1] == q
    columns = [pixel[major] for pixel in pixels]
    assert len(set(columns)) == len(columns)
    assert exact.gap_count(pixels) == 0 and exact.duplicate_count(pixels) == 0
    assert exact.is_8_connected(pixels)


@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_named_cases(p, q):
    textbook = pixels_of("line-bresenham", p, q, TEXTBOOK)
    symmetric = pixels_of("line-bresenham", p, q, SYMMETRIC)
    check_shape(p, q, textbook)
    check_shape(p, q, symmetric)
    assert textbook == exact.nearest_pixel_line(p, q, "toward-P")
    assert symmetric == exact.nearest_pixel_line(p, q, "down")


def test_the_tie_cases_by_hand():
    assert pixels_of("line-bresenham", (0, 0), (2, 1)) == [(0, 0), (1, 0), (2, 1)]
    assert pixels_of("line-bresenham", (2, 1), (0, 0)) == [(2, 1), (1, 1), (0, 0)]
    assert pixels_of("line-bresenham", (0, 0), (4, 2)) == [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]
    assert pixels_of("line-bresenham", (4, 2), (0, 0), SYMMETRIC) == [(4, 2), (3, 1), (2, 1), (1, 0), (0, 0)]


@settings(max_examples=300)
@given(segments())
def test_textbook_is_the_nearest_pixel_line_with_ties_toward_p(pq):
    p, q = pq
    pixels = pixels_of("line-bresenham", p, q, TEXTBOOK)
    check_shape(p, q, pixels)
    assert pixels == exact.nearest_pixel_line(p, q, "toward-P")


@settings(max_examples=300)
@given(segments())
def test_symmetric_is_the_nearest_pixel_line_with_ties_down(pq):
    p, q = pq
    forward = pixels_of("line-bresenham", p, q, SYMMETRIC)
    backward = pixels_of("line-bresenham", q, p, SYMMETRIC)
    check_shape(p, q, forward)
    assert forward == exact.nearest_pixel_line(p, q, "down")
    assert set(forward) == set(backward)


@given(segments())
def test_textbook_direction_matters_exactly_when_there_is_a_tie(pq):
    p, q = pq
    same = set(pixels_of("line-bresenham", p, q)) == set(pixels_of("line-bresenham", q, p))
    assert same == (not exact.has_ties(p, q))


def test_a_segment_whose_textbook_pixels_depend_on_direction_is_found():
    differing = [((0, 0), (dx, dy)) for dx, dy in itertools.product(range(-4, 5), repeat=2)
                 if set(pixels_of("line-bresenham", (0, 0), (dx, dy)))
                 != set(pixels_of("line-bresenham", (dx, dy), (0, 0)))]
    assert ((0, 0), (2, 1)) in differing
    assert all(exact.has_ties(p, q) for p, q in differing)
    for p, q in differing:
        assert set(pixels_of("line-bresenham", p, q, SYMMETRIC)) == set(pixels_of("line-bresenham", q, p, SYMMETRIC))


def test_decision_values_follow_the_textbook_recurrence():
    # (0,0)-(7,3): d0 = 2*3 - 7 = -1, incrE = 6, incrNE = -8, worked by hand.
    trace = trace_of("line-bresenham", (0, 0), (7, 3))
    decisions = [int(v) for v in trace.series("d")[2:-1]]
    assert decisions == [-1, 5, -3, 3, -5, 1, -7]
    assert [trace.step(i).branch for i in range(2, 9)] == ["E", "NE", "E", "NE", "E", "NE", "E"]
