"""Every triangle traversal against the exact rational oracle, for every fill rule.

The oracle (algorithms/exact/triangles.py) decides coverage from the
definition with Fractions: closed triangle, open triangle, or the centre
nudged right and a hair up (top-left). Traversals, their fast kernels and
the oracle must agree pixel for pixel, whatever the winding.
"""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.core import registry
from algorithms.core.registry import InputError
from algorithms.core.steps import Note, Start
from test_triangles_cases import (RULES, TRAVERSALS, as_window, centre_triangle, counts_of,
                                  far_triangle, oracle, plotted, run_frames, sliver, spec,
                                  subgrid_triangle, visited)

GRID = (12, 10)


def check_every_traversal(points, grid=GRID, rules=RULES):
    window = as_window(grid)
    for rule in rules:
        want = oracle(points, rule, window)
        for name in TRAVERSALS:
            options = {"fill_rule": rule}
            pixels = plotted(name, points, options, grid)
            assert counts_of(pixels) == want, (name, rule, points)
            kernel = spec(name).kernel
            if kernel is not None:
                fast = kernel(points, spec(name).resolve(options), grid)
                assert [tuple(p) for p in fast.tolist()] == pixels, (name, rule, "kernel")
        seen = visited("triangle-pineda", points, {"fill_rule": rule}, grid)
        assert len(seen) == len(set(seen)), "the Pineda walk visited a pixel twice"


@settings(max_examples=150)
@given(subgrid_triangle(-2, 14))
def test_random_triangles_on_the_subpixel_grid(points):
    check_every_traversal(points)


@settings(max_examples=100)
@given(centre_triangle(12, 10))
def test_vertices_exactly_on_pixel_centres(points):
    check_every_traversal(points)


@settings(max_examples=100)
@given(sliver())
def test_slivers_thinner_than_a_thousandth_of_a_pixel(points):
    check_every_traversal(points, grid=(16, 12))


@settings(max_examples=80)
@given(far_triangle())
def test_coordinates_up_to_a_million_through_a_small_window(case):
    points, window = case
    check_every_traversal(points, grid=window)


@settings(max_examples=30)
@given(subgrid_triangle(0, 12), st.sampled_from(RULES))
def test_both_windings_give_the_same_pixels_and_cull_drops_clockwise(points, rule):
    reverse = [points[0], points[2], points[1]]
    for name in ("triangle-bbox", "triangle-halfplane", "triangle-linewise", "triangle-pineda"):
        forward = counts_of(plotted(name, points, {"fill_rule": rule}))
        backward = counts_of(plotted(name, reverse, {"fill_rule": rule}))
        assert forward == backward
        culled = [counts_of(plotted(name, p, {"fill_rule": rule, "cull": True}))
                  for p in (points, reverse)]
        assert sorted(map(len, culled))[0] == 0  # the clockwise one draws nothing
        assert max(culled, key=len) == forward


@pytest.mark.parametrize("bits", [0, 1, 3, 8])
def test_subpixel_bits_snap_like_the_oracle(bits):
    rng = np.random.default_rng(bits)
    for _ in range(15):
        points = [tuple(map(float, rng.uniform(-1, 13, 2))) for _ in range(3)]
        for rule in RULES:
            want = oracle(points, rule, as_window(GRID), bits=bits)
            for name in ("triangle-bbox", "triangle-backtrack", "triangle-linewise"):
                got = plotted(name, points, {"fill_rule": rule, "subpixel_bits": bits}, GRID)
                assert counts_of(got) == want, (name, bits, points)


def test_the_top_left_rule_by_hand():
    # Centres on x = 0.5 (left edge) and y = 0.5 (bottom edge) are kept; those
    # on the hypotenuse x + y = 5 (a right/top edge) are not.
    points = [(0.5, 0.5), (4.5, 0.5), (0.5, 4.5)]
    pixels = set(plotted("triangle-bbox", points))
    assert (0, 0) in pixels and (0, 3) in pixels and (3, 0) in pixels
    assert (2, 2) not in pixels and (0, 4) not in pixels and (4, 0) not in pixels
    assert pixels == {(i, j) for i in range(4) for j in range(4) if i + j < 4}
    inclusive = set(plotted("triangle-bbox", points, {"fill_rule": "inclusive"}))
    assert inclusive == {(i, j) for i in range(5) for j in range(5) if i + j <= 4}
    strict = set(plotted("triangle-bbox", points, {"fill_rule": "strict"}))
    assert strict == {(i, j) for i in range(1, 4) for j in range(1, 4) if i + j < 4}


