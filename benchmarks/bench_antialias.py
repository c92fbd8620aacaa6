"""Supersampling speed against error, and the exact coverage it is measured against.

Random triangles on a 512 x 512 grid (vertices uniform over the grid, on
the 1/256 px lattice, so the supersampled shape and the exact one are the
same triangle). For every sample pattern (grid, jitter, random,
rotated-grid) and n = 1, 2, 4, 8 (n x n samples per pixel, box filter) the
vectorised kernel ``antialias.supersample_image`` draws each triangle on
its own, and its coverage is compared with ``exact_coverage``:

* time: the kernel's total over all triangles (best of --repeats), and
  samples per second (pixels of the triangles' boxes x n^2 / time);
* rms edge: root mean square error over the pixels the exact coverage
  puts strictly between 0 and 1 (the edge pixels: elsewhere every method
  is exact);
* rms grid: the same over all pixels of the grid, every triangle;
* max: the largest error of any pixel.

Then the filters on the 4 x 4 grid (weighted, tent and gaussian estimate a
differently weighted average, so their error against the box coverage
does not vanish), and the exact coverage itself: the float64 vectorised
path per triangle, the union of all triangles in one call (cut into
trapezoids first), and the Fraction path on a single small triangle.

    python benchmarks/bench_antialias.py [--triangles 20] [--repeats 1] [--size 512]
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from algorithms import antialias as aa  # noqa: E402
from algorithms.exact import coverage as ec  # noqa: E402


def random_triangles(count: int, size: int, rng) -> list[list[tuple[float, float]]]:
    tris = []
    while len(tris) < count:
        pts = np.round(rng.uniform(0, size, (3, 2)) * 256) / 256
        if abs(ec.twice_signed_area([tuple(p) for p in pts])) > 0:
            tris.append([tuple(map(float, p)) for p in pts])
    return tris


def best_time(function, repeats: int):
    best, result = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        result = function()
        best = min(best, time.perf_counter() - start)
    return best, result


def box_pixels(tri, size: int) -> int:
    xs = [p[0] for p in tri]
    ys = [p[1] for p in tri]
    width = min(int(max(xs)) + 1, size) - max(int(min(xs)), 0)
    height = min(int(max(ys)) + 1, size) - max(int(min(ys)), 0)
    return width * height


def errors(estimates, exacts):
    edge, whole = [], []
    worst = 0.0
    for estimate, exact in zip(estimates, exacts):
        diff = estimate - exact
        mask = (exact > 0) & (exact < 1)
        edge.append(diff[mask])
        whole.append(diff.ravel())
        worst = max(worst, float(np.abs(diff).max()))
    edge, whole = np.concatenate(edge), np.concatenate(whole)
    return float(np.sqrt(np.mean(edge ** 2))), float(np.sqrt(np.mean(whole ** 2))), worst


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--triangles", type=int, default=20)
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--seed", type=int, default=2024)
    args = parser.parse_args(argv)
    size = args.size
    grid = (size, size)
    rng = np.random.default_rng(args.seed)
    tris = random_triangles(args.triangles, size, rng)
    pixels = sum(box_pixels(t, size) for t in tris)
    edge_pixels = 0

    print(f"{len(tris)} random triangles on a {size} x {size} grid "
          f"({pixels:,} pixels in their bounding boxes), best of {args.repeats}")

    # ------------------------------------------------------------ exact
    exact_time, exacts = best_time(lambda: [ec.triangle_coverage(t, grid) for t in tris],
                                   args.repeats)
    areas = [abs(ec.twice_signed_area(t)) / 2 for t in tris]
    drift = max(abs(e.sum() - a) / a for e, a in zip(exacts, areas))
    edge_pixels = sum(int(((e > 0) & (e < 1)).sum()) for e in exacts)

    print()
    print(f"{'pattern':<13}{'n':>3}{'time s':>10}{'Msamples/s':>12}{'rms edge':>11}"
          f"{'rms grid':>11}{'max':>9}")
    for pattern in aa.PATTERNS:
        for n in (1, 2, 4, 8):
            options = {"pattern": pattern, "n": n, "filter": "box", "seed": 7}
            elapsed, estimates = best_time(
                lambda: [aa.supersample_image(t, options, grid, colors=False)[0] for t in tris],
                args.repeats)
            rms_edge, rms_grid, worst = errors(estimates, exacts)
            rate = pixels * n * n / elapsed / 1e6
            print(f"{pattern:<13}{n:>3}{elapsed:>10.3f}{rate:>12.1f}{rms_edge:>11.5f}"
                  f"{rms_grid:>11.6f}{worst:>9.4f}")

    print()
    print("filters on the 4 x 4 grid (error against the box coverage)")
    print(f"{'filter':<13}{'time s':>13}{'rms edge':>11}{'rms grid':>11}{'max':>9}")
    for name in aa.FILTERS:
        options = {"pattern": "grid", "n": 4, "filter": name, "sigma": 0.5}
        elapsed, estimates = best_time(
            lambda: [aa.supersample_image(t, options, grid, colors=False)[0] for t in tris],
            args.repeats)
        rms_edge, rms_grid, worst = errors(estimates, exacts)
        print(f"{name:<13}{elapsed:>13.3f}{rms_edge:>11.5f}{rms_grid:>11.6f}{worst:>9.4f}")

    print()
    print("exact coverage")
    print(f"  float64, one triangle at a time: {exact_time:.3f} s for {len(tris)} triangles "
          f"({exact_time / len(tris) * 1e3:.1f} ms each, {edge_pixels:,} edge pixels); "
          f"largest relative error of the sum against the area: {drift:.1e}")
    union_time, union = best_time(
        lambda: ec.triangle_coverage([p for t in tris for p in t], grid), args.repeats)
    print(f"  float64, the union of all {len(tris)} in one call (trapezoids): {union_time:.3f} s, "
          f"covered area {union.sum():,.2f} px^2")
    small = [(3.3, 2.1), (40.7, 9.2), (12.25, 35.5)]
    fraction_time, exact = best_time(lambda: ec.triangle_coverage(small, (48, 40), exact=True),
                                     args.repeats)
    floats = ec.triangle_coverage(small, (48, 40))
    print(f"  Fractions, one triangle in a 48 x 40 grid: {fraction_time:.3f} s; largest "
          f"difference from float64: {np.abs(ec.as_float(exact) - floats).max():.1e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
