"""Adaptive supersampling: five samples per square, and four smaller squares where they disagree."""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from algorithms.core.code import Code
from algorithms.triangles.interpolate import unpack
from algorithms.core.registry import Option
from algorithms.core.steps import CALC, PLOT, VISIT, Start, Vars

from .shapes import (INK, LOOP, NAN, POSITION, SHAPE_OPTIONS, UNIT, Shapes, code_shapes,
                     ink_blend, ops_sum, shape_vars, test_ops)

ADAPTIVE_OPTIONS = (Option("max_depth", "int", 3, "how often a square may be split in four",
                           minimum=0, maximum=7),) + SHAPE_OPTIONS


def adaptive_code(points, options) -> Code:
    depth = options.get("max_depth", 3)
    hit_test, miss_test = test_ops(code_shapes(points, options))
    # A new point: the cache lookup (1 compare), the test, the hit/miss
    # compare, the position and the counter (1 int_add); a point already
    # tested in the pixel yields no frame, its lookup is counted with the
    # square's decision. Every square ends on line "leaf" or "split", which
    # carries half the size (1 div), the four corner and centre coordinates
    # (4 int_add), the five lookups (5 compare), hits += hit (5 int_add) and
    # the agree and level tests (3 compare). "leaf" adds hits / 5 (1 div);
    # "split" the quarters' origins (2 int_add), their levels (4 int_add)
    # and the mean of four (4 float_add, 1 div).
    square = {"div": 1, "int_add": 9, "compare": 8}
    new = {"compare": 1, "int_add": 1}
    # The pixel: float(value) (1 div), value > 0, the bookkeeping of
    # samples spent (total, most, split: 2 int_add, 2 compare), the loop
    # and the mask test; the pixel's samples are looked at: one pixel tested.
    pixel = ops_sum({"div": 1, "compare": 3, "int_add": 2, "pixels_tested": 1}, LOOP,
                     {"compare": 1})
    code = Code()
    code.add("setup", "setup: snap the vertices to 1/256 px")
    code.add("pixels", "for each pixel (x, y) the shapes' bounding boxes reach:  refine(the "
                       "pixel square, level 0)")
    code.add("refine", "refine(square, level): test its four corners and its centre (a point "
                       "already tested in this pixel is not tested again):")
    code.add("hit", "    sample inside a shape", VISIT, "hit",
             ops=ops_sum({"samples": 1, "compare": 1}, POSITION, hit_test, new))
    code.add("miss", "    sample outside", VISIT, "miss",
             ops=ops_sum({"samples": 1, "compare": 1}, POSITION, miss_test, new))
    code.add("leaf", f"    if the five agree, or level == {depth}: value = (hits among the "
                     "five) / 5", ops=ops_sum(square, {"div": 1}))
    code.add("split", "    else: split the square into four;  value = mean of refine(quarter, "
                      "level + 1)", CALC, "split",
             ops=ops_sum(square, {"int_add": 6, "float_add": 4, "div": 1}))
    code.add("plot_write", "coverage = value;  if coverage > 0: write (x, y)", PLOT, ops=pixel)
    code.add("empty", "else: nothing to write", VISIT, ops=pixel)
    code.add("done", "done")
    return code


class _Adaptive:
    def __init__(self, shapes, max_depth, at):
        self.shapes = shapes
        self.max_depth = max_depth
        self.at = at

    def refine(self, x, y, ox, oy, size, level, cache, counter):
        """Frames of one square; returns its value as a Fraction."""
        at = self.at
        half = size // 2
        corners = ((ox, oy), (ox + size, oy), (ox, oy + size), (ox + size, oy + size),
                   (ox + half, oy + half))
        hits = 0
        for px, py in corners:
            hit = cache.get((px, py))
            if hit is None:
                sx, sy = x * UNIT + px, y * UNIT + py
                hit = self.shapes.owner(sx, sy) >= 0
                cache[(px, py)] = hit
                counter[0] += 1
                yield (at["hit"] if hit else at["miss"], x, y, sx / UNIT, sy / UNIT,
                       1.0 if hit else 0.0, float(level), NAN, NAN, NAN, NAN)
            hits += hit
        if hits in (0, 5) or level >= self.max_depth:
            value = Fraction(hits, 5)
            yield (at["leaf"], x, y, NAN, NAN, NAN, float(level), float(value), NAN, NAN, NAN)
            return value
        yield (at["split"], x, y, NAN, NAN, NAN, float(level), NAN, NAN, NAN, NAN)
        total = Fraction(0)
        for qx, qy in ((ox, oy), (ox + half, oy), (ox, oy + half), (ox + half, oy + half)):
            total += yield from self.refine(x, y, qx, qy, half, level + 1, cache, counter)
        return total / 4


def adaptive(points, options, grid):
    shapes = Shapes(points, options)
    depth = options["max_depth"]
    at = adaptive_code(points, options).at
    # The corners of the finest squares and their centres: the most a pixel can take.
    constants = {"max_depth": depth, "shape": shapes.kind,
                 "at most per pixel": (2 ** depth + 1) ** 2 + 4 ** depth}
    if shapes.kind == "polygon":
        constants["fill_rule"] = options["fill_rule"]
    yield Start(line=at["setup"],
                values=("sx", "sy", "hit", "level", "value", "samples", "coverage", "rgb"),
                constants=constants, pixel_value="coverage", color_value="rgb")
    yield from shape_vars(shapes, at["setup"])
    window = shapes.window(grid)
    x0, y0, x1, y1 = window
    mask = shapes.mask(window)
    ink = shapes.items[0].color if shapes.items else unpack(INK)
    engine = _Adaptive(shapes, depth, at)
    total = written = split = most = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            if not mask[y - y0, x - x0]:
                continue
            counter = [0]
            value = yield from engine.refine(x, y, 0, 0, UNIT, 0, {}, counter)
            spent = counter[0]
            total += spent
            most = max(most, spent)
            split += spent > 5
            coverage = float(value)
            written += value > 0
            yield (at["plot_write"] if value > 0 else at["empty"], x, y, NAN, NAN, NAN, NAN, NAN,
                   float(spent), coverage, float(ink_blend(ink, coverage)))
    yield Vars(line=at["done"], values={"pixels": written, "samples": total,
                                        "subdivided": split, "most in a pixel": most})


def adaptive_image(points, options, grid) -> tuple[np.ndarray, np.ndarray]:
    """(coverage, samples spent) per pixel, (H, W), from the adaptive generator."""
    options = {**{o.name: o.default for o in ADAPTIVE_OPTIONS}, **options}
    coverage = np.zeros((int(grid[1]), int(grid[0])))
    spent = np.zeros((int(grid[1]), int(grid[0])), np.int64)
    at = adaptive_code(points, options).at
    pixel_lines = (at["plot_write"], at["empty"])
    for frame in adaptive(points, options, grid):
        if type(frame) is tuple and frame[0] in pixel_lines:
            coverage[frame[2], frame[1]] = frame[9]
            spent[frame[2], frame[1]] = int(frame[8])
    return coverage, spent
