"""Supersampling: n x n samples per pixel, where they lie (pattern) and what they weigh (filter)."""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from algorithms.core.code import Code
from algorithms.core.registry import InputError, Option
from algorithms.core.steps import PLOT, VISIT, Note, Start, Table, Vars

from .shapes import (BACKGROUND, LOOP, NAN, SHAPE_OPTIONS, SNAP, UNIT, WHITE, Shapes, blend,
                     code_shapes, ops_sum, sample_ops, shape_vars, test_ops)

PATTERNS = ("grid", "jitter", "random", "rotated-grid")
# The buffer a pixel's weighted samples are summed in (shown as cover / W:
# the running coverage of the pixel's samples tested so far).
ACCUMULATION = "accumulation buffer"
FILTERS = ("box", "weighted", "tent", "gaussian")

PATTERN = Option("pattern", "choice", "grid", "where the samples lie in the pixel: a grid, "
                 "a jittered (stratified) grid, random, or a rotated grid", choices=PATTERNS)
N = Option("n", "int", 4, "samples per pixel: n x n", minimum=1, maximum=8)
FILTER = Option("filter", "choice", "box", "how the samples of a pixel are weighted: box "
                "(equally), weighted (more toward the centre; the 4 x 4 kernel 1 2 2 1 / "
                "2 3 3 2 / ... for n = 4), tent or gaussian", choices=FILTERS)
SIGMA = Option("sigma", "float", 0.5, "standard deviation of the gaussian filter, in px",
               minimum=0.05, maximum=4)
SEED = Option("seed", "int", 1, "seed of the random and jittered samples",
              minimum=0, maximum=2 ** 31 - 1)
SUPERSAMPLE_OPTIONS = (PATTERN, N, FILTER, SIGMA, SEED) + SHAPE_OPTIONS


_GAMMA = np.uint64(0x9E3779B97F4A7C15)


def _mix(z: np.ndarray) -> np.ndarray:
    """SplitMix64's finaliser: a bijection of 64-bit words that scatters every bit."""
    z = z ^ (z >> np.uint64(30))
    z = z * np.uint64(0xBF58476D1CE4E5B9)
    z = z ^ (z >> np.uint64(27))
    z = z * np.uint64(0x94D049BB133111EB)
    return z ^ (z >> np.uint64(31))


def random_bits(seed: int, x, y, stream) -> np.ndarray:
    """32 pseudo-random bits (int64) for each (seed, x, y, stream), from a counter-based hash.

    Each pixel's numbers depend on the seed and the pixel alone, not on the
    order or the window they are asked for in.
    """
    with np.errstate(over="ignore"):
        z = _mix(np.uint64(seed) + _GAMMA)
        for part in (x, y, stream):
            z = _mix(z ^ (np.asarray(part).astype(np.uint64) + _GAMMA))
    return (z >> np.uint64(32)).astype(np.int64)


def sample_strata(pattern: str, n: int, seed: int, y: int, xs: np.ndarray):
    """Per pixel of row y at columns xs: (k_x, k_y) int64 arrays (len(xs), m), and N.

    A sample sits at ((2 k_x + 1) / 2N, (2 k_y + 1) / 2N) of its pixel.
    """
    xs = np.asarray(xs, np.int64)
    if xs.size and (xs.min() < 0 or y < 0):
        raise InputError("samples exist for pixels of the grid only (x, y >= 0)")
    m = n * n
    s = np.arange(m)
    i, j = s % n, s // n
    if pattern == "grid":
        kx, ky, big = i, j, n
    elif pattern == "rotated-grid":
        kx, ky, big = n * i + j, n * j + (n - 1 - i), n * n
    elif pattern in ("jitter", "random"):
        big = SNAP
        sample = np.arange(m, dtype=np.uint64)[None, :]
        r = [random_bits(seed, xs[:, None], y, 2 * sample + axis) for axis in (0, 1)]
        if pattern == "jitter":
            # stratum i of n, then a uniform place in it: floor((i + u) * 256 / n), u = r / 2^32
            kx = (((i[None, :] << 32) + r[0]) * SNAP) // (n << 32)
            ky = (((j[None, :] << 32) + r[1]) * SNAP) // (n << 32)
        else:
            kx, ky = r[0] >> 24, r[1] >> 24  # 0 .. 255
        return kx, ky, big
    else:
        raise InputError(f"option pattern: unknown pattern {pattern!r}")
    kx = np.broadcast_to(np.asarray(kx, np.int64), (len(xs), m))
    ky = np.broadcast_to(np.asarray(ky, np.int64), (len(xs), m))
    return kx, ky, big


def lattice(k: np.ndarray, big: int) -> np.ndarray:
    """Offsets in the pixel, in 1/512 px: (2k + 1) / 2N of 512, rounded (halves up)."""
    return ((2 * k + 1) * UNIT + big) // (2 * big)


