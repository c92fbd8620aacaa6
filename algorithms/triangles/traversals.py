"""The traversals: in which order pixels are visited, and how the edge values follow them.

Every one yields, per triangle, one frame per pixel it looks at (see the
package's notes); they differ in which pixels they look at and in how the
edge values are obtained: evaluated afresh, stepped by e += a, walked
from the top vertex, or replaced by the span between two edges.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms.core.code import Code
from algorithms.core.steps import PLOT, VISIT, Note, Vars

from .edges import Edges, ExactView, Triangle, ceil_div, floor_div
from .run import (BASE, LOOP_OPS, TEST_OPS, Run, Traversal, evaluate_ops, footer, header,
                  ops_sum, plot_text, shade_ops, step_ops)

def _add_plot(code: Code, options, pixel: dict, weighted: bool = False) -> None:
    """The line of a pixel that passes the test: the test's work and the shading's."""
    code.add("plot", "            else: " + plot_text(options), PLOT,
             ops=ops_sum(pixel, shade_ops(options, weighted)))


# ----------------------------------------------------------- scan, bbox
def box_code(options, whole: bool) -> Code:
    code = Code()
    header(code, options)
    if whole:
        code.add("rows", "    for y = 0 .. H - 1:   (every row of the grid, bottom to top)")
        code.add("cols", "        for x = 0 .. W - 1:")
    else:
        code.add("rows", "    for y = ymin .. ymax:   (rows of the bounding box: centres "
                         "between the lowest and highest vertex)")
        code.add("cols", "        for x = xmin .. xmax:")
    pixel = ops_sum(evaluate_ops(options), TEST_OPS, LOOP_OPS)
    code.add("test", "            e_k = e_k(x + 1/2, y + 1/2);  "
                     "if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT, ops=pixel)
    _add_plot(code, options, pixel)
    footer(code)
    return code


def _box_traversal(whole: bool):
    def traverse(run, tri, edges, attrs, at):
        x0, y0, x1, y1 = run.window
        if whole:
            cols, rows = range(x0, x1), range(y0, y1)
        else:
            i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
            cols, rows = range(i_lo, i_hi + 1), range(j_lo, j_hi + 1)
        evaluate, test, count, lean = edges.at, edges.test, run.count, run.lean
        plot, skip = at["plot"], at["test"]
        for j in rows:
            for i in cols:
                es = evaluate(i, j)
                covered, tie = test(es)
                count(i, j, covered)
                yield lean(plot if covered else skip, i, j, es, edges, tie, covered, attrs=attrs)
    return traverse


SCAN = Traversal(lambda options: box_code(options, True), _box_traversal(True))
BBOX = Traversal(lambda options: box_code(options, False), _box_traversal(False))


# ----------------------------------------------------------- incremental
def _incremental_code(options):
    code = Code()
    header(code, options)
    code.add("first", "    e_row_k = e_k(xmin + 1/2, ymin + 1/2)   (the only full evaluation)",
             ops=evaluate_ops(options))
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("copy", "        e_k = e_row_k")
    code.add("cols", "        for x = xmin .. xmax:")
    # e_k += a_k (line step_x) follows every pixel's frame: counted with it.
    pixel = ops_sum(TEST_OPS, LOOP_OPS, step_ops(options))
    code.add("test", "            if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT,
             ops=pixel)
    _add_plot(code, options, pixel)
    code.add("step_x", "            e_k += a_k   (one pixel right: e(x + 1, y) = e(x, y) + a)")
    code.add("step_y", "        e_row_k += b_k   (one row up: e(x, y + 1) = e(x, y) + b)",
             ops=ops_sum(step_ops(options), LOOP_OPS))
    footer(code)
    return code


def _incremental_traversal(run, tri, edges, attrs, at):
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    if i_lo > i_hi or j_lo > j_hi:
        return
    row = edges.at(i_lo, j_lo)
    yield run.calc(at["first"], (i_lo, j_lo), row, edges)
    a, b = edges.a, edges.b
    plot, skip = at["plot"], at["test"]
    for j in range(j_lo, j_hi + 1):
        es = list(row)
        for i in range(i_lo, i_hi + 1):
            yield run.test(i, j, es, edges, attrs, plot, skip)
            es = [e + d for e, d in zip(es, a)]
        if j < j_hi:
            row = [e + d for e, d in zip(row, b)]
            yield run.calc(at["step_y"], (i_lo, j + 1), row, edges)


INCREMENTAL = Traversal(_incremental_code, _incremental_traversal)


# ----------------------------------------------------------- backtrack
def top_start(run: Run, tri: Triangle):
    """The pixel under the top vertex (its column, the highest row at or below it), clipped."""
    top = max(tri.v, key=lambda p: (p[1], -p[0]))
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    column = min(max(floor_div(top[0], tri.S), i_lo), i_hi)
    return column, j_hi, i_lo, i_hi, j_lo


def _backtrack_code(options):
    bounded = options.get("bounded", False)
    walls = "the bounding box's edges" if bounded else "the grid's edges"
    code = Code()
    header(code, options)
    code.add("sides", "    outsideLeft = not inside(e_k) for an edge with a_k > 0;  outsideRight: "
                      f"for one with a_k < 0   ({walls} count as outside)")
    code.add("start", "    x, y = the pixel under the top vertex", ops=evaluate_ops(options))
    code.add("rows", "    while y >= ymin:")
    # A side test looks at up to two edges; each visit also steps x and the
    # edge values, and tests the wall.
    visit = ops_sum({"compare": 3, "pixels_tested": 1}, LOOP_OPS, step_ops(options))
    code.add("back", "        while not outsideLeft(x, y): x -= 1   (backtrack, e_k -= a_k)", VISIT,
             ops=visit)
    code.add("right", "        x += 1;  while not outsideRight(x, y):   (e_k += a_k)")
    pixel = ops_sum(visit, {"compare": 3})
    code.add("test", "            if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT,
             ops=pixel)
    _add_plot(code, options, pixel)
    code.add("stop", "        outside to the right: y -= 1   (e_k -= b_k; the next row starts "
                     "under this pixel)", VISIT, ops=visit)
    code.add("left_box", "        (a row whose walk went past xmin or xmax: outside_box counts "
                         "those visits)" if not bounded else
                         "        (xmin - 1 and xmax + 1 are never visited: the box bounds the walk)")
    footer(code)
    return code


def _left_right(edges: Edges):
    """Edge indices whose outside is to the left (a > 0) and to the right (a < 0)."""
    a = [edges.sign * v for v in edges.a]
    return [k for k in range(3) if a[k] > 0], [k for k in range(3) if a[k] < 0]


def _backtrack_traversal(run, tri, edges, attrs, at):
    x, y, i_lo, i_hi, j_lo = top_start(run, tri)
    if x < i_lo or y < j_lo:
        return
    left, right = _left_right(edges)
    bounded = run.options.get("bounded", False)
    # The walls: the grid's edges, or (bounded) the box's, which hold every covered pixel.
    wx0, _, wx1, _ = run.window
    if bounded:
        wx0, wx1 = i_lo, i_hi + 1
    es = edges.at(x, y)
    outside = OutsideBox(run, tri, i_lo, i_hi)
    yield from outside.start(at["start"])
    yield run.calc(at["start"], (x, y), es, edges)
    a, b = edges.a, edges.b
    back, stop, plot, skip = at["back"], at["stop"], at["plot"], at["test"]
    while y >= j_lo:
        while x >= wx0:
            out = any(edges.outside(es, k) for k in left)
            run.tested += 1
            outside.visit(x, y)
            yield run.lean(back, x, y, es, edges, attrs=attrs)
            if out:
                break
            x -= 1
            es = [e - d for e, d in zip(es, a)]
        x += 1
        es = [e + d for e, d in zip(es, a)]
        while x < wx1:
            if any(edges.outside(es, k) for k in right):
                run.tested += 1
                outside.visit(x, y)
                yield run.lean(stop, x, y, es, edges, attrs=attrs)
                break
            yield run.test(x, y, es, edges, attrs, plot, skip)
            x += 1
            es = [e + d for e, d in zip(es, a)]
        if x >= wx1:  # stopped by the right wall: come back inside it
            x -= 1
            es = [e - d for e, d in zip(es, a)]
        yield from outside.row_done(at["left_box"])
        y -= 1
        es = [e - d for e, d in zip(es, b)]


class OutsideBox:
    """Counts the walk's visits outside the triangle's bounding box (columns
    i_lo .. i_hi), which the lecture remarks a traversal never needs; a row
    that left the box reports the running count, and the first such row of a
    triangle says where in a note. (Only the back and stop visits can land
    outside: a pixel tested for coverage lies between them.)"""

    def __init__(self, run, tri, i_lo: int, i_hi: int):
        self.run, self.i_lo, self.i_hi = run, i_lo, i_hi
        self.number = next(s.number for s in run.setups if s.tri is tri) + 1
        self.row: list[tuple[int, int]] = []
        self.noted = False

    def start(self, line: int):
        """The running count, shown from the triangle's first step (0 when bounded)."""
        yield Vars(line=line, values={"outside_box": self.run.outside_box})

    def visit(self, x: int, y: int) -> None:
        if not self.i_lo <= x <= self.i_hi:
            self.row.append((x, y))

    def row_done(self, line: int):
        if not self.row:
            return
        self.run.outside_box += len(self.row)
        if not self.noted:
            self.noted = True
            x, y = self.row[0]
            yield Note(line=line, pixel=(x, y), text=(
                f"Triangle {self.number}: the walk visits ({x}, {y}), outside the bounding box "
                f"(columns {self.i_lo} .. {self.i_hi}); the option bounded keeps it inside."))
        yield Vars(line=line, pixel=self.row[-1], values={"outside_box": self.run.outside_box})
        self.row = []


