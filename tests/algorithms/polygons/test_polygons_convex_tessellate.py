"""polygon-convex and polygon-tessellate: same pixels as polygon-scanline, clear refusals."""
from collections import Counter

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import polygons as oracle
from algorithms.polygons import CONVEX, SCANLINE, TESSELLATE, snap_contours
from algorithms.core.registry import InputError
from algorithms.core.steps import PLOT, Note, Span, Table
from test_polygons_cases import generator_pixels, kernel_pixels, star_shaped


def hull(points):
    """Convex hull (counter-clockwise, no collinear vertices) of snapped points."""
    points = sorted(set(points))
    if len(points) < 3:
        return points

    def half(sequence):
        chain = []
        for p in sequence:
            while len(chain) >= 2 and ((chain[-1][0] - chain[-2][0]) * (p[1] - chain[-2][1])
                                       - (chain[-1][1] - chain[-2][1]) * (p[0] - chain[-2][0])) <= 0:
                chain.pop()
            chain.append(p)
        return chain[:-1]
    return half(points) + half(reversed(points))


@st.composite
def convex_polygon(draw):
    grid = st.one_of(st.integers(0, 24 * 256), st.integers(0, 48).map(lambda k: 128 * k))
    points = draw(st.lists(st.tuples(grid, grid), min_size=3, max_size=12))
    vertices = hull(points)
    if len(vertices) < 3:
        vertices = [(0, 0), (24 * 256, 0), (0, 12 * 256)]
    if draw(st.booleans()):  # a vertex in the middle of an edge
        (ax, ay), (bx, by) = vertices[0], vertices[1]
        if (ax + bx) % 2 == 0 and (ay + by) % 2 == 0:
            vertices.insert(1, ((ax + bx) // 2, (ay + by) // 2))
    if draw(st.booleans()):
        vertices.reverse()
    start = draw(st.integers(0, len(vertices) - 1))
    vertices = vertices[start:] + vertices[:start]
    return [(x / 256, y / 256) for x, y in vertices]


# ---------------------------------------------------------------- convex
@settings(max_examples=200)
@given(convex_polygon())
def test_convex_equals_scanline_row_for_row(points):
    pixels = generator_pixels(CONVEX, [points])
    assert pixels == generator_pixels(SCANLINE, [points])
    assert kernel_pixels(CONVEX, [points]) == pixels


def test_convex_frames_one_span_per_row():
    trace = CONVEX.record([[(1, 1), (9, 3), (5, 9)]], grid=(12, 12))
    spans = [r for _, r in trace.records_of(Span)]
    # Centre lines 1.5 .. 8.5: rows 1 .. 8.
    assert [s.y for s in spans] == list(range(1, 9))
    chains = next(r for _, r in trace.records_of(Table))
    assert {row[0] for row in chains.rows} == {"left", "right"}
    assert trace.final_variables()["pixels"] == 28


@pytest.mark.parametrize("contours, message", [
    ([[(1, 1), (9, 1), (5, 4), (5, 9)]], "turns left at some vertices and right at others"),
    ([[(10, 1), (15.9, 18.1), (0.5, 7.5), (19.5, 7.5), (4.1, 18.1)]], "winds around more than once"),
    ([[(1, 1), (9, 1), (9, 5), (9, 3), (1, 5)]], "turns back on itself at P3"),
    ([[(1, 1), (5, 1), (3, 4)], [(6, 6), (9, 6), (7, 9)]], "fills one contour, got 2"),
])
def test_convex_refuses_what_it_cannot_fill(contours, message):
    with pytest.raises(InputError, match=message):
        list(CONVEX.frames(contours))


def test_convex_accepts_a_flat_polygon_and_fills_nothing():
    assert generator_pixels(CONVEX, [[(1, 1), (8, 8), (4.5, 4.5)]]) == []
    assert generator_pixels(CONVEX, [[(1, 1), (4.5, 4.5), (8, 8)]]) == []


# ------------------------------------------------------------ tessellate
@settings(max_examples=150)
@given(star_shaped())
def test_tessellate_equals_scanline(points):
    pixels = generator_pixels(TESSELLATE, [points])
    assert len(pixels) == len(set(pixels)), "two triangles share a pixel"
    assert set(pixels) == set(generator_pixels(SCANLINE, [points]))


COMB = [(1, 1), (13, 1), (13, 9), (11, 9), (11, 4), (9, 4), (9, 9), (7, 9), (7, 4), (5, 4),
        (5, 9), (3, 9), (3, 4), (1, 4)]
SPIRAL = [(1, 1), (15, 1), (15, 15), (3, 15), (3, 5), (11, 5), (11, 11), (7, 11), (7, 9),
          (9, 9), (9, 7), (5, 7), (5, 13), (13, 13), (13, 3), (1, 3)]


@pytest.mark.parametrize("points", [
    COMB, SPIRAL,
    [(1, 1), (4, 1), (7, 1), (7, 4.5), (7, 8), (4, 8), (1, 8), (1, 4.5)],  # collinear vertices
    [(1.5, 1.5), (9.5, 1.5), (5.5, 5.5), (9.5, 9.5), (1.5, 9.5)],  # on centres, a reflex vertex
    [(2.2, 1.1), (14.7, 3.3), (12.1, 9.9), (8.05, 4.4), (3.3, 12.6)],
], ids=["comb", "spiral", "collinear", "centres", "reals"])
def test_tessellate_named_simple_polygons(points):
    for ordered in (points, points[::-1]):
        pixels = generator_pixels(TESSELLATE, [ordered])
        assert len(pixels) == len(set(pixels))
        assert set(pixels) == oracle.covered_pixels([ordered])


def test_ear_tests_are_frames():
    trace = TESSELLATE.record([COMB], grid=(16, 12))
    branches = Counter(trace.code[int(line)].branch for line in trace.line if trace.code[int(line)].branch)
    triangles = next(r for _, r in trace.records_of(Table) if r.name == "triangles")
    assert branches["ear"] == len(triangles.rows) - 1  # the last triangle is what remains
    assert branches["reflex"] > 0 and branches["blocked"] > 0
    # Clipping an ear can leave a vertex on a straight line; it is dropped, not cut.
    dropped = [r for _, r in trace.records_of(Note) if "dropped" in r.text]
    assert dropped and len(triangles.rows) + len(dropped) == len(COMB) - 2
    spans = [r for _, r in trace.records_of(Span)]
    assert spans and all(trace.code[s.line].kind == PLOT for s in spans)
    # A blocked candidate highlights the vertex that blocks it.
    blocked = [i for i in range(len(trace)) if trace.code[int(trace.line[i])].branch == "blocked"]
    snapped = {(x // 256, y // 256) for x, y in snap_contours([COMB])[0]}
    assert all(trace.step(i).pixel in snapped for i in blocked)


@pytest.mark.parametrize("contours, message", [
    ([[(1, 1), (9, 9), (9, 1), (1, 9)]], "cross or touch"),
    ([[(1, 1), (9, 1), (5, 5), (9, 9), (1, 9), (5, 5)]], "cross or touch"),  # touches itself
    ([[(1, 1), (9, 1), (9, 5), (9, 3), (1, 5)]], "folds back on itself at P3"),
    ([[(1, 1), (8, 8), (4.5, 4.5)]], "folds back"),  # zero area
    ([[(1, 1), (15, 1), (15, 15), (1, 15)], [(5, 5), (5, 11), (11, 11), (11, 5)]],
     "fills one contour, got 2"),
])
def test_tessellate_refuses_what_it_cannot_cut(contours, message):
    with pytest.raises(InputError, match=message):
        list(TESSELLATE.frames(contours))


def test_tessellate_ties_nest():
    for points in (COMB, SPIRAL):
        inclusive = set(generator_pixels(TESSELLATE, [points], {"ties": "inclusive"}))
        default = set(generator_pixels(TESSELLATE, [points]))
        strict = set(generator_pixels(TESSELLATE, [points], {"ties": "strict"}))
        assert strict <= default <= inclusive