def sample_weights(kx, ky, big: int, name: str, sigma: float = 0.5) -> np.ndarray:
    """Whole-number filter weights of samples at strata (kx, ky) of N = big."""
    kx, ky = np.asarray(kx, np.int64), np.asarray(ky, np.int64)
    if name == "box":
        return np.ones(np.broadcast(kx, ky).shape, np.int64)
    hx = np.minimum(2 * kx + 1, 2 * big - 2 * kx - 1)
    hy = np.minimum(2 * ky + 1, 2 * big - 2 * ky - 1)
    if name == "weighted":
        return hx + hy
    if name == "tent":
        return hx * hy
    if name == "gaussian":
        du = (2 * kx + 1 - big) / (2.0 * big)
        dv = (2 * ky + 1 - big) / (2.0 * big)
        w = np.rint(65536.0 * np.exp(-(du * du + dv * dv) / (2.0 * sigma * sigma)))
        return np.maximum(w, 1).astype(np.int64)
    raise InputError(f"option filter: unknown filter {name!r}")


def normalised_weights(pattern, n, name, sigma=0.5, seed=1, x=0, y=0) -> list[Fraction]:
    """The weights of pixel (x, y)'s samples as exact fractions (they add up to 1)."""
    kx, ky, big = sample_strata(pattern, n, seed, y, np.array([x]))
    w = sample_weights(kx[0], ky[0], big, name, sigma)
    total = int(w.sum())
    return [Fraction(int(v), total) for v in w]


