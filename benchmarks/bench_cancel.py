"""Cancel: how long a recording goes on after Cancel, on the largest inputs.

For every algorithm on a 4096 x 4096 grid (its example shape made large),
and for the heavy cases of the issue (100,000-vertex polygons for the seed
fill, the tessellation and polygon supersampling, 33,333 triangles, the
temporal wheel), a recording runs in a background job as the window runs
it (at the default step cap, or a lower one the memory budget takes), is
cancelled after each delay, and the time from the cancel to the job's end
is printed (a run the budget refuses is named, not run). A run that ends
before its delay prints "ended first".

    python benchmarks/bench_cancel.py [--delays 0.25,1.5] [--only NAME]
"""
from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from algorithms.core import registry  # noqa: E402
from algorithms.core.trace import DEFAULT_STEP_CAP  # noqa: E402
from app.model.budget import BudgetError, check_budget  # noqa: E402
from app.model.examples import default_scene  # noqa: E402
from app.model.inputs import runnable_input  # noqa: E402
from app.model.recording import Job  # noqa: E402

GRID = (4096, 4096)
N = 100_000


def _zigzag(count: int) -> list:
    """Edges that each run the grid's height: no pixel inside is free."""
    return [(0 if k % 2 else 4095, k * 4095 // count) for k in range(count)]


def _ring(count: int, integer: bool) -> list:
    points = [(2048 + 2000 * math.cos(2 * math.pi * k / count),
               2048 + 2000 * math.sin(2 * math.pi * k / count)) for k in range(count)]
    return [(int(x), int(y)) for x, y in points] if integer else points


def _triangles(count: int) -> list:
    """Thin triangles stacked over the grid's middle: every sample tests them all."""
    return [p for k in range(count) for p in ((100.0 + k % 7, 100.0), (3990.0, 2048.0 + k % 5),
                                              (100.0, 3990.0))]


def heavy_cases():
    yield "flood-fill, 100k-vertex zigzag, seed search", "flood-fill", [_zigzag(N)], {}
    yield ("flood-fill, 100k-vertex zigzag outline", "flood-fill", [_zigzag(N)],
           {"seed": (5, 4095)})
    yield "flood-fill, 100k-vertex ring", "flood-fill", [_ring(N, True)], {}
    yield "polygon-tessellate, 100k-vertex ring", "polygon-tessellate", [_ring(N, False)], {}
    yield ("aa-supersample polygon, 100k-vertex ring, n=8", "aa-supersample",
           _ring(N, False), {"shape": "polygon", "n": 8})
    yield ("aa-supersample, 33,333 triangles, n=8", "aa-supersample", _triangles(N // 3),
           {"n": 8})
    yield ("aa-temporal motion blur, radius 2000", "aa-temporal", [(2048.0, 2048.0)],
           {"mode": "motion-blur", "time_samples": 64, "n": 8, "radius": 2000.0})


def example_cases():
    for spec in registry.all_specs():
        points, breaks, options = default_scene(spec, GRID)
        yield f"{spec.name}, example on 4096^2", spec.name, \
            runnable_input(spec, points, breaks), options


def measure(name, points, options, delay: float, cap: int) -> str:
    spec = registry.get(name)
    job = Job(lambda monitor: spec.record(points, options, GRID, step_cap=cap,
                                          monitor=monitor)).start()
    if job.wait(delay):
        return "ended first" if job.error is None else f"failed ({type(job.error).__name__})"
    cancelled = time.perf_counter()
    job.cancel()
    job.wait(None)
    return f"{(job.finished_at - cancelled) * 1000:7.1f} ms"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--delays", default="0.25,1.5")
    parser.add_argument("--only", default="")
    args = parser.parse_args()
    delays = [float(d) for d in args.delays.split(",")]
    print(f"{'case':58} " + " ".join(f"cancel at {d:g} s" for d in delays))
    for label, name, points, options in [*heavy_cases(), *example_cases()]:
        if args.only and args.only not in label:
            continue
        cap = fitting_cap(registry.get(name), points, options)
        if isinstance(cap, str):
            print(f"{label:58} refused by the budget: {cap[:70]}...")
            continue
        figures = [measure(name, points, options, delay, cap) for delay in delays]
        print(f"{label:58} " + "   ".join(figures) + f"   (cap {cap:,})", flush=True)


def fitting_cap(spec, points, options):
    """The default step cap, or a lower one the budget takes; or the refusal."""
    for cap in (DEFAULT_STEP_CAP, 1_000_000, 100_000):
        try:
            check_budget(spec, points, spec.resolve(options), GRID, cap)
            return cap
        except BudgetError as error:
            refusal = str(error)
    return refusal


if __name__ == "__main__":
    main()
