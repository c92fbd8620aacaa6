"""Wu's line kernel: the generator's pixels and intensities in order, to the
last bit, and the intensities from the line's definition in exact fractions."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.antialias.wu_kernel import draw_wu_lines, wu_lines
from algorithms.core.registry import get
from tests.support.antialias_oracles import wu_oracle as oracle
from tests.support.linecases import NAMED_CASES, segments, trace_of

ENDPOINTS = ("full", "gap")
EXTRA = [((3, 3), (3, 3)), ((0, 0), (9, 0)), ((0, 0), (-9, 0)), ((0, 0), (0, 9)), ((0, 0), (0, -9)),
         ((0, 0), (7, 7)), ((0, 0), (-7, 7)), ((0, 0), (-7, -7)), ((0, 0), (7, -7)),
         ((2, 1), (3, 2)), ((0, 0), (1, 0)), ((5, -4), (-20, 13))]


def check(p, q, endpoints):
    spec = get("line-wu")
    pixels, intensity = spec.kernel((p, q), spec.resolve({"endpoints": endpoints}))
    trace = trace_of("line-wu", p, q, {"endpoints": endpoints})
    assert pixels.dtype == np.int64 and np.array_equal(pixels, trace.written_pixels())
    assert intensity.tolist() == trace.pixel_values().tolist()  # bit for bit
    assert list(zip(map(tuple, pixels.tolist()), intensity.tolist())) == oracle(p, q, endpoints)


@pytest.mark.parametrize("endpoints", ENDPOINTS)
@pytest.mark.parametrize("p, q", NAMED_CASES + EXTRA)
def test_named_cases_every_octant(p, q, endpoints):
    check(p, q, endpoints)


@settings(max_examples=80)
@given(segments(60), st.sampled_from(ENDPOINTS))
def test_random_segments(segment, endpoints):
    check(*segment, endpoints)


def test_a_long_line_agrees_to_the_last_bit():
    check((0, 0), (3001, 1234), "full")  # e / dx with a dx that is not a power of two


@pytest.mark.parametrize("endpoints", ENDPOINTS)
def test_batched_lines_equal_one_line_at_a_time(endpoints):
    rng = np.random.default_rng(5)
    starts = rng.integers(-30, 30, (200, 2))
    ends = starts + rng.integers(-12, 13, (200, 2))
    ends[:4] = starts[:4]  # points
    pixels, intensity, segment = wu_lines(starts, ends, endpoints)
    assert np.all(np.diff(segment) >= 0)
    spec = get("line-wu")
    for k in range(len(starts)):
        points = (tuple(starts[k].tolist()), tuple(ends[k].tolist()))
        want_pixels, want = spec.kernel(points, {"endpoints": endpoints})
        assert np.array_equal(pixels[segment == k], want_pixels)
        assert intensity[segment == k].tolist() == want.tolist()


@pytest.mark.parametrize("endpoints", ENDPOINTS)
@pytest.mark.parametrize("dtype, level", [(np.uint8, 255), (np.float64, 1.0)])
def test_drawn_into_a_canvas_as_the_batched_pixels_scattered(endpoints, dtype, level):
    rng = np.random.default_rng(9)
    starts = rng.integers(-6, 46, (150, 2))  # some lines cross the edges or lie off the canvas
    ends = starts + rng.integers(-15, 16, (150, 2))
    ends[:3] = starts[:3]
    pixels, intensity, _ = wu_lines(starts, ends, endpoints)
    on = (pixels[:, 0] >= 0) & (pixels[:, 0] < 40) & (pixels[:, 1] >= 0) & (pixels[:, 1] < 30)
    want = np.zeros((30, 40), dtype)
    for (x, y), value in zip(pixels[on].tolist(), intensity[on].tolist()):
        want[y, x] = value * level  # in order: a later line's pixel stays
    drawn = draw_wu_lines(np.zeros((30, 40), dtype), starts, ends, endpoints, level)
    assert np.array_equal(drawn, want)
