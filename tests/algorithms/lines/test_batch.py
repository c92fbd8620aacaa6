"""Batched kernels give each primitive's pixels exactly as its own kernel does."""
import numpy as np
import pytest

from algorithms.circles.batch import midpoint_circles
from algorithms.lines.batch import bresenham_lines
from algorithms.circles.midpoint import midpoint_circle_pixels
from algorithms.lines.bresenham import bresenham_pixels


@pytest.mark.parametrize("symmetric", [False, True])
def test_bresenham_lines_equal_one_line_at_a_time(symmetric):
    rng = np.random.default_rng(4)
    starts = rng.integers(-20, 20, (300, 2))
    ends = starts + rng.integers(-9, 10, (300, 2))
    ends[:5] = starts[:5]  # points
    ends[5:10, 0] = starts[5:10, 0]  # vertical
    ends[10:15, 1] = starts[10:15, 1]  # horizontal
    ends[15:20] = starts[15:20] + [[4, 4], [-4, 4], [4, -4], [-4, -4], [6, -3]]  # diagonals, a tie
    pixels, segment = bresenham_lines(starts, ends, symmetric)
    for k in range(len(starts)):
        points = (tuple(starts[k].tolist()), tuple(ends[k].tolist()))
        expected = bresenham_pixels(points, {"symmetric": symmetric})
        assert np.array_equal(pixels[segment == k], expected), points
    assert np.all(np.diff(segment) >= 0)


def test_midpoint_circles_equal_one_circle_at_a_time():
    rng = np.random.default_rng(8)
    centres = rng.integers(-50, 50, (40, 2))
    for radius in (0, 1, 7, 10):
        pixels, circle = midpoint_circles(centres, radius)
        for k, centre in enumerate(centres.tolist()):
            expected = midpoint_circle_pixels([tuple(centre)], {"radius": radius})
            assert np.array_equal(pixels[circle == k], expected)
