"""Circles written straight into a canvas: the batched pixels, clipped, and
the midpoint rule checked in integers in the test."""
import numpy as np
import pytest

from algorithms.circles.batch import midpoint_circles
from algorithms.circles.batch import draw_midpoint_circles


def on_midpoint_circle(a: int, b: int, r: int) -> bool:
    """Offset (a, b) is a midpoint-circle pixel: with m <= M its smaller and
    larger magnitude, column m's cell holds the circle, (2M - 1)^2 < 4(r^2 - m^2)
    < (2M + 1)^2 (the left side odd, so never equal), and M >= m (one octant)."""
    if r == 0:
        return a == b == 0
    m, big = sorted((abs(a), abs(b)))
    return (2 * big - 1) ** 2 < 4 * (r * r - m * m) < (2 * big + 1) ** 2


def oracle(centres, r, shape):
    canvas = np.zeros(shape, np.uint8)
    for cx, cy in centres:
        for a in range(-r, r + 1):
            for b in range(-r, r + 1):
                x, y = cx + a, cy + b
                if on_midpoint_circle(a, b, r) and 0 <= x < shape[1] and 0 <= y < shape[0]:
                    canvas[y, x] = 7
    return canvas


@pytest.mark.parametrize("radius", [0, 1, 2, 5, 10])
def test_circles_in_the_canvas_equal_the_integer_rule(radius):
    rng = np.random.default_rng(radius)
    # Some wholly inside, some across an edge or a corner, some off the canvas.
    centres = rng.integers(-12, 52, (60, 2)).tolist() + [[0, 0], [39, 29], [-radius - 1, 5]]
    canvas = draw_midpoint_circles(np.zeros((30, 40), np.uint8), centres, radius, 7)
    assert np.array_equal(canvas, oracle(centres, radius, (30, 40)))


def test_the_same_pixels_as_the_batched_kernel_on_colour_and_strided_canvases():
    rng = np.random.default_rng(3)
    centres = rng.integers(0, 64, (200, 2))
    pixels, _ = midpoint_circles(centres, 6)
    on = (pixels >= 0).all(axis=1) & (pixels < 64).all(axis=1)
    want = np.zeros((64, 64, 3), np.uint8)
    want[pixels[on, 1], pixels[on, 0]] = (1, 2, 3)
    assert np.array_equal(draw_midpoint_circles(np.zeros_like(want), centres, 6, (1, 2, 3)), want)
    # A view that is not contiguous takes the clipped path and still draws into it.
    strided = np.zeros((64, 128), np.uint8)[:, ::2]
    draw_midpoint_circles(strided, centres, 6, 1)
    assert np.array_equal(strided, want[..., 0])
