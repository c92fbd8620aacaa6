"""Bresenham against scikit-image's skimage.draw.line.

skimage.draw.line is Bresenham's algorithm with the other tie rule. Its
loop steps the minor coordinate while the error term is >= 0, where the
textbook steps only when d > 0 (d <= 0 chooses E). So at a tie, a column
where the ideal line is exactly half-way between two pixels, scikit-image
takes the pixel on Q's side of the minor axis and the textbook the one on
P's side. Everywhere else both take the single nearest pixel.

Hence:
* skimage's P -> Q is the textbook's Q -> P, pixel for pixel, always;
* skimage and the textbook agree on P -> Q exactly when the segment has no
  tie, i.e. when the major extent divided by gcd(dx, dy) is odd; on every
  segment with a tie, such as (0, 0)-(2, 1), they differ.

skimage takes (row, column); the rule does not care which axis is which,
so x is passed as the row and y as the column.
"""
import pytest
from hypothesis import given, settings
from skimage.draw import line

from algorithms.exact import lines as exact
from tests.support.linecases import NAMED_CASES, pixels_of, segments


def skimage_pixels(p, q):
    rows, columns = line(p[0], p[1], q[0], q[1])
    return [(int(r), int(c)) for r, c in zip(rows, columns)]


def minor_decreases(p, q):
    major_is_x = exact.x_is_major(p, q)
    return (q[1] < p[1]) if major_is_x else (q[0] < p[0])


@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_skimage_is_the_textbook_run_backwards(p, q):
    assert skimage_pixels(p, q) == pixels_of("line-bresenham", q, p)[::-1]


@settings(max_examples=300)
@given(segments(60))
def test_skimage_breaks_ties_towards_q(pq):
    p, q = pq
    ours = skimage_pixels(p, q)
    # The exact oracle run from Q, ties toward its start (Q), read back from P.
    assert ours == exact.nearest_pixel_line(q, p, "toward-P")[::-1]
    assert ours == pixels_of("line-bresenham", q, p)[::-1]


@settings(max_examples=300)
@given(segments(60))
def test_skimage_equals_the_textbook_exactly_when_there_is_no_tie(pq):
    p, q = pq
    same = skimage_pixels(p, q) == pixels_of("line-bresenham", p, q)
    assert same == (not exact.has_ties(p, q))


@settings(max_examples=200)
@given(segments(60))
def test_skimage_equals_symmetric_bresenham_when_ties_fall_down_anyway(pq):
    # symmetric rounds ties down; towards Q is down when the minor coordinate falls.
    p, q = pq
    same = skimage_pixels(p, q) == pixels_of("line-bresenham", p, q, {"symmetric": True})
    assert same == (not exact.has_ties(p, q) or minor_decreases(p, q))


def test_a_named_segment_where_they_differ():
    assert skimage_pixels((0, 0), (2, 1)) == [(0, 0), (1, 1), (2, 1)]
    assert pixels_of("line-bresenham", (0, 0), (2, 1)) == [(0, 0), (1, 0), (2, 1)]


def test_named_segments_where_they_agree():
    for p, q in [((0, 0), (7, 3)), ((0, 0), (5, 5)), ((1, 2), (9, 2)), ((0, 0), (3, -7)), ((0, 0), (3, 9))]:
        assert not exact.has_ties(p, q)
        assert skimage_pixels(p, q) == pixels_of("line-bresenham", p, q)
