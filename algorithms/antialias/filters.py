"""Post-filtering: the aliased image first, then a convolution that blurs its stairs."""
from __future__ import annotations

import math

import numpy as np

from algorithms import triangles
from algorithms.core.code import Code
from algorithms.triangles.interpolate import unpack
from algorithms.core.registry import InputError, Option
from algorithms.core.steps import PLOT, Start, Table, Vars
from algorithms.core.trace import checkpoint
from algorithms.triangles.kernels import counts_from_spans, oriented, span_arrays

from .shapes import INK, NAN, Shapes, ink_blend, ops_sum, shape_vars

KERNELS = ("box3", "seed", "gaussian")
FILTER_OPTIONS = (Option("kernel", "choice", "seed", "the convolution kernel: box3 (3 x 3 "
                         "average), seed (1/36 [1 4 1; 4 16 4; 1 4 1]) or gaussian",
                         choices=KERNELS),
                  Option("sigma", "float", 0.8, "standard deviation of the gaussian kernel, "
                         "in px (its radius is ceil(3 sigma))", minimum=0.2, maximum=4),
                  triangles.FILL_RULE)


def filter_kernel(name: str, sigma: float = 0.8) -> np.ndarray:
    """Whole-number convolution weights, (2r + 1) x (2r + 1), row 0 at the bottom."""
    if name == "box3":
        return np.ones((3, 3), np.int64)
    if name == "seed":
        return np.array([[1, 4, 1], [4, 16, 4], [1, 4, 1]], np.int64)
    if name == "gaussian":
        r = max(1, math.ceil(3 * sigma))
        d = np.arange(-r, r + 1)
        g = np.exp(-(d[:, None] ** 2 + d[None, :] ** 2) / (2.0 * sigma * sigma))
        return np.rint(65536.0 * g).astype(np.int64)
    raise InputError(f"option kernel: unknown kernel {name!r}")


def aliased_image(points, options, grid) -> np.ndarray:
    """1 where the triangles cover the pixel centre (the fill rule of the triangle family)."""
    counts = triangles.fill(points, (int(grid[0]), int(grid[1])),
                            options.get("fill_rule", "top-left"))
    return (counts > 0).astype(np.int64)


# Rows of the aliased image made at once: a few tens of milliseconds of
# work even for tens of thousands of triangles, so a cancel is heard soon.
ROWS_PER_BLOCK = 16


def aliased_blocks(points, grid, rule: str):
    """The aliased image (covered pixel centres, booleans) as (first row,
    rows) blocks, bottom to top, each made only when asked for; the same
    pixels as ``aliased_image``, since a triangle's spans are exact per row."""
    width, height = int(grid[0]), int(grid[1])
    tris, _ = oriented(points, {"subpixel_bits": 8, "cull": False})
    for top in range(0, height, ROWS_PER_BLOCK):
        checkpoint()
        bottom = min(top + ROWS_PER_BLOCK, height)
        _, y, start, end = span_arrays(tris, 1 << 8, rule, (0, top, width, bottom))
        yield top, counts_from_spans(y - top, start, end, width, bottom - top) > 0


def filter_sums(image: np.ndarray, kernel: np.ndarray) -> np.ndarray:
    """sum over (u, v) of K[v, u] I[y + v, x + u] for every pixel; zeros beyond the grid."""
    r = kernel.shape[0] // 2
    height, width = image.shape
    padded = np.zeros((height + 2 * r, width + 2 * r), np.int64)
    padded[r:r + height, r:r + width] = image
    sums = np.zeros((height, width), np.int64)
    for v in range(-r, r + 1):
        for u in range(-r, r + 1):
            weight = int(kernel[v + r, u + r])
            if weight:
                sums += weight * padded[r + v:r + v + height, r + u:r + u + width]
    return sums


def filter_image(points, options, grid) -> np.ndarray:
    """Vectorised aa-filter: the filtered aliased image, values 0..1."""
    options = {**{o.name: o.default for o in FILTER_OPTIONS}, **options}
    kernel = filter_kernel(options["kernel"], options["sigma"])
    return filter_sums(aliased_image(points, options, grid), kernel) / int(kernel.sum())


