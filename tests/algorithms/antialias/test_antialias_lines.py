"""Antialiased lines: Xiaolin Wu's and the exact-area line, in every octant."""
import math
from collections import defaultdict
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings

from algorithms import antialias as aa
from algorithms.core.registry import get
from algorithms.core.steps import Note
from tests.support import record
from tests.support.linecases import NAMED_CASES, OCTANT_CASES, points


def major_axis(p, q) -> int:
    return 0 if abs(q[0] - p[0]) >= abs(q[1] - p[1]) else 1


def column_sums(image: dict, p, q) -> dict:
    axis = major_axis(p, q)
    sums = defaultdict(float)
    for pixel, value in image.items():
        sums[pixel[axis]] += value
    return dict(sums)


def wu_oracle(p, q) -> dict:
    """From the definition: in each major column the exact minor coordinate
    m = m0 + d_minor (c - c0) / d_major splits 1 - frac(m), frac(m) between
    floor(m) and floor(m) + 1."""
    axis = major_axis(p, q)
    c0, c1 = p[axis], q[axis]
    m0, m1 = p[1 - axis], q[1 - axis]
    if c0 == c1:
        return {tuple(p): 1.0}
    step = 1 if c1 > c0 else -1
    result = {}
    for c in range(c0, c1 + step, step):
        m = m0 + Fraction((m1 - m0) * (c - c0), c1 - c0)
        low = math.floor(m)
        frac = m - low
        for minor, share in ((low, 1 - frac), (low + 1, frac)):
            if share:
                pixel = (c, minor) if axis == 0 else (minor, c)
                result[pixel] = float(share)
    return result


# ----------------------------------------------------------------- Wu
@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_wu_matches_the_definition_in_every_octant(p, q):
    image = aa.wu_image((p, q), {})
    assert image == wu_oracle(p, q)
    sums = column_sums(image, p, q)
    axis = major_axis(p, q)
    assert sorted(sums) == list(range(min(p[axis], q[axis]), max(p[axis], q[axis]) + 1))
    assert all(abs(total - 1) < 1e-12 for total in sums.values())
    assert image[tuple(p)] == 1.0 and image[tuple(q)] == 1.0  # whole-pixel endpoints
    assert all(0 < v <= 1 for v in image.values())


@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_wu_is_the_same_in_both_directions(p, q):
    assert aa.wu_image((p, q), {}) == aa.wu_image((q, p), {})


@pytest.mark.parametrize("p, q", OCTANT_CASES)
def test_wu_gap_endpoints_give_half_columns(p, q):
    image = aa.wu_image((p, q), {"endpoints": "gap"})
    sums = column_sums(image, p, q)
    axis = major_axis(p, q)
    for column, total in sums.items():
        want = 0.5 if column in (p[axis], q[axis]) else 1.0
        assert abs(total - want) < 1e-12
    assert image[tuple(p)] == 0.5


@settings(max_examples=60)
@given(points(25), points(25))
def test_wu_property(p, q):
    image = aa.wu_image((p, q), {})
    assert image == wu_oracle(p, q) == aa.wu_image((q, p), {})
    for total in column_sums(image, p, q).values():
        assert abs(total - 1) < 1e-12


def test_wu_frames_and_values():
    trace = get("line-wu").record(((2, 3), (17, 9)), grid=(20, 12))
    pixels = trace.written_pixels()
    values = trace.pixel_values()
    assert len(pixels) == len(values) == 28
    assert trace.start.pixel_value == "intensity" and trace.start.color_value == "rgb"
    raster = trace.raster_at(len(trace) - 1)
    by_pixel = dict(zip(map(tuple, pixels.tolist()), values))
    for (x, y), v in by_pixel.items():
        assert raster.colors[y, x] & 0xFF == math.floor(255 * (1 - v) + 0.5)
    assert by_pixel[(2, 3)] == 1.0 and by_pixel[(17, 9)] == 1.0


