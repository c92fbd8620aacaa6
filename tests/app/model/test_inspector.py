"""The pixel inspector: its values against oracles written for the tests
(exact fractions from the vertices, an independent scan of the frames,
shapely's areas). The dock in the window: tests/app/gui/test_inspector_dock.py."""
from fractions import Fraction

import pytest
from shapely.geometry import Polygon, box

from algorithms.core import registry
from algorithms.core.steps import PLOT, VISIT, Span, Vars
from app.model.inspector import PixelInspector, inspect, rows_by_label
from tests.support.inspector_oracles import GRID, TRIANGLE, assert_weight, edge_values, snapped


def run(name, points, options=None, grid=GRID):
    spec = registry.get(name)
    options = spec.resolve(options or {})
    return spec, options, spec.record(points, options, grid)


def rows_at(name, points, pixel, options=None, index=-1):
    spec, options, trace = run(name, points, options)
    index = index % len(trace)
    return rows_by_label(inspect(trace, index, pixel, spec, points, options, GRID)), trace


# ------------------------------------------------------------ triangles
@pytest.mark.parametrize("pixel", [(5, 4), (3, 2), (9, 6), (1, 1), (6, 10)])
def test_edges_and_weights_are_the_exact_ones(pixel):
    rows, _ = rows_at("triangle-bbox", TRIANGLE, pixel)
    vertices = snapped(TRIANGLE)
    es = edge_values(vertices, pixel)
    for k in range(3):
        assert Fraction(rows[f"e{k}"].split()[0]) == es[k]
    total = sum(es)
    for name, e in zip(("alpha", "beta", "gamma"), es):
        assert_weight(rows[name], e / total)
    inside = all(e > 0 for e in es)
    assert rows["centre inside"] == ("yes" if inside else "no")


def test_clockwise_input_names_the_vertices_as_the_run_swapped_them():
    clockwise = [TRIANGLE[0], TRIANGLE[2], TRIANGLE[1]]
    rows, _ = rows_at("triangle-bbox", clockwise, (5, 4))
    # The run swaps P1 and P2, so P0 P1 P2 are the counter-clockwise order.
    es = edge_values(snapped(TRIANGLE), (5, 4))
    assert [Fraction(rows[f"e{k}"].split()[0]) for k in range(3)] == es


def test_perspective_weights_with_w():
    w = [1, 2, 4]
    rows, _ = rows_at("triangle-perspective", TRIANGLE, (6, 5), {"w": w, "z": [0.1, 0.5, 0.9]})
    es = edge_values(snapped(TRIANGLE), (6, 5))
    f = [e / sum(es) / wk for e, wk in zip(es, w)]
    for name, value in zip(("alpha_p", "beta_p", "gamma_p"), f):
        assert_weight(rows[name], value / sum(f))
    z = sum(e / sum(es) * Fraction(zk) for e, zk in zip(es, (0.1, 0.5, 0.9)))
    assert float(rows["fragment depth"].split()[0]) == float(z)


def test_a_line_run_shows_no_triangle_values():
    rows, _ = rows_at("line-bresenham", [(1, 1), (14, 6)], (4, 2))
    assert not {"e0", "alpha", "fragment depth", "coverage"} & set(rows)


# ------------------------------------------------------------ depth
ZSCENE = [(1.0, 1.0), (14.0, 2.0), (4.0, 12.0), (2.0, 9.0), (6.0, 0.5), (13.0, 11.0)]
ZS = [0.8, 0.6, 0.9, 0.2, 0.7, 0.5]


def exact_depth(tri, zs, pixel):
    es = edge_values(snapped(tri), pixel)
    assert all(e > 0 for e in es), "the probe must lie inside the triangle"
    return float(sum(e * Fraction(z) for e, z in zip(es, zs)) / sum(es))


def test_zbuffer_fragment_and_stored_depth():
    pixel = (6, 5)
    spec, options, trace = run("zbuffer", ZSCENE, {"z": ZS})
    first, second = exact_depth(ZSCENE[:3], ZS[:3], pixel), exact_depth(ZSCENE[3:], ZS[3:], pixel)
    # Triangle 2 starts at its Vars record; just before it only triangle 1 is drawn.
    start2 = min(i for i, r in trace.records_of(Vars) if r.values.get("triangle") == 2)
    before = rows_by_label(inspect(trace, start2 - 1, pixel, spec, ZSCENE, options, GRID))
    assert float(before["fragment depth"].split()[0]) == first
    assert float(before["stored depth"]) == first
    end = rows_by_label(inspect(trace, len(trace) - 1, pixel, spec, ZSCENE, options, GRID))
    assert float(end["fragment depth"].split()[0]) == second
    assert float(end["stored depth"]) == min(first, second)  # depth test "less", far = 1
    at_start = rows_by_label(inspect(trace, 0, pixel, spec, ZSCENE, options, GRID))
    assert at_start["stored depth"].startswith("clear")


