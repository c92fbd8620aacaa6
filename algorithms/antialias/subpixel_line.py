"""Line supersampling as one lecture draws it: split each pixel into n x n
subpixels and make a pixel's intensity depend on how many of them the
(zero-width) line passes through.

The line runs between the centres of its two end pixels, as the line family
draws it. Subpixels are half-open squares [a, a + 1/n) x [b, b + 1/n), so
they tile the plane and every point of the line lies in exactly one: a
line along a subpixel edge counts the subpixels above or to the right of
it, and one through a corner counts the subpixel whose corner it is. Every
test is exact (whole numbers in units of 1/(2n) px).
"""
from __future__ import annotations

import heapq
import math
from fractions import Fraction

from algorithms.circles.curves import grey_ink
from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Inputs, Option, Oracle
from algorithms.core.steps import PLOT, Start, Vars

N = Option("n", "int", 3, "subpixels per pixel side", minimum=1, maximum=16)
SEGMENT = Inputs(2, integer=True, names=("P", "Q"))


def clip(p, q, box):
    """The parameters (t0, t1) of the part of p + t (q - p), 0 <= t <= 1, in the
    closed box (x0, y0, x1, y1), or None."""
    lo, hi = Fraction(0), Fraction(1)
    for axis in (0, 1):
        d = q[axis] - p[axis]
        low, high = box[axis], box[axis + 2]
        if d == 0:
            if not low <= p[axis] <= high:
                return None
            continue
        a, b = sorted(((low - p[axis]) / d, (high - p[axis]) / d))
        lo, hi = max(lo, a), min(hi, b)
    return (lo, hi) if lo <= hi else None


def visited_cells(p, q, t0, t1) -> list[tuple[int, int]]:
    """The unit cells [i, i + 1) x [j, j + 1) holding a point of p + t (q - p),
    t0 <= t <= t1, in order along the segment (each once)."""
    return list(walk_cells(p, q, t0, t1))


def walk_cells(p, q, t0, t1):
    """``visited_cells`` one cell at a time, made as they are asked for: a
    long line on a big grid meets tens of thousands of grid lines."""
    d = (q[0] - p[0], q[1] - p[1])
    # The t where the segment meets a line x = k or y = k, in increasing t
    # (each axis is, so a merge is), and the midpoints between them: the
    # cells of those points are all the cells the segment passes through.
    ts = heapq.merge([t0], _meetings(p, d, 0, t0, t1), _meetings(p, d, 1, t0, t1), [t1])
    seen, last = set(), None
    for t in ts:
        if t == last:
            continue
        for probe in ((t,) if last is None else ((last + t) / 2, t)):
            cell = (math.floor(p[0] + probe * d[0]), math.floor(p[1] + probe * d[1]))
            if cell not in seen:
                seen.add(cell)
                yield cell
        last = t


def _meetings(p, d, axis: int, t0, t1):
    """The t in t0 .. t1 where the segment meets the lines of ``axis``, increasing."""
    if d[axis] == 0:
        return
    a, b = sorted((p[axis] + t0 * d[axis], p[axis] + t1 * d[axis]))
    ks = range(math.ceil(a), math.floor(b) + 1)
    for k in (ks if d[axis] > 0 else reversed(ks)):
        yield (k - p[axis]) / d[axis]


def subpixel_listing(points, options) -> Code:
    n = options["n"]
    code = Code()
    code.add("setup", f"n = {n}:  each pixel is {n} x {n} subpixels;  the line runs from P's "
                      "centre to Q's, clipped to the grid")
    code.add("plot_pixel", "for each pixel the line reaches:  k = subpixels it passes through;  "
                           "intensity = min(1, k / n)   (n: a straight run across one pixel)",
             PLOT, ops={"samples": 1, "div": 1, "compare": 1})
    code.add("done", "done")
    return code


def subpixel_line(points, options, grid):
    n = options["n"]
    at = subpixel_listing(points, options).at
    yield Start(line=at["setup"], values=("subpixels", "intensity", "rgb"),
                constants={"n": n}, pixel_value="intensity", color_value="rgb")
    # In subpixel units the centre of pixel x is at n x + n / 2.
    p, q = ((Fraction(2 * c + 1) * n / 2 for c in point) for point in points)
    p, q = tuple(p), tuple(q)
    span = clip(p, q, (0, 0, grid[0] * n, grid[1] * n))
    # The cells are walked as the frames go: a pixel's cells come one after
    # another (the segment meets its square in one piece), so a pixel's
    # frame comes when the walk leaves it.
    cells = walk_cells(p, q, *span) if span is not None else ()
    plot, pixels, subpixels = at["plot_pixel"], 0, 0
    for (x, y), k in _pixel_counts(cells, n, grid):
        pixels, subpixels = pixels + 1, subpixels + k
        intensity = min(1.0, k / n)
        yield (plot, x, y, float(k), intensity, grey_ink(intensity))
    yield Vars(line=at["done"], values={"pixels": pixels, "subpixels": subpixels})


def _pixel_counts(cells, n: int, grid):
    """(pixel, number of its cells) for runs of cells on the grid, in order."""
    pixel, count = None, 0
    for i, j in cells:
        if 0 <= i < grid[0] * n and 0 <= j < grid[1] * n:
            if (i // n, j // n) != pixel:
                if pixel is not None:
                    yield pixel, count
                pixel, count = (i // n, j // n), 0
            count += 1
    if pixel is not None:
        yield pixel, count


LINE_SUBPIXELS = AlgorithmSpec(
    name="line-subpixels",
    title="Line supersampling (subpixels crossed)",
    family="antialias",
    summary="split pixels into n x n subpixels; intensity by the number the line passes through",
    inputs=SEGMENT,
    options=(N,),
    code=listing(subpixel_listing),
    generator=subpixel_line,
    uses_grid=True,
    notes=("A line crossing a pixel straight passes through n of its subpixels, so k / n is "
           "full ink there; a diagonal one passes through up to 2n - 1 and is capped at 1.",
           "The line has no width: the count says how long the line runs in the pixel, "
           "roughly, not how much of the pixel it covers (line-area measures that).",
           "Only the part of the line inside the grid is counted."),
    oracle=Oracle(
        "exact",
        "Per pixel, how many of its n x n subpixels' half-open squares the segment meets, by a "
        "brute-force test of every subpixel in Fractions written in the test; intensity "
        "min(1, k / n).",
        ("algorithms/antialias/test_subpixel_line.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (LINE_SUBPIXELS,)
