"""Antialiased lines: Xiaolin Wu's two pixels per column, and the area of the line's rectangle."""
from __future__ import annotations

import math

import numpy as np

from algorithms.core.code import Code
from algorithms.exact import coverage as exact_coverage
from algorithms.lines import Octant
from algorithms.core.registry import Option
from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Note, Start, Vars
from algorithms.core.trace import checkpoint

from .shapes import CAPS, LOOP, NAN, ink_blend, ops_sum

WU_OPTIONS = (Option("endpoints", "choice", "full", "full: every column's two intensities add "
                     "up to 1, end columns too; gap: the end columns get half, as the segment "
                     "covers half of them (Wu's endpoint rule for whole-pixel endpoints)",
                     choices=("full", "gap")),)
AREA_OPTIONS = (Option("width", "float", 1.0, "line width in px", minimum=0.01, maximum=64),
                CAPS)


def ink_grey(intensity: float) -> float:
    """Black ink over white by the intensity, as the colour buffer shows it."""
    return float(ink_blend((0, 0, 0), intensity))


def wu_code(points, options) -> Code:
    gap = options.get("endpoints", "full") == "gap"
    scale = "  (x 1/2 in the two end columns)" if gap else ""
    # Line "map" maps into octant 1 as the line family does (2 int_add for
    # the differences, 3 compares). It runs once, so the resets e -= dx;
    # y += 1 of line "step", which happen about dy times along the line, are counted
    # there by its constant dy (2 int_add each). Each column's intensities
    # are worked out once, with the near pixel's frame: f = e/dx and 1 -
    # e/dx as (dx - e)/dx (1 int_add, 2 div), and in gap mode the end-column
    # test (2 compares) and the scaling (2 mul). Every pixel frame maps
    # (u, v) back to the grid (4 mul, 4 int_add) and tests intensity > 0.
    # Line "step" carries e += dy, the test e >= dx and the column loop.
    column = ops_sum({"int_add": 1, "div": 2}, {"compare": 2, "mul": 2} if gap else {})
    pixel = {"mul": 4, "int_add": 4, "compare": 1}
    code = Code()
    code.add("map", "map P, Q into octant 1:  dx = major extent, dy = minor extent;  e = 0;  "
                    "y = y0   (the ideal line is at y + e/dx)",
             ops={"int_add": 2, "compare": 3}, per={"dy": {"int_add": 2}})
    code.add("columns", "for x = x0 .. x1:")
    code.add("plot_near", f"    plot(x, y, 1 - e/dx){scale}", PLOT, "near", ops=ops_sum(pixel, column))
    code.add("plot_far", f"    plot(x, y + 1, e/dx){scale}", PLOT, "far", ops=pixel)
    code.add("zero", "    (intensity 0: the line passes exactly through this centre; nothing "
                     "written)", VISIT, ops=pixel)
    code.add("step", "    e += dy;  if e >= dx:  e -= dx;  y += 1",
             ops=ops_sum({"int_add": 1, "compare": 1}, LOOP))
    code.add("done", "done")
    return code


def wu(points, options):
    p, q = points
    octant = Octant(p, q)
    dx, dy = octant.dx, octant.dy
    gap = options["endpoints"] == "gap"
    at = wu_code(points, options).at
    yield Start(line=at["map"], values=("e", "f", "intensity", "rgb"),
                constants={"dx": dx, "dy": dy, "octant": octant.number,
                           "endpoints": options["endpoints"]},
                pixel_value="intensity", color_value="rgb")
    if dx == 0:
        yield (at["plot_near"], p[0], p[1], 0.0, 0.0, 1.0, ink_grey(1.0))
        yield Vars(line=at["done"], values={"pixels": 1})
        return
    e = v = 0
    written = 0
    near_line, far_line, zero_line, step_line = at["plot_near"], at["plot_far"], at["zero"], at["step"]
    for u in range(dx + 1):
        scale = 0.5 if gap and u in (0, dx) else 1.0
        f = e / dx
        near = (dx - e) / dx * scale
        far = e / dx * scale
        for offset, intensity in ((0, near), (1, far)):
            x, y = octant.to_grid(p, u, v + offset)
            if intensity > 0:
                written += 1
                yield (far_line if offset else near_line, x, y, float(e), f, intensity,
                       ink_grey(intensity))
            else:
                yield (zero_line, x, y, float(e), f, 0.0, NAN)
        e += dy
        if e >= dx:
            e -= dx
            v += 1
        yield (step_line, NO_PIXEL, NO_PIXEL, float(e), NAN, NAN, NAN)
    yield Vars(line=at["done"], values={"pixels": written})