def test_a_square_split_on_its_diagonal_covers_each_centre_once():
    a, b, c, d = (0.5, 0.5), (6.5, 0.5), (6.5, 6.5), (0.5, 6.5)
    for name in TRAVERSALS:
        pixels = plotted(name, [a, b, c, a, c, d])
        assert counts_of(pixels) == {(i, j): 1 for i in range(6) for j in range(6)}, name


def test_frames_start_with_start_and_carry_edge_values_and_the_tie_flag():
    points = [(0.5, 0.5), (4.5, 0.5), (0.5, 4.5)]
    lines, frames = run_frames("triangle-bbox", points)
    s = spec("triangle-bbox")
    first = next(s.generator(points, s.resolve({}), GRID))
    assert isinstance(first, Start) and first.values[:4] == ("e0", "e1", "e2", "tie")
    ties = 0
    for f in frames:
        if type(f) is tuple and f[1] >= 0 and not math.isnan(f[6]):
            e = f[3:6]
            assert (f[6] == 1.0) == (min(e) == 0 and min(e) >= 0), f
            ties += f[6] == 1.0
    assert ties > 0


def test_incremental_values_equal_direct_evaluation():
    points = [(1.3, 0.7), (9.9, 2.2), (4.1, 8.6)]
    direct = [f for f in run_frames("triangle-bbox", points)[1] if type(f) is tuple and f[1] >= 0]
    walked = [f for f in run_frames("triangle-incremental", points)[1]
              if type(f) is tuple and f[1] >= 0 and not math.isnan(f[6])]
    assert [f[1:] for f in direct] == [f[1:] for f in walked]


def test_degenerate_triangles_draw_nothing_and_say_so():
    for name in TRAVERSALS:
        points = [(1, 1), (3, 3), (5, 5)]
        lines, frames = run_frames(name, points)
        assert not plotted(name, points)
        assert any(isinstance(f, Note) and "no area" in f.text for f in frames)


def test_a_clockwise_triangle_is_swapped_and_noted():
    lines, frames = run_frames("triangle-bbox", [(1, 1), (1, 6), (6, 1)])
    assert any(isinstance(f, Note) and "swapped" in f.text for f in frames)


def test_final_variables_count_tests_and_fills():
    points = [(0.5, 0.5), (4.5, 0.5), (0.5, 4.5)]
    trace = spec("triangle-scan").record(points, {}, grid=(8, 6))
    final = trace.final_variables()
    assert final["tested"] == 48 and final["filled"] == 10
    assert final["overlaps"] == 0 and final["cracks"] == 0
    trace = spec("triangle-bbox").record(points, {}, grid=(8, 6))
    assert trace.final_variables()["tested"] == 25


def test_the_panel_explains_a_tie():
    s = spec("triangle-bbox")
    trace = s.record([(0.5, 0.5), (4.5, 0.5), (0.5, 4.5)], {}, grid=(8, 6))
    for i in range(len(trace)):
        step = trace.step(i)
        if step.pixel == (0, 0):
            rows = dict(s.panel_rows(trace, i))
            assert "left edge" in rows["e1 exactly"] or "bottom edge" in rows["e2 exactly"]
            assert rows["verdict"].startswith("in")
            break
    else:
        pytest.fail("pixel (0, 0) was never tested")


def test_every_traversal_is_registered_in_the_triangle_family():
    names = {s.name for s in registry.all_specs() if s.family == "triangles"}
    assert set(TRAVERSALS) <= names
    for name in TRAVERSALS:
        s = spec(name)
        assert {"fill_rule", "precision", "subpixel_bits", "cull"} <= {o.name for o in s.options}
        assert s.inputs.multiple and not s.inputs.integer and s.inputs.count == 3


def test_bad_options_are_input_errors():
    s = spec("triangle-bbox")
    with pytest.raises(InputError):
        s.record([(0, 0), (1, 0), (0, 1)], {"fill_rule": "sideways"})
    with pytest.raises(InputError):
        s.record([(0, 0), (1, 0), (0, 1), (2, 2)], {})
    with pytest.raises(InputError):
        s.record([(0, 0), (1, 0), (0, 1)], {"subpixel_bits": 9})