BACKTRACK = Traversal(_backtrack_code, _backtrack_traversal)


# ------------------------------------------------------------- pineda
def _pineda_code(options):
    code = Code()
    header(code, options)
    code.add("sides", "    outside on the left: not inside(e_k) for an edge with a_k > 0; "
                      "on the right: for one with a_k < 0   (the grid's edges count as outside)")
    code.add("start", "    x, y = the pixel under the top vertex;  dir = left",
             ops=evaluate_ops(options))
    code.add("rows", "    for each row from the top down   (y -= 1: e_k -= b_k)")
    # Every visit tests the pixel, the side it walks towards (up to two
    # edges) and the grid's edge, then steps x and the edge values.
    visit = ops_sum(TEST_OPS, {"compare": 2}, LOOP_OPS, step_ops(options))
    code.add("ahead", "        from x, walk on in dir until outside on that side   "
                      "(e_k += dir * a_k)", VISIT, ops=visit)
    code.add("turn", "        from the pixel beside x, walk against dir until outside on that "
                     "side", VISIT, ops=visit)
    code.add("plot", "            a visited pixel with inside(e0), inside(e1), inside(e2): "
             + plot_text(options), PLOT, ops=ops_sum(visit, shade_ops(options)))
    code.add("flip", "        dir = -dir; the next row starts under the last pixel visited   "
                     "(zig-zag: no pixel is visited twice)")
    footer(code)
    return code


