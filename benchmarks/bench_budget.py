"""The budget's figures: seconds per recorded step, and estimates against peaks.

``--steps``: for every algorithm, its example scene on a GRID x GRID grid
recorded up to CAP steps (once; in this process), printed as microseconds
per step and rich-table rows per step, the figures app/model/budget.py's
time model is calibrated from (the largest of each family, rounded up).

``--ratios``: for every algorithm, its example scene on a GRID x GRID grid
recorded in full (those estimated above a minute skipped), printed as the
seconds taken against the time estimate; a ratio above 1 is an estimate
that is too low.

``--peaks``: for a few scenes (among them star polygons of 4,000 and 20,000
vertices, made by ``star_scene``), `rasterlab run --scene` in a fresh child
process: its resident peak (``os.wait4``'s rusage of that child alone)
against the budget's estimate.

    python benchmarks/bench_budget.py [--steps] [--ratios] [--peaks] [--grid 1024] [--cap 100000]
"""
from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from algorithms.core import registry  # noqa: E402
from algorithms.core.steps import Table  # noqa: E402
from app.model import budget  # noqa: E402
from app.model.examples import default_scene  # noqa: E402
from app.model.inputs import runnable_input  # noqa: E402
from app.model.scene import Scene, save  # noqa: E402

MB = 1024 ** 2


def star_scene(vertices: int, grid: int = 4096) -> Scene:
    """A star polygon of ``vertices`` points (alternate radii 2000 and 1900
    around the grid's centre): most scan lines meet a few edges while the ET still holds most of them."""
    centre = grid // 2
    points = []
    for k in range(vertices):
        radius = 2000 * grid // 4096 if k % 2 == 0 else 1900 * grid // 4096
        angle = 2 * math.pi * k / vertices
        points.append((round(centre + radius * math.cos(angle)),
                       round(centre + radius * math.sin(angle))))
    return Scene(algorithm="polygon-scanline", points=[points], width=grid, height=grid)


def zigzag_scene(vertices: int, grid: int = 4096) -> Scene:
    """A polygon-scanline scene of a zigzag of ``vertices`` points climbing
    the grid, each edge one row high: every row meets about ten edges while
    the ET still holds the thousands above it (the snapshots kept grow as
    edges x steps)."""
    top = grid - 48
    points = [(200.0 if k % 2 else grid - 200.0, 8 + (top - 8) * k / vertices + k % 2)
              for k in range(vertices)]
    return Scene(algorithm="polygon-scanline", points=[points], width=grid, height=grid)


def step_costs(grid: int, cap: int) -> None:
    print(f"{'algorithm':<28} {'family':<11} {'steps':>8} {'us/step':>8} {'rows/step':>9}")
    for spec in registry.all_specs():
        points, breaks, options = default_scene(spec, (grid, grid))
        points = runnable_input(spec, points, breaks)
        start = time.perf_counter()
        trace = spec.record(points, options, (grid, grid), step_cap=cap)
        seconds = time.perf_counter() - start
        rows = sum(len(table.rows) for _, table in trace.records_of(Table))
        print(f"{spec.name:<28} {spec.family:<11} {len(trace):>8} "
              f"{1e6 * seconds / len(trace):>8.1f} {rows / len(trace):>9.1f}")


def time_ratios(grid: int, cap: int) -> None:
    print(f"{'algorithm':<28} {'steps':>8} {'seconds':>8} {'estimate':>9} {'ratio':>6}")
    for spec in registry.all_specs():
        points, breaks, options = default_scene(spec, (grid, grid))
        points = runnable_input(spec, points, breaks)
        estimate = budget.estimate_seconds(spec, points, options, (grid, grid), cap)
        if estimate > 60:
            print(f"{spec.name:<28} skipped: estimated {estimate:.0f} s")
            continue
        start = time.perf_counter()
        trace = spec.record(points, options, (grid, grid), step_cap=cap)
        seconds = time.perf_counter() - start
        print(f"{spec.name:<28} {len(trace):>8} {seconds:>8.2f} {estimate:>9.2f} "
              f"{seconds / estimate:>6.2f}")


def child_peak(argv: list[str]) -> tuple[int, int, float]:
    """(exit status, resident peak in bytes, seconds) of a fresh child."""
    start = time.perf_counter()
    child = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                             cwd=ROOT)
    _, status, usage = os.wait4(child.pid, 0)
    peak = usage.ru_maxrss * (1 if sys.platform == "darwin" else 1024)
    return os.waitstatus_to_exitcode(status), peak, time.perf_counter() - start


def peaks() -> None:
    cases = [(star_scene(4000), 5000), (star_scene(4000), 20000), (star_scene(20000), 2000),
             (star_scene(20000), 6000)]
    with tempfile.TemporaryDirectory() as folder:
        baseline = child_peak([sys.executable, "-m", "rasterlab", "list"])[1]
        print(f"baseline (rasterlab list): {baseline / MB:.0f} MB")
        for scene, cap in cases:
            path = Path(folder) / "scene.json"
            save(scene, path)
            estimate = budget.estimate_memory(scene.spec, scene.points, scene.options,
                                              scene.grid, cap)
            status, peak, seconds = child_peak(
                [sys.executable, "-m", "rasterlab", "run", "--scene", str(path), "--step-cap",
                 str(cap), "--memory-limit", "64G", "--time-limit", "100000"])
            print(f"{scene.algorithm} {len(scene.points[0])} vertices, cap {cap}: "
                  f"estimate {estimate / MB:.0f} MB, peak {peak / MB:.0f} MB "
                  f"(over baseline {(peak - baseline) / MB:.0f} MB), {seconds:.1f} s, "
                  f"exit {status}")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", action="store_true")
    parser.add_argument("--ratios", action="store_true")
    parser.add_argument("--peaks", action="store_true")
    parser.add_argument("--grid", type=int, default=1024)
    parser.add_argument("--cap", type=int, default=100_000)
    args = parser.parse_args()
    if args.steps:
        step_costs(args.grid, args.cap)
    if args.ratios:
        time_ratios(args.grid, args.cap)
    if args.peaks:
        peaks()


if __name__ == "__main__":
    main()
