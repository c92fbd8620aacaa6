"""polygon-scanline against the exact oracle, its fast kernel and its own frames.

The oracle (algorithms/exact/polygons.py) decides every pixel centre of the
bounding box on its own, with integer orientation tests and half-open
rules; it shares no code with the algorithms/polygons package.
"""
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import polygons as oracle
from algorithms.polygons import SCANLINE, scanline_mask, scanline_pixels
from algorithms.core.registry import InputError
from algorithms.core.steps import PLOT, Span, Start, Table
from algorithms.core.trace import Trace
from tests.support import record
from test_polygons_cases import generator_pixels, kernel_pixels, polygon
from tests.support.trace_oracle import slow_replay

RULES = ("evenodd", "nonzero")

# Named hard cases: (name, contours).
NAMED = [
    ("triangle", [[(1, 1), (9, 3), (5, 9)]]),
    ("horizontal bottom and top edges", [[(2, 2), (10, 2), (10, 8), (2, 8)]]),
    ("square on pixel centres", [[(1.5, 1.5), (6.5, 1.5), (6.5, 6.5), (1.5, 6.5)]]),
    ("vertices on scan lines", [[(2, 1.5), (8, 4.5), (4, 7.5), (6, 4.5)]]),
    ("local minimum and maximum on a scan line", [[(1, 4.5), (5, 1.5), (9, 4.5), (5, 7.5)]]),
    ("pentagram", [[(10, 1), (15.9, 18.1), (0.5, 7.5), (19.5, 7.5), (4.1, 18.1)]]),
    ("square with a hole (hole reversed)",
     [[(1, 1), (15, 1), (15, 15), (1, 15)], [(5, 5), (5, 11), (11, 11), (11, 5)]]),
    ("square with a hole (same orientation)",
     [[(1, 1), (15, 1), (15, 15), (1, 15)], [(5, 5), (11, 5), (11, 11), (5, 11)]]),
    ("collinear points", [[(1, 1), (4, 1), (7, 1), (7, 4.5), (7, 8), (4, 8), (1, 8), (1, 4.5)]]),
    ("zero-area polygon", [[(1, 1), (8, 8), (4.5, 4.5)]]),
    ("zero-area flat polygon", [[(1, 3.5), (8, 3.5), (4, 3.5)]]),
    ("bow tie", [[(1, 1), (9, 9), (9, 1), (1, 9)]]),
    ("comb with horizontal teeth tops",
     [[(1, 1), (13, 1), (13, 9), (11, 9), (11, 4), (9, 4), (9, 9), (7, 9), (7, 4), (5, 4),
       (5, 9), (3, 9), (3, 4), (1, 4)]]),
    ("sliver thinner than a pixel", [[(1, 1.2), (20, 1.6), (20, 1.7)]]),
    ("repeated vertices", [[(1, 1), (1, 1), (8, 2), (8, 2), (5, 8)]]),
    ("vertex exactly on a pixel centre", [[(3.5, 3.5), (9.5, 1.5), (7.5, 7.5)]]),
    ("two overlapping squares", [[(1, 1), (7, 1), (7, 7), (1, 7)], [(4, 4), (10, 4), (10, 10), (4, 10)]]),
    ("negative coordinates", [[(-3.25, -2.5), (4.5, -1), (0.5, 5.75)]]),
]


def oracle_pixels(contours, rule):
    return oracle.covered_pixels(contours, rule)


@pytest.mark.parametrize("rule", RULES)
@pytest.mark.parametrize("name, contours", NAMED, ids=[name for name, _ in NAMED])
def test_named_cases_match_the_oracle(name, contours, rule):
    pixels = generator_pixels(SCANLINE, contours, {"fill_rule": rule})
    assert len(pixels) == len(set(pixels)), "a pixel was written twice"
    assert set(pixels) == oracle_pixels(contours, rule)
    assert kernel_pixels(SCANLINE, contours, {"fill_rule": rule}) == pixels


