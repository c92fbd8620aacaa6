"""The z-buffer against an exact nearest-depth oracle; the painter's algorithm and its failures."""
import json
import math
import random

import numpy as np
import pytest

from algorithms.exact import triangles as exact_triangles
from algorithms.visibility import zbuffer_painter as vis
from algorithms.core.registry import get
from algorithms.core.steps import Table
from app.cli import main
from tests.support.trace_oracle import slow_replay
from tests.support.visibility_oracles import nearest_oracle

PALETTE = [int(c[1:], 16) for c in vis.PALETTE]


def random_scene(seed, count, grid=(20, 16)):
    rng = random.Random(seed)
    points, z = [], []
    for _ in range(count):
        for _ in range(3):
            points.append((rng.uniform(0, grid[0]), rng.uniform(0, grid[1])))
            z.append(rng.choice([rng.uniform(0, 1), rng.uniform(0, 1), 1.0, 0.25]))
    return points, z


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("test", vis.TESTS)
def test_zbuffer_keeps_the_nearest_fragment(seed, test):
    points, z = random_scene(seed, 4)
    grid = (20, 16)
    trace = get("zbuffer").record(points, {"z": tuple(z), "depth_test": test}, grid=grid)
    raster = trace.raster_at(len(trace) - 1)
    owner, depth = nearest_oracle(points, z, grid, test)
    want_colors = np.where(owner >= 0, np.array(PALETTE)[owner % len(PALETTE)], -1)
    assert np.array_equal(raster.colors, want_colors)
    stored = owner >= 0
    assert np.array_equal(raster.depth[stored],
                          np.array([float(d) for d in depth[stored]]))  # rounded once
    assert np.all(np.isnan(raster.depth[~stored]))
    assert np.array_equal(vis.depth_view(raster)[~stored], np.ones((~stored).sum()))
    final = trace.final_variables()
    assert final["visible"] == stored.sum()
    assert final["passed"] + final["failed"] == final["fragments"]


def test_the_depth_test_decides_ties():
    tri = [(1.5, 1.5), (9.0, 2.0), (3.0, 9.5)]
    options = {"z": (0.5,) * 6, "colors": ("#ff0000",) * 3 + ("#0000ff",) * 3}
    for test, colour in (("less", 0xFF0000), ("less-equal", 0x0000FF)):
        trace = get("zbuffer").record(tri + tri, {**options, "depth_test": test}, grid=(12, 12))
        colors = trace.raster_at(len(trace) - 1).colors
        assert set(np.unique(colors[colors >= 0])) == {colour}


def test_fragments_that_fail_are_visits_with_both_depths():
    near = [(1, 1), (10, 1), (1, 10)]
    far = [(0.5, 0.5), (11, 0.5), (0.5, 11)]
    trace = get("zbuffer").record(near + far, {"z": (0.2, 0.2, 0.2, 0.6, 0.6, 0.6)},
                                  grid=(12, 12))
    fails = [trace.step(i) for i in range(len(trace)) if trace.step(i).branch == "fail"]
    assert fails and all(s.kind == "visit" for s in fails)
    assert all(s.values["z"] == 0.6 and s.values["zb"] == 0.2 for s in fails)
    rows = get("zbuffer").panel_rows(trace, trace.step(len(trace) - 2).index)
    assert any(name == "depth test" for name, _ in rows)


def test_clear_depth_and_far_fragments():
    tri = [(1, 1), (10, 1), (1, 10)]
    trace = get("zbuffer").record(tri, {"z": (1.0, 1.5, 0.5)}, grid=(12, 12))
    raster = trace.raster_at(len(trace) - 1)
    assert np.nanmax(raster.depth) < 1.0  # only fragments nearer than the clear depth stay
    trace = get("zbuffer").record(tri, {"z": (1.0, 1.5, 0.5), "clear_depth": 2.0}, grid=(12, 12))
    assert trace.final_variables()["failed"] == 0


def test_state_at_equals_slow_replay_with_the_depth_buffer(small_keyframes):
    small_keyframes(7)
    points, z = random_scene(3, 3, (14, 12))
    trace = get("zbuffer").record(points, {"z": tuple(z)}, grid=(14, 12))
    assert len(trace._ensure_keyframes()) > 3
    for i in range(len(trace)):
        fast, slow = trace.state_at(i).raster, slow_replay(trace, i)
        assert np.array_equal(fast.counts, slow.counts)
        assert np.array_equal(fast.colors, slow.colors)
        assert np.array_equal(fast.depth, slow.depth, equal_nan=True)
    # the depth buffer grows step by step: the value written is the frame's z
    for i in range(1, len(trace)):
        step = trace.step(i)
        if step.writes:
            x, y = step.pixel
            assert trace.state_at(i).raster.depth[y, x] == step.values["z"]


def test_gouraud_colours_per_vertex():
    tri = [(0.5, 0.5), (8.5, 0.5), (0.5, 8.5)]
    trace = get("zbuffer").record(tri, {"z": (0.1, 0.2, 0.3),
                                        "colors": ("#ff0000", "#00ff00", "#0000ff")},
                                  grid=(10, 10))
    colors = trace.raster_at(len(trace) - 1).colors
    assert colors[0, 0] == 0xFF0000 and colors[0, 7] != colors[0, 0]