def _pineda_traversal(run, tri, edges, attrs, at):
    x, y, i_lo, i_hi, j_lo = top_start(run, tri)
    if x < i_lo or y < j_lo:
        return
    sides = _left_right(edges)
    wx0, _, wx1, _ = run.window
    a, b = edges.a, edges.b
    es = edges.at(x, y)
    yield run.calc(at["start"], (x, y), es, edges)
    direction = -1
    plot = at["plot"]

    def outside(values, d):
        return any(edges.outside(values, k) for k in sides[0 if d < 0 else 1])

    def walk(cx, ces, d, skip, frames):
        """Visit from (cx, ces) in direction d until outside on that side; the last visit."""
        last = None
        while wx0 <= cx < wx1:
            covered, tie = edges.test(ces)
            run.count(cx, y, covered)
            frame_line = plot if covered else skip
            frames.append(run.lean(frame_line, cx, y, ces, edges, tie, covered, attrs=attrs))
            last = (cx, ces)
            if outside(ces, d):
                break
            cx += d
            ces = [e + d * v for e, v in zip(ces, a)]
        return last

    while y >= j_lo:
        frames = []
        walk(x, es, direction, at["ahead"], frames)
        beside = [e - direction * v for e, v in zip(es, a)]
        back = walk(x - direction, beside, -direction, at["turn"], frames)
        yield from frames
        if back is not None:
            x, es = back
        direction = -direction
        y -= 1
        es = [e - v for e, v in zip(es, b)]


PINEDA = Traversal(_pineda_code, _pineda_traversal)


# ------------------------------------------------------------ linewise
SPAN_COLUMNS = ("x_left", "x_right") + BASE
BOUNDS_TEXT = {"top-left": "x_left <= x + 1/2 < x_right", "inclusive": "x_left <= x + 1/2 <= x_right",
               "strict": "x_left < x + 1/2 < x_right"}
ROW_TEXT = {"top-left": "a row exactly on a horizontal top edge is skipped (a bottom edge's row is kept)",
            "inclusive": "rows on horizontal edges are kept",
            "strict": "rows exactly on a horizontal edge are skipped"}


