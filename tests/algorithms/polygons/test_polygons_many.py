"""scanline_fill_many, the compiled batch of scan-line fills: the per-polygon kernel's
pixels and an exact crossing-number oracle's."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.polygons import scanline_pixels
from algorithms.polygons.many import scanline_fill_many
from algorithms.core.registry import InputError

ONE = 256


def oracle_counts(polygons, grid, rule="evenodd", sample=ONE // 2):
    """Per pixel, exact integer crossing counts (written for this test).

    Row j's scan line runs at y = j + sample/256 px; an edge crosses it when
    low.y <= y < high.y (so a vertex on the line counts once), and the
    crossing is left of the centre (or on it) when
    (cx - low.x) dy >= (y - low.y) dx. Even-odd fills an odd count, nonzero
    a non-zero sum of the crossings' directions.
    """
    width, height = grid
    cx = np.arange(width, dtype=object)[None, :] * ONE + ONE // 2
    cy = np.arange(height, dtype=object)[:, None] * ONE + sample
    counts = np.zeros((height, width), np.int32)
    for polygon in polygons:
        winding = np.zeros((height, width), np.int64)
        for contour in polygon:
            snapped = [(round(x * ONE), round(y * ONE)) for x, y in contour]
            for k, a in enumerate(snapped):
                b = snapped[(k + 1) % len(snapped)]
                if a[1] == b[1]:
                    continue
                direction = 1 if b[1] > a[1] else -1
                low, high = (a, b) if direction > 0 else (b, a)
                dx, dy = high[0] - low[0], high[1] - low[1]
                meets = (low[1] <= cy) & (cy < high[1])
                left = (cx - low[0]) * dy >= (cy - low[1]) * dx
                crossing = (meets & left).astype(np.int64)
                winding += crossing * (direction if rule == "nonzero" else 1)
        counts += (winding % 2 == 1) if rule == "evenodd" else (winding != 0)
    return counts


def per_polygon(polygons, grid, options):
    """The existing kernel, one polygon at a time, clipped to the grid."""
    width, height = grid
    counts = np.zeros((height, width), np.int32)
    for polygon in polygons:
        for x, y in scanline_pixels(polygon, options).tolist():
            if 0 <= x < width and 0 <= y < height:
                counts[y, x] += 1
    return counts


def check(polygons, grid, rule="evenodd", edge_x=None, whole_box=True):
    options = {"fill_rule": rule, **({"edge_x": edge_x} if edge_x else {})}
    want = oracle_counts(polygons, grid, rule, 0 if edge_x == "x-low" else ONE // 2)
    got = scanline_fill_many(polygons, grid, options=options)
    assert np.array_equal(got, want)
    if whole_box:  # the per-polygon kernel decodes the polygon's whole box of pixels
        assert np.array_equal(per_polygon(polygons, grid, options), want)
    picture = np.full((grid[1], grid[0]), 9, np.uint8)
    scanline_fill_many(polygons, grid, picture, 250, options)
    assert np.array_equal(picture, np.where(want > 0, 250, 9))
    return want


coordinate = st.integers(-3 * ONE, 21 * ONE).map(lambda n: n / ONE)
contour = st.lists(st.tuples(coordinate, coordinate), min_size=3, max_size=8)
polygon = st.lists(contour, min_size=1, max_size=2)


@settings(max_examples=60)
@given(st.lists(polygon, min_size=1, max_size=4), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([None, "x-low"]))
def test_random_polygons_with_holes_and_crossings(polygons, rule, edge_x):
    check(polygons, (18, 14), rule, edge_x)


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_a_pentagram_differs_between_the_rules_only_in_its_centre(rule):
    star = [[(8.0, 15.5), (3.1, 0.7), (15.5, 10.2), (0.5, 10.2), (12.9, 0.7)]]
    counts = check([star], (16, 16), rule)
    assert counts[8, 8] == (rule == "nonzero")


def test_vertices_and_edges_on_pixel_centres_and_shared_edges():
    # A square cut into four polygons through its middle: every centre of the square
    # in exactly one of them, centres on the cuts included.
    a, m, b = 1.5, 6.5, 11.5
    pieces = [[[(a, a), (m, a), (m, m), (a, m)]], [[(m, a), (b, a), (b, m), (m, m)]],
              [[(a, m), (m, m), (m, b), (a, b)]], [[(m, m), (b, m), (b, b), (m, b)]]]
    counts = check(pieces, (14, 14))
    assert counts.max() == 1
    assert counts[1:11, 1:11].min() == 1 and counts.sum() == 100


def test_slivers_degenerate_and_clipped_polygons():
    polygons = [[[(0.1, 0.2), (17.9, 12.7), (17.9, 12.71)]],     # a sliver
                [[(2, 3.5), (9, 3.5), (14, 3.5)]],               # on one centre line: nothing
                [[(-30, -8), (40, 2.25), (3.5, 60)]],             # far beyond the grid
                [[(-9, -9), (-2, -9), (-2, -2)]]]                # all outside
    counts = check(polygons, (18, 14))
    assert counts.sum() > 0


def test_an_array_of_polygons_gives_what_the_list_gives():
    rng = np.random.default_rng(5)
    shapes = rng.integers(-2 * ONE, 34 * ONE, (40, 5, 2)) / ONE
    lists = [[[tuple(p) for p in shape]] for shape in shapes.tolist()]
    for rule in ("evenodd", "nonzero"):
        want = oracle_counts(lists, (32, 32), rule)
        assert np.array_equal(scanline_fill_many(shapes, (32, 32), options={"fill_rule": rule}),
                              want)


def test_many_edges_in_one_polygon():
    # Over 32 edges take the sort for long polygons: a 48-point zigzag ring.
    angles = np.arange(48) * (2 * np.pi / 48)
    radius = np.where(np.arange(48) % 2, 9.3, 4.1)
    ring = [(round(16 + r * np.cos(t), 3), round(15 + r * np.sin(t), 3))
            for r, t in zip(radius, angles)]
    ring = ring[::2][::-1] + ring[1::2]  # shuffled so its edges cross: self-intersecting
    for rule in ("evenodd", "nonzero"):
        check([[ring]], (32, 30), rule)


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_a_star_of_thousands_of_spikes_gives_the_per_polygon_kernels_pixels(rule):
    # Hundreds of edges on each row: the active edges keep their order from row to row.
    n = 4000
    angles = np.arange(n) * (2 * np.pi / n)
    radius = np.where(np.arange(n) % 2, 47.0, 19.0)
    star = [[(x, y) for x, y in zip(np.round(48 + radius * np.cos(angles), 3).tolist(),
                                     np.round(48 + radius * np.sin(angles), 3).tolist())]]
    options = {"fill_rule": rule}
    assert np.array_equal(scanline_fill_many([star], (96, 96), options=options),
                          per_polygon([star], (96, 96), options))


def test_float_arithmetic_takes_the_per_polygon_kernel():
    polygons = [[[(0.3, 0.1), (9.7, 2.9), (4.4, 8.6)]], [[(1, 1), (7, 1.5), (7, 7), (1, 6)]]]
    for arithmetic in ("float64", "float32"):
        options = {"arithmetic": arithmetic}
        assert np.array_equal(scanline_fill_many(polygons, (10, 10), options=options),
                              per_polygon(polygons, (10, 10), options))


def test_coordinates_at_the_limit_stay_exact_and_beyond_it_are_refused():
    m = 2.0 ** 20
    far = [[(-m, -m), (m, -m + 0.5), (3.25, m)], [(1.5, 1.5), (6, 2), (2, 7)]]
    check([far], (9, 9), whole_box=False)
    check([far], (9, 9), "nonzero", whole_box=False)
    with pytest.raises(InputError):
        scanline_fill_many([[[(0, 0), (m + 1, 0), (0, 1)]]], (4, 4))


def test_no_polygons_and_nan_coordinates():
    for nothing in ([], np.zeros((0, 5, 2)), np.zeros((3, 0, 2)), [[], [[]]]):
        assert not scanline_fill_many(nothing, (4, 4)).any()
    with pytest.raises(InputError):
        scanline_fill_many([[[(0, 0), (float("nan"), 0), (0, 1)]]], (4, 4))


def test_bad_rule_and_canvas_are_refused():
    square = [[[(0, 0), (2, 0), (2, 2)]]]
    with pytest.raises(InputError):
        scanline_fill_many(square, (4, 4), options={"fill_rule": "odd"})
    with pytest.raises(ValueError):
        scanline_fill_many(square, (4, 4), np.zeros((4, 5), np.uint8))
