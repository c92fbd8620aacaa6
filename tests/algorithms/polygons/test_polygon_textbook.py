"""The brute-force scan line and the X_low edge table, against the exact
polygon oracle, and the brute force's cost against the edge table's."""
from __future__ import annotations

import math
from fractions import Fraction

import pytest

from algorithms.core import registry
from algorithms.exact import polygons as exact
from algorithms.core.steps import Table

POLYGONS = {
    "triangle": [[(2, 2), (12, 3), (8, 9)]],
    "star": [[(10, 1), (12.5, 7.25), (19, 7.5), (13.75, 11.5), (15.5, 18), (10, 14),
              (4.5, 18), (6.25, 11.5), (1, 7.5), (7.5, 7.25)]],
    "bowtie": [[(2, 2), (18, 14), (18, 2), (2, 14)]],
    "with hole": [[(1, 1), (19, 1), (19, 15), (1, 15)], [(5, 5), (5, 10), (14, 10), (14, 5)]],
    "self-overlapping": [[(2, 2), (16, 2), (16, 12), (6, 12), (6, 6), (12, 6), (12, 16), (2, 16)]],
}


def pixels(name, contours, **options):
    trace = registry.get(name).record(contours, options, grid=(24, 20))
    return trace, [tuple(p) for p in trace.written_pixels().tolist()]


@pytest.mark.parametrize("shape", POLYGONS)
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_brute_force_fills_the_exact_polygon(shape, rule):
    trace, filled = pixels("polygon-brute-scanline", POLYGONS[shape], fill_rule=rule)
    assert len(filled) == len(set(filled))
    assert set(filled) == exact.covered_pixels(POLYGONS[shape], rule)


def sorted_aets(trace):
    """The AET as sorted for each row (the snapshot after x += 1/m is the next row's)."""
    return [(index, table) for index, table in trace.records_of(Table)
            if table.name == "AET" and trace.code[table.line].text.strip().startswith("sort")]


@pytest.mark.parametrize("shape", POLYGONS)
def test_brute_force_tests_every_edge_on_every_row_and_the_edge_table_fewer(shape):
    contours = POLYGONS[shape]
    trace, _ = pixels("polygon-brute-scanline", contours)
    ys = [y for contour in contours for _, y in contour]
    # Rows whose centre line y + 1/2 lies in [min y, max y).
    rows = math.ceil(max(ys) - 0.5) - math.ceil(min(ys) - 0.5)
    edges = sum(len(contour) for contour in contours)
    final = trace.final_variables()
    assert final["tests"] == rows * edges
    # The crossings it finds are the ones the edge table keeps active, row by row.
    et, _ = pixels("polygon-scanline", contours)
    active = sum(len(table.rows) for _, table in sorted_aets(et))
    assert final["crossings"] == active <= final["tests"]
    if shape == "star":  # ten edges, few of them on any one row
        assert 2 * active < final["tests"]


@pytest.mark.parametrize("shape", POLYGONS)
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_xlow_samples_each_pixel_at_its_bottom_edge(shape, rule):
    _, filled = pixels("polygon-scanline-xlow", POLYGONS[shape], fill_rule=rule)
    # A sample at (i + 1/2, j) is the centre rule on the polygon lifted by 1/2 px.
    lifted = [[(x, y + 0.5) for x, y in contour] for contour in POLYGONS[shape]]
    assert set(filled) == exact.covered_pixels(lifted, rule)


def test_xlow_table_holds_the_lower_end_points_x():
    trace, filled = pixels("polygon-scanline-xlow", POLYGONS["triangle"])
    table = next(t for _, t in trace.records_of(Table) if t.name == "ET")
    xs = {row[1]: row[3] for row in table.rows}  # edge label -> x
    assert xs == {"P3P1": 2, "P1P2": 2, "P2P3": 12}  # each edge's lower vertex
    _, centred = pixels("polygon-scanline", POLYGONS["triangle"])
    assert set(filled) != set(centred)


@pytest.mark.parametrize("shape", POLYGONS)
def test_integer_walk_fills_the_exact_polygon_and_keeps_x_as_whole_and_error(shape):
    contours = POLYGONS[shape]
    trace, filled = pixels("polygon-scanline-integer", contours)
    assert set(filled) == exact.covered_pixels(contours, "evenodd")
    edges = {}
    for contour_index, contour in enumerate(contours):
        for k, a in enumerate(contour):
            b = contour[(k + 1) % len(contour)]
            label = (f"C{contour_index + 1}." if len(contours) > 1 else "") + \
                f"P{k + 1}P{(k + 1) % len(contour) + 1}"
            edges[label] = (a, b)
    seen = 0
    for index, table in sorted_aets(trace):
        y = int(trace.variables_at(index)["y"])  # the row the AET was sorted for
        for label, _, (whole, error), _ in table.rows:
            num, over = map(int, error.split("/"))
            assert 0 <= num < over
            (ax, ay), (bx, by) = edges[label]
            line = Fraction(y) + Fraction(1, 2)  # the row's centre line, exactly
            x = Fraction(ax) + (line - Fraction(ay)) * Fraction(bx - ax) / Fraction(by - ay)
            assert whole + Fraction(num, over) == x
            seen += 1
    assert seen > 0


@pytest.mark.parametrize("shape", POLYGONS)
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_trapezoid_tessellation_fills_any_polygon_exactly(shape, rule):
    trace, filled = pixels("polygon-tessellate-any", POLYGONS[shape], fill_rule=rule)
    assert len(filled) == len(set(filled)), "two triangles share a pixel"
    assert set(filled) == exact.covered_pixels(POLYGONS[shape], rule)
    final = trace.final_variables()
    assert final["triangles"] >= 1 and final["pixels"] == len(filled)


@pytest.mark.parametrize("shape", ["bowtie", "with hole"])
def test_ear_clipping_refuses_what_the_trapezoids_tessellate(shape):
    from algorithms.core.errors import InputError
    with pytest.raises(InputError):
        registry.get("polygon-tessellate").record(POLYGONS[shape], {}, grid=(24, 20))
    trace, _ = pixels("polygon-tessellate-any", POLYGONS[shape])
    cuts = next(t for _, t in trace.records_of(Table) if t.name == "cuts")
    ys = sorted({y for contour in POLYGONS[shape] for _, y in contour})
    if shape == "bowtie":  # the two diagonals cross at (10, 8): a cut there too
        ys = sorted(ys + [8])
    assert [row[0] for row in cuts.rows] == ys
