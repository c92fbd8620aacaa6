"""Triangle fill speed: the exact span kernel against scikit-image and Pillow.

Two workloads on a 1024 x 1024 grid, the same triangles for every
contender, timed in the same run:

* large: triangles whose bounding box is the whole 1024 x 1024 grid;
* small: 10,000 triangles of a few pixels each, scattered over the grid.

Contenders, each writing into a framebuffer allocated beforehand:

* kernel -> counts: triangles.fill, exact top-left coverage counts, all
  triangles in one call (and, for the large workload, one call each);
* kernel -> pixels: the registered kernel's (n, 2) pixel list (what a
  trace or a test compares against);
* skimage.draw.polygon: coordinates per triangle, added into the counts;
* Pillow ImageDraw.polygon: drawn into an 8-bit image per triangle (it
  cannot count, so the small workload is compared as a union). Pillow
  rounds vertices to whole pixels and includes the outline, so it differs
  on every edge; small triangles differ the most.

Coordinates: our pixel (i, j) is sampled at (i + 1/2, j + 1/2); scikit-image
and Pillow sample pixel (c, r) at the integer point, so their vertices are
shifted by -1/2. Their boundary rules differ from top-left, so their
pixels differ on edges; the differing pixel counts are printed. Times are
the best of --repeats runs (time.perf_counter); fragments/s = covered
pixels (exact count) / time.

    python benchmarks/bench_triangles.py [--large 20] [--small 10000] [--repeats 5]
"""
from __future__ import annotations

import argparse
import sys
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from algorithms.exact import triangles as exact_triangles
from algorithms import triangles  # noqa: E402

SIZE = 1024


def large_triangles(n: int, rng) -> np.ndarray:
    """n triangles touching all four sides of [0, 1024]^2, on the 1/256 grid."""
    tris = []
    for _ in range(n):
        u, v = rng.uniform(0.05, 0.95, 2)
        corner = [(u * SIZE, 0.0), (SIZE, v * SIZE), (0.0, SIZE)]
        if rng.random() < 0.5:  # the other diagonal shape
            corner = [(0.0, u * SIZE), (v * SIZE, 0.0), (SIZE, SIZE)]
        tris += corner
    return np.round(np.array(tris) * 256) / 256


def small_triangles(n: int, rng) -> np.ndarray:
    centres = rng.uniform(8, SIZE - 8, (n, 1, 2))
    offsets = rng.uniform(-6, 6, (n, 3, 2))
    return (np.round((centres + offsets) * 256) / 256).reshape(-1, 2)


def best_time(run, repeats: int, reset=None):
    best = float("inf")
    result = None
    for _ in range(repeats):
        if reset is not None:
            reset()
        start = time.perf_counter()
        result = run()
        best = min(best, time.perf_counter() - start)
    return best, result


# ------------------------------------------------------------ contenders
def kernel_counts(points):
    return triangles.fill(points, (SIZE, SIZE))


def kernel_pixels(points):
    return triangles.kernel_pixels(points, {"subpixel_bits": 8, "fill_rule": "top-left"},
                                   (SIZE, SIZE))


def skimage_counts(points, counts):
    from skimage.draw import polygon

    for k in range(0, len(points), 3):
        tri = points[k:k + 3]
        rr, cc = polygon(tri[:, 1] - 0.5, tri[:, 0] - 0.5, (SIZE, SIZE))
        counts[rr, cc] += 1
    return counts


def pillow_images(points, draws):
    for n, k in enumerate(range(0, len(points), 3)):
        tri = [(float(x) - 0.5, float(y) - 0.5) for x, y in points[k:k + 3]]
        draws[n % len(draws)].polygon(tri, fill=1)
    return draws