# ------------------------------------------------------ visits, plots
def scan(trace, pixel, index):
    """Visits and plots of the pixel up to index, one frame at a time."""
    visits, plots = [], []
    for k in range(index + 1):
        step = trace.step(k)
        record = step.record
        if isinstance(record, Span):
            cells = [(x, record.y) for x in range(record.x_start, record.x_end)]
        elif record is None and step.pixel is not None:
            cells = [step.pixel]
        else:
            continue
        if pixel in cells and step.kind in (VISIT, PLOT):
            visits.append(k)
            if step.kind == PLOT:
                plots.append(k)
    return visits, plots


def describe(steps):
    if not steps:
        return "never"
    if len(steps) == 1:
        return f"once, step {steps[0]:,}"
    return f"{len(steps):,} times, steps {steps[0]:,} \u2026 {steps[-1]:,}"


@pytest.mark.parametrize("name, points, options, pixel", [
    ("line-bresenham", [(1, 1), (14, 6)], {}, (5, 3)),
    ("line-wu", [(1, 1), (14, 6)], {}, (5, 3)),
    ("flood-fill", [[(1, 1), (12, 1), (12, 10), (1, 10)]], {"seed": (5, 5)}, (5, 6)),
    ("polygon-scanline", [[(1.5, 1.0), (13.0, 4.5), (4.0, 12.0)]], {}, (5, 6)),
])
def test_visit_and_plot_steps_match_a_scan_of_the_frames(name, points, options, pixel):
    spec, options, trace = run(name, points, options)
    flat = points[0] if isinstance(points[0], list) else points
    inspector = PixelInspector(trace, spec, flat, options, GRID)
    for index in (len(trace) // 3, len(trace) // 2, len(trace) - 1):
        visits, plots = scan(trace, pixel, index)
        got_visits, got_plots = inspector.steps_at(pixel, index)
        assert list(got_visits) == visits and list(got_plots) == plots
        rows = rows_by_label(inspector.rows(index, pixel))
        assert rows["visited"] == describe(visits)
        assert rows["plotted"] == describe(plots)
        if visits:
            line = trace.code[int(trace.line[visits[-1]])]
            assert rows["last visit"].endswith(line.text.strip())
    assert plots, "the probe must be plotted by the end"


# ------------------------------------------------------ antialiasing
AA_TRIANGLE = [(3.25, 2.5), (12.5, 5.75), (6.125, 11.25)]  # on the 1/256 grid


def last_value(trace, pixel, index):
    value = 0.0
    for k in range(index + 1):
        step = trace.step(k)
        if step.writes and step.pixel == pixel:
            value = step.values[trace.start.pixel_value]
    return value


@pytest.mark.parametrize("pixel", [(3, 3), (4, 5), (8, 4), (6, 10), (11, 7)])
def test_exact_coverage_is_shapelys_area_and_error_is_the_difference(pixel):
    spec, options, trace = run("aa-supersample", AA_TRIANGLE, {"n": 4})
    index = len(trace) - 1
    rows = rows_by_label(inspect(trace, index, pixel, spec, AA_TRIANGLE, options, GRID))
    area = Polygon(AA_TRIANGLE).intersection(box(pixel[0], pixel[1], pixel[0] + 1,
                                                 pixel[1] + 1)).area
    assert float(rows["exact coverage"]) == pytest.approx(area, abs=1e-12)
    assert 0 < area < 1, "the probe must straddle an edge"
    coverage = last_value(trace, pixel, index)
    assert float(rows["coverage"]) == coverage
    assert float(rows["error"].split()[0]) == pytest.approx(coverage - area, abs=1e-12)
    hits, tested = rows["hit / tested"].split(" = ")[0].split(" / ")
    assert int(tested) == 16  # n = 4: a 4 x 4 grid of samples


def test_samples_follow_the_step():
    pixel = (5, 5)
    spec, options, trace = run("aa-supersample", AA_TRIANGLE, {"n": 4})
    inspector = PixelInspector(trace, spec, AA_TRIANGLE, options, GRID)
    visits, _ = inspector.steps_at(pixel, len(trace) - 1)
    middle = int(visits[7])  # the pixel's eighth sample
    rows = rows_by_label(inspector.rows(middle, pixel))
    sx, sy, hit = (trace.series(n) for n in ("sx", "sy", "hit"))
    samples = [k for k in range(middle + 1) if trace.step(k).pixel == pixel
               and sx[k] == sx[k]]
    assert rows["hit / tested"].startswith(f"{sum(hit[k] > 0 for k in samples)} / {len(samples)}")
    assert rows["coverage"] == "0.0"  # not written yet at this step


def test_a_float_run_shows_its_own_edge_values_beside_the_exact_ones():
    rows, trace = rows_at("triangle-bbox", TRIANGLE, (5, 4), {"precision": "float32"})
    es = edge_values(snapped(TRIANGLE), (5, 4))
    assert [Fraction(rows[f"e{k}"].split()[0]) for k in range(3)] == es
    own = rows["e0 e1 e2 (float32)"].split()[:3]
    last = max(k for k in range(len(trace)) if trace.step(k).pixel == (5, 4)
               and trace.step(k).kind in (VISIT, PLOT))
    assert [float(v) for v in own] == [trace.step(last).values[f"e{k}"] for k in range(3)]