def test_oracle_numpy_and_plain_integer_versions_agree():
    for _, contours in NAMED:
        for rule in RULES:
            assert oracle.covered_pixels(contours, rule) == oracle.covered_pixels_slowly(contours, rule)


def test_hand_checked_triangle():
    # Row 1 (centre line y = 1.5): the left edge (1,1)-(5,9) is at x = 1.25, the
    # right edge (1,1)-(9,3) at x = 3: centres 1.5 and 2.5, pixels 1 and 2.
    pixels = generator_pixels(SCANLINE, [[(1, 1), (9, 3), (5, 9)]])
    assert [p for p in pixels if p[1] == 1] == [(1, 1), (2, 1)]
    assert [p for p in pixels if p[1] == 2] == [(2, 2), (3, 2), (4, 2), (5, 2), (6, 2)]


def test_square_on_centres_takes_left_and_bottom_edges_only():
    # Centres on the left edge x = 1.5 and the bottom edge y = 1.5 are in; on the
    # right edge x = 6.5 and the top edge y = 6.5 out: 5 x 5 pixels from (1, 1).
    pixels = set(generator_pixels(SCANLINE, [[(1.5, 1.5), (6.5, 1.5), (6.5, 6.5), (1.5, 6.5)]]))
    assert pixels == {(i, j) for i in range(1, 6) for j in range(1, 6)}


def test_pentagram_centre_differs_between_the_rules():
    star = NAMED[5][1]
    evenodd = set(generator_pixels(SCANLINE, star, {"fill_rule": "evenodd"}))
    nonzero = set(generator_pixels(SCANLINE, star, {"fill_rule": "nonzero"}))
    assert (10, 9) in nonzero and (10, 9) not in evenodd
    assert evenodd < nonzero


@settings(max_examples=250)
@given(polygon(), st.sampled_from(RULES))
def test_random_polygons_match_the_oracle(contours, rule):
    pixels = generator_pixels(SCANLINE, contours, {"fill_rule": rule})
    assert len(pixels) == len(set(pixels))
    assert set(pixels) == oracle_pixels(contours, rule)


@settings(max_examples=250)
@given(polygon(), st.sampled_from(RULES))
def test_fast_kernel_gives_the_generator_pixels_in_order(contours, rule):
    options = {"fill_rule": rule}
    assert kernel_pixels(SCANLINE, contours, options) == generator_pixels(SCANLINE, contours, options)


@settings(max_examples=150)
@given(polygon(), st.sampled_from(RULES), st.integers(-6, 6), st.integers(-6, 6),
       st.integers(1, 30), st.integers(1, 30))
def test_grid_mask_is_the_clipped_pixel_set(contours, rule, x0, y0, width, height):
    options = {"fill_rule": rule}
    mask = scanline_mask(contours, options, (width, height), (x0, y0))
    expected = {(x - x0, y - y0) for x, y in oracle_pixels(contours, rule)
                if x0 <= x < x0 + width and y0 <= y < y0 + height}
    ys, xs = np.nonzero(mask)
    assert set(zip(xs.tolist(), ys.tolist())) == expected


@settings(max_examples=200)
@given(polygon())
def test_evenodd_and_nonzero_differ_exactly_where_the_winding_is_even_and_not_zero(contours):
    evenodd = set(kernel_pixels(SCANLINE, contours, {"fill_rule": "evenodd"}))
    nonzero = set(kernel_pixels(SCANLINE, contours, {"fill_rule": "nonzero"}))
    winding, i0, j0 = oracle.winding_grid(oracle.snap_polygon(contours))
    js, is_ = np.nonzero((winding != 0) & (winding % 2 == 0))
    assert evenodd ^ nonzero == {(int(i) + i0, int(j) + j0) for i, j in zip(is_, js)}


def test_winding_two_is_filled_only_by_nonzero():
    # The same square twice, one orientation: winding 2 everywhere inside.
    square = [(1, 1), (6, 1), (6, 6), (1, 6)]
    assert generator_pixels(SCANLINE, [square, square], {"fill_rule": "evenodd"}) == []
    assert len(generator_pixels(SCANLINE, [square, square], {"fill_rule": "nonzero"})) == 25