def wu_image(points, options) -> dict:
    """{(x, y): intensity} of Wu's line (the sum where a pixel is written twice)."""
    options = {**{o.name: o.default for o in WU_OPTIONS}, **options}
    at = wu_code(points, options).at
    plotted = (at["plot_near"], at["plot_far"])
    result = {}
    for frame in wu(points, options):
        if type(frame) is tuple and frame[0] in plotted:
            result[(frame[1], frame[2])] = result.get((frame[1], frame[2]), 0.0) + frame[5]
    return result


def area_code(points, options) -> Code:
    caps = options.get("caps", "butt")
    # The areas come from the exact coverage reference, vectorised over the
    # rectangle's window: per pixel a running sum down its column (1
    # float_add) and, where an edge of R crosses the pixel, the mean of a
    # clamped linear function over the crossing (2 mul, 1 div, 6 float_add,
    # 6 compares). One crossing per pixel is counted: R's two long edges
    # cross the pixels along its border and none cross the inner ones, so
    # this is an estimate. The near pixel's frame also tests a > 0 (1
    # compare) and a written one adds a to the column total (1 float_add);
    # line "column" closes a column (the loop step and test). The
    # rectangle's corners (line "rectangle": 4 mul, 1 sqrt, 1 div, 8 float_add for the unit
    # direction and the offsets) are computed once, with the Start record.
    area = {"float_add": 7, "mul": 2, "div": 1, "compare": 7, "pixels_tested": 1}
    code = Code()
    ends = "" if caps == "butt" else " and at each end"
    code.add("rectangle", "R = the rectangle of the segment between the centres of P and Q, "
                          f"widened by w/2 on each side{ends}",
             ops={"mul": 4, "sqrt": 1, "div": 1, "float_add": 8})
    code.add("columns", "for each column along the major axis, from P's side to Q's:")
    code.add("plot_pixel", "    for each pixel of the column that R reaches:  a = area(R and the pixel "
                      "square);  plot(x, y, a)", PLOT, ops=ops_sum(area, {"float_add": 1}, LOOP))
    code.add("touch", "        (a = 0: R only touches the pixel; nothing written)", VISIT,
             ops=ops_sum(area, LOOP))
    code.add("column", "    column total = sum of a   (= w * length / dx where R crosses the "
                       "whole column)", ops=LOOP)
    code.add("done", "done")
    return code


def segment_window(p, q, width, caps):
    corners = exact_coverage.segment_rectangle((p[0] + 0.5, p[1] + 0.5),
                                               (q[0] + 0.5, q[1] + 0.5), width, caps)
    xs = [c[0] for c in corners]
    ys = [c[1] for c in corners]
    return (math.floor(min(xs)), math.floor(min(ys)), math.ceil(max(xs)) + 1,
            math.ceil(max(ys)) + 1)


def area_image(points, options, exact: bool = False):
    """(window, coverage) of the line's rectangle: pixel (x, y) is coverage[y - y0, x - x0]."""
    options = {**{o.name: o.default for o in AREA_OPTIONS}, **options}
    p, q = points
    window = segment_window(p, q, options["width"], options["caps"])
    coverage = exact_coverage.segment_coverage((p[0] + 0.5, p[1] + 0.5), (q[0] + 0.5, q[1] + 0.5),
                                               options["width"], window, options["caps"], exact)
    return window, coverage