# --------------------------------------------------------------- area
def area_dict(p, q, options):
    window, coverage = aa.area_image((p, q), options)
    x0, y0 = window[0], window[1]
    return {(x0 + c, y0 + r): float(coverage[r, c]) for r, c in np.argwhere(coverage > 0)}


@pytest.mark.parametrize("p, q", [c for c in NAMED_CASES if c[0] != c[1]])
@pytest.mark.parametrize("width", [1.0, 2.5])
def test_area_line_columns_carry_width_times_secant(p, q, width):
    image = area_dict(p, q, {"width": width})
    axis = major_axis(p, q)
    d_major = abs(q[axis] - p[axis])
    length = math.dist(p, q)
    sums = column_sums(image, p, q)
    # Columns the rectangle crosses from side to side, clear of both ends:
    # the rectangle's cross-section there is width * length / d_major.
    reach = width / 2 * abs(q[1 - axis] - p[1 - axis]) / length + 1
    lo, hi = min(p[axis], q[axis]), max(p[axis], q[axis])
    full = [c for c in sums if lo + reach <= c <= hi - reach]
    for c in full:
        assert sums[c] == pytest.approx(width * length / d_major, rel=1e-12)
    assert sum(image.values()) == pytest.approx(width * length, rel=1e-12)
    assert all(0 < v <= 1 + 1e-15 for v in image.values())


@pytest.mark.parametrize("p, q", [c for c in NAMED_CASES if c[0] != c[1]])
def test_area_line_is_the_same_in_both_directions(p, q):
    forward, backward = area_dict(p, q, {"width": 1.5}), area_dict(q, p, {"width": 1.5})
    assert forward.keys() == backward.keys()
    assert all(abs(forward[k] - backward[k]) < 1e-12 for k in forward)


def test_area_line_endpoints():
    image = area_dict((2, 3), (10, 3), {"width": 1.0})
    assert image[(2, 3)] == 0.5 and image[(10, 3)] == 0.5
    assert all(image[(x, 3)] == 1.0 for x in range(3, 10))
    assert len(image) == 9
    square = area_dict((2, 3), (10, 3), {"width": 1.0, "caps": "square"})
    assert square[(2, 3)] == 1.0 and square[(10, 3)] == 1.0
    assert len(square) == 9 and sum(square.values()) == 9.0


@pytest.mark.parametrize("p, q", OCTANT_CASES)
def test_area_line_float_equals_exact(p, q):
    _, floats = aa.area_image((p, q), {"width": 1.3})
    _, exact = aa.area_image((p, q), {"width": 1.3}, exact=True)
    assert np.abs(floats - np.vectorize(float)(exact)).max() < 1e-12


@pytest.mark.parametrize("p, q", OCTANT_CASES)
def test_area_line_generator_walks_the_columns_from_p_to_q(p, q):
    trace = get("line-area").record((p, q), {"width": 1.0}, grid=(20, 20))
    pixels = trace.written_pixels()
    values = trace.pixel_values()
    assert dict(zip(map(tuple, pixels.tolist()), values)) == area_dict(p, q, {"width": 1.0})
    axis = major_axis(p, q)
    majors = pixels[:, axis]
    direction = 1 if q[axis] >= p[axis] else -1
    assert np.all(np.diff(majors) * direction >= 0)
    final = trace.final_variables()
    assert final["area"] == pytest.approx(math.dist(p, q), rel=1e-12)


def test_a_zero_length_area_line_says_why_it_draws_nothing():
    trace = record("line-area", [(3, 3), (3, 3)], grid=(8, 8))
    assert not trace.written_pixels().size
    notes = [r.text for _, r in trace.records_of(Note)]
    assert len(notes) == 1 and "no area" in notes[0] and "caps=square" in notes[0]


def test_a_zero_length_square_capped_area_line_fills_its_one_pixel():
    # A w x w square centred on the pixel centre is exactly that pixel for w = 1.
    trace = record("line-area", [(3, 3), (3, 3)], {"caps": "square"}, grid=(8, 8))
    assert [tuple(p) for p in trace.written_pixels()] == [(3, 3)]
    assert not trace.records_of(Note)