# ------------------------------------------------------- snapping
def test_vertices_snap_to_the_256th_grid():
    # 1/512 apart: both snap to the same 1/256 step (halves go to even).
    a = generator_pixels(SCANLINE, [[(1.5 + 1 / 512, 1), (9, 3), (5, 9)]])
    b = generator_pixels(SCANLINE, [[(1.5, 1), (9, 3), (5, 9)]])
    assert a == b
    assert oracle.snap(1.5 + 1 / 512) == 384 and oracle.snap(1.5 + 3 / 512) == 386


def test_coordinates_beyond_the_limit_are_refused():
    with pytest.raises(InputError, match="within"):
        list(SCANLINE.frames([[(0, 0), (2e7, 0), (0, 5)]]))


# ------------------------------------------------------- arithmetic option
HALF_GRID = st.lists(st.lists(st.tuples(st.integers(0, 400), st.integers(0, 400))
                              .map(lambda p: (p[0] / 2, p[1] / 2)), min_size=3, max_size=6),
                     min_size=1, max_size=2)


def near_boundary(contours, pixels, epsilon):
    """Is every pixel's centre closer than epsilon to an edge?"""
    snapped = oracle.snap_polygon(contours)
    return all(oracle.distance_squared_to_boundary(snapped, *oracle.centre(i, j)) < Fraction(epsilon) ** 2
               for i, j in pixels)


@settings(max_examples=120)
@given(HALF_GRID, st.sampled_from(RULES))
def test_float64_agrees_with_exact_except_at_centres_on_an_edge(contours, rule):
    exact = set(kernel_pixels(SCANLINE, contours, {"fill_rule": rule}))
    floats = set(kernel_pixels(SCANLINE, contours, {"fill_rule": rule, "arithmetic": "float64"}))
    assert near_boundary(contours, exact ^ floats, 1e-9)


def test_a_float64_case_that_disagrees():
    # The left edge (12, 18.5)-(101, 166.5) runs exactly through the centre
    # (56.5, 92.5), 148 rows up; 1/m = 89/148 added up in float64 misses it.
    contours = [[(82.5, 38.5), (101.0, 166.5), (12.0, 18.5)]]
    exact = set(generator_pixels(SCANLINE, contours))
    floats = set(generator_pixels(SCANLINE, contours, {"arithmetic": "float64"}))
    assert exact ^ floats == {(56, 92)}
    assert oracle.on_boundary(oracle.snap_polygon(contours), *oracle.centre(56, 92))


def test_float32_disagrees_at_large_coordinates():
    contours = [[(3959.3203125, 682.94140625), (3523.53125, 9.19140625), (3693.68359375, 344.125)]]
    exact = set(kernel_pixels(SCANLINE, contours))
    float64 = set(kernel_pixels(SCANLINE, contours, {"arithmetic": "float64"}))
    float32 = set(kernel_pixels(SCANLINE, contours, {"arithmetic": "float32"}))
    assert float64 == exact
    differ = exact ^ float32
    assert len(differ) > 10
    # Still only near the edges: float32 resolves 1/4096 px at x ~ 4000, and the
    # rounding of hundreds of additions drifts by a few hundredths of a pixel.
    assert near_boundary(contours, differ, 0.05)


@pytest.mark.parametrize("arithmetic", ("float64", "float32"))
def test_kernel_follows_the_generator_in_float_arithmetic(arithmetic):
    cases = [c for _, c in NAMED] + [
        [[(3959.3203125, 682.94140625), (3523.53125, 9.19140625), (3693.68359375, 344.125)]],
        [[(82.5, 38.5), (101.0, 166.5), (12.0, 18.5)]]]
    for contours in cases:
        for rule in RULES:
            options = {"fill_rule": rule, "arithmetic": arithmetic}
            assert kernel_pixels(SCANLINE, contours, options) == generator_pixels(SCANLINE, contours, options)