# ------------------------------------------------------------- checks
def sampled_exactness(points, rng, samples=3000, most=20) -> int:
    """Mismatches between the kernel and the Fraction oracle at random pixels near triangles.

    Each of (at most ``most``) triangles is filled alone and sampled in its
    bounding box, so overlaps between triangles do not matter.
    """
    bad = 0
    tris = exact_triangles.triangles_of([tuple(map(float, p)) for p in points])[:most]
    per = max(1, samples // len(tris))
    for tri in tris:
        alone = triangles.fill(np.array(tri), (SIZE, SIZE))
        snapped = exact_triangles.snap_triangle(tri, 8)
        xs = [float(p[0]) for p in snapped]
        ys = [float(p[1]) for p in snapped]
        for _ in range(per):
            i = int(rng.integers(max(0, int(min(xs)) - 1), min(SIZE, int(max(xs)) + 1)))
            j = int(rng.integers(max(0, int(min(ys)) - 1), min(SIZE, int(max(ys)) + 1)))
            want = exact_triangles.covers(snapped, (Fraction(2 * i + 1, 2), Fraction(2 * j + 1, 2)),
                                          "top-left")
            bad += want != bool(alone[j, i])
    return bad


def python_exactness(points) -> int:
    """Pixels where the int64 kernel and the same bounds in Python integers differ."""
    tris = [s.tri.ccw() for s in triangles.prepare([tuple(p) for p in points],
                                                   {"subpixel_bits": 8, "fill_rule": "top-left",
                                                    "cull": False}) if s.tri]
    spans = [triangles._spans_python(t, n, 256, "top-left", (0, 0, SIZE, SIZE))
             for n, t in enumerate(tris)]
    counts = np.zeros((SIZE, SIZE), np.int32)
    for _, ys, starts, ends in spans:
        for y, s, e in zip(ys.tolist(), starts.tolist(), ends.tolist()):
            counts[y, s:e] += 1
    return int(np.abs(counts - kernel_counts(points)).sum())


def report(name, points, repeats, rng, per_triangle_compare):
    from PIL import Image, ImageDraw

    k = len(points) // 3
    counts = kernel_counts(points)
    fragments = int(counts.sum())
    print(f"\n{name}: {k} triangles on {SIZE}x{SIZE}, {fragments:,} fragments "
          f"({fragments / k:,.1f} per triangle)")

    rows = []
    t, _ = best_time(lambda: kernel_counts(points), repeats)
    rows.append(("kernel -> counts (exact)", t, 0))
    if per_triangle_compare:  # the same, one call per triangle: no batching across triangles
        t, _ = best_time(lambda: [kernel_counts(points[n:n + 3]) for n in range(0, len(points), 3)],
                         repeats)
        rows.append(("  ... one call per triangle", t, 0))
    t, pixels = best_time(lambda: kernel_pixels(points), repeats)
    assert len(pixels) == fragments
    rows.append(("kernel -> pixel list (exact)", t, 0))

    fb = np.zeros((SIZE, SIZE), np.int32)
    t, sk = best_time(lambda: skimage_counts(points, fb), max(1, repeats // 2), reset=lambda: fb.fill(0))
    rows.append(("skimage.draw.polygon", t, int((sk != counts).sum())))

    images = [Image.new("L", (SIZE, SIZE), 0) for _ in range(k if per_triangle_compare else 1)]

    def clear():
        for image in images:
            image.paste(0, (0, 0, SIZE, SIZE))

    draws = [ImageDraw.Draw(image) for image in images]
    t, _ = best_time(lambda: pillow_images(points, draws), max(1, repeats // 2), reset=clear)
    if per_triangle_compare:
        diff = 0
        for n, image in enumerate(images):
            mine = triangles.fill(points[3 * n:3 * n + 3], (SIZE, SIZE)) > 0
            diff += int(((np.asarray(image) > 0) ^ mine).sum())
    else:
        diff = int(((np.asarray(images[0]) > 0) ^ (counts > 0)).sum())
    rows.append(("Pillow ImageDraw.polygon", t, diff))

    print(f"  {'contender':<30} {'time':>10} {'fragments/s':>14} {'vs kernel':>9} {'pixels differing':>17}")
    base = rows[0][1]
    for label, seconds, differing in rows:
        print(f"  {label:<30} {seconds * 1e3:8.2f} ms {fragments / seconds / 1e6:10.1f} M/s "
              f"{seconds / base:8.1f}x {differing:>17,}")
    print(f"  exactness: {sampled_exactness(points, rng)} mismatches against the "
          f"Fraction oracle at sampled pixels; {python_exactness(points)} against the "
          f"Python-integer span bounds on every pixel")
    return rows


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--large", type=int, default=20, help="large triangles (default 20)")
    parser.add_argument("--small", type=int, default=10_000, help="small triangles (default 10000)")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    print(f"numpy {np.__version__}; best of {args.repeats} runs (contenders from other "
          "libraries: best of half as many)")
    report("large", large_triangles(args.large, rng), args.repeats, rng, True)
    report("small", small_triangles(args.small, rng), args.repeats, rng, False)


if __name__ == "__main__":
    main()
