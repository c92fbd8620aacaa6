"""The pipeline one stage at a time: its lines in order per triangle, each stage's per-vertex
numbers against 4x4 matrices written here from the camera's parameters, and the clipping
table's counts against the plane inequalities tested here."""
from __future__ import annotations

import json

import pytest

from algorithms.core import registry
from algorithms.core.steps import Table, Vars
from app.model import shipped
from tests.support import pipeline as matrices

SPEC = registry.get("pipeline")
STAGES = ("model", "view", "projection", "clip", "divide", "viewport", "fan")


def _scene(name):
    with open(shipped.scene_path(name), encoding="utf-8") as handle:
        data = json.load(handle)
    points = [tuple(p) for primitive in data["primitives"] for p in primitive["points"]]
    options = SPEC.resolve(data["options"])
    return points, options, (data["grid"]["width"], data["grid"]["height"])


def _stage_values(trace, key):
    line = _lines(trace)[key]
    return [record.values for step, record in trace.records_of(Vars)
            if trace.step(step).line == line]


def _lines(trace):
    """Line numbers by the start of their text, read from the listing the trace holds."""
    starts = {"model": "for each triangle", "view": "    eye_k = view",
              "projection": "    clip_k = projection", "clip": "    clip against",
              "divide": "    each corner C_k", "viewport": "    x_win =",
              "fan": "    rasterize each triangle"}
    return {key: next(n for n, line in enumerate(trace.code) if line.text.startswith(text))
            for key, text in starts.items()}


def test_each_triangle_goes_through_the_stages_in_order():
    points, options, grid = _scene("rendering/pipeline-cube")
    trace = SPEC.record(points, options, grid)
    lines = _lines(trace)
    stage_of = {line: key for key, line in lines.items()}
    seen = []
    for i in range(1, len(trace)):  # step 0 starts the run
        key = stage_of.get(trace.step(i).line)
        if key and (not seen or seen[-1] != key or key == "model"):
            seen.append(key)
    # Twelve triangles, none cut by a plane: the seven stages per triangle, in order.
    assert seen == list(STAGES) * 12


def test_each_stage_matches_the_matrices():
    points, options, grid = _scene("rendering/pipeline-cube")
    trace = SPEC.record(points, options, grid)
    expected = matrices.stages(points, options["z"], options, grid)
    world, eye, clip, ndc, window = (expected[key] for key in
                                     ("world", "eye", "clip", "ndc", "window"))
    stages = {key: _stage_values(trace, key)
              for key in ("model", "view", "projection", "divide", "viewport")}
    for n in range(len(points) // 3):
        for k in range(3):
            row = 3 * n + k
            got = {key: stages[key][n] for key in stages}
            assert [got["model"][f"{a}_world{k}"] for a in "xyz"] == pytest.approx(world[row, :3])
            assert [got["view"][f"{a}_eye{k}"] for a in "xyz"] == pytest.approx(eye[row, :3])
            assert [got["projection"][f"{a}_clip{k}"] for a in "xyz"] + \
                [got["projection"][f"w{k}"]] == pytest.approx(clip[row])
            assert [got["divide"][f"{a}_ndc{k}"] for a in "xyz"] == pytest.approx(ndc[row])
            assert [got["viewport"][f"{a}{k}"] for a in ("x_win", "y_win", "depth")] == \
                pytest.approx(window[row])


def _inside(plane, c):
    x, y, z, w = c
    return {"near": -w <= z, "far": z <= w, "left": -w <= x, "right": x <= w,
            "bottom": -w <= y, "top": y <= w}[plane]


@pytest.mark.parametrize("name", ["rendering/pipeline-near-crossing", "rendering/pipeline-floor",
                                  "rendering/pipeline-cube"])
def test_the_clipping_table_counts_the_vertices_inside_each_plane(name):
    points, options, grid = _scene(name)
    trace = SPEC.record(points, options, grid)
    projection = _stage_values(trace, "projection")
    tables = [record for _, record in trace.records_of(Table) if record.name == "clipping"]
    assert len(tables) == len(points) // 3
    split = 0
    for values, table in zip(projection, tables):
        clips = [tuple(values[f"{a}{k}"] for a in ("x_clip", "y_clip", "z_clip", "w"))
                 for k in range(3)]
        assert [row[0] for row in table.rows] == ["near", "far", "left", "right", "bottom",
                                                   "top"]
        for plane, _, inside, outside, _ in table.rows:
            expected = sum(_inside(plane, c) for c in clips)
            assert (inside, outside) == (expected, 3 - expected)
            split += 0 < expected < 3
    if name.endswith("near-crossing"):
        assert split > 0  # some plane cuts a triangle: the counts differ from plane to plane
