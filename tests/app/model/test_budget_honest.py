"""Honest budgets: what a run keeps per step (the scan line's table
snapshots), a time estimate checked before the work starts, every command
that runs a scene held to them, and the address-space backstop."""
import os
import random
import subprocess
import sys

import pytest

from algorithms.core.registry import get
from algorithms.core.steps import Table
from app.model import budget
from app.model import scene as scenes
from tests.support import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))
from bench_budget import star_scene, zigzag_scene  # noqa: E402

MB = 1024 ** 2


@pytest.mark.parametrize("make, vertices, cap", [(zigzag_scene, 20000, 300),
                                                 (zigzag_scene, 2000, 3000),
                                                 (star_scene, 4000, 2000)])
def test_the_table_rows_counted_cover_the_rows_the_run_keeps(make, vertices, cap):
    scene = make(vertices)
    trace = scene.spec.record(scene.points, scene.options, scene.grid, step_cap=cap)
    kept = sum(len(table.rows) for _, table in trace.records_of(Table))
    counted = budget.table_rows(scene.spec, scene.points, scene.options, cap)[0]
    assert kept <= counted <= 3 * kept


def _saved(tmp_path, scene, name="scene.json"):
    path = tmp_path / name
    scenes.save(scene, path)
    return path


def test_the_twenty_thousand_vertex_polygon_is_refused_at_a_160M_budget(run_cli, tmp_path):
    # accepted before (estimated 144 MB) while its ET snapshots took gigabytes
    path = _saved(tmp_path, zigzag_scene(20000))
    status, out, err = run_cli("run", "--scene", path, "--step-cap", "20000",
                               "--memory-limit", "160M")
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and "memory" in err and "Traceback" not in err


def test_worksheet_is_held_to_the_budget(run_cli, tmp_path):
    path = _saved(tmp_path, zigzag_scene(20000))
    out = tmp_path / "sheet"
    status, _, err = run_cli("worksheet", path, "--format", "csv", "--out", out,
                             "--memory-limit", "160M")
    assert status == 2 and "memory" in err and err.count("\n") == 1
    assert not out.exists()  # refused before anything is made


TEMPORAL = ("run", "aa-temporal", "--points", "64,64", "--set", "frames=240", "--set",
            "mode=motion-blur", "--set", "time_samples=64", "--set", "n=8", "--set",
            "radius=60", "--set", "spokes=32", "--grid", "128,128", "--json")


def test_a_long_motion_blur_is_refused_under_the_default_time_limit(run_cli):
    status, out, err = run_cli(*TEMPORAL)
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and "--time-limit" in err and "time limit of 2 min" in err


@pytest.mark.parametrize("argv", [
    ("run", "triangle-bbox", "--points", "0,0", "4095,0", "0,4095", "--grid", "4096,4096"),
    ("run", "aa-supersample", "--points", "0,0", "4095,0", "0,4095", "--set", "n=8",
     "--grid", "4096,4096"),
])
def test_the_slow_runs_of_the_issue_are_refused_up_front(run_cli, argv):
    status, out, err = run_cli(*argv)
    assert status == 2 and out == "" and "--time-limit" in err


def test_a_hundred_thousand_point_polygon_is_refused_up_front(run_cli, tmp_path):
    path = _saved(tmp_path, star_scene(100_000))
    status, out, err = run_cli("run", "--scene", path)
    assert status == 2 and out == "" and err.count("\n") == 1


def test_export_is_held_to_the_time_limit(run_cli, tmp_path):
    gif = tmp_path / "a.gif"
    status, _, err = run_cli("export", "demo-bresenham", "--gif", gif, "--time-limit", "1e-9")
    assert status == 2 and "time limit" in err
    assert not gif.exists()


def test_raising_the_time_limit_lets_a_run_through(run_cli):
    argv = ("run", "line-bresenham", "--points", "0,0", "60,20", "--grid", "64,24")
    assert run_cli(*argv, "--time-limit", "1e-9")[0] == 2
    assert run_cli(*argv, "--time-limit", "1")[0] == 0


@pytest.mark.parametrize("text", ["0", "-1", "soon", "nan"])
def test_a_bad_time_limit_is_one_line(run_cli, text):
    status, _, err = run_cli("run", "line-bresenham", "--points", "0,0", "6,2",
                             "--time-limit", text)
    assert status == 2 and err.count("\n") == 1 and "--time-limit" in err


def test_the_window_is_not_held_to_a_time_limit():
    # the window shows the recording's progress and Cancel instead
    spec, points, grid = get("aa-temporal"), [(64.0, 64.0)], (128, 128)
    options = {"frames": 240, "n": 8, "mode": "motion-blur", "time_samples": 64}
    budget.check_budget(spec, points, options, grid, 5_000_000, time_limit=float("inf"))
    with pytest.raises(budget.BudgetError):
        budget.check_budget(spec, points, options, grid, 5_000_000)


