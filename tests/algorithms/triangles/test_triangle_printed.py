"""Two triangle listings as printed (triangle-barycentric-printed,
triangle-lininterp) against the listings ported here in exact arithmetic."""
from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.core import registry
from algorithms.core.cases import TRIANGLE_CASES

GRID = (24, 20)
HALF = Fraction(1, 2)


def cross(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1])


def record(name, triangle, **options):
    return registry.get(name).record(tuple(triangle), options, grid=GRID)


def written(trace):
    return [tuple(p) for p in trace.written_pixels().tolist()]


def centres_of_box(triangle):
    """Pixels whose centres lie in the triangle's bounding box (and the grid)."""
    xs, ys = [p[0] for p in triangle], [p[1] for p in triangle]
    columns = range(max(0, math.ceil(min(xs) - HALF)), min(GRID[0], math.floor(max(xs) - HALF) + 1))
    rows = range(max(0, math.ceil(min(ys) - HALF)), min(GRID[1], math.floor(max(ys) - HALF) + 1))
    return columns, rows


quarters = st.integers(0, 4 * 20).map(lambda n: n / 4)
triangles = st.lists(st.tuples(quarters, quarters), min_size=3, max_size=3)
HARD = [t for t in TRIANGLE_CASES if len(t) == 3]


# ------------------------------------------------ the barycentric test as printed
class Distance:
    """A distance to a line kept exactly: |cross| over the length of the line's
    segment, the length held as its square (a ratio of two distances to one
    line is then a Fraction)."""

    def __init__(self, numerator, squared_length):
        self.numerator, self.squared_length = numerator, squared_length

    def __truediv__(self, other):
        assert other.squared_length == self.squared_length
        return Fraction(self.numerator) / other.numerator


