"""Operation counts from executed pseudo-code lines, and the report's own error measures."""
from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from algorithms.exact import lines as exact, triangles as exact_triangles
from app.analysis import measure
from algorithms.core import registry
from algorithms.core.steps import OP_NAMES, CodeLine


def test_bresenham_counts_follow_its_lines():
    # dx = 10, dy = 3: ten steps, each E (2 additions) or NE (3), two tests each.
    spec = registry.get("line-bresenham")
    trace = spec.record(((0, 0), (10, 3)))
    branches = [trace.code[line].branch for line in trace.line]
    east, north_east = branches.count("E"), branches.count("NE")
    assert (east, north_east) == (7, 3)
    counts = measure.op_counts(trace)
    assert counts["int_add"] == 5 + 2 + 2 * east + 3 * north_east
    assert counts["compare"] == 3 + 2 * 10
    assert counts["mul"] == counts["div"] == counts["float_add"] == counts["sqrt"] == 0
    assert measure.total_ops(counts) == counts["int_add"] + counts["compare"]


def test_counts_are_deterministic_and_scale_with_the_work():
    spec = registry.get("line-dda")
    short = measure.op_counts(spec.record(((0, 0), (100, 37))))
    long = measure.op_counts(spec.record(((0, 0), (1000, 370))))
    assert short == measure.op_counts(spec.record(((0, 0), (100, 37))))
    # Per step: two float additions, two roundings, the loop's counter and test.
    assert long["float_add"] - short["float_add"] == 2 * 900
    assert long["round"] - short["round"] == 2 * 900


def test_span_pixels_and_active_edges_are_counted():
    spec = registry.get("polygon-scanline")
    square = (((0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)),)
    trace = spec.record(square)
    counts = measure.op_counts(trace)
    # 10 rows of 10 pixels: a step and a test per pixel, two roundings per span;
    # two active edges per row, each stepped exactly (two additions and a carry test).
    pixels, rows = 100, 10
    # Roundings: two per span, two per snapped vertex, two per edge set up (the
    # two horizontal edges meet no scan line and are left out of the table).
    assert counts["round"] == 2 * rows + 2 * 4 + 2 * 2
    assert counts["int_add"] >= pixels + 2 * 2 * rows
    wider = measure.op_counts(spec.record((((0.0, 0.0), (20.0, 0.0), (20.0, 10.0),
                                            (0.0, 10.0)),)))
    assert wider["int_add"] - counts["int_add"] == 100  # only the pixels grew
    assert wider["compare"] - counts["compare"] == 100


def test_notes_count_nothing():
    spec = registry.get("triangle-bbox")
    drawn = measure.op_counts(spec.record([(1.0, 1.0), (9.0, 2.0), (4.0, 8.0)], {}, (12, 12)))
    with_degenerate = measure.op_counts(spec.record(
        [(1.0, 1.0), (9.0, 2.0), (4.0, 8.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)], {}, (12, 12)))
    # The degenerate triangle costs its snap and area test only (a Vars frame);
    # its Note adds nothing.
    snap = registry.get("triangle-bbox").code([], registry.get("triangle-bbox").resolve({}))
    snap_ops = next(line.ops for line in snap if line.text.strip().startswith("snap"))
    for name in OP_NAMES:
        assert with_degenerate[name] - drawn[name] == snap_ops.get(name, 0)


def test_every_line_of_every_algorithm_names_known_operations():
    for spec in registry.all_specs():
        if spec.family not in ("lines", "circles", "polygons", "fill", "triangles"):
            continue
        points = {"lines": ((1, 2), (9, 5)), "circles": ((4, 4),),
                  "polygons": (((1.0, 1.0), (9.0, 2.0), (4.0, 8.0)),),
                  "fill": (((1, 1), (9, 2), (4, 8)),),
                  "triangles": ((1.0, 1.0), (9.0, 2.0), (4.0, 8.0))}[spec.family]
        if spec.inputs.count == 1:
            points = ((6, 6),)  # a circle's centre (a seed fill inside a circle too)
        if spec.inputs.count == 4:
            points = ((1, 1), (3, 9), (8, 9), (10, 1))  # a Bezier curve's control points
        trace = spec.record(points, {}, (12, 12))
        counts = measure.op_counts(trace)
        assert measure.total_ops(counts) > 0, spec.name
    with pytest.raises(ValueError):
        CodeLine("x", ops={"flops": 1})
    with pytest.raises(ValueError):
        CodeLine("x", ops={"int_add": -1})


