"""The budget: estimates against measured peaks, and refusals before any allocation."""
import json
import pathlib
import tracemalloc

import pytest

from algorithms.core.registry import get
from app.model import budget
from app.model import scene as scenes

SCENES = sorted(pathlib.Path("resources/scenes").glob("*.json"))
CAP = 20_000


def _peak(spec, points, options, grid, step_cap) -> int:
    tracemalloc.start()
    try:
        spec.record(points, options, grid=grid, step_cap=step_cap)
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_the_estimate_covers_the_measured_peak_of_each_shipped_scene(path):
    scene = scenes.load(path)
    grid = (scene.width, scene.height)
    measured = _peak(scene.spec, scene.points, scene.options, grid, CAP)
    estimate = budget.estimate_memory(scene.spec, scene.points, scene.options, grid, CAP)
    assert estimate >= measured
    assert estimate <= 16 * measured + 8 * 1024 ** 2


@pytest.mark.parametrize("name, points, options, grid", [
    ("flood-fill", [[(1, 1), (120, 1), (120, 120), (1, 120)]], {}, (128, 128)),
    ("aa-temporal", [(32.0, 32.0)], {"frames": 3, "n": 4, "radius": 30}, (64, 64)),
    ("polygon-scanline", [[(2, 2), (120, 10), (60, 120)]], {}, (128, 128)),
    ("aa-supersample", [(2.0, 2.0), (60.0, 5.0), (30.0, 60.0), (5.0, 40.0)],
     {"shape": "polygon", "n": 4}, (64, 64)),
])
def test_the_estimate_covers_larger_runs_at_the_cap(name, points, options, grid):
    spec = get(name)
    measured = _peak(spec, points, options, grid, CAP)
    estimate = budget.estimate_memory(spec, points, options, grid, CAP)
    assert measured <= estimate <= 16 * measured + 8 * 1024 ** 2


def test_a_huge_temporal_request_is_refused_without_allocating():
    spec = get("aa-temporal")
    options = {"frames": 240, "n": 8, "radius": 2048, "spokes": 32}
    tracemalloc.start()
    try:
        with pytest.raises(budget.BudgetError, match="memory"):
            budget.check_budget(spec, [(2048.0, 2048.0)], options, (4096, 4096), 5_000_000)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 1024 ** 2


def test_a_motion_blur_band_too_slow_for_the_time_limit_is_refused():
    spec = get("aa-temporal")
    options = {"frames": 240, "n": 8, "mode": "motion-blur", "time_samples": 64,
               "radius": 2048, "spokes": 32}
    with pytest.raises(budget.BudgetError, match="over the time limit"):
        budget.check_budget(spec, [(2048.0, 2048.0)], options, (4096, 4096), 100,
                            memory_limit=10 ** 12, time_limit=10)


def test_a_long_motion_blur_on_a_small_grid_is_refused_by_its_time():
    # about 3 hours in all: each frame's image is made band by band between
    # steps, so a cancel is heard, but the command line refuses it up front
    spec, points, grid = get("aa-temporal"), [(64.0, 64.0)], (128, 128)
    options = {"frames": 240, "n": 8, "mode": "motion-blur", "time_samples": 64}
    with pytest.raises(budget.BudgetError, match="--time-limit"):
        budget.check_budget(spec, points, options, grid, 5_000_000)
    one_frame = budget.estimate_seconds(spec, points, options | {"frames": 1}, grid, 5_000_000)
    assert budget.estimate_seconds(spec, points, options, grid, 5_000_000) > 100 * one_frame


def test_a_many_vertex_tessellation_is_refused_up_front():
    spec = get("polygon-tessellate")
    ring = [(x, 0) for x in range(50_000)] + [(x, 5) for x in range(50_000, 0, -1)]
    with pytest.raises(budget.BudgetError):
        budget.check_budget(spec, [ring], {}, (4096, 4096), 100)


def test_an_ordinary_run_fits_the_default_budget():
    spec, points, grid = get("line-bresenham"), [(0, 0), (4000, 4000)], (4096, 4096)
    budget.check_budget(spec, points, {}, grid, 5_000_000)
    estimate = budget.estimate_memory(spec, points, {}, grid, 5_000_000)
    assert _peak(spec, points, {}, grid, 5_000_000) <= estimate <= budget.DEFAULT_MEMORY_LIMIT


@pytest.mark.parametrize("text, size", [("2G", 2 * 1024 ** 3), ("512m", 512 * 1024 ** 2),
                                        ("1000", 1000), ("64KB", 65536)])
def test_sizes_read(text, size):
    assert budget.parse_size(text) == size


@pytest.mark.parametrize("text", ["", "G", "1x", "-5", "0", "\u0661\u0662M", "1.5G"])
def test_bad_sizes_are_one_line_input_errors(text):
    with pytest.raises(budget.InputError):
        budget.parse_size(text)


def test_the_command_line_refuses_the_eight_gib_temporal_run_in_one_line(run_cli):
    status, out, err = run_cli("run", "aa-temporal", "--points", "2048,2048", "--set",
                               "frames=240", "--set", "n=8", "--set", "radius=2048", "--set",
                               "spokes=32", "--grid", "4096,4096")
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and "memory" in err and "Traceback" not in err


def test_memory_limit_on_the_command_line(run_cli):
    argv = ("run", "line-bresenham", "--points", "0,0", "60,20", "--grid", "64,24")
    assert run_cli(*argv)[0] == 0
    status, _, err = run_cli(*argv, "--memory-limit", "1K")
    assert status == 2 and "over the limit of 1.0 KB" in err
    status, _, err = run_cli(*argv, "--memory-limit", "lots")
    assert status == 2 and "--memory-limit" in err


def test_a_scene_file_is_held_to_the_budget_too(run_cli):
    status, _, err = run_cli("run", "--scene", SCENES[0], "--memory-limit", "1K")
    assert status == 2 and "memory" in err


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_every_shipped_scene_fits_the_default_budget(path):
    scene = scenes.load(path)
    budget.check_budget(scene.spec, scene.points, scene.options, (scene.width, scene.height),
                        5_000_000)


def _zigzag(vertices: int) -> list:
    """A polygon whose edges each run the whole height of a 4096 grid."""
    return [(4000 * k // vertices, 4000 * (k % 2)) for k in range(vertices)] + [(4000, 4050),
                                                                               (0, 4050)]


def test_a_flood_fill_with_a_long_outline_stops_at_the_step_cap(run_cli):
    # 4,000 edges of 4,000 pixels: the outline was drawn pixel by pixel before the
    # first step (about 140 s and 2.3 GB, then refused by the time estimate); now
    # the frames draw it and the cap stops it
    args = [f"{x},{y}" for x, y in _zigzag(4000)]
    status, out, err = run_cli("run", "flood-fill", "--points", *args, "--grid", "4096,4096",
                               "--set", "seed=1,4049", "--step-cap", "100", "--json")
    assert status == 0, err
    assert json.loads(out)["steps"] == 100


def test_a_polygon_supersample_of_many_edges_fits_the_budget():
    # each sample tested every edge in Python (hours for this polygon, refused);
    # a sample is now a binary search in its row's crossing table
    spec = get("aa-supersample")
    points = [(float(x), float(y)) for x, y in _zigzag(2000)]
    budget.check_budget(spec, points, {"shape": "polygon", "n": 1}, (4096, 4096), 5_000)
    trace = spec.record(points, {"shape": "polygon", "n": 1}, grid=(4096, 4096),
                        step_cap=5_000)
    assert trace.truncated and len(trace) == 5_000