def _linewise_code(options):
    code = Code()
    header(code, options)
    code.add("sort", "    sort the vertices by y: bottom B, middle M, top T  "
                     "(B -> T is the long edge)", ops={"compare": 3, "mul": 2, "int_add": 5})
    code.add("rows", "    for y = each row whose centre yc = y + 1/2 lies in [B.y, T.y]:")
    # Per row: x on two edges, x = xp + (xq - xp)(yc - yp) / (yq - yp), the
    # choice of the short edge, the horizontal-edge tests, and the first
    # and last columns (exact: a floor division each; float: a rounding).
    if options["precision"] == "fixed":
        row = {"int_add": 8, "mul": 4, "div": 2, "compare": 3}
    else:
        row = {"float_add": 8, "mul": 2, "div": 2, "round": 2, "compare": 3}
    code.add("span", "        x_long = x on B -> T at yc;  x_short = x on B -> M (below M) or "
                     "M -> T;  x_left, x_right = the two in order;  "
                     + ROW_TEXT[options["fill_rule"]], ops=ops_sum(row, LOOP_OPS))
    code.add("cols", "        for x with " + BOUNDS_TEXT[options["fill_rule"]] + ":")
    # A pixel of the span is decided by the bounds alone: no test of its
    # own (the run's counters still call it tested, as it is visited).
    code.add("plot", "            " + plot_text(options), PLOT,
             ops=ops_sum(LOOP_OPS, {"pixels_tested": 1}, shade_ops(options)))
    footer(code)
    return code


def linewise_rows(tri: Triangle, rule: str, precision: str, window):
    """Per row j of the window: (j, x_left, x_right, first column, last column) in px.

    Exact for "fixed" (rational intersections compared in integers); the
    float precisions compute x on each edge as x_p + (x_q - x_p)(yc - y_p)
    / (y_q - y_p) in that type. The fill rule decides the span's ends:
    the left end lies on a left edge, the right end on a right edge.
    """
    scale = tri.S
    bottom, middle, top = sorted(tri.v, key=lambda p: (p[1], p[0]))
    o = (top[0] - bottom[0]) * (middle[1] - bottom[1]) - (top[1] - bottom[1]) * (middle[0] - bottom[0])
    short_is_left = o > 0  # M lies left of B -> T
    left_closed = rule in ("top-left", "inclusive")
    right_closed = rule == "inclusive"
    _, _, j_lo, j_hi = tri.box()
    wx0, wy0, wx1, wy1 = window
    for j in range(max(j_lo, wy0), min(j_hi, wy1 - 1) + 1):
        yc = (2 * j + 1) * scale  # doubled units: vertices count twice
        if yc < 2 * middle[1] or middle[1] == top[1]:
            short = (bottom, middle)
        else:
            short = (middle, top)
        on_bottom = middle[1] == bottom[1] and yc == 2 * bottom[1]
        on_top = middle[1] == top[1] and yc == 2 * top[1]
        if (on_bottom and rule == "strict") or (on_top and rule != "inclusive"):
            continue  # the row runs along a horizontal edge the rule leaves out
        if precision == "fixed":
            long_x = _x_on(bottom, top, yc)
            short_x = _x_on(*short, yc)
            xl, xr = (short_x, long_x) if short_is_left else (long_x, short_x)
            first = _first_column(xl, scale, left_closed)
            last = _last_column(xr, scale, right_closed)
            shown = (xl[0] / (xl[1] * 2 * scale), xr[0] / (xr[1] * 2 * scale))
        else:
            t = float if precision == "float64" else np.float32
            y = t(j + 0.5)
            long_x = _x_on_float(bottom, top, y, scale, t)
            short_x = _x_on_float(*short, y, scale, t)
            xl, xr = (short_x, long_x) if short_is_left else (long_x, short_x)
            half = t(0.5)
            first = math.ceil(float(xl - half)) if left_closed else math.floor(float(xl - half)) + 1
            last = math.floor(float(xr - half)) if right_closed else math.ceil(float(xr - half)) - 1
            shown = (float(xl), float(xr))
        yield j, shown[0], shown[1], max(first, wx0), min(last, wx1 - 1)


def _x_on(p, q, yc):
    """x (doubled 1/S units) on the edge p -> q at doubled height yc: (numerator, denominator > 0)."""
    den = 2 * (q[1] - p[1])
    num = 2 * p[0] * den + 2 * (q[0] - p[0]) * (yc - 2 * p[1])
    return (num, den) if den > 0 else (-num, -den)


def _first_column(x, scale, closed):
    # centre (2i + 1) * scale against num / den: the smallest i at (or past) it
    num, den = x
    return ceil_div(num - scale * den, 2 * scale * den) if closed else \
        floor_div(num - scale * den, 2 * scale * den) + 1


def _last_column(x, scale, closed):
    num, den = x
    return floor_div(num - scale * den, 2 * scale * den) if closed else \
        ceil_div(num - scale * den, 2 * scale * den) - 1


