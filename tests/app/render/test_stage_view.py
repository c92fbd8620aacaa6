"""The pipeline's stage pictures: which stage each step is in, and each picture's corners
against the matrices written out in tests/support/pipeline.py."""
from __future__ import annotations

import pytest

from algorithms.core import registry
from app.render.stage_view import StagePictures
from tests.support import pipeline as matrices

SPEC = registry.get("pipeline")
POINTS = [(21, 15), (24, 15), (27, 15), (8, 6), (24, 20), (40, 6)]
OPTIONS = SPEC.resolve({"z": (-5, 10, -5, -30, -30, -30), "eye": (24, 16, 3),
                        "target": (24, 15, -5), "fov": 60, "near": 0.5, "far": 50})
GRID = (48, 32)


def _corners(ring):
    """The ring's corners, flat: x0, y0, x1, y1, ..."""
    return [float(v) for a, _ in ring for v in a]


def _flat(pairs):
    return [float(v) for pair in pairs for v in pair]


@pytest.fixture(scope="module")
def pictures():
    trace = SPEC.record(POINTS, OPTIONS, GRID)
    return trace, StagePictures(trace, POINTS, OPTIONS, GRID)


def test_the_steps_go_through_the_stages_in_order(pictures):
    trace, stages = pictures
    titles = []
    for i in range(len(trace)):
        title = stages.at(i).title
        if not titles or titles[-1] != title:
            titles.append(title)
    per_triangle = ["Model: the world", "View: eye space", "Projection: clip space",
                    "Clip: planes that cut", "Divide: NDC",
                    "Viewport: window", "Rasterize: window"]
    assert titles == per_triangle * 2


def _first_step(trace, stages, stage, triangle):
    return next(i for i in range(len(trace)) if stages.stage_at(i) == stage
                and trace.variables_at(i).get("triangle") == triangle)


@pytest.mark.parametrize("triangle", [1, 2])
def test_each_picture_shows_the_triangle_where_its_stage_puts_it(pictures, triangle):
    trace, stages = pictures
    expected = matrices.stages(POINTS, OPTIONS["z"], OPTIONS, GRID)
    rows = slice(3 * triangle - 3, 3 * triangle)
    eye = _corners(stages.at(_first_step(trace, stages, "view", triangle)).current)
    assert eye == pytest.approx(_flat((x, z) for x, _, z in expected["eye"][rows]))
    clip_view = stages.at(_first_step(trace, stages, "clip", triangle))
    assert _corners(clip_view.current) == pytest.approx(
        _flat((c[0], c[3]) for c in expected["clip"][rows]))
    outside = {plane for plane in ("near", "far", "left", "right", "bottom", "top")
               if any(not inside for inside in _tests(plane, expected["clip"][rows]))}
    named = clip_view.caption.split("cut by ")[1].split(", ")
    assert set(named) == (outside or {"no plane"})
    divide = stages.at(_first_step(trace, stages, "divide", triangle))
    assert all(-1 - 1e-9 <= v <= 1 + 1e-9 for v in _corners(divide.current))
    if triangle == 2:  # a triangle no plane cuts keeps its own corners
        assert not outside
        assert _corners(divide.current) == pytest.approx(
            _flat(p[:2] for p in expected["ndc"][rows]))
        window = stages.at(_first_step(trace, stages, "viewport", triangle))
        assert _corners(window.current) == pytest.approx(
            _flat(p[:2] for p in expected["window"][rows]))


def _tests(plane, clips):
    return [{"near": -w <= z, "far": z <= w, "left": -w <= x, "right": x <= w,
             "bottom": -w <= y, "top": y <= w}[plane] for x, y, z, w in clips]
