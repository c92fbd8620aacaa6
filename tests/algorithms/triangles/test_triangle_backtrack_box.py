"""The backtracking walk and its bounding box.

Lecture 000 remarks that traversal never needs to leave the bounding box;
the walk as the slides describe it does (it backs up until a pixel fails a
left edge, which may lie past xmin). The option bounded makes the box's
edges walls. Both are held to the covered pixel centres from exact edge
functions written here, and the bounded walk to the box.
"""
from __future__ import annotations

import math
import random
from fractions import Fraction

import pytest

from algorithms.core import registry
from algorithms.core.steps import NO_PIXEL, Note, Vars

GRID = (32, 24)
SPEC = registry.get("triangle-backtrack")


def random_triangles(count, seed):
    """Vertices on a 1/16 px lattice, so snapping to 1/256 keeps them exact."""
    rng = random.Random(seed)
    return [[(Fraction(rng.randint(0, 31 * 16), 16), Fraction(rng.randint(0, 23 * 16), 16))
             for _ in range(3)] for _ in range(count)]


HARD = [[(2, 2), (20, 2), (11, 20)], [(1.5, 1.5), (9.5, 1.5), (1.5, 9.5)],
        [(3, 3), (29, 4), (4, 22)], [(10.5, 0.5), (11.5, 23.5), (12, 0.5)]]
TRIANGLES = [[(Fraction(x), Fraction(y)) for x, y in tri] for tri in HARD] + \
    random_triangles(60, 12)


def covered(tri, rule):
    """Pixel centres inside the triangle by exact edge functions.

    For a counter-clockwise triangle, edge A -> B has e(p) = a x + b y + c with
    a = Ay - By, b = Bx - Ax; inside is e > 0. On an edge (e = 0) the centre
    counts with inclusive, never with strict, and with top-left when a > 0 or
    a = 0 and b > 0."""
    p0, p1, p2 = tri
    area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1])
    if area == 0:
        return set()
    if area < 0:
        p1, p2 = p2, p1
    edges = [(a[1] - b[1], b[0] - a[0], a[0] * b[1] - a[1] * b[0])
             for a, b in ((p0, p1), (p1, p2), (p2, p0))]

    def inside(x, y):
        for a, b, c in edges:
            e = a * x + b * y + c
            if e < 0 or (e == 0 and not (rule == "inclusive" or
                                         (rule == "top-left" and (a > 0 or (a == 0 and b > 0))))):
                return False
        return True
    half = Fraction(1, 2)
    return {(i, j) for i in range(GRID[0]) for j in range(GRID[1]) if inside(i + half, j + half)}


def box(tri):
    """Columns and rows whose centres lie within the triangle's bounding box."""
    xs, ys = [p[0] for p in tri], [p[1] for p in tri]
    return (math.ceil(min(xs) - Fraction(1, 2)), math.floor(max(xs) - Fraction(1, 2)),
            math.ceil(min(ys) - Fraction(1, 2)), math.floor(max(ys) - Fraction(1, 2)))


def record(tri, **options):
    return SPEC.record([(float(x), float(y)) for x, y in tri], options, grid=GRID)


def visited(trace):
    steps = (trace.step(i) for i in range(len(trace)))
    return [step.pixel for step in steps if step.pixel is not None and step.record is None
            and step.pixel[0] != NO_PIXEL]


@pytest.mark.parametrize("rule", ["top-left", "inclusive", "strict"])
@pytest.mark.parametrize("bounded", [False, True])
def test_the_walk_fills_exactly_the_covered_centres(rule, bounded):
    for tri in TRIANGLES:
        trace = record(tri, fill_rule=rule, bounded=bounded)
        assert {tuple(p) for p in trace.written_pixels().tolist()} == covered(tri, rule), tri


def test_the_bounded_walk_never_visits_outside_the_box():
    for tri in TRIANGLES:
        i_lo, i_hi, j_lo, j_hi = box(tri)
        trace = record(tri, bounded=True)
        for x, y in visited(trace):
            assert i_lo <= x <= i_hi and j_lo <= y <= j_hi, (tri, (x, y))
        assert trace.variables_at(len(trace) - 1).get("outside_box", 0) == 0


def test_the_unbounded_walk_leaves_the_box_and_counts_each_visit_outside():
    left = 0
    for tri in TRIANGLES:
        i_lo, i_hi, _, _ = box(tri)
        trace = record(tri)
        outside = [(x, y) for x, y in visited(trace) if not i_lo <= x <= i_hi]
        shown = trace.variables_at(len(trace) - 1).get("outside_box", 0)
        assert shown == len(outside), tri
        notes = [trace.step(i).record for i in range(len(trace))
                 if isinstance(trace.step(i).record, Note)
                 and "outside the bounding box" in trace.step(i).record.text]
        assert len(notes) == (1 if outside else 0)
        if outside:
            assert notes[0].pixel == outside[0]
        left += bool(outside)
    # Most random triangles: the remark's point.
    assert left > len(TRIANGLES) // 2


def test_bounded_visits_fewer_pixels_for_the_same_fill():
    tri = TRIANGLES[2]
    free, bounded = record(tri), record(tri, bounded=True)
    assert len(visited(bounded)) < len(visited(free))
    assert bounded.written_pixels().tolist() == free.written_pixels().tolist()


def test_the_shipped_scene_shows_the_walk_leaving_the_box():
    from app.model import shipped
    from app.model.scene import load
    scene = load(shipped.scene_path("triangle-backtrack-box"))
    assert scene.algorithm == "triangle-backtrack" and not scene.options.get("bounded")
    trace = SPEC.record(scene.points, scene.options, grid=scene.grid)
    assert trace.variables_at(len(trace) - 1)["outside_box"] > 0
    assert any(isinstance(trace.step(i).record, Vars) for i in range(len(trace)))
