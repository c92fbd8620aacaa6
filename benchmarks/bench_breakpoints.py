"""Breakpoint searches and step units on a long Bresenham trace.

Prints, per condition and unit: the first search (which scans the trace's
columns with numpy once) and a later one (a binary search in the kept
stops), in milliseconds.

    python benchmarks/bench_breakpoints.py [--steps 1000000]
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from algorithms.lines import bresenham, bresenham_code  # noqa: E402
from algorithms.core.trace import Trace  # noqa: E402
from app.model import breakpoints as bp  # noqa: E402


def timed(call):
    start = time.perf_counter()
    result = call()
    return (time.perf_counter() - start) * 1000, result


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=1_000_000)
    steps = parser.parse_args(argv).steps
    points = [(0, 0), (steps, steps * 3 // 8 + 1)]
    ms, trace = timed(lambda: Trace.record(bresenham(points, {}), bresenham_code(points, {}),
                                           4096, 4096, step_cap=steps + 10))
    print(f"recorded {len(trace):,} steps in {ms:.0f} ms")
    middle = len(trace) // 2
    pixel = tuple(int(v) for v in trace.step(middle + 1000).pixel)
    for condition in ("sign", "branch", "scanline", ("pixel", pixel)):
        first, found = timed(lambda: bp.next_stop(trace, middle, condition))
        again, back = timed(lambda: bp.next_stop(trace, middle + 10, condition, -1))
        print(f"{str(condition):28} first {first:7.2f} ms -> {found}; "
              f"later {again:6.3f} ms -> {back}")
    for unit in ("decision", "scanline"):
        first, found = timed(lambda: bp.step_target(trace, middle, unit, 1))
        print(f"step by {unit:20} first {first:7.2f} ms -> {found}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