# ------------------------------------------------------- frames
def test_frames_show_every_phase():
    trace = record(SCANLINE.name, NAMED[6][1], {"fill_rule": "nonzero"})
    code = trace.code
    records = [trace.record_at(i) for i in range(len(trace))]
    assert isinstance(records[0], Start)
    tables = [(i, r) for i, r in enumerate(records) if isinstance(r, Table)]
    assert tables[0][1].name == "ET"
    et = tables[0][1]
    assert et.columns == ("ymin", "edge", "ymax", "x", "1/m", "dir")
    # 8 edges, 4 of them horizontal and left out.
    assert len(et.rows) == 4
    sorted_aets = [r for _, r in tables if r.name == "AET" and code[r.line].text.strip()
                   .startswith("sort")]
    # Rows 1 .. 14 carry the polygon, plus the last pass that empties the AET.
    assert len(sorted_aets) == 15
    for table in sorted_aets:
        xs = [row[2] for row in table.rows]
        assert xs == sorted(xs)
    spans = [r for r in records if isinstance(r, Span)]
    assert spans and all(code[s.line].kind == PLOT for s in spans)
    # Every line has frames, the loop header included (it sets y).
    assert set(trace.line.tolist()) == set(range(len(code)))


def _line_named(trace, start: str) -> int:
    return next(k for k, line in enumerate(trace.code) if line.text.strip().startswith(start))


SHAPES = [NAMED[0][1], NAMED[5][1], NAMED[6][1], [[(2.25, 2), (28, 3.5), (20, 20.75)]]]


@pytest.mark.parametrize("arithmetic", ["exact", "float64"])
@pytest.mark.parametrize("contours", SHAPES)
def test_aet_x_values_change_at_the_step_that_adds_one_over_m(contours, arithmetic):
    # The x += 1/m line is on show exactly when the AET's x values move,
    # and each moves by its own 1/m (worked out here from the table before).
    trace = record(SCANLINE.name, contours, {"arithmetic": arithmetic}, grid=(32, 24))
    step_x = _line_named(trace, "for each edge in the AET: x += 1/m")
    aets = [(i, r) for i, r in trace.records_of(Table) if r.name == "AET"]
    assert any(int(trace.line[i]) == step_x for i, _ in aets)
    for (_, before), (i, after) in zip(aets, aets[1:]):
        old = {row[0]: (row[2], row[3]) for row in before.rows}
        new = {row[0]: row[2] for row in after.rows}
        moved = {edge for edge in new if edge in old and new[edge] != old[edge][0]}
        if int(trace.line[i]) == step_x:
            assert set(new) == set(old)
            assert all(new[edge] == old[edge][0] + old[edge][1] for edge in new)
        else:
            assert not moved, (i, moved)


@pytest.mark.parametrize("contours", SHAPES)
def test_edge_table_empties_as_edges_move_to_the_aet(contours):
    trace = record(SCANLINE.name, contours, grid=(32, 24))
    ets = [r for _, r in trace.records_of(Table) if r.name == "ET"]
    sizes = [len(r.rows) for r in ets]
    assert sizes[0] > 0 and sizes[-1] == 0
    assert sizes == sorted(sizes, reverse=True)
    # An edge leaves the ET at the step it enters the AET, never before.
    first_row = {row[1]: row[0] for row in ets[0].rows}
    for i, table in trace.records_of(Table)[1:]:
        if table.name == "ET":
            y = trace.variables_at(i)["y"]
            assert {row[1] for row in table.rows} == {edge for edge, ymin in first_row.items()
                                                      if ymin > y}