def _x_on_float(p, q, y, scale, t):
    xp, yp, xq, yq = (t(v / scale) for v in (p[0], p[1], q[0], q[1]))
    return xp + (xq - xp) * (y - yp) / (yq - yp)


def _linewise_traversal(run, tri, edges, attrs, at):
    view = ExactView(tri)
    yield run.calc(at["sort"])
    for j, xl, xr, first, last in linewise_rows(tri, run.rule, run.precision, run.window):
        yield run.calc(at["span"], None, extra=(xl, xr))
        for i in range(first, last + 1):
            es = tri.at(i, j)
            _, tie = view.test(es)
            run.count(i, j, True)
            yield run.lean(at["plot"], i, j, es, view, tie, True, extra=(xl, xr), attrs=attrs)


LINEWISE = Traversal(_linewise_code, _linewise_traversal, SPAN_COLUMNS)


# ----------------------------------------------------------- half-plane
def _halfplane_code(options):
    code = Code()
    header(code, options, winding="keep")
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("cols", "        for x = xmin .. xmax:")
    # Three side products (V - U) x (P - U): five additions and two
    # products each (exactly the expanded a x + b y + c in fixed precision).
    if options["precision"] == "fixed":
        sides = evaluate_ops(options)
    else:
        sides = {"float_add": 17, "mul": 6}
    pixel = ops_sum(sides, TEST_OPS, LOOP_OPS)
    code.add("test", "            P = (x + 1/2, y + 1/2);  side(P, U, V) = (V - U) x (P - U);  "
                     "if not (P on the winding's side of A->B, B->C, C->A, or on a kept edge): skip",
             VISIT, ops=pixel)
    _add_plot(code, options, pixel)
    footer(code)
    return code


class _SideEdges(Edges):
    """Edge values as the half-plane test computes them: (V - U) x (P - U)."""

    def at(self, i, j):
        if self.kind is int:
            return Edges.at(self, i, j)
        t = self.kind
        x, y = t(i + 0.5), t(j + 0.5)
        pts = [tuple(t(c) for c in self.tri.px(k)) for k in range(3)]
        values = []
        for k in range(3):
            (ux, uy), (vx, vy) = pts[(k + 1) % 3], pts[(k + 2) % 3]
            values.append((vx - ux) * (y - uy) - (vy - uy) * (x - ux))
        return values


def _halfplane_traversal(run, tri, edges, attrs, at):
    sides = _SideEdges(tri, run.precision)
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    plot, skip = at["plot"], at["test"]
    for j in range(j_lo, j_hi + 1):
        for i in range(i_lo, i_hi + 1):
            yield run.test(i, j, sides.at(i, j), sides, attrs, plot, skip)


HALFPLANE = Traversal(_halfplane_code, _halfplane_traversal, keep_winding=True)


# ---------------------------------------------------------- barycentric
def _barycentric_code(options):
    code = Code()
    header(code, options)
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("cols", "        for x = xmin .. xmax:")
    code.add("weights", "            alpha = e0 / 2A;  beta = e1 / 2A;  gamma = e2 / 2A   "
                        "(at the centre; they sum to 1)")
    # The weights line has no frame of its own: the edge values and the
    # three divisions are counted with the pixel's test.
    pixel = ops_sum(evaluate_ops(options), {"div": 3}, TEST_OPS, LOOP_OPS)
    code.add("test", "            if not (alpha, beta, gamma >= 0, a zero one kept only by the "
                     "fill rule on its edge): skip   (each is then <= 1 too)", VISIT, ops=pixel)
    _add_plot(code, options, pixel, weighted=True)
    footer(code)
    return code


def _barycentric_traversal(run, tri, edges, attrs, at):
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    for j in range(j_lo, j_hi + 1):
        for i in range(i_lo, i_hi + 1):
            es = edges.at(i, j)
            # Exact fractions in fixed precision; the float types divide in their own type.
            weights = [Fraction(e, edges.area2) if edges.kind is int else e / edges.area2
                       for e in es]
            covered, tie = edges.test(weights)
            run.count(i, j, covered)
            frame = run.lean(at["plot"] if covered else at["test"], i, j, es, edges, tie, covered,
                             attrs=attrs)
            if not covered:  # the test used the weights, so show them on rejected pixels too
                at_weights = 3 + len(BASE)  # alpha, beta, gamma follow line, x, y and BASE
                frame = (frame[:at_weights] + tuple(float(w) for w in weights)
                         + frame[at_weights + 3:])
            yield frame


BARYCENTRIC = Traversal(_barycentric_code, _barycentric_traversal, weights_always=True)