def supersample_image(points, options, grid, colors: bool = True):
    """Vectorised supersampling: (coverage (H, W) float64, colour (H, W) int64 or None).

    Pixels outside every shape's box have coverage 0 and the background
    colour. Rows go in blocks of about a million samples; each shape is
    tested only on the samples of its own bounding box.
    """
    options = {**{o.name: o.default for o in SUPERSAMPLE_OPTIONS}, **options}
    shapes = Shapes(points, options)
    width, height = int(grid[0]), int(grid[1])
    coverage = np.zeros((height, width))
    rgb = np.full((height, width), WHITE, np.int64) if colors else None
    x0, y0, x1, y1 = shapes.window(grid)
    if x1 <= x0 or y1 <= y0:
        return coverage, rgb
    n, pattern, name = options["n"], options["pattern"], options["filter"]
    xs = np.arange(x0, x1, dtype=np.int64)
    palette = np.array([s.color for s in shapes.items] + [BACKGROUND], np.int64)
    boxes = [(s.box[0] // UNIT, s.box[1] // UNIT, s.box[2] // UNIT + 1, s.box[3] // UNIT + 1)
             for s in shapes.items]
    rows_per_block = max(1, (1 << 20) // (len(xs) * n * n))
    for top in range(y0, y1, rows_per_block):
        bottom = min(top + rows_per_block, y1)
        strata = [sample_strata(pattern, n, options["seed"], y, xs) for y in range(top, bottom)]
        big = strata[0][2]
        kx = np.stack([k[0] for k in strata])
        ky = np.stack([k[1] for k in strata])
        w = sample_weights(kx, ky, big, name, options["sigma"])
        sx = xs[None, :, None] * UNIT + lattice(kx, big)
        sy = np.arange(top, bottom, dtype=np.int64)[:, None, None] * UNIT + lattice(ky, big)
        owner = np.full(sx.shape, -1, np.int64)
        for index, (shape, box) in enumerate(zip(shapes.items, boxes)):
            c0, c1 = max(box[0], x0) - x0, min(box[2], x1) - x0
            r0, r1 = max(box[1], top) - top, min(box[3], bottom) - top
            if c0 >= c1 or r0 >= r1:
                continue
            part = owner[r0:r1, c0:c1]
            part[shape.hits(sx[r0:r1, c0:c1], sy[r0:r1, c0:c1])] = index
        total = w.sum(axis=2)
        coverage[top:bottom, x0:x1] = (w * (owner >= 0)).sum(axis=2) / total
        if colors:
            sums = (w[..., None] * palette[owner]).sum(axis=2)  # owner -1: the background
            channels = (2 * sums + total[..., None]) // (2 * total[..., None])
            rgb[top:bottom, x0:x1] = ((channels[..., 0] << 16) | (channels[..., 1] << 8)
                                      | channels[..., 2])
    return coverage, rgb


def supersample_code(points, options) -> Code:
    hit_test, miss_test = test_ops(code_shapes(points, options))
    m = options.get("n", 4) ** 2
    # Each sample adds w_s times the colour it takes (3 mul, 3 int_add); a
    # hit also adds w_s to cover. The pixel's frame carries W = sum of w_s
    # (m - 1 int_add), cover / W (1 div), colour / W rounded half up per
    # channel ((2 c + W) // 2W: 2 mul, 1 int_add, 1 div), the cover > 0
    # test, the pixel loop and its mask test; its samples' results are
    # looked at: one pixel tested.
    accumulate = {"mul": 3, "int_add": 3}
    pixel = ops_sum({"int_add": m - 1 + 3, "div": 4, "mul": 6, "compare": 1,
                      "pixels_tested": 1}, LOOP, {"compare": 1})
    code = Code()
    code.add("setup", "setup: snap the vertices to 1/256 px;  samples s of the pattern with "
                      "filter weights w_s (whole numbers);  W = sum of w_s")
    code.add("pixels", "for each pixel (x, y) the shapes' bounding boxes reach, row by row:")
    code.add("samples", "    cover = 0;  colour = 0;  for each sample s at (x + u_s, y + v_s):")
    code.add("hit", "        if s is inside a shape:  cover += w_s;  colour += w_s * colour of "
                    "the last shape containing s", VISIT, "hit",
             ops=sample_ops(True, hit_test, ops_sum(accumulate, {"int_add": 1})))
    code.add("miss", "        else:  colour += w_s * background", VISIT, "miss",
             ops=sample_ops(False, miss_test, accumulate))
    code.add("plot_write", "    coverage = cover / W;  if coverage > 0: write (x, y) with coverage and "
                      "colour / W", PLOT, ops=pixel)
    code.add("empty", "    else: nothing covers the pixel's samples", VISIT, ops=pixel)
    code.add("done", "done")
    return code


def _sample_table(options, line: int):
    pattern, n, name = options["pattern"], options["n"], options["filter"]
    if pattern in ("jitter", "random"):
        return Note(line=line, text=f"{pattern}: every pixel has samples of its own (seed "
                                    f"{options['seed']}); the values sx, sy show each one.")
    kx, ky, big = sample_strata(pattern, n, options["seed"], 0, np.array([0]))
    w = sample_weights(kx[0], ky[0], big, name, options["sigma"])
    total = int(w.sum())
    rows = tuple((s + 1, f"{2 * int(a) + 1}/{2 * big}", f"{2 * int(b) + 1}/{2 * big}", int(v),
                  f"{Fraction(int(v), total)}")
                 for s, (a, b, v) in enumerate(zip(kx[0], ky[0], w)))
    return Table(line=line, name="samples", columns=("s", "u", "v", "w", "w / W"), rows=rows)


def supersample(points, options, grid):
    shapes = Shapes(points, options)
    at = supersample_code(points, options).at
    n, pattern, name = options["n"], options["pattern"], options["filter"]
    constants = {"pattern": pattern, "n": n, "samples per pixel": n * n, "filter": name,
                 "shape": shapes.kind}
    if pattern in ("jitter", "random"):
        constants["seed"] = options["seed"]
    if name == "gaussian":
        constants["sigma"] = options["sigma"]
    if shapes.kind == "polygon":
        constants["fill_rule"] = options["fill_rule"]
    yield Start(line=at["setup"], values=("sx", "sy", "hit", "weight", "coverage", "rgb"),
                constants=constants, pixel_value="coverage", color_value="rgb",
                buffer_value="coverage", buffer_name=ACCUMULATION)
    yield from shape_vars(shapes, at["setup"])
    yield _sample_table(options, at["setup"])
    window = shapes.window(grid)
    x0, y0, x1, y1 = window
    mask = shapes.mask(window)
    xs = np.arange(x0, x1, dtype=np.int64)
    tested = written = 0
    area = 0.0
    nothing = (NAN,) * 4
    hit_line, miss_line, write_line, empty_line = at["hit"], at["miss"], at["plot_write"], at["empty"]
    for y in range(y0, y1):
        kx, ky, big = sample_strata(pattern, n, options["seed"], y, xs)
        weights = sample_weights(kx, ky, big, name, options["sigma"])
        offsets_x, offsets_y = lattice(kx, big), lattice(ky, big)
        for column, x in enumerate(range(x0, x1)):
            if not mask[y - y0, column]:
                continue
            w = [int(v) for v in weights[column]]
            total = sum(w)
            cover = 0
            sums = [0, 0, 0]
            for s in range(len(w)):
                sx = x * UNIT + int(offsets_x[column, s])
                sy = y * UNIT + int(offsets_y[column, s])
                owner = shapes.owner(sx, sy)
                tested += 1
                color = shapes.items[owner].color if owner >= 0 else BACKGROUND
                for c in range(3):
                    sums[c] += w[s] * color[c]
                if owner >= 0:
                    cover += w[s]
                yield (hit_line if owner >= 0 else miss_line, x, y, sx / UNIT, sy / UNIT,
                       1.0 if owner >= 0 else 0.0, w[s] / total, cover / total, NAN)
            coverage = cover / total
            rgb = float(blend(sums, total))
            if cover:
                written += 1
                area += coverage
                yield (write_line, x, y, *nothing, coverage, rgb)
            else:
                yield (empty_line, x, y, *nothing, 0.0, rgb)
    yield Vars(line=at["done"], values={"pixels": written, "samples": tested, "area": area})