def distance(p, line, signed_toward=None):
    a, b = line
    value = cross(a, b, p)
    if signed_toward is None:  # as printed: no sign
        value = abs(value)
    elif cross(a, b, signed_toward) < 0:  # positive on the vertex's side
        value = -value
    return Distance(value, (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2)


def barycentric_listing(triangle, signed=False):
    A, B, C = (tuple(Fraction(c) for c in p) for p in triangle)
    out = []
    columns, rows = centres_of_box((A, B, C))
    for y in rows:
        for x in columns:
            p = (x + HALF, y + HALF)
            alpha = distance(p, (B, C), A if signed else None) / distance(A, (B, C), A if signed else None)
            gamma = distance(p, (A, B), C if signed else None) / distance(C, (A, B), C if signed else None)
            beta = 1 - alpha - gamma
            if (alpha < 0) or (beta < 0) or (gamma < 0):
                continue
            out.append((x, y))
    return out


def closed_inside(triangle, p):
    a, b, c = (tuple(Fraction(v) for v in q) for q in triangle)
    signs = [cross(a, b, p), cross(b, c, p), cross(c, a, p)]
    return all(s >= 0 for s in signs) or all(s <= 0 for s in signs)


def has_area(triangle):
    a, b, c = (tuple(Fraction(v) for v in q) for q in triangle)
    return cross(a, b, c) != 0


def test_the_unit_triangles_outside_point_passes_as_printed():
    # (0.6, 0.6) scaled by 10 is the centre of pixel (5.5, 5.5) - 1/2.
    triangle = ((0.0, 0.0), (10.0, 0.0), (0.0, 10.0))
    printed = set(written(record("triangle-barycentric-printed", triangle)))
    signed = set(written(record("triangle-barycentric-printed", triangle, distance="signed")))
    assert (5, 5) in printed and (5, 5) not in signed
    assert not closed_inside(triangle, (Fraction(11, 2), Fraction(11, 2)))


@settings(max_examples=120, deadline=None)
@given(triangles)
def test_barycentric_as_printed_on_random_triangles(triangle):
    check_barycentric(triangle)


@pytest.mark.parametrize("triangle", HARD)
def test_barycentric_as_printed_on_the_hard_triangles(triangle):
    check_barycentric(triangle)


def check_barycentric(triangle):
    unsigned = record("triangle-barycentric-printed", triangle)
    signed = record("triangle-barycentric-printed", triangle, distance="signed")
    if not has_area(triangle):
        assert written(unsigned) == written(signed) == []
        return
    assert written(unsigned) == barycentric_listing(triangle)
    assert written(signed) == barycentric_listing(triangle, signed=True)
    # Signed: exactly the centres of the closed triangle. Unsigned: more, counted.
    columns, rows = centres_of_box(triangle)
    inside = [(x, y) for y in rows for x in columns if closed_inside(triangle, (x + HALF, y + HALF))]
    assert written(signed) == inside
    extra = set(written(unsigned)) - set(inside)
    assert set(inside) <= set(written(unsigned))
    assert unsigned.final_variables()["outside_triangle"] == len(extra)


# ------------------------------------------------------------ linInterp
def lininterp_listing(triangle, q, printed):
    """linInterp ported: xl..xh, yl..yh the box's pixels; a coordinate c's
    pixel (for the loops from x1, y1) is the first whose centre is at or past it."""
    (x0, y0), (x1, y1), (x2, y2) = (tuple(Fraction(c) for c in p) for p in triangle)
    q0, q1, q2 = (Fraction(v) for v in q)
    columns, rows = centres_of_box(triangle)
    xl, xh, yl, yh = columns.start, columns.stop - 1, rows.start, rows.stop - 1
    det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    cx = ((q1 - q0) * (y2 - y0) - (q2 - q0) * (y1 - y0)) / det
    cy = ((q2 - q0) * (x1 - x0) - (q1 - q0) * (x2 - x0)) / det
    out = []
    if printed:
        qRow = cx * (x1 - x0) + cy * (y1 - y0) + q0
        first_x, first_y = math.ceil(x1 - HALF), math.ceil(y1 - HALF)
    else:
        qRow = cx * (xl + HALF - x0) + cy * (yl + HALF - y0) + q0
        first_x, first_y = xl, yl
    for y in range(first_y, yh + 1):
        qPix = qRow
        for x in range(first_x, xh + 1):
            out.append((x, y, qPix))
            qPix += cx
        qRow += cy
    qRow += cy
    return out


def plane_at(triangle, q, p):
    """alpha q0 + beta q1 + gamma q2 at p, from the sub-triangle areas."""
    a, b, c = (tuple(Fraction(v) for v in t) for t in triangle)
    area = cross(a, b, c)
    alpha, beta = cross(b, c, p) / area, cross(c, a, p) / area
    q0, q1, q2 = (Fraction(v) for v in q)
    return alpha * q0 + beta * q1 + (1 - alpha - beta) * q2


inside_grid = st.lists(st.tuples(st.integers(0, 4 * 23).map(lambda n: n / 4),
                                 st.integers(0, 4 * 19).map(lambda n: n / 4)),
                       min_size=3, max_size=3)
vertex_values = st.tuples(*[st.integers(-8, 8).map(lambda n: n / 4)] * 3)


@settings(max_examples=120, deadline=None)
@given(inside_grid, vertex_values)
def test_lininterp_as_printed_and_corrected_on_random_triangles(triangle, q):
    check_lininterp(triangle, q)


@pytest.mark.parametrize("triangle", [t for t in HARD if all(
    0 <= x < GRID[0] and 0 <= y < GRID[1] for x, y in t)])
def test_lininterp_on_the_hard_triangles(triangle):
    check_lininterp(triangle, (0.0, 0.5, 1.0))


def check_lininterp(triangle, q):
    runs = {name: record("triangle-lininterp", triangle, listing=name, s=q)
            for name in ("printed", "corrected")}
    if not has_area(triangle):
        assert all(written(t) == [] for t in runs.values())
        return
    for name, trace in runs.items():
        expected = lininterp_listing(triangle, q, name == "printed")
        assert written(trace) == [(x, y) for x, y, _ in expected]
        values = [float(v) for _, _, v in expected]
        got = [trace.step(i).values["q"] for i in range(len(trace)) if trace.step(i).writes]
        assert got == pytest.approx(values, abs=1e-12)
    # Corrected: the plane at every centre of the box; printed: fewer pixels, counted.
    corrected = lininterp_listing(triangle, q, False)
    for x, y, value in corrected:
        assert value == plane_at(triangle, q, (x + HALF, y + HALF))
    missing = len(corrected) - len(lininterp_listing(triangle, q, True))
    assert runs["printed"].final_variables()["missing"] == missing >= 0


def test_lininterp_as_printed_starts_at_vertex_one():
    triangle, q = ((2.0, 2.0), (9.0, 8.0), (20.0, 15.0)), (0.0, 1.0, 0.0)
    trace = record("triangle-lininterp", triangle, listing="printed", s=q)
    pixels = written(trace)
    assert min(x for x, _ in pixels) == 9 and min(y for _, y in pixels) == 8
    assert trace.final_variables()["missing"] > 0