@pytest.mark.parametrize("seed", range(5))
def test_exact_cover_agrees_with_the_triangle_oracle(seed):
    rng = np.random.default_rng(seed)
    triangle = [(float(rng.uniform(0, 12)), float(rng.uniform(0, 12))) for _ in range(3)]
    if seed == 0:
        triangle = [(1.5, 1.5), (9.5, 1.5), (1.5, 9.5)]  # edges through pixel centres
    for rule in ("top-left", "inclusive", "strict"):
        mask = measure.exact_cover(triangle, (0, 0, 12, 12), rule)
        snapped = [(Fraction(x), Fraction(y)) for x, y in triangle]
        expected = {(i, j) for j in range(12) for i in range(12)
                    if exact_triangles.covers(snapped, exact_triangles.centre(i, j), rule)}
        got = {(int(i), int(j)) for j, i in zip(*np.nonzero(mask))}
        assert got == expected, rule


def test_line_errors_against_the_exact_nearest_line():
    p, q = (0, 0), (12, 5)
    nearest = exact.nearest_pixel_line(p, q)
    assert measure.line_errors(p, q, nearest)["differing"] == 0
    moved = list(nearest)
    moved[3] = (moved[3][0], moved[3][1] + 1)
    errors = measure.line_errors(p, q, moved)
    assert (errors["differing"], errors["missed"], errors["extra"]) == (2, 1, 1)
    assert measure.line_errors(p, q, nearest + [nearest[4]])["duplicates"] == 1
    gappy = nearest[:5] + nearest[7:]
    assert measure.line_errors(p, q, gappy)["gaps"] == 1


def test_pareto_front():
    points = [(1, 0.1, "a"), (4, 0.05, "b"), (4, 0.2, "c"), (16, 0.06, "d"), (64, 0.01, "e")]
    assert [label for _, _, label in measure.pareto_front(points)] == ["a", "b", "e"]


# ------------------------------------- operation counts of antialiasing and visibility
def test_every_algorithm_has_counted_operations():
    for spec in registry.all_specs():
        points = spec.inputs.example if hasattr(spec.inputs, "example") else None
        code = None
        for sample in (points, [(1, 1), (7, 1), (1, 6)], [(1, 1), (7, 3)], [(4.0, 4.0)]):
            if sample is None:
                continue
            try:
                code = spec.code(sample, spec.resolve({}))
                break
            except Exception:
                continue
        assert code is not None, spec.name
        assert any(line.ops or line.per for line in code), spec.name
        assert any(line.ops for line in code), spec.name


def test_supersample_counts_n_squared_samples_per_pixel_of_the_box():
    # The triangle's bounding box [1, 7] x [1, 6] reaches columns 1..7 and
    # rows 1..6 (the pixels whose squares it touches, the far edges
    # included): 7 * 6 pixels, each sampled n * n times.
    n = 3
    trace = registry.get("aa-supersample").record([(1, 1), (7, 1), (1, 6)], {"n": n}, (10, 10))
    counts = measure.op_counts(trace)
    pixels = 7 * 6
    assert counts["pixels_tested"] == pixels
    assert counts["samples"] == pixels * n * n


def test_zbuffer_counts_one_test_and_one_depth_per_fragment():
    grid = (12, 10)
    tris = [[(1.0, 1.0), (10.0, 2.0), (3.0, 8.0)], [(2.0, 7.0), (11.0, 6.0), (6.0, 0.5)]]
    points = tris[0] + tris[1]
    z = (0.2, 0.4, 0.6, 0.5, 0.5, 0.1)
    window = (0, 0, grid[0], grid[1])
    fragments = sum(int(measure.exact_cover(t, window, "top-left").sum()) for t in tris)
    assert fragments > 0
    trace = registry.get("zbuffer").record(points, {"z": z}, grid)
    counts = measure.op_counts(trace)
    assert counts["pixels_tested"] == fragments
    # Per fragment: three sign tests, the loop test and the depth test.
    assert counts["compare"] == 5 * fragments + 14 * len(tris)
    # Per fragment: e_k (6 mul) and the depth alpha z0 + beta z1 + gamma z2 (3 mul).
    assert counts["mul"] == 9 * fragments + 18 * len(tris)
    assert counts["float_add"] == 2 * fragments
    assert counts["samples"] == 0
