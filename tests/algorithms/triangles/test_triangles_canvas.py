"""fill_canvas, the compiled triangle fill: the span kernel's counts and an exact oracle's."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms import triangles
from algorithms.core.registry import InputError
from algorithms.triangles.canvas import fill_canvas

SUB = 256
RULES = ("top-left", "inclusive", "strict")


def oracle_counts(points, grid, rule, cull=False):
    """Per pixel centre, exact integer edge tests in 1/512 px (written for this test).

    A centre counts when it is strictly inside a counter-clockwise triangle,
    or (top-left) exactly on an edge that runs downwards (a left edge) or a
    horizontal one that runs right (a bottom edge); inclusive keeps every
    edge, strict none.
    """
    width, height = grid
    counts = np.zeros((height, width), np.int32)
    pts = [(round(x * SUB) * 2, round(y * SUB) * 2) for x, y in np.asarray(points, float).tolist()]
    for n in range(0, len(pts), 3):
        p, q, r = pts[n:n + 3]
        area = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
        if area == 0 or (cull and area < 0):
            continue
        if area < 0:
            q, r = r, q
        edges = [(p, q), (q, r), (r, p)]
        left_or_bottom = [b[1] < a[1] or (b[1] == a[1] and b[0] > a[0]) for a, b in edges]
        keep = [rule == "inclusive" or (rule == "top-left" and tie) for tie in left_or_bottom]
        for j in range(height):
            cy = 2 * SUB * j + SUB
            for i in range(width):
                cx = 2 * SUB * i + SUB
                inside = True
                for (a, b), tie in zip(edges, keep):
                    e = (b[0] - a[0]) * (cy - a[1]) - (b[1] - a[1]) * (cx - a[0])
                    if e < 0 or (e == 0 and not tie):
                        inside = False
                        break
                counts[j, i] += inside
    return counts


def check(points, grid, rule="top-left", cull=False):
    width, height = grid
    want = oracle_counts(points, grid, rule, cull)
    got = fill_canvas(points, grid, rule=rule, cull=cull)
    assert np.array_equal(got, want)
    if not cull:
        assert np.array_equal(triangles.fill(points, grid, rule), want)  # the span kernel
    picture = np.full((height, width), 7, np.uint8)
    fill_canvas(points, grid, picture, 200, rule=rule, cull=cull)
    assert np.array_equal(picture, np.where(want > 0, 200, 7))
    return want


coordinate = st.integers(-3 * SUB, 19 * SUB).map(lambda n: n / SUB)


@settings(max_examples=40)
@given(st.lists(st.tuples(coordinate, coordinate), min_size=3, max_size=12).filter(
    lambda p: len(p) % 3 == 0), st.sampled_from(RULES))
def test_random_triangles_on_the_sub_pixel_grid(points, rule):
    check(points, (16, 12), rule)


@pytest.mark.parametrize("rule", RULES)
def test_vertices_on_pixel_centres_put_centres_on_every_edge(rule):
    points = [(1.5, 1.5), (9.5, 1.5), (1.5, 9.5), (9.5, 1.5), (9.5, 9.5), (1.5, 9.5),
              (3.5, 0.5), (3.5, 7.5), (10.5, 4.5)]
    check(points, (12, 11), rule)


def test_shared_edges_give_each_centre_to_one_triangle():
    # A fan around a centre point, vertices on centres and off them.
    centre = (6.5, 5.5)
    ring = [(0.5, 0.5), (6.0, 0.25), (12.5, 0.5), (12.5, 10.5), (6.5, 10.5), (0.5, 10.5)]
    points = [v for k in range(len(ring)) for v in (centre, ring[k], ring[(k + 1) % len(ring)])]
    counts = check(points, (14, 12))
    assert counts.max() == 1
    assert counts[1:10, 1:12].min() == 1  # no crack inside the fan


def test_slivers_and_degenerate_triangles():
    points = [(0.2, 0.3), (15.9, 11.7), (15.9, 11.72),     # a sliver along a diagonal
              (0.0, 5.5), (16.0, 5.5), (16.0, 5.50390625),  # one along a row of centres
              (1, 1), (3, 3), (5, 5)]                       # no area
    check(points, (16, 12))
    check(points, (16, 12), "inclusive")


def test_cull_drops_clockwise_triangles():
    points = [(1, 1), (1, 8), (8, 1), (1, 1), (8, 1), (1, 8)]
    counts = check(points, (10, 10), cull=True)
    assert counts.sum() == oracle_counts(points[3:], (10, 10), "top-left").sum() > 0


@pytest.mark.parametrize("far", [1e9, 3e13])
def test_triangles_beyond_int64_fall_back_and_stay_exact(far):
    points = [(-far, -far / 3), (far / 2, 10.3), (11.25, far), (1.5, 1.5), (9, 2), (3, 8)]
    tris, _ = triangles.oriented(points, {})
    assert not triangles._fits_int64_array(tris, SUB)[0]
    counts = check(points, (16, 12))
    assert counts.max() == 2


def test_triangles_outside_the_canvas_are_clipped():
    points = [(-40, -40), (-1, -30), (-20, 50), (-5, -5), (30, -2), (40, 25)]
    check(points, (12, 10))


def test_bad_rule_and_canvas_shape_are_refused():
    with pytest.raises(InputError):
        fill_canvas([(0, 0), (1, 0), (0, 1)], (4, 4), rule="even")
    with pytest.raises(ValueError):
        fill_canvas([(0, 0), (1, 0), (0, 1)], (4, 4), np.zeros((5, 4), np.uint8))
