"""The exact oracles themselves, against hand-worked values and each other."""
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import lines as exact
from tests.support.linecases import points, segments


def test_rounding_of_fractions_including_negatives():
    assert exact.floor_exact(Fraction(7, 2)) == 3
    assert exact.floor_exact(Fraction(-1, 2)) == -1
    assert exact.round_half_up_exact(Fraction(1, 2)) == 1
    assert exact.round_half_up_exact(Fraction(-1, 2)) == 0
    assert exact.round_half_up_exact(Fraction(-3, 2)) == -1
    assert exact.round_half_up_exact(Fraction(-5, 3)) == -2
    assert exact.is_half(Fraction(-3, 2)) and not exact.is_half(Fraction(1, 4))
    assert exact.is_integer(Fraction(4, 2)) and not exact.is_integer(Fraction(1, 2))


def test_line_values():
    assert exact.y_at((0, 0), (4, 2), 1) == Fraction(1, 2)
    assert exact.y_at((2, 1), (-2, 3), 0) == 2
    assert exact.x_at((0, 0), (1, 3), 2) == Fraction(2, 3)
    assert exact.line_value((0, 0), (1, 3), 2) == Fraction(2, 3)  # y is major here
    assert exact.line_value((5, 5), (5, 5), 5) == 5


def test_nearest_pixel_line_by_hand():
    assert exact.nearest_pixel_line((0, 0), (4, 2), "down") == [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]
    assert exact.nearest_pixel_line((0, 0), (4, 2), "up") == [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]
    assert exact.nearest_pixel_line((0, 0), (4, 2), "toward-P") == [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]
    assert exact.nearest_pixel_line((4, 2), (0, 0), "toward-P") == [(4, 2), (3, 2), (2, 1), (1, 1), (0, 0)]
    assert exact.nearest_pixel_line((0, 0), (1, 2), "down") == [(0, 0), (0, 1), (1, 2)]
    assert exact.nearest_pixel_line((0, 0), (7, 3), "down") == [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2), (5, 2), (6, 3), (7, 3)]
    assert exact.nearest_pixel_line((3, 3), (3, 3)) == [(3, 3)]


@given(segments())
def test_tie_formula_agrees_with_the_tie_columns(pq):
    p, q = pq
    assert exact.has_ties(p, q) == bool(exact.tie_columns(p, q))


def test_distance_to_segment_not_line():
    p, q = (0, 0), (4, 0)
    assert exact.segment_distance_sq(p, q, (-1, 0)) == 1     # beyond P: the line would say 0
    assert exact.segment_distance_sq(p, q, (6, 1)) == 5      # beyond Q
    assert exact.segment_distance_sq(p, q, (2, 3)) == 9
    assert exact.segment_distance_sq((0, 0), (3, 4), (4, -3)) == 25
    assert exact.segment_distance_sq((0, 0), (4, 2), (1, 0)) == Fraction(1, 5)
    assert not exact.within_half(p, q, (-1, 0)) and exact.within_half(p, q, (4, 0))
    assert exact.within_half((0, 0), (4, 2), (1, 0)) and not exact.within_half((0, 0), (4, 2), (0, 1))


@settings(max_examples=300)
@given(segments(12), points(14))
def test_within_half_agrees_with_the_squared_distance(pq, point):
    p, q = pq
    assert exact.within_half(p, q, point) == (exact.segment_distance_sq(p, q, point) < Fraction(1, 4))
    # A plain float computation of the clamped projection agrees to rounding error.
    dx, dy = q[0] - p[0], q[1] - p[1]
    length_sq = dx * dx + dy * dy
    t = 0.0 if not length_sq else min(1.0, max(0.0, ((point[0] - p[0]) * dx + (point[1] - p[1]) * dy) / length_sq))
    nx, ny = p[0] + t * dx - point[0], p[1] + t * dy - point[1]
    assert abs(float(exact.segment_distance_sq(p, q, point)) - (nx * nx + ny * ny)) < 1e-9


def test_deviation():
    assert exact.deviation_sq((0, 0), (4, 2), (1, 0)) == Fraction(1, 5)
    assert exact.deviation_sq((0, 0), (4, 0), (9, 3)) == 9  # the infinite line, unlike the segment
    assert exact.deviation_sq((1, 1), (1, 1), (4, 5)) == 25
    assert abs(exact.deviation((0, 0), (3, 4), (0, 5)) - 3.0) < 1e-12
    assert exact.max_deviation_sq((0, 0), (4, 2), [(0, 0), (1, 0), (2, 1)]) == Fraction(1, 5)


def test_gap_and_duplicate_counts():
    run = [(0, 0), (0, 0), (1, 1), (3, 1), (3, 1), (4, 2), (7, 2), (6, 2)]
    assert exact.duplicate_count(run) == 2
    assert exact.gap_count(run) == 2           # (1,1)->(3,1) and (4,2)->(7,2)
    assert exact.duplicate_count([(0, 0), (1, 0), (0, 0)]) == 1  # an earlier pixel, not the previous
    assert exact.gap_count([]) == 0 and exact.duplicate_count([]) == 0
    assert exact.is_8_connected([(0, 0), (1, 1), (2, 1)])
    assert not exact.is_8_connected([(0, 0), (2, 0)])
    assert exact.are_8_neighbours((0, 0), (1, -1)) and not exact.are_8_neighbours((0, 0), (0, 0))


@given(st.lists(points(3), max_size=12))
def test_counts_match_their_definitions(run):
    assert exact.duplicate_count(run) == len(run) - len(set(run))
    distinct_steps = [(a, b) for a, b in zip(run, run[1:]) if a != b]
    assert exact.gap_count(run) == sum(max(abs(a[0] - b[0]), abs(a[1] - b[1])) > 1
                                       for a, b in distinct_steps)
