"""Barycentric weights by Cramer's rule and the triangle as three lines,
against oracles written in exact arithmetic (tests/support/triangle_variant_oracles.py)."""
from collections import Counter
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.support import record
from tests.support.triangle_variant_oracles import (cramer_oracle, plane_value, printed_columns,
                                                    wireframe_oracle)

GRID = (24, 20)
# Vertices on the 1/8 grid, some off the grid, so edges pass through centres.
COORD = st.integers(-40, 220).map(lambda v: v / 8)
TRIANGLE = st.tuples(*(st.tuples(COORD, COORD) for _ in range(3)))


@settings(max_examples=20)
@given(TRIANGLE)
def test_cramer_covers_the_closed_triangle(triangle):
    trace = record("triangle-cramer", triangle, {}, GRID)
    got = Counter(tuple(p) for p in trace.written_pixels().tolist())
    assert got == cramer_oracle(triangle, GRID)


@settings(max_examples=25)
@given(TRIANGLE)
def test_cramer_weights_are_the_edge_functions_over_2a_and_sum_to_1(triangle):
    trace = record("triangle-cramer", triangle, {}, GRID)
    (x0, y0), (x1, y1), (x2, y2) = [tuple(Fraction(c) for c in v) for v in triangle]
    two_a = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    for i in range(len(trace)):
        step = trace.step(i)
        if step.record is not None or step.pixel is None:
            continue
        px, py = step.pixel[0] + Fraction(1, 2), step.pixel[1] + Fraction(1, 2)
        # Edge function of P1 P2 at p, written as a 2x2 determinant of vectors.
        e0 = (x1 - px) * (y2 - py) - (x2 - px) * (y1 - py)
        e1 = (x2 - px) * (y0 - py) - (x0 - px) * (y2 - py)
        assert step.values["D"] == float(two_a)
        assert step.values["alpha"] == float(e0 / two_a)
        assert step.values["beta"] == float(e1 / two_a)
        assert step.values["area_check"] == 1.0


def test_clockwise_and_shared_edges():
    # Two triangles sharing the edge (4.5, 4.5)-(20.5, 16.5), which passes through
    # centres: with the closed test both fill those; clockwise order changes nothing.
    mesh = ((4.5, 4.5), (20.5, 4.5), (20.5, 16.5), (4.5, 4.5), (20.5, 16.5), (4.5, 16.5))
    got = Counter(tuple(p) for p in record("triangle-cramer", mesh, {}, GRID)
                  .written_pixels().tolist())
    twice = {p for p, n in got.items() if n == 2}
    assert twice and all(4 * (y - 4) == 3 * (x - 4) for x, y in twice)
    clockwise = ((4.5, 4.5), (20.5, 16.5), (20.5, 4.5))
    assert set(tuple(p) for p in record("triangle-cramer", clockwise, {}, GRID)
               .written_pixels().tolist()) == set(cramer_oracle(clockwise, GRID))


@settings(max_examples=40)
@given(TRIANGLE)
def test_wireframe_is_three_nearest_pixel_lines(triangle):
    trace = record("triangle-wireframe", triangle, {}, GRID)
    assert [tuple(p) for p in trace.written_pixels().tolist()] == wireframe_oracle(triangle, GRID)


def test_wireframe_of_a_huge_triangle_costs_only_the_grid():
    huge = ((-1e12, -3e11), (1e12, 2.5), (7.5, 1e12))
    trace = record("triangle-wireframe", huge, {}, GRID)
    assert len(trace) < 200
    assert [tuple(p) for p in trace.written_pixels().tolist()] == wireframe_oracle(huge, GRID)


@settings(max_examples=10)
@given(TRIANGLE)
def test_trilinear_distances_convert_to_the_barycentric_weights(triangle):
    trace = record("triangle-trilinear", triangle, {}, GRID)
    got = Counter(tuple(p) for p in trace.written_pixels().tolist())
    assert got == cramer_oracle(triangle, GRID)
    tri = [tuple(Fraction(c) for c in v) for v in triangle]
    two_a = (tri[1][0] - tri[0][0]) * (tri[2][1] - tri[0][1]) - \
        (tri[2][0] - tri[0][0]) * (tri[1][1] - tri[0][1])
    for i in range(len(trace)):
        step = trace.step(i)
        if step.record is not None or step.pixel is None:
            continue
        p = (step.pixel[0] + Fraction(1, 2), step.pixel[1] + Fraction(1, 2))
        for k, name in enumerate(("alpha", "beta", "gamma")):
            a, b = tri[(k + 1) % 3], tri[(k + 2) % 3]
            e = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
            side2 = (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2
            d = step.values[f"d{k}"]
            # d_k^2 = e_k^2 / L_k^2, positive inside whatever the winding, to rounding.
            inward = e if two_a > 0 else -e
            assert (d > 0) == (inward > 0) and (d < 0) == (inward < 0)
            assert d * d == pytest.approx(float(e * e / side2), rel=1e-9, abs=1e-12)
            assert step.values[name] == pytest.approx(float(e / two_a), rel=1e-9, abs=1e-12)


@settings(max_examples=30)
@given(TRIANGLE)
def test_columns_fill_the_closed_triangle_and_the_printed_code_fills_nothing_of_it(triangle):
    correct = record("triangle-columns", triangle, {}, GRID)
    got = Counter(tuple(p) for p in correct.written_pixels().tolist())
    expected = cramer_oracle(triangle, GRID)
    assert got == expected and correct.final_variables()["missing"] == 0
    printed = record("triangle-columns", triangle, {"swap": "printed"}, GRID)
    drawn = [tuple(p) for p in printed.written_pixels().tolist()]
    assert drawn == printed_columns(triangle, GRID)
    # The difference from the exact result, counted.
    assert printed.final_variables()["missing"] == sum(expected.values()) - len(drawn)
    assert len(drawn) <= 1 or sum(expected.values()) == 0 or len(drawn) < sum(expected.values())


@settings(max_examples=12)
@given(TRIANGLE, st.tuples(*(st.integers(-8, 8).map(lambda v: v / 4) for _ in range(3))))
def test_edges_then_spans_give_the_plane_exactly(triangle, values):
    trace = record("triangle-span-interpolate", triangle, {"s": values}, GRID)
    pixels = [tuple(p) for p in trace.written_pixels().tolist()]
    assert Counter(pixels) == cramer_oracle(triangle, GRID)
    for pixel, f in zip(pixels, trace.series("f")[trace.writes()]):
        assert f == float(plane_value(triangle, values, pixel))