def filter_code(points, options) -> Code:
    kernel = options.get("kernel", "seed")
    text = {"box3": "K = 1/9 [1 1 1; 1 1 1; 1 1 1]",
            "seed": "K = 1/36 [1 4 1; 4 16 4; 1 4 1]",
            "gaussian": f"K = exp(-(u^2 + v^2) / 2 sigma^2), sigma = {options.get('sigma', 0.8):g},"
                        " as whole numbers, divided by their sum"}[kernel]
    # Line "aliased": each covered centre is one frame of the aliased triangle
    # rasterizer: e_k at the centre (6 mul, 6 int_add), three sign tests, one
    # pixel tested. Counted per unit of the frame's coverage, which is 1 on
    # every such frame, so the summary record on that line counts nothing;
    # centres the triangles miss yield no frame and are not counted.
    # Line "out": every tap of the kernel, (2r + 1)^2 of them, reads I: its
    # position (2 int_add), the bounds tests in full (4 compares), the test
    # of I (1 compare, one pixel tested) and the tap loop (1 int_add, 1
    # compare); a covered tap adds its weight and counts itself (2 int_add,
    # per value taps); then out = acc / sum (1 div). The kernel's weights
    # and the reach mask are setup, not counted.
    radius = 1
    try:
        radius = filter_kernel(kernel, options.get("sigma", 0.8)).shape[0] // 2
    except InputError:
        pass
    taps = (2 * radius + 1) ** 2
    tap = {"int_add": 3, "compare": 6, "pixels_tested": 1}
    code = Code()
    code.add("setup", f"setup: {text}")
    code.add("plot_aliased", "aliased image: I[x, y] = 1 where the triangles cover the pixel centre",
             PLOT, per={"coverage": {"mul": 6, "int_add": 6, "compare": 3, "pixels_tested": 1}})
    code.add("pixels", "for each pixel (x, y) that the kernel reaches from a covered pixel, "
                       "row by row:")
    code.add("plot_out", "    out[x, y] = sum over (u, v) of K[u, v] * I[x + u, y + v];  write (x, y) "
                    "with out[x, y]", PLOT, ops=ops_sum(tap, times=taps) | {"div": 1},
             per={"taps": {"int_add": 2}})
    code.add("done", "done")
    return code


def _reached(image: np.ndarray, support):
    """Row by row, the pixels (y, x) whose kernel support ``[(v, u), ...]``
    holds a set pixel of ``image``, left to right."""
    height, width = image.shape
    for y in range(height):
        checkpoint()  # rows that reach nothing yield no frame
        row = np.zeros(width, bool)
        for v, u in support:
            if 0 <= y + v < height and abs(u) < width:
                source = image[y + v]
                if u >= 0:
                    row[:width - u] |= source[u:]
                else:
                    row[-u:] |= source[:width + u]
        for x in np.flatnonzero(row).tolist():
            yield y, x


def post_filter(points, options, grid):
    kernel = filter_kernel(options["kernel"], options["sigma"])
    at = filter_code(points, options).at
    total = int(kernel.sum())
    r = kernel.shape[0] // 2
    constants = {"kernel": options["kernel"], "size": f"{2 * r + 1} x {2 * r + 1}",
                 "kernel sum": total}
    if options["kernel"] == "gaussian":
        constants["sigma"] = options["sigma"]
    yield Start(line=at["setup"], values=("coverage", "taps", "rgb"), constants=constants,
                pixel_value="coverage", color_value="rgb")
    rows = tuple((v, *(int(kernel[v + r, u + r]) for u in range(-r, r + 1)))
                 for v in range(r, -r - 1, -1))
    yield Table(line=at["setup"], name="kernel",
                columns=("v \\ u", *(str(u) for u in range(-r, r + 1))), rows=rows)
    yield from shape_vars(Shapes(points, {"shape": "triangles"}), at["setup"])
    # Booleans, made a block of rows at a time as the frames reach them: on
    # a 4096 grid filling many triangles at once held up the first frame
    # for seconds no cancel could interrupt.
    width, height = int(grid[0]), int(grid[1])
    image = np.zeros((height, width), bool)
    ink = unpack(INK)
    aliased = 0
    for top, block in aliased_blocks(points, grid, options.get("fill_rule", "top-left")):
        image[top:top + len(block)] = block
        for y in range(top, top + len(block)):
            for x in np.flatnonzero(image[y]).tolist():
                aliased += 1
                yield (at["plot_aliased"], x, y, 1.0, NAN, float(ink_blend(ink, 1.0)))
    yield Vars(line=at["plot_aliased"], values={"aliased pixels": aliased})
    support = [(v, u) for v in range(-r, r + 1) for u in range(-r, r + 1) if kernel[v + r, u + r]]
    written = 0
    for y, x in _reached(image, support):
        acc = taps = 0
        for v in range(-r, r + 1):
            for u in range(-r, r + 1):
                if 0 <= y + v < height and 0 <= x + u < width and image[y + v, x + u]:
                    acc += int(kernel[v + r, u + r])
                    taps += 1
        value = acc / total
        written += 1
        yield (at["plot_out"], x, y, value, float(taps), float(ink_blend(ink, value)))
    yield Vars(line=at["done"], values={"pixels": written})
