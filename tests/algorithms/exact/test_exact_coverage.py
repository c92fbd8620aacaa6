"""The exact coverage reference against shapely, its own Fraction path and areas."""
import math
import random
from fractions import Fraction

import numpy as np
import pytest

# shapely is a test dependency (pyproject's test extra).
from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import polygonize, unary_union

from algorithms.exact import coverage as ec

GRID = (24, 20)


def random_triangle(rng, grid=GRID, margin=0.0):
    w, h = grid
    return [(rng.uniform(margin, w - margin), rng.uniform(margin, h - margin)) for _ in range(3)]


def random_star_polygon(rng, centre, radius, count):
    """A simple polygon: vertices at increasing angles, random radii."""
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(count))
    return [(centre[0] + r * math.cos(a), centre[1] + r * math.sin(a))
            for a, r in zip(angles, (rng.uniform(0.3, 1) * radius for _ in angles))]


def shapely_coverage(geometry, grid):
    w, h = grid
    out = np.zeros((h, w))
    for j in range(h):
        for i in range(w):
            out[j, i] = geometry.intersection(box(i, j, i + 1, j + 1)).area
    return out


# ------------------------------------------------------------ triangles
@pytest.mark.parametrize("seed", range(6))
def test_random_triangle_sums_to_its_area_and_matches_shapely(seed):
    rng = random.Random(seed)
    tri = random_triangle(rng)
    cov = ec.triangle_coverage(tri, GRID)
    area = abs(ec.twice_signed_area(tri)) / 2
    assert math.isclose(cov.sum(), area, rel_tol=1e-9)
    want = shapely_coverage(Polygon(tri), GRID)
    assert np.abs(cov - want).max() < 1e-9
    assert cov.min() >= 0 and cov.max() <= 1


@pytest.mark.parametrize("seed", range(4))
def test_fraction_path_equals_float_path_and_whole_pixels_are_exact(seed):
    rng = random.Random(100 + seed)
    # a fat triangle (some whole pixels inside) with random real vertices
    tri = [(x + rng.uniform(-1, 1), y + rng.uniform(-1, 1))
           for x, y in [(1.5, 1.5), (12.5, 2), (5, 10.5)]]
    exact = ec.triangle_coverage(tri, (14, 12), exact=True)
    assert all(isinstance(v, Fraction) for v in exact.flat)
    assert sum(exact.flat) == abs(ec.twice_signed_area([tuple(map(Fraction, p)) for p in tri])) / 2
    floats = ec.triangle_coverage(tri, (14, 12))
    assert np.abs(ec.as_float(exact) - floats).max() < 1e-12
    inside = np.vectorize(lambda v: v == 1)(exact)
    outside = np.vectorize(lambda v: v == 0)(exact)
    assert inside.any() and outside.any()
    assert np.all(floats[inside] == 1.0)   # exactly, not nearly
    assert np.all(floats[outside] == 0.0)


def test_a_triangle_on_whole_pixels():
    cov = ec.triangle_coverage([(1, 1), (5, 1), (1, 5)], (6, 6))
    assert cov[1, 1] == 1 and cov[1, 4] == 0.5 and cov[4, 1] == 0.5 and cov[2, 3] == 0.5
    assert cov[0].sum() == 0 and cov.sum() == 8


def test_union_of_overlapping_triangles_counts_once_and_sum_counts_twice():
    a = [(2.5, 2.5), (12.25, 3.0), (4.0, 11.5)]
    b = [(3.0, 4.0), (13.0, 6.0), (6.5, 13.0)]
    union = ec.triangle_coverage(a + b, (16, 16))
    summed = ec.triangle_coverage(a + b, (16, 16), union=False)
    want = shapely_coverage(Polygon(a).union(Polygon(b)), (16, 16))
    assert np.abs(union - want).max() < 1e-9
    assert math.isclose(summed.sum(), Polygon(a).area + Polygon(b).area, rel_tol=1e-12)
    exact = ec.triangle_coverage(a + b, (16, 16), exact=True)
    assert np.abs(ec.as_float(exact) - union).max() < 1e-12