# Columns of the window whose coverage is computed at once, as the frames
# reach them: the whole window of a long diagonal line (16M pixels on a
# 4096 grid) took over half a second before the first frame.
COLUMNS_PER_BLOCK = 32


def _coverage_blocks(points, options, window, steep: bool, forward: bool):
    """(first major index, coverage laid out [major][minor]) blocks in the
    order the frames visit them; each column is computed exactly as the
    whole window computes it. A steep line goes along the rows, which need
    every column: its blocks are made together, a cancel heard between them."""
    p, q = points
    centres = (p[0] + 0.5, p[1] + 0.5), (q[0] + 0.5, q[1] + 0.5)
    x0, y0, x1, y1 = window

    def columns(first, end):
        checkpoint()
        return exact_coverage.segment_coverage(*centres, options["width"], window,
                                               options["caps"], columns=(first, end))
    starts = range(0, x1 - x0, COLUMNS_PER_BLOCK)
    if steep:
        blocks = [columns(c, min(c + COLUMNS_PER_BLOCK, x1 - x0)) for c in starts]
        yield 0, np.concatenate(blocks, axis=1) if blocks else np.zeros((y1 - y0, 0))
        return
    for c in (starts if forward else reversed(starts)):
        yield c, columns(c, min(c + COLUMNS_PER_BLOCK, x1 - x0)).T


def line_area(points, options):
    p, q = points
    octant = Octant(p, q)
    window = segment_window(p, q, options["width"], options["caps"])
    x0, y0, _, _ = window
    at = area_code(points, options).at
    yield Start(line=at["rectangle"], values=("intensity", "column", "rgb"),
                constants={"width": options["width"], "caps": options["caps"],
                           "octant": octant.number},
                pixel_value="intensity", color_value="rgb")
    steep = octant.steep
    major_sign = octant.major[1] if steep else octant.major[0]
    minor_sign = octant.minor_sign
    origin_major, origin_minor = (y0, x0) if steep else (x0, y0)
    if tuple(p) == tuple(q) and options["caps"] == "butt":
        # Said aloud because every other line algorithm plots the one pixel.
        yield Note(line=at["done"], text="P = Q: with butt caps the rectangle has no length, "
                                         "so it covers no area and nothing is drawn "
                                         "(caps=square draws a w x w square)")
    counts = [0, 0.0]  # pixels written, total area
    for base, table in _coverage_blocks(points, options, window, steep, major_sign > 0):
        columns = [c for c in range(table.shape[0]) if table[c].any()]
        columns.sort(key=lambda c: major_sign * c)
        for c in columns:
            yield from _area_column(table[c], origin_major + base + c, origin_minor, steep,
                                    minor_sign, at, counts)
    written, total_area = counts
    rectangle = options["width"] * math.hypot(q[0] - p[0], q[1] - p[1]) \
        + (options["width"] ** 2 if options["caps"] == "square" else 0.0)
    yield Vars(line=at["done"], values={"pixels": written, "area": total_area,
                                        "rectangle area": rectangle})


def _area_column(line_values, major, origin_minor, steep, minor_sign, at, counts):
    """The frames of one column along the major axis; ``counts`` (pixels
    written, total area) goes on from column to column."""
    nonzero = np.flatnonzero(line_values)
    rows = range(int(nonzero.min()), int(nonzero.max()) + 1)
    rows = sorted(rows, key=lambda r: minor_sign * r)
    column_total = 0.0
    pixel_line, touch_line = at["plot_pixel"], at["touch"]
    for r in rows:
        a = float(line_values[r])
        minor = origin_minor + r
        x, y = (minor, major) if steep else (major, minor)
        if a > 0:
            column_total += a
            counts[0] += 1
            yield (pixel_line, x, y, a, column_total, ink_grey(a))
        else:
            yield (touch_line, x, y, 0.0, column_total, NAN)
    counts[1] += column_total
    yield (at["column"], NO_PIXEL, NO_PIXEL, NAN, column_total, NAN)