@pytest.mark.parametrize("contours", SHAPES)
def test_y_and_the_aet_size_hold_on_every_step_of_the_loop(contours):
    trace = record(SCANLINE.name, contours, grid=(32, 24))
    first = _line_named(trace, "AET = empty")
    begin = int(np.flatnonzero(trace.line == first)[0])
    rows_filled = {}
    for i in range(begin, len(trace)):
        values = trace.variables_at(i)
        assert "y" in values and "active" in values, i
        record_ = trace.record_at(i)
        if isinstance(record_, Span):
            rows_filled[record_.y] = values["y"]
    # A span's row is the y the panel shows at its step.
    assert rows_filled and all(y == shown for y, shown in rows_filled.items())


def test_aet_rows_are_exact_fractions():
    trace = record(SCANLINE.name, [[(1, 1), (9, 3), (5, 9)]])
    et = next(r for _, r in trace.records_of(Table) if r.name == "ET")
    # Edge P1P2 from (1, 1) to (9, 3): 1/m = 4, x at the centre line y = 1.5 is 3.
    row = next(row for row in et.rows if row[1] == "P1P2")
    assert row == (1, "P1P2", 3, 3, 4)
    assert any(isinstance(cell, Fraction) for row in et.rows for cell in row)


def test_trace_pixels_are_the_generator_pixels():
    for _, contours in NAMED[:8]:
        trace = record(SCANLINE.name, contours, grid=(40, 40))
        assert [tuple(p) for p in trace.written_pixels().tolist()] == generator_pixels(SCANLINE, contours)


@pytest.mark.parametrize("contours", [NAMED[6][1], [[(-3.5, 2), (40, 5.5), (10, 30)]]])
def test_state_at_equals_a_slow_replay(contours):
    trace = record(SCANLINE.name, contours, {"fill_rule": "nonzero"}, grid=(20, 18))
    assert len(trace.spans())
    for i in range(len(trace)):
        assert np.array_equal(trace.state_at(i).raster.counts, slow_replay(trace, i).counts), i


def test_state_at_equals_a_slow_replay_across_keyframes():
    # Enough frames for several keyframes.
    contours = [[(0.3, 0.2), (250, 3), (120, 499.5)], [(60, 60), (70, 200), (90, 90)]]
    trace = SCANLINE.record(contours, {}, grid=(256, 512))
    assert len(trace) > 3000
    for i in list(range(0, len(trace), 397)) + [len(trace) - 1]:
        assert np.array_equal(trace.state_at(i).raster.counts, slow_replay(trace, i).counts)


def test_explain_names_the_pair_of_a_span():
    trace = record(SCANLINE.name, [[(1, 1), (9, 3), (5, 9)]])
    index = int(trace.steps_of(Span)[0])
    rows = dict(SCANLINE.panel_rows(trace, index))
    assert rows["run"].startswith("x_left = 5/4")
    assert rows["pixels"].endswith("i = 1 .. 2")


def test_trace_records_cleanly():
    for _, contours in NAMED:
        for rule in RULES:
            trace = Trace.record(SCANLINE.frames(contours, {"fill_rule": rule}),
                                 SCANLINE.code(SCANLINE.inputs.check(contours),
                                               SCANLINE.resolve({"fill_rule": rule})), 32, 24)
            assert trace.final_variables()["pixels"] == len(oracle_pixels(contours, rule))


# ------------------------------------------------------- the fast kernel's bounds
def test_kernel_on_an_empty_and_a_large_polygon():
    assert scanline_pixels([[(1, 1), (8, 8), (4.5, 4.5)]]).shape == (0, 2)
    big = [[(0.25, 0.75), (2047.5, 13.1), (1800.3, 2047.9), (900, 400)]]
    mask = scanline_mask(big, {}, (2048, 2048))
    winding, i0, j0 = oracle.winding_grid(oracle.snap_polygon(big), (0, 0, 2048, 2048))
    assert np.array_equal(mask, winding % 2 == 1)


def test_oracle_outline_grid_matches_the_exact_distance():
    for _, contours in NAMED:
        snapped = oracle.snap_polygon(contours)
        on, i0, j0 = oracle.outline_grid(snapped)
        for (j, i), value in np.ndenumerate(on):
            assert value == oracle.on_boundary(snapped, *oracle.centre(i + i0, j + j0))
