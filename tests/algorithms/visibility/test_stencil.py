"""stencil-triangle: the pixels written are the triangle's pixels that are
also the stencil polygon's, each found here in exact arithmetic."""
from __future__ import annotations

from fractions import Fraction

import numpy as np
from hypothesis import assume, given, settings, strategies as st

from algorithms.core import registry
from app.model.buffers import side_buffer
from tests.support.triangle_variant_oracles import strictly_inside

GRID = (24, 18)
HALF = Fraction(1, 2)

coordinate = st.integers(-256, 256 * GRID[0]).map(lambda v: Fraction(v, 256))
point = st.tuples(coordinate, coordinate)


def polygon_covers(contour, c) -> bool | None:
    """Even-odd: crossings of the ray to the right of c, each edge taken
    for ymin <= y < ymax; None when c lies on an edge."""
    crossings = 0
    for a, b in zip(contour, contour[1:] + contour[:1]):
        low, high = (a, b) if a[1] < b[1] else (b, a)
        if not low[1] <= c[1] < high[1]:
            if a[1] == b[1] == c[1] and min(a[0], b[0]) <= c[0] <= max(a[0], b[0]):
                return None
            continue
        x = low[0] + (c[1] - low[1]) * (high[0] - low[0]) / (high[1] - low[1])
        if x == c[0]:
            return None
        crossings += x > c[0]
    return crossings % 2 == 1


def oracle(cover, shape):
    """The pixels whose centres the shape covers; None when a centre is a tie."""
    pixels = set()
    for y in range(GRID[1]):
        for x in range(GRID[0]):
            inside = cover(shape, (x + HALF, y + HALF))
            if inside is None:
                return None
            if inside:
                pixels.add((x, y))
    return pixels


def floats(points):
    return tuple((float(x), float(y)) for x, y in points)


@settings(max_examples=30)
@given(st.lists(point, min_size=3, max_size=7), st.lists(point, min_size=3, max_size=3))
def test_the_triangle_is_written_only_where_the_polygon_set_the_stencil(polygon, tri):
    trace = registry.get("stencil-triangle").record((floats(polygon), floats(tri)), {}, GRID)
    fragments = oracle(strictly_inside, tri)
    stencil = oracle(polygon_covers, polygon)
    assume(fragments is not None and stencil is not None)
    written = {tuple(map(int, p)) for p in np.argwhere(trace.state_at(len(trace) - 1)
                                                       .raster.written())[:, ::-1]}
    assert written == fragments & stencil
    dropped = {trace.step(i).pixel for i in range(len(trace))
               if trace.step(i).branch == "fail"}
    assert dropped == fragments - stencil
    buffer = side_buffer(trace, len(trace) - 1)
    assert buffer.name == "stencil buffer"
    assert {(x, y) for y, x in np.argwhere(buffer.values == 1)} == stencil
    assert np.isnan(buffer.values).sum() == GRID[0] * GRID[1] - len(stencil)


def test_the_stencil_is_complete_before_the_first_fragment_and_colours_nothing():
    polygon = ((2.0625, 3.0625), (20.0625, 2.0625), (23.0625, 12.0625), (14.0625, 17.0625),
               (4.0625, 14.0625))
    tri = ((6.5, 1.25), (23.5, 9.5), (12.25, 16.75))
    trace = registry.get("stencil-triangle").record((polygon, tri), {}, GRID)
    steps = [trace.step(i) for i in range(len(trace))]
    first = next(s.index for s in steps if s.branch in ("pass", "fail"))
    assert not trace.state_at(first - 1).raster.written().any()
    stencil = oracle(polygon_covers, [tuple(map(Fraction, p)) for p in polygon])
    assert stencil and np.count_nonzero(side_buffer(trace, first - 1).values == 1) == len(stencil)


def test_one_contour_is_a_triangle_with_no_stencil_buffer():
    tri = ((1.5625, 1.3125), (20.4375, 4.5625), (8.3125, 15.6875))
    trace = registry.get("stencil-triangle").record((tri,), {}, GRID)
    assert side_buffer(trace, len(trace) - 1) is None
    written = {tuple(map(int, p)) for p in np.argwhere(trace.state_at(len(trace) - 1)
                                                       .raster.written())[:, ::-1]}
    assert written == oracle(strictly_inside, [tuple(map(Fraction, p)) for p in tri])
