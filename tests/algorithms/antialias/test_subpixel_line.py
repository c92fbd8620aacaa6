"""Line supersampling by subpixels crossed, against a brute-force oracle: for
every subpixel of the grid, does the segment meet its half-open square?"""
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.support import record
from tests.support.antialias_oracles import subpixel_counts as oracle

GRID = (12, 8)


PIXEL = st.tuples(st.integers(-3, GRID[0] + 2), st.integers(-3, GRID[1] + 2))


@settings(max_examples=30)
@given(PIXEL, PIXEL, st.integers(1, 4))
def test_counts_are_the_subpixels_the_segment_meets(p, q, n):
    trace = record("line-subpixels", (p, q), {"n": n}, GRID)
    pixels = [tuple(x) for x in trace.written_pixels().tolist()]
    counts = oracle((p, q), n, GRID)
    assert len(pixels) == len(set(pixels)) and set(pixels) == set(counts)
    for pixel, k, value in zip(pixels, trace.series("subpixels")[trace.writes()],
                               trace.pixel_values()):
        assert k == counts[pixel] and value == min(1.0, k / n)


@pytest.mark.parametrize("n", [2, 3, 4])
def test_a_horizontal_line_is_full_and_a_diagonal_counts_each_corner_once(n):
    flat = record("line-subpixels", ((1, 3), (9, 3)), {"n": n}, GRID)
    # Along its inside pixels a straight line crosses exactly n subpixels.
    inside = [k for (x, _), k in zip(flat.written_pixels().tolist(),
                                     flat.series("subpixels")[flat.writes()]) if 1 < x < 9]
    assert inside == [n] * 7
    diagonal = record("line-subpixels", ((1, 1), (6, 6)), {"n": n}, GRID)
    counts = diagonal.series("subpixels")[diagonal.writes()]
    # Through the corners of the subpixels: one subpixel per step along the diagonal.
    assert set(counts[1:-1].tolist()) == {n}


def test_a_line_far_outside_counts_nothing_and_a_long_one_only_the_grid():
    assert len(record("line-subpixels", ((100, 100), (200, 150)), {}, GRID).written_pixels()) == 0
    long = record("line-subpixels", ((-10 ** 9, 4), (10 ** 9, 4)), {"n": 2}, GRID)
    assert len(long.written_pixels()) == GRID[0]
