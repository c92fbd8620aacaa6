"""Watertight meshes: the top-left rule fills every interior centre exactly once.

Meshes: a grid of quads split along random diagonals, fans of 3..64
triangles around a vertex, and Delaunay triangulations of random point
sets (scipy), each triangle in a random winding. The union's interior is
taken from the exact oracle and checked against the mesh's known outline
(rectangle, star polygon, convex hull). Inclusive and strict rules must
produce exactly the overlaps and cracks the oracle predicts.
"""
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from algorithms.exact import triangles as exact_triangles
from algorithms import triangles
from test_triangles_cases import SUB, as_window, oracle, spec, sub
from tests.support.trace_oracle import slow_replay

SETTINGS = dict(suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


def ccw(a, b, c) -> Fraction:
    return exact_triangles.cross(a, b, c)


def flatten(tris, flips):
    """Points of the triangles, each one's winding reversed where flips says so."""
    points = []
    for (a, b, c), flip in zip(tris, flips):
        points += [a, c, b] if flip else [a, b, c]
    return [(sub(x), sub(y)) for x, y in points]


# ------------------------------------------------------------ meshes
@st.composite
def quad_grid(draw):
    """(points, grid, outline test) of an nx x ny grid of jittered quads, 1 px margin."""
    nx, ny = draw(st.integers(2, 5)), draw(st.integers(2, 4))
    cell = 3 * SUB
    ox, oy = SUB + draw(st.integers(0, SUB)), SUB + draw(st.integers(0, SUB))
    jitter = st.integers(-SUB * 2 // 3, SUB * 2 // 3)
    vertex = {}
    for i in range(nx + 1):
        for j in range(ny + 1):
            dx = draw(jitter) if 0 < i < nx else 0
            dy = draw(jitter) if 0 < j < ny else 0
            vertex[i, j] = (ox + i * cell + dx, oy + j * cell + dy)
    tris = []
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = vertex[i, j], vertex[i + 1, j], vertex[i + 1, j + 1], vertex[i, j + 1]
            tris += [(a, b, c), (a, c, d)] if draw(st.booleans()) else [(a, b, d), (b, c, d)]
    assume(all(ccw(*t) > 0 for t in tris))
    flips = draw(st.lists(st.booleans(), min_size=len(tris), max_size=len(tris)))
    x0, y0, x1, y1 = ox, oy, ox + nx * cell, oy + ny * cell

    def inside(px, py):  # centre in sub-pixel units, doubled
        return 2 * x0 < px < 2 * x1 and 2 * y0 < py < 2 * y1

    grid = (x1 // SUB + 2, y1 // SUB + 2)
    return flatten(tris, flips), grid, inside


@st.composite
def fan(draw):
    """A closed fan of n triangles around a centre vertex (on a pixel centre, or anywhere)."""
    n = draw(st.integers(3, 64))
    if draw(st.booleans()):
        centre = (8 * SUB + SUB // 2, 8 * SUB + SUB // 2)
    else:
        centre = (draw(st.integers(7 * SUB, 9 * SUB)), draw(st.integers(7 * SUB, 9 * SUB)))
    outer = []
    for k in range(n):
        angle = 2 * np.pi * (k + 0.5 * draw(st.floats(0, 0.999))) / n
        radius = draw(st.floats(2.0, 6.5))
        outer.append((centre[0] + round(radius * np.cos(angle) * SUB),
                      centre[1] + round(radius * np.sin(angle) * SUB)))
    tris = [(centre, outer[k], outer[(k + 1) % n]) for k in range(n)]
    assume(all(ccw(*t) > 0 for t in tris))
    flips = draw(st.lists(st.booleans(), min_size=n, max_size=n))

    def inside(px, py):  # strictly inside the star polygon of the outer points
        return _in_polygon(outer, (Fraction(px, 2), Fraction(py, 2)))

    return flatten(tris, flips), (18, 18), inside


def _in_polygon(polygon, p) -> bool:
    """Strictly inside a simple polygon: even-odd crossings, and not on an edge."""
    inside = False
    n = len(polygon)
    for k in range(n):
        a, b = polygon[k], polygon[(k + 1) % n]
        if ccw(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) \
                and min(a[1], b[1]) <= p[1] <= max(a[1], b[1]):
            return False
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + Fraction(p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if p[0] < x:
                inside = not inside
    return inside


@st.composite
def delaunay(draw):
    """A Delaunay triangulation of 4..24 points on the sub-pixel grid (some on pixel centres)."""
    from scipy.spatial import ConvexHull, Delaunay

    n = draw(st.integers(4, 24))
    pts = set()
    for _ in range(n):
        if draw(st.booleans()):
            pts.add((draw(st.integers(1, 13)) * SUB + SUB // 2, draw(st.integers(1, 11)) * SUB + SUB // 2))
        else:
            pts.add((draw(st.integers(SUB, 14 * SUB)), draw(st.integers(SUB, 12 * SUB))))
    pts = sorted(pts)
    array = np.array(pts, dtype=float)
    assume(len(pts) >= 4 and np.linalg.matrix_rank(array[1:] - array[0]) == 2)
    tri = Delaunay(array)
    tris = []
    for simplex in tri.simplices:
        a, b, c = (pts[k] for k in simplex)
        tris.append((a, b, c) if ccw(a, b, c) >= 0 else (a, c, b))
    hull = [pts[k] for k in ConvexHull(array).vertices]  # counter-clockwise
    hull_area = sum(ccw(hull[0], hull[k], hull[k + 1]) for k in range(1, len(hull) - 1))
    assume(all(ccw(*t) > 0 for t in tris))
    assume(sum(ccw(*t) for t in tris) == hull_area)  # no overlaps: the areas add up exactly
    flips = draw(st.lists(st.booleans(), min_size=len(tris), max_size=len(tris)))

    def inside(px, py):
        p = (Fraction(px, 2), Fraction(py, 2))
        return all(ccw(hull[k], hull[(k + 1) % len(hull)], p) > 0 for k in range(len(hull)))

    return flatten(tris, flips), (16, 14), inside


MESHES = st.one_of(quad_grid(), fan(), delaunay())


# ------------------------------------------------------------- checks
def interior_from_outline(grid, inside):
    """Pixels whose centre is strictly inside the known outline (independent of the oracle)."""
    return {(i, j) for i in range(grid[0]) for j in range(grid[1])
            if inside((2 * i + 1) * SUB, (2 * j + 1) * SUB)}


def counts_of_run(name, points, rule, grid):
    trace = spec(name).record(points, {"fill_rule": rule}, grid=grid)
    counts = trace.raster_at(len(trace) - 1).counts
    return counts, trace.final_variables()


@settings(max_examples=80, **SETTINGS)
@given(MESHES)
def test_the_oracle_union_interior_is_the_outline_interior(mesh):
    points, grid, inside = mesh
    assert exact_triangles.union_interior(points, 8, as_window(grid)) == \
        interior_from_outline(grid, inside)


@settings(max_examples=100, **SETTINGS)
@given(MESHES, st.sampled_from(["triangle-bbox", "triangle-pineda", "triangle-linewise",
                                "triangle-halfplane"]))
def test_top_left_fills_every_interior_centre_exactly_once(mesh, name):
    points, grid, inside = mesh
    interior = interior_from_outline(grid, inside)
    counts, final = counts_of_run(name, points, "top-left", grid)
    assert counts.max() <= 1
    for i, j in interior:
        assert counts[j, i] == 1, (name, (i, j))
    closed = oracle(points, "inclusive", as_window(grid))  # nothing outside the closed union
    assert {(i, j) for j, i in zip(*np.nonzero(counts))} <= set(closed)
    assert final["overlaps"] == 0 and final["cracks"] == 0
    assert np.array_equal(triangles.fill(points, grid), counts)


@settings(max_examples=80, **SETTINGS)
@given(MESHES, st.sampled_from(["inclusive", "strict"]))
def test_inclusive_and_strict_flaws_are_what_the_oracle_predicts(mesh, rule):
    points, grid, inside = mesh
    window = as_window(grid)
    want = oracle(points, rule, window)
    interior = interior_from_outline(grid, inside)
    overlaps, cracks = exact_triangles.overlaps_and_cracks(want, interior)
    counts, final = counts_of_run("triangle-bbox", points, rule, grid)
    assert {(i, j): int(counts[j, i]) for j, i in zip(*np.nonzero(counts))} == want
    assert (final["overlaps"], final["cracks"]) == (overlaps, cracks)
    if rule == "inclusive":
        assert cracks == 0
    else:
        assert overlaps == 0


def test_centres_on_shared_edges_show_overlaps_and_cracks():
    # A 4 x 4 grid of 2 px quads with corners on pixel centres: every shared
    # edge runs through centres.
    tris = []
    for i in range(4):
        for j in range(4):
            a = (2 * i + 0.5, 2 * j + 0.5)
            b, c, d = (a[0] + 2, a[1]), (a[0] + 2, a[1] + 2), (a[0], a[1] + 2)
            tris += [a, b, c, a, c, d]
    results = {}
    for rule in ("top-left", "inclusive", "strict"):
        trace = spec("triangle-bbox").record(tris, {"fill_rule": rule}, grid=(10, 10))
        results[rule] = trace.final_variables()
    assert results["top-left"]["overlaps"] == 0 and results["top-left"]["cracks"] == 0
    assert results["inclusive"]["overlaps"] > 0 and results["inclusive"]["cracks"] == 0
    assert results["strict"]["cracks"] > 0 and results["strict"]["overlaps"] == 0
    # interior centres: x, y in 1..7 (the outline runs through centres 0 and 8)
    interior = {(i, j) for i in range(1, 8) for j in range(1, 8)}
    want = oracle(tris, "strict", (0, 0, 10, 10))
    assert results["strict"]["cracks"] == sum(1 for p in interior if p not in want)


def test_state_at_equals_a_slow_replay_on_a_mesh():
    rng = np.random.default_rng(3)
    points = []
    for i in range(3):
        for j in range(3):
            a = (1 + 3 * i + rng.uniform(0, 0.3), 1 + 3 * j + rng.uniform(0, 0.3))
            b, c, d = (a[0] + 3, a[1]), (a[0] + 3, a[1] + 3), (a[0], a[1] + 3)
            points += [a, b, c, a, c, d]
    colors = ["#ff0000", "#00ff00", "#0000ff"]
    for name in ("triangle-bbox", "triangle-pineda", "triangle-backtrack"):
        trace = spec(name).record(points, {"colors": colors}, grid=(12, 12))
        for i in list(range(0, len(trace), max(1, len(trace) // 9))) + [len(trace) - 1]:
            fast, slow = trace.state_at(i).raster, slow_replay(trace, i)
            assert np.array_equal(fast.counts, slow.counts), (name, i)
            assert np.array_equal(fast.colors, slow.colors), (name, i)


@pytest.mark.parametrize("rule", ["top-left", "inclusive", "strict"])
def test_the_kernel_fill_matches_the_oracle_on_many_triangles(rule):
    rng = np.random.default_rng(11)
    points = [tuple(rng.integers(0, 16 * SUB, 2) / SUB) for _ in range(3 * 40)]
    want = oracle(points, rule, (0, 0, 16, 16))
    counts = triangles.fill(points, (16, 16), rule)
    assert {(i, j): int(counts[j, i]) for j, i in zip(*np.nonzero(counts))} == want


@pytest.mark.parametrize("n", [3, 17, 64])
def test_closed_fans_around_a_pixel_centre(n):
    centre = (8.5, 8.5)
    outer = [(8.5 + 6 * np.cos(2 * np.pi * k / n), 8.5 + 6 * np.sin(2 * np.pi * k / n))
             for k in range(n)]
    points = []
    for k in range(n):
        points += [centre, outer[k], outer[(k + 1) % n]]
    window = (0, 0, 18, 18)
    interior = exact_triangles.union_interior(points, 8, window)
    assert (8, 8) in interior
    for rule in ("top-left", "inclusive", "strict"):
        want = oracle(points, rule, window)
        counts, final = counts_of_run("triangle-bbox", points, rule, (18, 18))
        assert {(i, j): int(counts[j, i]) for j, i in zip(*np.nonzero(counts))} == want
        assert (final["overlaps"], final["cracks"]) == exact_triangles.overlaps_and_cracks(want, interior)
        if rule == "top-left":
            assert all(want.get(p) == 1 for p in interior) and max(want.values()) == 1
    # the centre vertex sits on every spoke: inclusive counts it n times, strict never
    assert oracle(points, "inclusive", window)[(8, 8)] == n
    assert (8, 8) not in oracle(points, "strict", window)