def test_windows_and_shapes_beyond_the_grid():
    tri = [(-3.5, -2.0), (9.25, 1.5), (2.0, 8.0)]
    window = (-4, -3, 10, 9)
    cov = ec.triangle_coverage(tri, window)
    assert cov.shape == (12, 14)
    assert math.isclose(cov.sum(), abs(ec.twice_signed_area(tri)) / 2, rel_tol=1e-12)
    clipped = ec.triangle_coverage(tri, (8, 6))
    assert np.abs(clipped - cov[3:9, 4:12]).max() < 1e-14
    want = shapely_coverage(Polygon(tri).intersection(box(0, 0, 8, 6)), (8, 6))
    assert np.abs(clipped - want).max() < 1e-9


# ------------------------------------------------------------- polygons
@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("rule", ["evenodd", "nonzero", "signed"])
def test_random_simple_polygons_match_shapely(seed, rule):
    rng = random.Random(200 + seed)
    poly = random_star_polygon(rng, (12, 10), 9, 9)
    if seed % 2:
        poly = poly[::-1]  # clockwise: signed coverage is negative
    cov = ec.polygon_coverage(poly, GRID, rule)
    want = shapely_coverage(Polygon(poly), GRID)
    sign = -1 if (rule == "signed" and seed % 2) else 1
    assert np.abs(cov - sign * want).max() < 1e-9
    assert math.isclose(cov.sum(), sign * Polygon(poly).area, rel_tol=1e-9)
    exact = ec.polygon_coverage(poly, GRID, rule, exact=True)
    assert np.abs(ec.as_float(exact) - cov).max() < 1e-12
    whole = np.vectorize(lambda v: v in (-1, 0, 1))(exact)
    assert np.array_equal(cov[whole], ec.as_float(exact)[whole])  # exactly 0 or +-1


@pytest.mark.parametrize("hole_turn", ["clockwise", "counter-clockwise"])
def test_polygon_with_a_hole(hole_turn):
    outer = [(2.0, 2.0), (20.5, 2.5), (19.0, 17.0), (3.5, 16.0)]
    inner = [(7.25, 6.0), (8.0, 12.5), (14.0, 11.0), (13.5, 6.5)]  # clockwise
    if hole_turn == "counter-clockwise":
        inner = inner[::-1]
    with_hole = Polygon(outer, [inner])
    evenodd = ec.polygon_coverage([outer, inner], GRID, "evenodd")
    assert np.abs(evenodd - shapely_coverage(with_hole, GRID)).max() < 1e-9
    nonzero = ec.polygon_coverage([outer, inner], GRID, "nonzero")
    want = with_hole if hole_turn == "clockwise" else Polygon(outer)
    assert np.abs(nonzero - shapely_coverage(want, GRID)).max() < 1e-9


def faces_oracle(contour, rule, grid):
    """Coverage of a self-intersecting contour, from the faces of its arrangement.

    shapely cuts the plane along the contour into faces; each face's
    winding number is counted at an inside point by the plain ray rule.
    """
    ring = LineString(list(contour) + [contour[0]])
    faces = list(polygonize(unary_union(ring)))

    def winding(point):
        x, y = point.x, point.y
        w = 0
        for k in range(len(contour)):
            (ax, ay), (bx, by) = contour[k], contour[(k + 1) % len(contour)]
            if ay <= y < by and (bx - ax) * (y - ay) - (by - ay) * (x - ax) > 0:
                w += 1
            elif by <= y < ay and (ax - bx) * (y - by) - (ay - by) * (x - bx) > 0:
                w -= 1
        return w

    region = [f for f in faces if (winding(f.representative_point()) % 2 == 1 if rule == "evenodd"
                                   else winding(f.representative_point()) != 0)]
    return shapely_coverage(unary_union(region), grid)


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_self_intersecting_polygons_against_their_faces(seed, rule):
    rng = random.Random(300 + seed)
    contour = [(rng.uniform(1, 19), rng.uniform(1, 15)) for _ in range(7)]
    cov = ec.polygon_coverage(contour, (20, 16), rule)
    want = faces_oracle(contour, rule, (20, 16))
    assert np.abs(cov - want).max() < 1e-9
    assert math.isclose(cov.sum(), ec.region_area(contour, rule), rel_tol=1e-9)
    exact = ec.polygon_coverage(contour, (20, 16), rule, exact=True)
    assert np.abs(ec.as_float(exact) - cov).max() < 1e-12


