"""Exact polygon fill against scikit-image, Pillow and OpenCV.

Fills one concave polygon (a jittered star with real-valued vertices) on a
W x W grid with polygon-scanline's fast kernel, which is exact, and with the
three libraries in the same run. Prints each one's median time and the
pixels where it differs from the exact result (extra / missing).

    python benchmarks/bench_polygons.py [--size 2048] [--vertices 400] [--repeats 9] [--halves]

scikit-image and Pillow are test dependencies of RasterLab. OpenCV is not a
dependency at all; install it for this script only, if you want its figures:

    pip install opencv-python-headless

All three libraries put pixel centres at whole coordinates, RasterLab at
halves, so they are given each vertex shifted by (-1/2, -1/2) (after
snapping to 1/256 px, so every library sees the same polygon). Where they
differ from the exact result:

* scikit-image fills by the same even-odd test but also fills every centre
  on the outline (right and top edges too), so it differs only where a
  centre lies exactly on an edge (try --halves);
* Pillow rounds the vertices to whole pixels and fills closed, both
  boundary columns included;
* OpenCV (fixed point, shift=8) fills its rasterized outline as well.
"""
from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from algorithms.polygons import ONE, scanline_mask, scanline_pixels, snap  # noqa: E402


def star(size: int, vertices: int, seed: int, halves: bool = False) -> list[tuple[float, float]]:
    """A concave star filling most of the grid, spikes of random length.

    With ``halves`` the vertices are rounded to half pixels, so many edges
    run through pixel centres, where the libraries' boundary rules differ.
    """
    rng = np.random.default_rng(seed)
    centre = size / 2
    points = []
    for k in range(vertices):
        angle = 2 * math.pi * (k + rng.uniform(-0.3, 0.3)) / vertices
        radius = size * (0.48 if k % 2 == 0 else rng.uniform(0.15, 0.4))
        points.append((centre + radius * math.cos(angle), centre + radius * math.sin(angle)))
    if halves:
        return [(round(2 * x) / 2, round(2 * y) / 2) for x, y in points]
    # Snapped here, so the libraries get exactly the polygon the kernel fills.
    return [(snap(x) / ONE, snap(y) / ONE) for x, y in points]


def timed(action, repeats: int):
    """(median seconds, min seconds, last result) of several runs after one warm-up."""
    result = action()
    times = []
    for _ in range(max(1, repeats)):
        start = time.perf_counter()
        result = action()
        times.append(time.perf_counter() - start)
    return statistics.median(times), min(times), result


def compare(mask: np.ndarray, exact: np.ndarray) -> str:
    extra = int(np.count_nonzero(mask & ~exact))
    missing = int(np.count_nonzero(~mask & exact))
    return f"{extra + missing:>7} differ ({extra} extra, {missing} missing)"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=2048)
    parser.add_argument("--vertices", type=int, default=400)
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument("--skimage-repeats", type=int, default=1,
                        help="scikit-image takes seconds per fill at 2048x2048")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--halves", action="store_true",
                        help="vertices on half pixels: edges through pixel centres")
    args = parser.parse_args(argv)
    size = args.size
    points = star(size, args.vertices, args.seed, args.halves)
    contours = [points]
    options = {"fill_rule": "evenodd", "arithmetic": "exact"}
    xs = np.array([x for x, _ in points]) - 0.5
    ys = np.array([y for _, y in points]) - 0.5

    print(f"polygon: jittered star, {len(points)} vertices{' on half pixels' if args.halves else ''}, "
          f"on a {size}x{size} grid "
          f"(median of {args.repeats} runs after a warm-up)")
    ours, ours_min, exact = timed(lambda: scanline_mask(contours, options, (size, size)),
                                  args.repeats)
    print(f"{'RasterLab kernel, mask':<28} {ours * 1e3:9.2f} ms (min {ours_min * 1e3:.2f})"
          f"   exact: {int(exact.sum())} pixels")
    listed, _, pixels = timed(lambda: scanline_pixels(contours, options), args.repeats)
    print(f"{'RasterLab kernel, pixel list':<28} {listed * 1e3:9.2f} ms"
          f"   {len(pixels)} (x, y) pairs in emission order")
    rows = {}

    try:
        import skimage.draw

        def skimage_fill():
            rr, cc = skimage.draw.polygon(ys, xs, (size, size))
            mask = np.zeros((size, size), dtype=bool)
            mask[rr, cc] = True
            return mask
        rows["scikit-image draw.polygon"] = timed(skimage_fill, args.skimage_repeats)
    except ImportError:
        print("scikit-image: not installed")

    try:
        from PIL import Image, ImageDraw

        def pillow_fill():
            image = Image.new("1", (size, size))
            ImageDraw.Draw(image).polygon(list(zip(xs, ys)), fill=1)
            return image
        median, low, image = timed(pillow_fill, args.repeats)
        rows["Pillow ImageDraw.polygon"] = (median, low, np.asarray(image, dtype=bool))
    except ImportError:
        print("Pillow: not installed")

    try:
        import cv2
        fixed = np.array([[[snap(x), snap(y)] for x, y in zip(xs, ys)]], dtype=np.int32)

        def opencv_fill():
            mask = np.zeros((size, size), dtype=np.uint8)
            cv2.fillPoly(mask, fixed, 1, lineType=cv2.LINE_8, shift=8)
            return mask
        median, low, mask = timed(opencv_fill, args.repeats)
        rows["OpenCV fillPoly (shift=8)"] = (median, low, mask.astype(bool))
    except ImportError:
        print("OpenCV: not installed (pip install opencv-python-headless)")

    for name, (median, low, mask) in rows.items():
        print(f"{name:<28} {median * 1e3:9.2f} ms (min {low * 1e3:.2f})   {compare(mask, exact)}")
    print()
    if "scikit-image draw.polygon" in rows:
        print(f"RasterLab is {rows['scikit-image draw.polygon'][0] / ours:.0f}x faster than "
              "scikit-image (target: at least 50x)")
    if "Pillow ImageDraw.polygon" in rows:
        print(f"RasterLab takes {ours / rows['Pillow ImageDraw.polygon'][0]:.1f}x Pillow's time "
              "(target: within 10x)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
