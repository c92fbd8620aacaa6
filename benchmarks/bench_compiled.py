"""What numba costs and what it saves: the figures of docs/developers/numba.md.

Each figure is taken in fresh processes (a process pays numba's import and
compile or cache load once), and printed as the median over --repeats:

* ``import numba``: wall time of the import alone;
* first call: every workload below called once, wall and CPU time, with
  numba's cache empty (NUMBA_CACHE_DIR a new folder: the loops compile) and
  with it filled by an earlier process (they load);
* steady state: each workload's median time per call after a first call,
  with numba and with numba made unimportable (the plain Python loops), and
  whether both gave the same pixels;
* the installed size of numba and llvmlite.

    python benchmarks/bench_compiled.py [--repeats 5]

The workloads are those of run_all.py's kernels section (--quick sizes).
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
SIZE = 1024


def workloads() -> dict:
    """name -> a call of a compiled kernel's public function; each returns its canvas."""
    from algorithms import triangles
    from algorithms.antialias.wu_kernel import draw_wu_lines
    from algorithms.core import registry
    from algorithms.polygons import scanline_fill_many

    rng = np.random.default_rng(7)
    large = np.array([p for u, v in rng.uniform(0.05, 0.95, (20, 2))
                      for p in ((u * SIZE, 0.0), (SIZE, v * SIZE), (0.0, SIZE))])
    small = (rng.uniform(8, SIZE - 8, (10_000, 1, 2)) + rng.uniform(-6, 6, (10_000, 3, 2)))
    polygons = rng.uniform(8, SIZE - 8, (2000, 1, 2)) + rng.uniform(-6, 6, (2000, 5, 2))
    ends = rng.integers(20, SIZE - 20, (200, 1, 2)) + rng.integers(-8, 9, (200, 2, 2))
    flood = registry.get("flood-fill")
    square = [(1, 1), (SIZE - 2, 1), (SIZE - 2, SIZE - 2), (1, SIZE - 2)]
    seeded = flood.resolve({"seed": (SIZE // 2, SIZE // 2)})

    def canvas():
        return np.zeros((SIZE, SIZE), np.uint8)

    return {
        "fill_canvas, 20 large triangles": lambda: triangles.fill_canvas(
            large, (SIZE, SIZE), canvas(), 1),
        "fill_canvas, 10k small triangles": lambda: triangles.fill_canvas(
            small.reshape(-1, 2), (SIZE, SIZE), canvas(), 1),
        "scanline_fill_many, 2000 polygons": lambda: scanline_fill_many(
            polygons, (SIZE, SIZE), canvas(), 1),
        "draw_wu_lines, 200 lines": lambda: draw_wu_lines(canvas(), ends[:, 0], ends[:, 1]),
        "flood-fill kernel, 1024^2": lambda: flood.kernel([square], seeded, (SIZE, SIZE)),
    }


def worker(mode: str, repeats: int) -> None:
    """In a fresh process: print one JSON object of this process's figures."""
    from algorithms.core.compiled import path

    out = {"path": path(), "first": {}, "steady": {}, "digest": {}}
    start_wall, start_cpu = time.perf_counter(), time.process_time()
    for name, work in workloads().items():
        wall, cpu = time.perf_counter(), time.process_time()
        result = work()
        out["first"][name] = (time.perf_counter() - wall, time.process_time() - cpu)
        out["digest"][name] = hashlib.sha256(np.ascontiguousarray(result).tobytes()).hexdigest()
        if mode == "steady":
            out["steady"][name] = statistics.median(_seconds(work) for _ in range(repeats))
    out["total"] = (time.perf_counter() - start_wall, time.process_time() - start_cpu)
    print(json.dumps(out))


def _seconds(work) -> float:
    start = time.perf_counter()
    work()
    return time.perf_counter() - start


def _run(mode: str, repeats: int, cache: str, numba: bool = True) -> dict:
    # Without numba: a None in sys.modules makes `import numba` raise ImportError.
    code = ("import sys; " + ("" if numba else "sys.modules['numba'] = None; ")
            + f"sys.path.insert(0, {str(ROOT / 'benchmarks')!r}); "
            + f"import bench_compiled; bench_compiled.worker({mode!r}, {repeats})")
    env = {**os.environ, "NUMBA_CACHE_DIR": cache, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                          check=True)
    return json.loads(done.stdout.splitlines()[-1])


def import_seconds() -> float:
    code = "import time; t = time.perf_counter(); import numba; print(time.perf_counter() - t)"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return float(done.stdout)


def installed_megabytes(name: str) -> float:
    folder = Path(__import__(name).__file__).parent
    return sum(f.stat().st_size for f in folder.rglob("*") if f.is_file()) / 1e6


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    repeats = parser.parse_args().repeats
    median = statistics.median
    print(f"import numba: {median(import_seconds() for _ in range(repeats)):.2f} s wall")
    cold, warm = [], []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as cache:
            cold.append(_run("first", 1, cache))
            warm.append(_run("first", 1, cache))
    for label, runs in (("empty cache (compile)", cold), ("filled cache (load)", warm)):
        print(f"first call of every workload, {label}, path {runs[0]['path']}: "
              f"{median(r['total'][0] for r in runs):.2f} s wall, "
              f"{median(r['total'][1] for r in runs):.2f} s CPU")
        for name in runs[0]["first"]:
            print(f"  {name:<36} {median(r['first'][name][0] for r in runs):6.2f} s wall "
                  f"{median(r['first'][name][1] for r in runs):6.2f} s CPU")
    with tempfile.TemporaryDirectory() as cache:
        _run("first", 1, cache)
        fast, plain = _run("steady", repeats, cache), _run("steady", repeats, cache, numba=False)
    print(f"steady state, median of {repeats} calls: path {fast['path']} | path {plain['path']}")
    for name, seconds in fast["steady"].items():
        same = "same pixels" if fast["digest"][name] == plain["digest"][name] else "PIXELS DIFFER"
        print(f"  {name:<36} {seconds * 1e3:9.2f} ms | {plain['steady'][name] * 1e3:9.2f} ms "
              f"(first call {plain['first'][name][0]:.2f} s)  {same}")
    for name in ("numba", "llvmlite"):
        print(f"installed size of {name}: {installed_megabytes(name):.0f} MB")


if __name__ == "__main__":
    main()
