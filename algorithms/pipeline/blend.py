"""blend-over: transparent triangles composited with `over` and a z-buffer.

Each vertex has a colour and an alpha (opacity, 0..1), interpolated over
the triangle like the depth: exactly from the integer edge values at the
pixel centre (the visibility family's fragments), then rounded once. A
fragment that passes the depth test (z < ZB) is composited over what the
colour buffer holds:

    CB = alpha src + (1 - alpha) CB          (per channel, `over`)

and writes its depth only when it is opaque (``depth_write`` opaque, the
usual rule, so that surfaces behind a transparent one still show), always
(all: transparent surfaces then hide what is drawn after them behind
them), or never (none).

`over` is not commutative: two transparent surfaces give different colours
in the two orders. Drawing opaque surfaces first and then the transparent
ones back to front (``order`` back-to-front: by the mean depth of each
triangle, farthest first) gives the right result wherever whole triangles
can be ordered; it cannot be right for triangles that pierce each other,
where each is in front over part of the other.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms import triangles
from algorithms.core.code import Code
from algorithms.triangles.interpolate import pack, per_vertex
from algorithms.core.registry import InputError, Option
from algorithms.core.steps import PER_ROW, PLOT, VISIT, Start, Table, Vars
from algorithms.visibility.zbuffer_painter import Scene

ORDERS = ("input", "back-to-front", "front-to-back")
WRITES = ("opaque", "all", "none")
BACKGROUND = (255.0, 255.0, 255.0)
FRAGMENT_OPS = {"int_add": 7, "mul": 18, "compare": 5, "pixels_tested": 1, "float_add": 11,
                "div": 5, "round": 3}

ALPHA = Option("alpha", "numbers", (0.5, 0.5, 0.5), "an opacity 0..1 per point (or three "
               "shared by every triangle), interpolated over each triangle")
ORDER = Option("order", "choice", "input", "drawing order of the triangles: as given, or "
               "sorted by mean depth (back-to-front is the painter's order)", choices=ORDERS)
DEPTH_WRITE = Option("depth_write", "choice", "opaque", "which passing fragments write their "
                     "depth: opaque ones (alpha = 1), all, or none", choices=WRITES)


def blend_code(options) -> Code:
    code = Code()
    code.add("clear", "CB[x, y] = white;  ZB[x, y] = +infinity (far), for every pixel")
    order = {"input": "in input order", "back-to-front": "sorted by mean z, farthest first",
             "front-to-back": "sorted by mean z, nearest first"}[options["order"]]
    code.add("order", f"order the triangles {order}", per={PER_ROW: {"float_add": 2, "div": 1}})
    code.add("triangle", "for each triangle T in that order:")
    code.add("fragments", "    for each fragment (x, y) of T (pixel centres T covers):")
    write = {"opaque": "if alpha == 1: ZB[x, y] = z", "all": "ZB[x, y] = z",
             "none": "ZB unchanged"}[options["depth_write"]]
    code.add("plot_over", "        z, alpha, src interpolated;  if z < ZB[x, y]:  "
                          f"CB = alpha src + (1 - alpha) CB;  {write}", PLOT, "pass",
             ops=FRAGMENT_OPS)
    code.add("hidden", "        else: hidden behind a nearer surface already written; "
                       "CB unchanged", VISIT, "fail", ops=FRAGMENT_OPS)
    code.add("done", "misordered = pixels whose colour differs from compositing their blended "
                     "fragments sorted by depth, farthest first (the right order)")
    return code


def _alphas(options, count):
    alpha = per_vertex(options, "alpha", count)
    if alpha is None:
        return [1.0] * count
    if any(not 0 <= a <= 1 for a in alpha):
        raise InputError("option alpha: every alpha must be between 0 and 1")
    return [float(a) for a in alpha]


def ordered(scene: Scene, order: str) -> list:
    """The drawn triangles in drawing order, with their mean depths."""
    drawn = [(s, math.fsum(scene.z[k] for k in s.tri.order) / 3) for s in scene.drawn()]
    if order == "back-to-front":
        drawn.sort(key=lambda item: -item[1])
    elif order == "front-to-back":
        drawn.sort(key=lambda item: item[1])
    return drawn


def fragments(scene: Scene, setup, alphas):
    """(i, j, z, alpha, (r, g, b)) of every pixel centre the triangle covers, row by row."""
    tri = setup.tri
    edges = triangles.Edges(tri, "fixed")
    total = sum(tri.at(0, 0))
    zs = [Fraction(scene.z[k]) for k in tri.order]
    als = [Fraction(alphas[k]) for k in tri.order]
    flat = int(scene.color_of(setup.number)[1:], 16)
    colors = [scene.colors[k] for k in tri.order] if scene.colors is not None else \
        [((flat >> 16) & 255, (flat >> 8) & 255, flat & 255)] * 3
    i_lo, i_hi, j_lo, j_hi = tri.box()
    for j in range(max(j_lo, 0), min(j_hi, scene.height - 1) + 1):
        for i in range(max(i_lo, 0), min(i_hi, scene.width - 1) + 1):
            es = tri.at(i, j)
            if not edges.test(es)[0]:
                continue
            z = float(sum(e * zk for e, zk in zip(es, zs)) / total)
            alpha = float(sum(e * ak for e, ak in zip(es, als)) / total)
            src = tuple(float(sum(e * c[n] for e, c in zip(es, colors)) / total)
                        for n in range(3))
            yield i, j, z, alpha, src


def blend(points, options, grid):
    scene = Scene(points, options, grid)
    alphas = _alphas(options, len(points))
    at = blend_code(options).at
    yield Start(line=at["clear"], values=("z", "zb", "alpha", "src", "dst", "rgb"),
                constants={"order": options["order"], "depth_write": options["depth_write"],
                           "triangles": len(scene.setups)}, pixel_value="rgb",
                colour_values=("src", "dst"))
    drawing = ordered(scene, options["order"])
    yield Table(line=at["order"], name="drawing order", columns=("rank", "triangle", "mean z"),
                rows=tuple((rank + 1, s.number + 1, key) for rank, (s, key) in
                           enumerate(drawing)))
    # Zeroed buffers cost nothing until written (filling 16M pixels with the
    # background and the far depth took over a second before the first
    # fragment, which no cancel could interrupt); a pixel not yet painted
    # holds the background, one whose depth is not yet written is far.
    color = np.zeros((scene.height, scene.width, 3))
    painted = np.zeros((scene.height, scene.width), bool)
    depth = np.zeros((scene.height, scene.width))
    deep = np.zeros((scene.height, scene.width), bool)
    background = np.array(BACKGROUND, np.float64)
    counts = {"fragments": 0, "blended": 0, "hidden": 0}
    blended = {}  # (i, j): the fragments composited there, to check the order at the end
    for setup, key in drawing:
        yield Vars(line=at["triangle"], values={"triangle": setup.number + 1, "mean z": key})
        for i, j, z, alpha, src in fragments(scene, setup, alphas):
            counts["fragments"] += 1
            stored = depth[j, i] if deep[j, i] else math.inf
            dst = color[j, i].copy() if painted[j, i] else background.copy()
            zb = float(stored) if math.isfinite(stored) else math.nan
            if not z < stored:
                counts["hidden"] += 1
                yield (at["hidden"], i, j, z, zb, alpha, float(pack(src)), float(pack(dst)),
                       math.nan)
                continue
            counts["blended"] += 1
            blended.setdefault((i, j), []).append((z, alpha, src))
            color[j, i] = [alpha * s + (1 - alpha) * d for s, d in zip(src, dst)]
            painted[j, i] = True
            if options["depth_write"] == "all" or (options["depth_write"] == "opaque"
                                                   and alpha == 1):
                depth[j, i], deep[j, i] = z, True
            yield (at["plot_over"], i, j, z, zb, alpha, float(pack(src)), float(pack(dst)),
                   float(pack(color[j, i])))
    wrong = misordered(blended, color)
    yield Vars(line=at["done"], values=counts | {"misordered": len(wrong)})
    if wrong:
        yield Table(line=at["done"], name="misordered", columns=("x", "y"), rows=tuple(wrong))


def misordered(blended: dict, color: np.ndarray) -> list:
    """The pixels whose colour differs (by more than rounding) from their fragments
    composited farthest first."""
    wrong = []
    for (i, j), frags in sorted(blended.items(), key=lambda item: (item[0][1], item[0][0])):
        right = list(BACKGROUND)
        for _, alpha, src in sorted(frags, key=lambda f: -f[0]):
            right = [alpha * s + (1 - alpha) * d for s, d in zip(src, right)]
        if max(abs(a - b) for a, b in zip(right, color[j, i])) > 0.5:
            wrong.append((i, j))
    return wrong


def final_colors(points, options, grid) -> np.ndarray:
    """(H, W, 3) float colour buffer at the end (for the report and tests of order)."""
    image = np.empty((int(grid[1]), int(grid[0]), 3))
    image[:] = BACKGROUND
    for frame in blend(points, options, grid):
        if type(frame) is tuple and not math.isnan(frame[-1]):
            value = int(frame[-1])
            image[frame[2], frame[1]] = ((value >> 16) & 255, (value >> 8) & 255, value & 255)
    return image