# -------------------------------------------------------------- painter
@pytest.mark.parametrize("scene", [vis.intersecting_scene, vis.cyclic_scene])
@pytest.mark.parametrize("key", vis.SORT_KEYS)
def test_painter_fails_on_its_two_scenes(scene, key):
    s = scene()
    options = {**s["options"], "sort": key}
    trace = get("painter").record(s["points"], options, grid=s["grid"])
    final = trace.final_variables()
    assert final["disagree"] > 0 and final["wrong_triangle"] > 0
    table = [r for _, r in trace.records_of(Table) if r.name == "disagreement"][0]
    assert len(table.rows) == min(final["disagree"], vis.MAX_TABLE_ROWS)
    colors, _ = vis.painter_image(s["points"], options, s["grid"])
    reference, _, _ = vis.zbuffer_image(s["points"], options, s["grid"])
    assert (colors != reference).sum() == final["disagree"]


def test_the_cyclic_scene_really_is_a_cycle():
    s = vis.cyclic_scene()
    _, _, owner = vis.zbuffer_image(s["points"], s["options"], s["grid"])
    covered = [exact_triangles.coverage(s["points"][3 * k:3 * k + 3], 8, "top-left",
                                        (0, 0, *s["grid"])) for k in range(3)]
    for front in range(3):
        back = (front + 1) % 3
        both = set(covered[front]) & set(covered[back])
        assert both and all(owner[y, x] == front for x, y in both)


@pytest.mark.parametrize("name, scene", sorted(vis.SCENES.items()))
def test_scenes_fit_their_grids_and_run_from_the_command_line(capsys, name, scene):
    s = scene()
    width, height = s["grid"]
    assert all(0 <= x <= width and 0 <= y <= height for x, y in s["points"])
    argv = ["run", s["algorithm"], "--points", *[f"{x},{y}" for x, y in s["points"]],
            "--grid", f"{width},{height}", "--set", "z=" + ",".join(map(str, s["options"]["z"]))]
    status = main(argv + ["--json"])
    out, err = capsys.readouterr()
    assert status == 0, err
    assert (json.loads(out)["final"]["disagree"] > 0) == (name != "painter-separate")


def test_painter_equals_zbuffer_without_overlaps_and_for_sortable_stacks():
    s = vis.separate_scene()
    painter_colors, _ = vis.painter_image(s["points"], s["options"], s["grid"])
    trace = get("zbuffer").record(s["points"], {"z": s["options"]["z"]}, grid=s["grid"])
    assert np.array_equal(painter_colors, trace.raster_at(len(trace) - 1).colors)
    # overlapping, but each triangle flat: back to front is right
    stack = [(2, 2), (20, 3), (6, 18), (5, 4), (24, 8), (10, 20), (8, 1), (28, 12), (3, 14)]
    z = (0.5,) * 3 + (0.2,) * 3 + (0.8,) * 3
    for key in vis.SORT_KEYS:
        trace = get("painter").record(stack, {"z": z, "sort": key}, grid=(30, 22))
        assert trace.final_variables()["disagree"] == 0
    zb = get("zbuffer").record(stack, {"z": z}, grid=(30, 22))
    painter_colors, _ = vis.painter_image(stack, {"z": z}, (30, 22))
    assert np.array_equal(painter_colors, zb.raster_at(len(zb) - 1).colors)


def test_painter_draws_back_to_front_by_the_key():
    s = vis.cyclic_scene()
    points = s["points"] + [(20.0, 1.0), (31.0, 1.0), (31.0, 6.0)]
    z = tuple(s["options"]["z"]) + (0.05, 0.99, 0.5)
    expected = {"mean": [1, 2, 3, 4], "min": [1, 2, 3, 4], "max": [4, 1, 2, 3]}
    for key in vis.SORT_KEYS:
        trace = get("painter").record(points, {"z": z, "sort": key}, grid=(32, 24))
        order = trace.record_at(1)
        assert order.name == "drawing order"
        keys = [row[2] for row in order.rows]
        assert keys == sorted(keys, reverse=True)
        if key != "mean":
            assert [row[1] for row in order.rows] == expected[key]
        else:
            assert math.isclose(keys[-1], (0.05 + 0.99 + 0.5) / 3)


# --------------------------------------------------------- command line
def test_zbuffer_from_the_command_line(capsys):
    status = main(["run", "zbuffer", "--points", "1.5,2", "20,3.25", "8,17", "3,15", "25,12",
                   "5,4", "--set", "z=0.2,0.5,0.9,0.8,0.1,0.3", "--json"])
    out, err = capsys.readouterr()
    assert status == 0, err
    result = json.loads(out)
    assert all(v.startswith("#") for v in result["values"])
    assert result["final"]["visible"] <= result["final"]["passed"] <= result["final"]["fragments"]


@pytest.mark.parametrize("argv, words", [
    (["--set", "z=0.1,0.2"], "one value per point"),
    (["--set", "depth_test=greater"], "expected one of"),
    (["--set", "z=0.1,nan,0.3"], "not a finite number"),
])
def test_bad_zbuffer_input(capsys, argv, words):
    status = main(["run", "zbuffer", "--points", "1,1", "9,1", "1,9", "2,2", "8,3", "3,8", *argv])
    out, err = capsys.readouterr()
    assert status == 2 and words in err and err.count("\n") == 1
