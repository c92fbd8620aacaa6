"""An animated run (aa-temporal) exports one frame per animation frame, each
showing that frame's whole image; other runs export one frame per step."""
import json
from fractions import Fraction

import pytest
from PIL import Image

from algorithms.core import registry
from algorithms.antialias import animation_frame_steps
from app.render import export as exporting
from app.model.scene import Scene, save

GRID = (20, 12)
# Vertices a quarter pixel off the lattice: no pixel centre lies on an edge.
TRIANGLE = [[2.25, 2.25], [8.25, 2.75], [4.75, 9.25]]
MOVING = {"primitive": "triangle", "motion": "move", "speed": 2.0, "frames": 5, "n": 1}


def inside(point, triangle) -> bool:
    """Strictly inside, by the signs of three exact cross products."""
    signs = []
    for k in range(3):
        (ax, ay), (bx, by) = triangle[k], triangle[(k + 1) % 3]
        signs.append((bx - ax) * (point[1] - ay) - (by - ay) * (point[0] - ax))
    return all(s > 0 for s in signs) or all(s < 0 for s in signs)


def expected_image(k: int) -> set:
    """Pixels whose centre the triangle, moved 2 px per frame, covers at frame k."""
    moved = [(Fraction(x) + 2 * k, Fraction(y)) for x, y in TRIANGLE]
    return {(x, y) for x in range(GRID[0]) for y in range(GRID[1])
            if inside((Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2)), moved)}


def coverage_at(trace, step: int) -> set:
    """Pixels whose last written coverage at ``step`` is 1 (replayed here)."""
    shown = {}
    for i in range(1, step + 1):
        frame = trace.step(i)
        if frame.pixel is not None and frame.writes:
            shown[frame.pixel] = frame.values["coverage"]
    return {p for p, value in shown.items() if value == 1.0}


def moving_trace():
    return registry.get("aa-temporal").record(TRIANGLE, MOVING, GRID)


def test_each_animation_frame_step_shows_that_frames_image():
    spec, trace = registry.get("aa-temporal"), moving_trace()
    steps = animation_frame_steps(spec, trace)
    assert len(steps) == MOVING["frames"]
    assert steps == sorted(steps)
    for k, step in enumerate(steps):
        assert coverage_at(trace, step) == expected_image(k), k
        assert trace.variables_at(step)["frame"] == k


def test_other_runs_have_no_animation_frames():
    spec = registry.get("line-bresenham")
    assert animation_frame_steps(spec, spec.record([(0, 0), (5, 2)])) == []


def scene_file(tmp_path, algorithm="aa-temporal", points=TRIANGLE, options=MOVING):
    path = tmp_path / "scene.json"
    save(Scene(algorithm, points, dict(options), *GRID), path)
    return path


def test_export_writes_one_png_per_animation_frame(tmp_path):
    scene = Scene("aa-temporal", TRIANGLE, dict(MOVING), *GRID)
    settings = exporting.ExportSettings(scale=4, caption=False, panel="none")
    result = exporting.export(scene, settings, frames_dir=tmp_path / "frames",
                              gif=tmp_path / "wheel.gif", trace=moving_trace())
    assert result.frames == MOVING["frames"]
    frames = sorted((tmp_path / "frames").glob("frame_*.png"))
    assert len(frames) == MOVING["frames"]
    # The triangle moves: consecutive frames differ, and the GIF keeps them all.
    images = [Image.open(f).convert("RGB").tobytes() for f in frames]
    assert all(a != b for a, b in zip(images, images[1:]))
    with Image.open(tmp_path / "wheel.gif") as gif:
        assert gif.n_frames == MOVING["frames"]


def test_per_step_and_per_animation_choices(tmp_path):
    spec, trace = registry.get("aa-temporal"), moving_trace()
    scene = Scene("aa-temporal", TRIANGLE, dict(MOVING), *GRID)
    every = exporting.ExportSettings(per="step", first=0, last=9)
    assert list(exporting.frame_steps(scene, trace, every)) == list(range(10))
    # A range keeps the animation frames that end inside it.
    steps = animation_frame_steps(spec, trace)
    part = exporting.ExportSettings(per="animation", first=steps[1], last=steps[3])
    assert exporting.frame_steps(scene, trace, part) == steps[1:4]
    line = Scene("line-bresenham", [[0, 0], [5, 2]])
    line_trace = exporting.record(line)
    assert list(exporting.frame_steps(line, line_trace, exporting.ExportSettings())) \
        == list(range(len(line_trace)))
    with pytest.raises(exporting.ExportError, match="no animation frames"):
        exporting.frame_steps(line, line_trace, exporting.ExportSettings(per="animation"))
    with pytest.raises(exporting.ExportError, match="frames per"):
        exporting.ExportSettings(per="sometimes").checked()


def test_command_line_exports_animation_frames_and_refuses_them_for_a_line(tmp_path, run_cli):
    scene = scene_file(tmp_path)
    status, _, err = run_cli("export", scene, "--frames-dir", tmp_path / "out", "--scale", "2",
                             child=True)
    assert status == 0, err
    assert len(list((tmp_path / "out").glob("frame_*.png"))) == MOVING["frames"]
    line = scene_file(tmp_path, "line-bresenham", [[0, 0], [5, 2]], {})
    status, _, err = run_cli("export", line, "--gif", tmp_path / "line.gif", "--per", "animation",
                             child=True)
    assert status == 2
    assert "no animation frames" in err and "Traceback" not in err
    assert not (tmp_path / "line.gif").exists()
    json.loads(run_cli("run", "--scene", scene, "--json", child=True)[1])  # the scene itself runs


def test_a_pixel_left_by_the_moving_triangle_shows_white_not_overdraw():
    """Writing a pixel again in a later animation frame replaces it: a cell
    the triangle has left is drawn white (coverage 0 blended over white),
    a covered one in full ink, never darkened as overdraw."""
    from app.render.compose import compose
    spec, trace = registry.get("aa-temporal"), moving_trace()
    last = animation_frame_steps(spec, trace)[-1]
    image = compose(trace.raster_at(last), scale=1)  # row 0 is y = 0
    raster = trace.raster_at(last)
    covered = expected_image(MOVING["frames"] - 1)
    left = {(x, y) for y, x in zip(*(raster.counts > 1).nonzero())} - covered
    assert left, "the triangle moved off some pixels"
    for x, y in left:
        assert tuple(image[y, x, :3]) == (255, 255, 255), (x, y)
    ink = tuple(image[y, x, :3] for x, y in covered)
    assert len(set(map(tuple, ink))) == 1 and max(ink[0]) < 128