def _child_peak(argv) -> tuple[int, int, str]:
    """(exit status, resident peak in bytes, stderr) of a fresh child, from
    wait4's rusage of that child alone."""
    child = subprocess.Popen(argv, cwd=ROOT, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    err = child.stderr.read().decode(errors="replace")
    child.stderr.close()
    return (os.waitstatus_to_exitcode(status),
            usage.ru_maxrss * (1 if sys.platform == "darwin" else 1024), err)


@pytest.mark.slow
@pytest.mark.skipif(not hasattr(os, "wait4"), reason="os.wait4 gives a child's own rusage")
@pytest.mark.parametrize("make, vertices, cap", [(zigzag_scene, 20000, 1000),
                                                 (star_scene, 4000, 5000)])
def test_the_estimate_is_within_a_factor_of_a_fresh_childs_peak(tmp_path, make, vertices,
                                                                 cap, capsys):
    scene = make(vertices)
    path = _saved(tmp_path, scene)
    baseline = _child_peak([sys.executable, "-m", "rasterlab", "list"])[1]
    status, peak, err = _child_peak([sys.executable, "-m", "rasterlab", "run", "--scene",
                                     str(path), "--step-cap", str(cap), "--memory-limit", "8G"])
    assert status == 0, err
    estimate = budget.estimate_memory(scene.spec, scene.points, scene.options, scene.grid, cap)
    with capsys.disabled():
        print(f"\n{make.__name__}({vertices}) cap {cap}: estimate {estimate / MB:.0f} MB, "
              f"peak {peak / MB:.0f} MB, of which {(peak - baseline) / MB:.0f} MB above "
              f"the baseline")
    assert peak - baseline <= estimate <= 4 * peak


BACKSTOP = """
import sys
from app import cli
from app.model import budget
if budget.limit_address_space(budget.parse_size(sys.argv[1])) is None:
    sys.exit(77)
sys.exit(cli.main(sys.argv[2:]))
"""


@pytest.mark.slow
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS is set on Linux")
def test_an_estimate_that_is_wrong_ends_in_one_line_at_the_backstop(tmp_path):
    # the backstop set for a 1 MB budget under a run estimated (and
    # allowed) at gigabytes: the run meets MemoryError, said in one line
    path = _saved(tmp_path, zigzag_scene(20000))
    done = subprocess.run([sys.executable, "-c", BACKSTOP, "1M", "run", "--scene", str(path),
                           "--step-cap", "5000", "--memory-limit", "64G",
                           "--time-limit", "100000"],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    if done.returncode == 77:
        pytest.skip("this system refuses an address-space limit")
    assert done.returncode == 2 and done.stdout == "" and "Traceback" not in done.stderr
    last = done.stderr.splitlines()[-1]
    assert "needed more memory than its budget (--memory-limit 64.0 GB)" in last


def test_the_backstop_keeps_a_lower_hard_limit():
    class Limits:  # a resource module whose hard limit is already low
        RLIMIT_AS, RLIM_INFINITY = 9, -1
        set = None

        def getrlimit(self, number):
            return (-1, 64 * MB)

        def setrlimit(self, number, limits):
            self.set = limits
    limits = Limits()
    assert budget.limit_address_space(MB, limits) is None and limits.set is None


# ------------------------------------------------------- the step bound holds
def _full_grid_triangles(count: int, size: int) -> list:
    """``count`` triangles, each covering most of a size x size grid."""
    return [point for k in range(count)
            for point in ((0.5, 0.5 + k / 1000), (size - 0.5, 0.7), (size / 2, size - 0.5))]


def _random_segments(count: int, size: int, seed: int) -> list:
    generator = random.Random(seed)
    return [[(generator.randrange(size), generator.randrange(size)) for _ in range(2)]
            for _ in range(count)]


@pytest.mark.parametrize("name, points, grid", [
    # 60 overlapping triangles: each walks its own box (the old bound counted the grid once)
    ("zbuffer", _full_grid_triangles(60, 32), (32, 32)),
    ("painter", _full_grid_triangles(60, 32), (32, 32)),
    ("triangle-scan", _full_grid_triangles(30, 40), (40, 40)),
    ("triangle-barycentric-printed", _full_grid_triangles(30, 40), (40, 40)),
    # the implicit forms test every pixel of the box, or of the grid
    *[("line-implicit", segment, (96, 64)) for segment in _random_segments(4, 64, 1)],
    *[("line-implicit-infinite", segment, (96, 64)) for segment in _random_segments(4, 64, 2)],
])
def test_a_run_never_records_more_steps_than_its_bound(name, points, grid):
    spec = get(name)
    cap = 10 ** 7
    recorded = len(spec.record(points, {}, grid, step_cap=cap))
    assert recorded <= budget.step_bound(spec, points, {}, grid, cap)
