"""triangle-texture: a triangle traversal that looks a texture up at every covered pixel.

Coverage is the triangle family's (snapped vertices, edge functions, the
fill rule); each covered pixel then gets u, v and their derivatives from
the exact mapping at its centre, rho and lambda, the level(s) its filter
reads, the texels fetched with their weights, and the filtered colour.
"""
from __future__ import annotations

import math

from algorithms.core.code import Code
from algorithms.core.errors import InputError
from algorithms.triangles.interpolate import pack, per_vertex
from algorithms.core.steps import PLOT, VISIT, Vars
from algorithms.triangles.attributes import NoAttributes
from algorithms.triangles.edges import NAN
from algorithms.triangles.run import BASE, LOOP_OPS, TEST_OPS, Traversal, evaluate_ops, footer, \
    header, ops_sum

from . import texels
from .sampling import MIPMAPPED, Mapping, Sampler

SHOWN_FETCHES = 4
FETCH_COLUMNS = tuple(f"t{k}{part}" for k in range(SHOWN_FETCHES) for part in ("x", "y", "w"))
TEXTURE_COLUMNS = BASE + ("u", "v", "du/dx", "dv/dx", "du/dy", "dv/dy", "rho", "lambda",
                          "level", "level_weight", "fetches") + FETCH_COLUMNS


def fetches_per_pixel(options) -> int:
    """Texels a covered pixel reads (at most; anisotropic reads up to max_aniso probes)."""
    name = options["filter"]
    per = {"nearest": 1, "bilinear": 4, "mip-nearest": 4, "trilinear": 8,
           "anisotropic": 8 * options["max_aniso"], "reference": options["samples"] ** 2}
    return per[name]


def _code(options):
    code = Code()
    header(code, options)
    perspective = options["perspective"]
    code.add("setup", "    planes through the vertices of " + (
        "U = u/w, V = v/w, Q = 1/w" if perspective else "u and v (affine: w ignored)")
        + " by Cramer's rule", ops={"mul": 6, "float_add": 12, "div": 9})
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("cols", "        for x = xmin .. xmax:")
    pixel = ops_sum(evaluate_ops(options), TEST_OPS, LOOP_OPS)
    code.add("test", "            if not (inside(e0) and inside(e1) and inside(e2)): skip",
             VISIT, ops=pixel)
    lookup = {"nearest": "the texel containing (u W, v H)",
              "bilinear": "4 texels around (u W - 1/2, v H - 1/2), weighted by the fractions",
              "mip-nearest": "bilinear in level ceil(lambda + 1/2) - 1",
              "trilinear": "bilinear in levels floor(lambda) and floor(lambda) + 1, mixed by "
                           "its fraction",
              "anisotropic": "N = min(ceil(major / minor), max_aniso) trilinear probes along "
                             "the longer axis, lambda = log2(major / N)",
              "reference": "average of the texels under an n x n grid of sub-pixel points"
              }[options["filter"]]
    code.add("plot", "            " + ("u = U / Q,  v = V / Q;  du/dx = (U_x - u Q_x) / Q, ...;  "
                                       if perspective else "u, v, du/dx = u_x, ...;  ")
             + "rho = max(|(du/dx, dv/dx)|, |(du/dy, dv/dy)|) in texels;  lambda = log2(rho);  "
             + f"colour = {lookup};  setPixel(x, y, colour)", PLOT,
             ops=ops_sum(pixel, {"mul": 14, "float_add": 10, "div": 7, "sqrt": 2}))
    footer(code)
    return code


class TextureColumns(NoAttributes):
    """The run's texture, sampler and per-vertex uv and w, checked."""

    names = ("rgb",)
    nothing = (NAN,)
    pixel_value = "rgb"

    def __init__(self, options, count):
        flat = options.get("uv") or ()
        if len(flat) == 2 * count:
            self.uv = [(flat[2 * k], flat[2 * k + 1]) for k in range(count)]
        elif len(flat) == 6:
            self.uv = [(flat[2 * (k % 3)], flat[2 * (k % 3) + 1]) for k in range(count)]
        else:
            shared = " or 6 shared by every triangle" if count > 3 else ""
            raise InputError(f"option uv: give u,v per point ({2 * count} numbers{shared}), "
                             f"not {len(flat)}")
        self.w = per_vertex(options, "w", count) or [1.0] * count
        if any(not wk > 0 for wk in self.w):
            raise InputError("option w: every w must be greater than 0")
        self.perspective = options["perspective"]
        texture = texels.load(options["texture"])
        self.sampler = Sampler(texture, options["filter"], options["wrap"],
                               options["max_aniso"], options["samples"])


def mapping_of(tri, cols) -> Mapping:
    order = tri.order
    return Mapping([tri.px(k) for k in range(3)], [cols.uv[k] for k in order],
                   [cols.w[k] for k in order], cols.perspective)


def fragment_values(sample) -> tuple:
    """The frame's values after e0..tie for a covered pixel's lookup."""
    level, weight = sample.levels[0]
    shown = []
    for k in range(SHOWN_FETCHES):
        if k < len(sample.fetches):
            _, i, j, w = sample.fetches[k]
            shown += [i, j, w]
        else:
            shown += [NAN, NAN, NAN]
    # A derivative that overflowed (next to a vertex with w near 0) is not shown.
    d = [value if math.isfinite(value) else NAN for value in sample.d]
    return (*sample.uv, *d, sample.rho, sample.lam, level, weight, len(sample.fetches), *shown,
            float(pack(sample.color)))


def _traverse(run, tri, edges, attrs, at):
    cols = run.attributes
    mapping = mapping_of(tri, cols)
    texture = cols.sampler.texture
    order = tri.order
    # The vertices' uv and w in the order drawn (with P0..P2), so a panel can
    # rebuild the mapping of the triangle on show.
    yield Vars(line=at["setup"], values={"texture": texture.name,
                                         "size": f"{texture.width} x {texture.height}",
                                         "levels": texture.top + 1}
               | {f"uv{k}": cols.uv[order[k]] for k in range(3)}
               | {f"w{k}": cols.w[order[k]] for k in range(3)})
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    empty = (NAN,) * (len(TEXTURE_COLUMNS) - len(BASE) + 1)
    plot, skip = at["plot"], at["test"]
    for j in range(j_lo, j_hi + 1):
        for i in range(i_lo, i_hi + 1):
            es = edges.at(i, j)
            covered, tie = edges.test(es)
            run.count(i, j, covered)
            shown = edges.shown(es)
            if not covered:
                yield (skip, i, j, *shown, 1.0 if tie else 0.0, *empty)
                continue
            sample = cols.sampler.sample(mapping, i, j)
            yield (plot, i, j, *shown, 1.0 if tie else 0.0, *map(float, fragment_values(sample)))


TEXTURED = Traversal(_code, _traverse, TEXTURE_COLUMNS, attributes=TextureColumns)


def code_lines(points, options) -> tuple:
    return tuple(_code(options).lines)


def generator(points, options, grid=None):
    return TEXTURED.generator(points, options, grid)


def uses_mip(options) -> bool:
    return options.get("filter") in MIPMAPPED
