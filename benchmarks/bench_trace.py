"""Recording and replay cost of a long Bresenham trace and of a span run.

Prints: recording time against a bare generator running the same loop and
yielding (x, y); bytes retained per step; state_at at random positions;
the same for a scan-line polygon fill, whose Span records write runs.

    python benchmarks/bench_trace.py [--steps 1000000] [--repeats 5]
"""
from __future__ import annotations

import argparse
import collections
import random
import statistics
import sys
import time
import tracemalloc
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from algorithms.core import registry  # noqa: E402
from algorithms.lines import Octant  # noqa: E402


def bare_bresenham(p, q):
    """The same loop as line-bresenham, yielding only (x, y)."""
    octant = Octant(p, q)
    dx, dy = octant.dx, octant.dy
    (ex, ey), (nx, ny) = octant.major, octant.minor
    nx, ny = nx + ex, ny + ey
    x, y = p
    d = 2 * dy - dx
    incr_e, incr_ne = 2 * dy, 2 * (dy - dx)
    yield (x, y)
    for _ in range(dx):
        if d <= 0:
            x += ex
            y += ey
            d += incr_e
        else:
            x += nx
            y += ny
            d += incr_ne
        yield (x, y)


def median_time(action, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    p, q = (0, 0), (args.steps - 1, (args.steps - 1) * 3 // 10)
    spec = registry.get("line-bresenham")

    bare = median_time(lambda: collections.deque(bare_bresenham(p, q), 0), args.repeats)
    recording = median_time(lambda: spec.record([p, q], grid=(4096, 4096)), args.repeats)
    print(f"steps: {args.steps:,} (segment {p} -> {q}, clipped to the grid)")
    print(f"bare generator yielding (x, y): {bare * 1000:8.1f} ms (median of {args.repeats})")
    print(f"recording the trace:            {recording * 1000:8.1f} ms  = {recording / bare:.2f}x the bare loop"
          "  (target <= 4x)")

    tracemalloc.start()
    trace = spec.record([p, q], grid=(4096, 4096))
    retained, _ = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    print(f"retained after recording:       {retained / len(trace):8.1f} bytes per step"
          f"  (columns alone {trace.nbytes() / len(trace):.1f}; target <= 64)")

    for grid in ((4096, 4096), (512, 512)):
        trace = spec.record([p, q], grid=grid)
        build = median_time(lambda: trace.state_at(0), 1)
        rng = random.Random(1)
        positions = [rng.randrange(len(trace)) for _ in range(200)]
        times = []
        for i in positions:
            start = time.perf_counter()
            trace.state_at(i)
            times.append(time.perf_counter() - start)
        times.sort()
        print(f"state_at on a {grid[0]}x{grid[1]} grid: median {statistics.median(times) * 1000:.2f} ms, "
              f"p90 {times[int(0.9 * len(times))] * 1000:.2f} ms over {len(times)} random steps "
              f"(first call, building keyframes: {build * 1000:.0f} ms; target median <= 20 ms); "
              f"with its replay caches the trace holds "
              f"{(trace.nbytes() + trace.cache_nbytes()) / len(trace):.1f} bytes per step")
    span_run(args.repeats)


def span_run(repeats: int) -> None:
    """A scan-line fill on a big grid: few steps, each span writing a long run."""
    spec = registry.get("polygon-scanline")
    contours = [[(0.5, 0.5), (1020, 30), (500, 1020)], [(150, 150), (350, 750), (450, 200)]]
    recording = median_time(lambda: spec.record(contours, grid=(1024, 1024)), repeats)
    trace = spec.record(contours, grid=(1024, 1024))
    pixels = median_time(trace.written_pixels, repeats)
    trace.state_at(0)
    rng = random.Random(2)
    times = []
    for i in (rng.randrange(len(trace)) for _ in range(50)):
        start = time.perf_counter()
        trace.state_at(i)
        times.append(time.perf_counter() - start)
    print(f"polygon-scanline on 1024x1024: {len(trace):,} steps, {len(trace.written_pixels()):,} "
          f"pixels written; recording {recording * 1000:.0f} ms, written_pixels "
          f"{pixels * 1000:.1f} ms, state_at median {statistics.median(times) * 1000:.1f} ms "
          f"over {len(times)} random steps")


if __name__ == "__main__":
    main()
