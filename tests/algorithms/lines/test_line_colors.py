"""Endpoint colours: P's at the first pixel, Q's at the last, monotone between."""
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import lines as exact
from tests.support.linecases import (LINE_ALGORITHMS, NAMED_CASES, channels, pack, segments,
                                     trace_of)

HEX = st.integers(0, 0xFFFFFF).map(lambda v: f"#{v:06x}")


def colored(name, p, q, first, last):
    trace = trace_of(name, p, q, {"colors": [first, last], **({"dt": "auto"} if name == "line-parametric" else {})})
    pixels = [tuple(map(int, pixel)) for pixel in trace.written_pixels()]
    values = [int(v) for v in trace.pixel_values()]
    assert trace.start.pixel_value == "rgb" and len(values) == len(pixels)
    return pixels, values


def check(name, p, q, first, last):
    pixels, values = colored(name, p, q, first, last)
    assert values[0] == pack(first)
    if p != q:
        assert values[-1] == pack(last)
    if name == "line-implicit":
        # A box scan does not visit pixels in order along the line; sort them
        # by where they project onto PQ, exactly.
        order = sorted(range(len(pixels)), key=lambda k: exact.projection(p, q, pixels[k]))
        values = [values[k] for k in order]
    for channel, (a, b) in enumerate(zip(channels(pack(first)), channels(pack(last)))):
        series = [channels(v)[channel] for v in values]
        assert all(lo <= hi for lo, hi in zip(series, series[1:])) if b >= a \
            else all(lo >= hi for lo, hi in zip(series, series[1:]))
        assert all(min(a, b) <= c <= max(a, b) for c in series)


@pytest.mark.parametrize("name", LINE_ALGORITHMS)
@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_named_cases(name, p, q):
    check(name, p, q, "#ff8000", "#0040ff")


@pytest.mark.parametrize("name", LINE_ALGORITHMS)
@settings(max_examples=40)
@given(pq=segments(20), first=HEX, last=HEX)
def test_random_colours(name, pq, first, last):
    check(name, *pq, first, last)


def test_the_middle_of_a_line_is_the_mixture():
    # (0,0)-(4,0) from red to blue: the middle pixel is half of each, 127.5 -> 128 (round half even).
    for name in LINE_ALGORITHMS:
        pixels, values = colored(name, (0, 0), (4, 0), "#ff0000", "#0000ff")
        middle = values[pixels.index((2, 0))]
        assert channels(middle) == (128, 0, 128), name


def test_the_raster_keeps_the_colours():
    trace = trace_of("line-bresenham", (1, 1), (5, 3), {"colors": ["#102030", "#405060"]})
    raster = trace.raster_at(len(trace) - 1)
    assert raster.colors[1, 1] == pack("#102030") and raster.colors[3, 5] == pack("#405060")
