"""Polygons that share edges cover every pixel of their union exactly once.

The fill rule hands a centre on a shared edge to exactly one side (the one
for which it is a left or a bottom edge), so adjacent polygons neither
overlap nor leave cracks. Checked for the scan-line generator and kernel,
for the convex fill and for tessellation, against the exact oracle's fill
of the union's outline.
"""
import math
from collections import Counter

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from algorithms.exact import polygons as oracle
from algorithms.polygons import CONVEX, SCANLINE, TESSELLATE, convexity_problem, snap_contours
from test_polygons_cases import generator_pixels, kernel_pixels, star_shaped

snap_point = st.integers(0, 24 * 256).map(lambda k: k / 256)
half_point = st.integers(0, 48).map(lambda k: k / 2)
coordinate = st.one_of(snap_point, half_point)


def side(p, q, r):
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def assert_tiles(pieces, outline, fill=lambda piece: kernel_pixels(SCANLINE, [piece])):
    counts = Counter(p for piece in pieces for p in fill(piece))
    assert all(count == 1 for count in counts.values()), \
        [p for p, count in counts.items() if count > 1][:5]
    assert set(counts) == oracle.covered_pixels([outline])


@settings(max_examples=200)
@given(st.tuples(coordinate, coordinate), st.tuples(coordinate, coordinate),
       st.tuples(coordinate, coordinate), st.tuples(coordinate, coordinate))
def test_two_triangles_on_one_edge(p, q, r, s):
    # r and s on opposite sides of pq: triangles pqr and qps share the edge pq.
    assume(side(p, q, r) != 0 and side(p, q, s) != 0)
    if side(p, q, r) < 0:
        p, q = q, p
    if side(p, q, s) > 0:  # turn s about the middle of pq, to the other side
        s = (p[0] + q[0] - s[0], p[1] + q[1] - s[1])
    first, second = [p, q, r], [q, p, s]
    counts = Counter(generator_pixels(SCANLINE, [first]) + generator_pixels(SCANLINE, [second]))
    assert max(counts.values(), default=1) == 1
    # Their union is the quadrilateral p, s, q, r (simple; maybe concave).
    assert set(counts) == oracle.covered_pixels([[p, s, q, r]])


@settings(max_examples=120)
@given(star_shaped())
def test_a_fan_of_triangles_tiles_its_star(points):
    xs, ys = zip(*points)
    centre = (sum(xs) / len(xs), sum(ys) / len(ys))
    snapped = snap_contours([points])[0]
    c = snap_contours([[centre]])[0][0]
    # Only fans whose triangles all turn the polygon's way tile it.
    turns = [side(c, snapped[k], snapped[(k + 1) % len(snapped)]) for k in range(len(snapped))]
    assume(all(t > 0 for t in turns) or all(t < 0 for t in turns))
    fan = [[centre, points[k], points[(k + 1) % len(points)]] for k in range(len(points))]
    assert_tiles(fan, points)
    assert_tiles(fan, points, lambda piece: generator_pixels(TESSELLATE, [piece]))


@st.composite
def quad_mesh(draw):
    """A 4 x 3 grid of quads of side 6; inner vertices jittered, outer ones slid along the border."""
    columns, rows, side_length = 4, 3, 6
    jitter = st.integers(-1 * 256 * 3 // 2, 256 * 3 // 2).map(lambda k: k / 256)
    vertices = {}
    for a in range(columns + 1):
        for b in range(rows + 1):
            x, y = 1 + a * side_length, 1 + b * side_length
            if 0 < a < columns:
                x += draw(jitter)
            if 0 < b < rows:
                y += draw(jitter)
            vertices[a, b] = (x, y)
    quads = [[vertices[a, b], vertices[a + 1, b], vertices[a + 1, b + 1], vertices[a, b + 1]]
             for a in range(columns) for b in range(rows)]
    outline = [vertices[0, 0], vertices[columns, 0], vertices[columns, rows], vertices[0, rows]]
    return quads, outline


@settings(max_examples=60)
@given(quad_mesh())
def test_a_mesh_of_perturbed_quads_covers_each_pixel_once(mesh):
    quads, outline = mesh
    assert_tiles(quads, outline)
    assert_tiles(quads, outline, lambda quad: generator_pixels(SCANLINE, [quad]))
    assert_tiles(quads, outline, lambda quad: generator_pixels(TESSELLATE, [quad]))
    convex = [quad for quad in quads if not convexity_problem(snap_contours([quad])[0])]
    for quad in convex:
        assert generator_pixels(CONVEX, [quad]) == generator_pixels(SCANLINE, [quad])


def test_a_mesh_on_pixel_centres():
    # Every vertex and every edge on centres: the hardest case for ties.
    quads = [[(1.5 + 4 * a, 1.5 + 4 * b), (5.5 + 4 * a, 1.5 + 4 * b), (5.5 + 4 * a, 5.5 + 4 * b),
              (1.5 + 4 * a, 5.5 + 4 * b)] for a in range(3) for b in range(3)]
    assert_tiles(quads, [(1.5, 1.5), (13.5, 1.5), (13.5, 13.5), (1.5, 13.5)])
    # And a diamond fan around a centre, edges at 45 degrees through centres.
    centre = (8.5, 8.5)
    ring = [(8.5 + 6 * math.cos(k * math.pi / 4), 8.5 + 6 * math.sin(k * math.pi / 4)) for k in range(8)]
    ring = [(round(2 * x) / 2, round(2 * y) / 2) for x, y in ring]
    fan = [[centre, ring[k], ring[(k + 1) % 8]] for k in range(8)]
    assert_tiles(fan, ring)


def test_tie_options_show_overlaps_and_cracks():
    # Two triangles sharing the diagonal (1, 1)-(9, 9), which runs through centres.
    lower, upper = [(1, 1), (9, 1), (9, 9)], [(1, 1), (9, 9), (1, 9)]

    def counts(ties):
        return Counter(generator_pixels(TESSELLATE, [lower], {"ties": ties})
                       + generator_pixels(TESSELLATE, [upper], {"ties": ties}))
    square = oracle.covered_pixels([[(1, 1), (9, 1), (9, 9), (1, 9)]])
    assert set(counts("left-bottom")) == square and max(counts("left-bottom").values()) == 1
    assert max(counts("inclusive").values()) == 2  # the diagonal's centres twice
    assert set(counts("strict")) < square  # the diagonal's centres in neither