def test_the_pentagram_under_each_rule():
    star = [(10 + 8 * math.cos(math.pi / 2 + k * 4 * math.pi / 5),
             10 + 8 * math.sin(math.pi / 2 + k * 4 * math.pi / 5)) for k in range(5)]
    evenodd = ec.polygon_coverage(star, (20, 20), "evenodd")
    nonzero = ec.polygon_coverage(star, (20, 20), "nonzero")
    signed = ec.polygon_coverage(star, (20, 20), "signed")
    assert evenodd[10, 10] == 0 and nonzero[10, 10] == 1 and signed[10, 10] == 2
    # signed = evenodd + 2 * (the pentagon in the middle): the middle winds twice
    pentagon = nonzero.sum() - evenodd.sum()
    assert math.isclose(signed.sum(), evenodd.sum() + 2 * pentagon, rel_tol=1e-12)


# ----------------------------------------------------------------- lines
@pytest.mark.parametrize("caps", ec.CAPS)
@pytest.mark.parametrize("seed", range(3))
def test_line_rectangle(caps, seed):
    rng = random.Random(400 + seed)
    p = (rng.uniform(3, 9), rng.uniform(3, 16))
    q = (rng.uniform(12, 21), rng.uniform(3, 16))
    width = rng.uniform(0.3, 3)
    cov = ec.segment_coverage(p, q, width, GRID, caps)
    length = math.dist(p, q) + (width if caps == "square" else 0)
    assert math.isclose(cov.sum(), width * length, rel_tol=1e-9)
    shape = LineString([p, q]).buffer(width / 2, cap_style="flat" if caps == "butt" else "square")
    assert np.abs(cov - shapely_coverage(shape, GRID)).max() < 1e-9
    exact = ec.segment_coverage(p, q, width, GRID, caps, exact=True)
    assert np.abs(ec.as_float(exact) - cov).max() < 1e-12


def test_axis_aligned_rectangle_on_half_pixels():
    cov = ec.segment_coverage((2.5, 3.5), (10.5, 3.5), 1.0, (12, 6))
    assert cov[3, 2] == 0.5 and cov[3, 10] == 0.5
    assert np.all(cov[3, 3:10] == 1.0) and cov[2].sum() == 0 and cov.sum() == 8


def test_mean_clamp_closed_form():
    s0 = np.array([-1.0, 0.25, 0.5, -0.5, 2.0, 0.3])
    s1 = np.array([2.0, 0.75, 0.5, 0.5, 3.0, 0.3])
    got = ec.mean_clamp(s0, s1)
    # midpoint-rule check with many points
    t = np.linspace(0, 1, 200001)
    want = [np.clip(a + (b - a) * t, 0, 1).mean() for a, b in zip(s0, s1)]
    assert np.allclose(got, want, atol=1e-5)
    assert got[2] == 0.5 and got[4] == 1.0


def test_unknown_rule_is_refused():
    with pytest.raises(ValueError):
        ec.polygon_coverage([(0, 0), (1, 0), (0, 1)], (2, 2), "winding")


def test_point_inside_helper_for_shapely_is_consistent():
    # the faces oracle's winding rule agrees with shapely on a simple square
    square = [(1, 1), (5, 1), (5, 5), (1, 5)]
    assert faces_oracle(square, "evenodd", (6, 6)).sum() == pytest.approx(16)
    assert Polygon(square).contains(Point(3, 3))
