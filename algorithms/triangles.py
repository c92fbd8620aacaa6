"""The triangle family: traversals that decide which pixel centres a triangle covers.

Conventions (see DESIGN.md): pixel (i, j) is the square [i, i+1) x [j, j+1),
sampled at its centre (i + 1/2, j + 1/2), y up. Vertices are real numbers,
snapped to the nearest multiple of 1/S px, S = 2^subpixel_bits (halves to
even), and every decision is made on those snapped vertices.

Edge functions. Edge k joins the two vertices other than P_k, from
P_i = P_(k+1) to P_j = P_(k+2) (indices mod 3):

    a_k = -(y_j - y_i),  b_k = x_j - x_i,  c_k = x_i*y_j - y_i*x_j,
    e_k(x, y) = a_k x + b_k y + c_k,

so e_k(x + 1, y) = e_k + a_k and e_k(x, y + 1) = e_k + b_k, and e_k is twice
the signed area of the triangle (P_i, P_j, point). For a counter-clockwise
triangle (2A = e_0(P_0) > 0) the inside is where all three are positive.
Clockwise input has P1 and P2 swapped (or is culled with ``cull``).

Exact arithmetic ("fixed" precision). In units of 1/S px, with the pixel
centre at (2i+1) S / 2, every E_k(i, j) = 2 S^2 e_k(i + 1/2, j + 1/2) is an
integer, E_k(i, j) = A_k i + B_k j + C_k with A_k = 2 S^2 a_k and
B_k = 2 S^2 b_k. The generators use Python integers (no limit); the numpy
kernel uses int64 where the bound 12 M^2 + 32 S M < 2^63 holds for the
triangle's extent M (in 1/S units, measured from its first vertex), which
covers every triangle with coordinates within +-2^20 px at S = 256, and
falls back to Python integers beyond. Frames show e_k in px^2
(E_k / 2S^2): exact whenever |E_k| < 2^53, which holds while the triangle
and the pixel fit in a box about 180,000 px wide; the decision itself is
always exact, and the panel's explanation recomputes the exact value.

Fill rule "top-left" (y up: left edges and bottom horizontal edges). A
centre with e_k = 0 lies on edge k. The tie rule keeps it when a_k > 0, or
a_k = 0 and b_k > 0. With counter-clockwise order the inside lies to the
left of each directed edge; a_k = y_i - y_j > 0 means the edge runs
downwards, and the left of a downward edge is the +x side, so the triangle
lies to the right of the edge: it is a *left* edge. a_k = 0 and b_k > 0 is
an edge running in +x, with the inside above it: a *bottom* edge. Two
counter-clockwise triangles sharing an edge see it with opposite a and b,
so exactly one of them keeps a centre on it. "inclusive" keeps every edge
(e >= 0: shared centres twice), "strict" none (e > 0: shared centres
never).

Precision "float64" and "float32" snap the same way and then evaluate the
implicit form a*x + b*y + c with a, b, c and the centre in that
floating-point type (the product terms cancel badly far from the origin,
which is what the option is there to show). For coordinates below 2^m px
on the 1/256 grid every intermediate is a multiple of 2^-16 below
2^(2m+2), so the result is exact while 2m + 18 bits fit the significand:
float32 is exact below 8 px, float64 below 2^17 px. The sweep in
tests/algorithms/test_triangles_float.py measures where they really start
to differ: float32 at coordinates of 16-32 px (a centre exactly on an
edge rounds to the wrong side), float64 at 2^19-2^20 px.

Frames. Every run starts with a Start record naming the values and the
constants S, fill_rule, precision and the number of triangles. Per
triangle: a Vars record (its number, snapped P0 P1 P2 in the order used,
2A, winding), a Note when it is degenerate, culled or swapped, and a Table
"edges" (a, b, c and the side of each edge). Every tested pixel is one
lean frame (line, x, y, e0, e1, e2, tie, ...): a PLOT frame on the
setPixel line when covered, a VISIT frame on the test line when not; tie
is 1 when no edge value is negative and one is exactly zero, so the fill
rule decided. Traversal bookkeeping (row starts, the backtracking walk,
linewise spans) uses CALC or VISIT frames on their own lines. With vertex
attributes (colors, z, w, s) covered pixels also carry alpha, beta, gamma,
the perspective-correct weights and 1/w (with w), z, s_affine and s_persp,
and a packed colour rgb (Start.pixel_value). The last frame is a Vars
record: tested, filled, overlaps (pixels filled more than once), cracks
(centres in the interior of the drawn triangles' union that no triangle
filled, decided exactly), drawn, degenerate, culled.

The generators take the grid (``uses_grid``) and never leave it; a
4-tuple (x0, y0, x1, y1) instead of (W, H) is a window anywhere in the
plane, which the tests use for coordinates up to 1e6 px.

Offset. The option offset = (X, Y), whole pixels, adds (X S, Y S) to the
snapped vertices and moves the window by (X, Y), so every edge function
is evaluated a long way from the origin while the frames name pixels of
the grid (moved back; Vars show the vertices where the run put them, and
Start's constants the offset). Exact arithmetic does not care: the pixels
equal those at offset 0. The float precisions do, which is what the option
shows. |X|, |Y| <= 2^21 px keeps every fixed-point term within int64.

Near-plane clipping (triangle-perspective, option near > 0). A vertex with
w <= 0 lies behind the eye, and the screen triangle of the projected
corners is not what it shows. Each triangle is first cut by w >= near in
homogeneous space (see clip_near); the 3 or 4 corners left are drawn as a
fan of triangles, with a Note and a Table "near clip" after Start.
"""
from __future__ import annotations

import math
from decimal import Decimal, localcontext
from fractions import Fraction

import numpy as np

from algorithms.exact import triangles as exact_triangles
from .interpolate import (ATTRIBUTE_OPTIONS, COLORS as VERTEX_COLORS, PERSPECTIVE, S as S_OPTION,
                          W as W_OPTION, Z as Z_OPTION, VertexAttributes, affine_value,
                          barycentric_weights, check_w, mix, pack, perspective_weights,
                          plane_coefficients, unpack, per_vertex)
from algorithms import registry as registry_module
from .code import Code, nonzero
from .registry import AlgorithmSpec, InputError, Inputs, Option, register
from .steps import CALC, NO_PIXEL, PER_ROW, PLOT, VISIT, CodeLine, Note, Start, Table, Vars

NAN = math.nan
RULES = ("top-left", "inclusive", "strict")
PRECISIONS = ("fixed", "float64", "float32")
MAX_COORDINATE = 1e15  # px; far beyond any grid, and still exact as a float times 256
MAX_REGION = 1 << 24  # pixels a run may look at when no grid bounds it
MAX_KERNEL_PIXELS = 1 << 28

FILL_RULE = Option("fill_rule", "choice", "top-left",
                   "which centres exactly on an edge count: top-left (left and bottom edges, "
                   "each shared centre once), inclusive (e >= 0), strict (e > 0)", choices=RULES)
PRECISION = Option("precision", "choice", "fixed",
                   "fixed: exact integers on the sub-pixel grid; float64/float32: the "
                   "edge functions a*x + b*y + c in floating point", choices=PRECISIONS)
SUBPIXEL_BITS = Option("subpixel_bits", "int", 8,
                       "vertices snap to multiples of 1/2^bits px (8: 1/256 px)",
                       minimum=0, maximum=8)
CULL = Option("cull", "bool", False,
              "drop clockwise triangles (back faces) instead of swapping P1 and P2")
# Whole pixels, so that the exact run is a pure integer translation. The
# bound keeps every fixed-point edge term within 64-bit integers, as
# hardware would hold them: at 2^21 px and S = 256 the products
# x_i * y_j reach 2^58 and c stays below 2^60.
MAX_OFFSET = 1 << 21
OFFSET = Option("offset", "point", (0, 0),
                "whole pixels X,Y added to the vertices and the pixel centres before the edge "
                "functions are evaluated: the grid shows the window at (X, Y), so the arithmetic "
                f"runs far from the origin (at most +-{MAX_OFFSET:,} px)",
                minimum=-MAX_OFFSET, maximum=MAX_OFFSET)
BASE_OPTIONS = (FILL_RULE, PRECISION, SUBPIXEL_BITS, CULL, OFFSET)
OPTIONS = BASE_OPTIONS + ATTRIBUTE_OPTIONS
TRIANGLES = Inputs(3, integer=False, names=("P0", "P1", "P2"), multiple=True)


# ================================================================ setup
def snap_fixed(value: float, scale: int) -> int:
    """The vertex coordinate in units of 1/scale px, nearest, halves to even."""
    if not abs(value) <= MAX_COORDINATE:
        raise InputError(f"coordinate {value} is beyond +-{MAX_COORDINATE:g} px")
    return round(value * scale)  # value * 2^k is exact, and round() is half-to-even


def floor_div(p: int, q: int) -> int:
    return p // q


def ceil_div(p: int, q: int) -> int:
    return -((-p) // q)


class Triangle:
    """One snapped triangle: vertices in 1/S px units and its integer edge functions.

    ``sign`` is +1 for counter-clockwise vertices and -1 for clockwise ones
    (kept only by the half-plane traversal); inside means sign * E > 0.
    """

    def __init__(self, number: int, vertices, order, scale: int, rule: str):
        self.number = number
        self.rule = rule
        self.v = tuple(vertices)
        self.order = tuple(order)
        self.S = scale
        (x0, y0), (x1, y1), (x2, y2) = self.v
        self.area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)  # S^2 * 2A
        self.sign = 1 if self.area2 > 0 else -1
        self.A, self.B, self.C = [], [], []
        for k in range(3):
            (xi, yi), (xj, yj) = self.v[(k + 1) % 3], self.v[(k + 2) % 3]
            self.A.append(-2 * scale * (yj - yi))
            self.B.append(2 * scale * (xj - xi))
            self.C.append(scale * (xj - xi) - scale * (yj - yi) + 2 * (xi * yj - yi * xj))
        self.include = tuple(tie_keeps(rule, self.sign * a, self.sign * b)
                             for a, b in zip(self.A, self.B))

    # -------------------------------------------------------- queries
    def at(self, i: int, j: int) -> list[int]:
        return [a * i + b * j + c for a, b, c in zip(self.A, self.B, self.C)]

    def side(self, k: int) -> str:
        a, b = self.sign * self.A[k], self.sign * self.B[k]
        if a > 0:
            return "left"
        if a < 0:
            return "right"
        return "bottom" if b > 0 else "top"

    def box(self) -> tuple[int, int, int, int]:
        """Pixel columns and rows (inclusive) whose centres lie within the bounding box."""
        xs = [p[0] for p in self.v]
        ys = [p[1] for p in self.v]
        s = self.S
        return (ceil_div(2 * min(xs) - s, 2 * s), floor_div(2 * max(xs) - s, 2 * s),
                ceil_div(2 * min(ys) - s, 2 * s), floor_div(2 * max(ys) - s, 2 * s))

    def px(self, k: int) -> tuple[float, float]:
        """Vertex k in pixels (exact while below 2^45 px)."""
        return (self.v[k][0] / self.S, self.v[k][1] / self.S)

    def ccw(self) -> tuple:
        return self.v if self.sign > 0 else (self.v[0], self.v[2], self.v[1])


def tie_keeps(rule: str, a, b) -> bool:
    """Does the fill rule keep a centre exactly on an edge with these (oriented) a, b?"""
    if rule == "inclusive":
        return True
    if rule == "strict":
        return False
    return a > 0 or (a == 0 and b > 0)


class Setup:
    """What became of one input triangle: drawn (``tri``), degenerate or culled."""

    def __init__(self, number, status, tri=None, snapped=()):
        self.number, self.status, self.tri, self.snapped = number, status, tri, snapped


def offset_of(options) -> tuple[int, int]:
    """The run's offset in whole pixels, checked against MAX_OFFSET."""
    ox, oy = (int(v) for v in options.get("offset", (0, 0)))
    if max(abs(ox), abs(oy)) > MAX_OFFSET:
        raise InputError(f"option offset: ({ox}, {oy}) is beyond +-{MAX_OFFSET:,} px, where "
                         "the edge values would no longer fit 64-bit integers")
    return ox, oy


def prepare(points, options, keep_winding: bool = False) -> list[Setup]:
    scale = 1 << options["subpixel_bits"]
    rule = options["fill_rule"]
    # Snap first, then translate in integers: the offset run is then exactly
    # the same triangles moved by whole pixels.
    ox, oy = offset_of(options)
    setups = []
    for n in range(len(points) // 3):
        snapped = [(snap_fixed(x, scale) + ox * scale, snap_fixed(y, scale) + oy * scale)
                   for x, y in points[3 * n:3 * n + 3]]
        (x0, y0), (x1, y1), (x2, y2) = snapped
        area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        indices = (3 * n, 3 * n + 1, 3 * n + 2)
        if area2 == 0:
            setups.append(Setup(n, "degenerate", snapped=snapped))
        elif area2 < 0 and options["cull"]:
            setups.append(Setup(n, "culled", snapped=snapped))
        elif area2 < 0 and not keep_winding:
            order = (indices[0], indices[2], indices[1])
            tri = Triangle(n, (snapped[0], snapped[2], snapped[1]), order, scale, rule)
            setups.append(Setup(n, "swapped", tri, snapped))
        else:
            status = "ccw" if area2 > 0 else "cw"
            setups.append(Setup(n, status, Triangle(n, snapped, indices, scale, rule), snapped))
    return setups


# ====================================================== evaluating edges
class Edges:
    """The three edge functions of one triangle in the chosen precision.

    ``at`` gives them at a pixel; ``a`` and ``b`` are the steps to the next
    pixel right and up (integers A, B in fixed precision); ``test`` applies
    the fill rule.
    """

    def __init__(self, tri: Triangle, precision: str):
        self.tri = tri
        self.precision = precision
        self.sign = tri.sign
        self.include = tri.include
        if precision == "fixed":
            self.kind = int
            self.a, self.b, self.c = tri.A, tri.B, tri.C
            self.unit = 2 * tri.S * tri.S
            self.area2 = 2 * tri.area2  # E0 at P0: 2 S^2 * 2A
            return
        self.kind = float if precision == "float64" else np.float32
        t = self.kind
        pts = [(t(x), t(y)) for x, y in (tri.px(k) for k in range(3))]
        self.a, self.b, self.c = [], [], []
        for k in range(3):
            (xi, yi), (xj, yj) = pts[(k + 1) % 3], pts[(k + 2) % 3]
            self.a.append(-(yj - yi))
            self.b.append(xj - xi)
            self.c.append(xi * yj - yi * xj)
        self.include = tuple(tie_keeps(tri.rule, self.sign * a, self.sign * b)
                             for a, b in zip(self.a, self.b))
        self.unit = 1
        (x0, y0), (x1, y1), (x2, y2) = pts
        self.area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)

    def at(self, i: int, j: int) -> tuple:
        (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) = self.a, self.b, self.c
        if self.kind is not int:
            i, j = self.kind(i + 0.5), self.kind(j + 0.5)  # the centre, in the float type
        return (a0 * i + b0 * j + c0, a1 * i + b1 * j + c1, a2 * i + b2 * j + c2)

    def test(self, es) -> tuple[bool, bool]:
        """(covered, tie): tie when no value is negative and one is exactly zero."""
        covered, zero = True, False
        for e, keep in zip(es, self.include):
            if self.sign < 0:
                e = -e
            if e > 0:
                continue
            if e < 0:
                return False, False
            zero = True
            covered = covered and keep
        return covered, zero

    def outside(self, es, k: int) -> bool:
        e = self.sign * es[k]
        return e < 0 or (e == 0 and not self.include[k])

    def shown(self, es) -> tuple:
        """The edge values in px^2, for the frames."""
        if self.kind is int:
            unit = self.unit
            return (es[0] / unit, es[1] / unit, es[2] / unit)
        return (float(es[0]), float(es[1]), float(es[2]))

    def weights(self, es):
        return tuple(float(w) for w in barycentric_weights(es[0], es[1], es[2], self.area2))


# ======================================================== pseudo-code
# ------------------------------------------------- operation counts
# The operations each line performs (CodeLine.ops), for the report's
# counts. Edge values are integers in fixed precision and floats otherwise,
# so their additions count as int_add or float_add by the precision. Work
# of a loop header or an update that yields no frame of its own (the
# column loop, e += a after a pixel) is counted with the frame of the
# pixel it belongs to; per-row work without a frame (the row loop, the
# pixel walks' row steps) is not counted. The three sign tests of a
# pixel are counted in full, as hardware does them side by side.
def _sum(*parts) -> dict:
    total = {}
    for part in parts:
        for name, count in part.items():
            total[name] = total.get(name, 0) + count
    return nonzero(total)


def _add(options) -> str:
    return "int_add" if options["precision"] == "fixed" else "float_add"


def _evaluate(options) -> dict:
    """e_k = a_k x + b_k y + c_k for three edges, at a centre."""
    centre = {} if options["precision"] == "fixed" else {"float_add": 2}
    return _sum({"mul": 6, _add(options): 6}, centre)


def _step(options) -> dict:
    """e_k += a_k (or b_k) for three edges."""
    return {_add(options): 3}


TEST_OPS = {"compare": 3, "pixels_tested": 1}
LOOP_OPS = {"int_add": 1, "compare": 1}


def _shade(options, weighted: bool = False) -> dict:
    """What a covered pixel adds for its vertex attributes (colour, z, s, w).

    ``weighted``: the traversal has the weights alpha, beta, gamma already.
    """
    colors, z, s, w = (options.get(name) for name in ("colors", "z", "s", "w"))
    if not (colors or z or s or w):
        return {}
    blend = {"mul": 3, "float_add": 2}  # alpha q0 + beta q1 + gamma q2
    parts = [] if weighted else [{"mul": 3}]  # alpha, beta, gamma = e_k * (1 / 2A)
    if w:  # perspective weights: e_k / w_k, their sum, a division, three products
        parts += [{"mul": 6, "float_add": 2, "div": 1}, blend]
    if colors:
        parts += [blend, blend, blend, {"round": 3}]
    if z:
        parts.append(blend)
    if s:
        parts += [blend] * (2 if w else 1)
    return _sum(*parts)


INSIDE_TEXT = {
    "top-left": "inside(e, a, b) = e > 0, or e == 0 on a left edge (a > 0) or a bottom "
                "edge (a == 0 and b > 0)",
    "inclusive": "inside(e, a, b) = e >= 0   (a centre on an edge belongs to both neighbours)",
    "strict": "inside(e, a, b) = e > 0   (a centre on an edge belongs to neither neighbour)",
}


def header(code: Code, options, winding: str = "swap") -> None:
    scale = 1 << options["subpixel_bits"]
    code.add("triangle", "for each triangle P0 P1 P2, in input order:")
    # Six snaps, 2A, and the tests of lines "degenerate" and "winding"
    # (which have frames only as notes).
    code.add("snap", f"    snap the vertices to multiples of 1/{scale} px;  "
                     "2A = (P1 - P0) x (P2 - P0)",
             ops={"mul": 8, "round": 6, "int_add": 5, "compare": 2})
    code.add("degenerate", "    if 2A == 0: skip the triangle (no area, so no pixels)")
    if options["cull"]:
        code.add("winding", "    if 2A < 0: skip the triangle (clockwise: a back face, culled)")
    elif winding == "keep":
        code.add("winding", "    winding = sign of 2A: inside lies left of every edge (ccw) "
                            "or right of every edge (cw)")
    else:
        code.add("winding", "    if 2A < 0: swap P1 and P2   (clockwise becomes counter-clockwise)")
    code.add("edges", "    edge k joins the other two vertices, Pi -> Pj:  a = yi - yj,  "
                      "b = xj - xi,  c = xi*yj - yi*xj;  e_k(x, y) = a x + b y + c",
             per={PER_ROW: {"mul": 2, _add(options): 3}})
    code.add("inside", "    " + INSIDE_TEXT[options["fill_rule"]])


def footer(code: Code) -> None:
    code.add("done", "count pixels tested and filled, overlaps (pixels filled more than once) "
                     "and cracks (centres inside the mesh that no triangle fills)")


def plot_text(options, what: str = "setPixel(x, y)") -> str:
    if options.get("colors"):
        return what[:-1] + ", alpha c0 + beta c1 + gamma c2)"
    return what


# ============================================================ the run
def window_of(grid, setups, offset=(0, 0)):
    """The pixels a run may touch: (x0, y0, x1, y1), x1 and y1 excluded.

    ``grid`` is (W, H) for the grid [0, W) x [0, H), or a window
    (x0, y0, x1, y1) of pixel indices, either moved by ``offset``. Without
    one, the bounding boxes of the drawn triangles.
    """
    if grid is not None:
        ox, oy = offset
        if len(grid) == 2:
            return (ox, oy, ox + int(grid[0]), oy + int(grid[1]))
        x0, y0, x1, y1 = (int(v) for v in grid)
        return (x0 + ox, y0 + oy, x1 + ox, y1 + oy)
    boxes = [s.tri.box() for s in setups if s.tri is not None]
    if not boxes:
        return (0, 0, 1, 1)
    window = (min(b[0] for b in boxes), min(b[2] for b in boxes),
              max(b[1] for b in boxes) + 1, max(b[3] for b in boxes) + 1)
    if (window[2] - window[0]) * (window[3] - window[1]) > MAX_REGION:
        raise InputError("the triangles span too many pixels to visit; give a grid")
    return window


class Run:
    """State shared by every traversal: options, triangles, counters, frame layout."""

    def __init__(self, points, options, grid, base_columns, keep_winding=False,
                 weights_always=False, attributes=None):
        if options["precision"] not in PRECISIONS:
            raise InputError(f"option precision: unknown precision {options['precision']!r}")
        self.options = options
        self.rule = options["fill_rule"]
        self.precision = options["precision"]
        self.S = 1 << options["subpixel_bits"]
        self.attributes = attributes or VertexAttributes(options, len(points), weights_always)
        self.setups = prepare(points, options, keep_winding)
        self.offset = offset_of(options)
        self.window = window_of(grid, self.setups, self.offset)
        x0, y0, x1, y1 = self.window
        self.base = tuple(base_columns)
        self.columns = self.base + self.attributes.names
        self.counts = np.zeros((max(0, y1 - y0), max(0, x1 - x0)), np.int32)
        self.tested = 0
        self.filled = 0

    # ------------------------------------------------------------ frames
    def start(self, line: int) -> Start:
        constants = {"S": self.S, "fill_rule": self.rule, "precision": self.precision,
                     "triangles": len(self.setups)}
        if any(self.offset):
            constants["offset"] = self.offset
        return Start(line, self.columns, constants, self.attributes.pixel_value)

    def setup_frames(self, setup: Setup, at: dict):
        """Vars, notes and the edge table of one triangle, as frames."""
        n = setup.number + 1
        snapped = [(x / self.S, y / self.S) for x, y in setup.snapped]
        values = {"triangle": n}
        if setup.tri is None:
            values.update({f"P{k}": snapped[k] for k in range(3)})
            values["2A"] = 0.0 if setup.status == "degenerate" else _area(setup.snapped, self.S)
            yield Vars(at["snap"], values)
            if setup.status == "degenerate":
                yield Note(at["degenerate"], f"Triangle {n} has no area (its vertices are "
                                             "collinear once snapped): no pixels.")
            else:
                yield Note(at["winding"], f"Triangle {n} is clockwise, a back face: culled.")
            return
        tri = setup.tri
        values.update({f"P{k}": tri.px(k) for k in range(3)})
        values["2A"] = tri.area2 / (self.S * self.S)
        values["winding"] = {"ccw": "counter-clockwise", "swapped": "clockwise: P1, P2 swapped",
                             "cw": "clockwise"}[setup.status]
        yield Vars(at["snap"], values)
        if setup.status == "swapped":
            yield Note(at["winding"], f"Triangle {n} was clockwise: P1 and P2 swapped, so "
                                      "the inside is where all e_k > 0.")
        yield edge_table(tri, at["edges"])

    def lean(self, line: int, i: int, j: int, es, edges: Edges, tie=False, covered=False,
             extra=(), attrs=None):
        """A frame at pixel (i, j) with the edge values and, where filled, the attributes."""
        shown = edges.shown(es)
        values = (*extra, *shown, 1.0 if tie else 0.0)
        if covered and attrs is not None and self.attributes.names:
            return (line, i, j, *values, *attrs.values(edges.weights(es)))
        return (line, i, j, *values, *self.attributes.nothing)

    def count(self, i: int, j: int, covered: bool) -> None:
        self.tested += 1
        if covered:
            self.filled += 1
            x0, y0, _, _ = self.window
            self.counts[j - y0, i - x0] += 1

    def calc(self, line: int, pixel=None, es=None, edges=None, extra=()):
        """A CALC frame, optionally at a pixel with edge values."""
        i, j = pixel if pixel else (NO_PIXEL, NO_PIXEL)
        if es is None:
            return (line, i, j, *extra, *((NAN,) * (len(self.base) - len(extra))),
                    *self.attributes.nothing)
        shown = edges.shown(es)
        pad = (NAN,) * (len(self.base) - len(extra) - 4)
        return (line, i, j, *extra, *shown, NAN, *pad, *self.attributes.nothing)

    def finish(self, line: int):
        overlaps, crack_cells = mesh_flaws(self)
        cracks = len(crack_cells)
        values = {"tested": self.tested, "filled": self.filled, "overlaps": overlaps,
                  "cracks": cracks,
                  "drawn": sum(1 for s in self.setups if s.tri is not None),
                  "degenerate": sum(1 for s in self.setups if s.status == "degenerate"),
                  "culled": sum(1 for s in self.setups if s.status == "culled")}
        yield Vars(line, values)
        if crack_cells:
            # The cracks themselves, so that a view can mark them on the grid.
            yield Table(line, "cracks", ("x", "y"), tuple(crack_cells))

    def drawn(self):
        for setup in self.setups:
            if setup.tri is not None:
                yield setup.tri

    def clip(self, box):
        """A triangle's box (columns and rows, inclusive) cut to the window."""
        x0, y0, x1, y1 = self.window
        return (max(box[0], x0), min(box[1], x1 - 1), max(box[2], y0), min(box[3], y1 - 1))


def _area(snapped, scale):
    (x0, y0), (x1, y1), (x2, y2) = snapped
    return ((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)) / (scale * scale)


def dyadic_text(numerator: int, denominator: int) -> str:
    """numerator / denominator exactly in decimal (the denominator a power of two)."""
    with localcontext() as context:
        context.prec = max(40, len(str(abs(numerator))) + 2 * denominator.bit_length())
        value = Decimal(numerator) / Decimal(denominator)
    text = format(value.normalize(), "f")
    return text


def edge_table(tri: Triangle, line: int) -> Table:
    rows = []
    unit = 2 * tri.S * tri.S
    for k in range(3):
        c_px = tri.C[k] - (tri.A[k] + tri.B[k]) // 2  # c at the pixel origin, not the centre
        rows.append((f"e{k}", f"P{(k + 1) % 3} -> P{(k + 2) % 3}", dyadic_text(tri.A[k], unit),
                     dyadic_text(tri.B[k], unit), dyadic_text(c_px, unit),
                     f"{tri.side(k)} ({'kept' if tri.include[k] else 'left out'} on a tie)"))
    return Table(line, "edges", ("edge", "from -> to", "a", "b", "c", "side"), tuple(rows))


# ================================================== overlaps and cracks
def mesh_flaws(run: Run) -> tuple[int, list]:
    """(how many pixels are filled more than once, the pixels (x, y) whose
    centres are interior but filled by none) in the window.

    The interior is that of the union of the drawn triangles' closed areas,
    decided exactly: centres strictly inside some triangle are interior;
    centres only on boundaries go to the exact direction test of
    exact_triangles.in_union_interior. Counts come from the run itself, so
    a floating-point run shows its own cracks and overlaps.
    """
    counts = run.counts
    overlaps = int((counts > 1).sum())
    tris = [tri.ccw() for tri in run.drawn()]
    if not tris or counts.size == 0:
        return overlaps, []
    x0, y0, x1, y1 = run.window
    strict = span_mask(tris, run.S, "strict", run.window)
    closed = span_mask(tris, run.S, "inclusive", run.window)
    interior = strict
    edges_only = np.argwhere(closed & ~strict)
    if len(edges_only):
        scaled = [tuple((2 * x, 2 * y) for x, y in tri) for tri in tris]
        boxes = [(min(p[0] for p in t), max(p[0] for p in t), min(p[1] for p in t),
                  max(p[1] for p in t)) for t in scaled]
        for r, c in edges_only:
            px, py = (2 * (c + x0) + 1) * run.S, (2 * (r + y0) + 1) * run.S
            near = [t for t, b in zip(scaled, boxes) if b[0] <= px <= b[1] and b[2] <= py <= b[3]]
            if exact_triangles.in_union_interior(near, (px, py)):
                interior[r, c] = True
    rows, columns = np.nonzero(interior & (counts == 0))
    return overlaps, [(int(c + x0), int(r + y0)) for r, c in zip(rows, columns)]


# ======================================================== explanations
def explain(trace, i):
    """Exact edge values at the step's pixel and why the pixel is in or out."""
    step = trace.step(i)
    if step.pixel is None or "e0" not in step.values:
        return []
    var = trace.variables_at(i)
    if not all(f"P{k}" in var for k in range(3)) or "S" not in var:
        return []
    scale = var["S"]
    vertices = [(round(x * scale), round(y * scale)) for x, y in (var[f"P{k}"] for k in range(3))]
    tri = Triangle(0, vertices, (0, 1, 2), scale, var["fill_rule"])
    if tri.area2 == 0:
        return []
    ox, oy = var.get("offset", (0, 0))  # the vertices are shown where the run put them
    es = tri.at(step.pixel[0] + ox, step.pixel[1] + oy)
    unit = 2 * scale * scale
    rows = []
    if "rgb" in step.values:
        rows.append(("colour", f"#{int(step.values['rgb']):06x}"))
    for k, e in enumerate(es):
        text = dyadic_text(e, unit)
        if var["precision"] != "fixed" and f"e{k}" in step.values:
            text += f"  ({var['precision']}: {step.values[f'e{k}']:.9g})"
        if e == 0:
            verdict = "kept" if tri.include[k] else "left out"
            text += f"  on the {tri.side(k)} edge: the fill rule says {verdict}"
        rows.append((f"e{k} exactly", text))
    if step.kind not in (PLOT, VISIT):
        return rows
    failing = [k for k in range(3) if tri.sign * es[k] < 0 or (es[k] == 0 and not tri.include[k])]
    if failing:
        rows.append(("verdict", "out: fails edge " + ", ".join(f"e{k}" for k in failing)))
        if step.kind == PLOT and var["precision"] != "fixed":
            rows.append(("rounding", f"{var['precision']} filled a pixel exact arithmetic "
                                     "leaves out"))
    else:
        rows.append(("verdict", "in: passes all three edges"))
    return rows


# ===================================================== the traversals
BASE = ("e0", "e1", "e2", "tie")


def _drive(run: Run, code: Code, traverse):
    """Start, each triangle's setup and traversal, then the totals; with an
    offset, pixels moved back onto the grid the trace shows."""
    frames = _frames(run, code, traverse)
    return _moved_back(frames, run.offset) if any(run.offset) else frames


def _moved_back(frames, offset):
    ox, oy = offset
    for frame in frames:
        if type(frame) is tuple:
            if frame[1] != NO_PIXEL:
                frame = (frame[0], frame[1] - ox, frame[2] - oy, *frame[3:])
        elif isinstance(frame, Table) and frame.name == "cracks":
            frame = Table(frame.line, frame.name, frame.columns,
                          tuple((x - ox, y - oy) for x, y in frame.rows))
        yield frame


def _frames(run: Run, code: Code, traverse):
    at = code.at
    yield run.start(at["triangle"])
    for setup in run.setups:
        yield from run.setup_frames(setup, at)
        if setup.tri is None:
            continue
        edges = Edges(setup.tri, run.precision)
        attrs = run.attributes.for_triangle(setup.tri.order)
        yield from traverse(run, setup.tri, edges, attrs, at)
    yield from run.finish(at["done"])


def _test_frame(run, at, i, j, es, edges, attrs, test_line="test", plot_line="plot"):
    covered, tie = edges.test(es)
    run.count(i, j, covered)
    line = at[plot_line] if covered else at[test_line]
    return run.lean(line, i, j, es, edges, tie, covered, attrs=attrs)


# ----------------------------------------------------------- scan, bbox
def box_code(points, options, whole: bool):
    code = Code()
    header(code, options)
    if whole:
        code.add("rows", "    for y = 0 .. H - 1:   (every row of the grid, bottom to top)")
        code.add("cols", "        for x = 0 .. W - 1:")
    else:
        code.add("rows", "    for y = ymin .. ymax:   (rows of the bounding box: centres "
                         "between the lowest and highest vertex)")
        code.add("cols", "        for x = xmin .. xmax:")
    pixel = _sum(_evaluate(options), TEST_OPS, LOOP_OPS)
    code.add("test", "            e_k = e_k(x + 1/2, y + 1/2);  "
                     "if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT, ops=pixel)
    code.add("plot", "            else: " + plot_text(options), PLOT, ops=_sum(pixel, _shade(options)))
    footer(code)
    return code


def scan_code(points, options):
    return tuple(box_code(points, options, True).lines)


def bbox_code(points, options):
    return tuple(box_code(points, options, False).lines)


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


def scan(points, options, grid=None):
    run = Run(points, options, grid, BASE)
    return _drive(run, box_code(points, options, True), _box_traversal(True))


def bbox(points, options, grid=None):
    run = Run(points, options, grid, BASE)
    return _drive(run, box_code(points, options, False), _box_traversal(False))


# ----------------------------------------------------------- incremental
def incremental_code(points, options):
    return tuple(_incremental_code(options).lines)


def _incremental_code(options):
    code = Code()
    header(code, options)
    code.add("first", "    e_row_k = e_k(xmin + 1/2, ymin + 1/2)   (the only full evaluation)",
             ops=_evaluate(options))
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("copy", "        e_k = e_row_k")
    code.add("cols", "        for x = xmin .. xmax:")
    # e_k += a_k (line step_x) follows every pixel's frame: counted with it.
    pixel = _sum(TEST_OPS, LOOP_OPS, _step(options))
    code.add("test", "            if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT,
             ops=pixel)
    code.add("plot", "            else: " + plot_text(options), PLOT, ops=_sum(pixel, _shade(options)))
    code.add("step_x", "            e_k += a_k   (one pixel right: e(x + 1, y) = e(x, y) + a)")
    code.add("step_y", "        e_row_k += b_k   (one row up: e(x, y + 1) = e(x, y) + b)",
             ops=_sum(_step(options), LOOP_OPS))
    footer(code)
    return code


def _incremental_traversal(run, tri, edges, attrs, at):
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    if i_lo > i_hi or j_lo > j_hi:
        return
    row = edges.at(i_lo, j_lo)
    yield run.calc(at["first"], (i_lo, j_lo), row, edges)
    a, b = edges.a, edges.b
    for j in range(j_lo, j_hi + 1):
        es = list(row)
        for i in range(i_lo, i_hi + 1):
            yield _test_frame(run, at, i, j, es, edges, attrs)
            es = [e + d for e, d in zip(es, a)]
        if j < j_hi:
            row = [e + d for e, d in zip(row, b)]
            yield run.calc(at["step_y"], (i_lo, j + 1), row, edges)


def incremental(points, options, grid=None):
    run = Run(points, options, grid, BASE)
    return _drive(run, _incremental_code(options), _incremental_traversal)


# ----------------------------------------------------------- backtrack
def top_start(run: Run, tri: Triangle):
    """The pixel under the top vertex (its column, the highest row at or below it), clipped."""
    top = max(tri.v, key=lambda p: (p[1], -p[0]))
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    column = min(max(floor_div(top[0], tri.S), i_lo), i_hi)
    return column, j_hi, i_lo, i_hi, j_lo


def _backtrack_code(options):
    code = Code()
    header(code, options)
    code.add("sides", "    outsideLeft = not inside(e_k) for an edge with a_k > 0;  outsideRight: "
                      "for one with a_k < 0   (the grid's edges count as outside)")
    code.add("start", "    x, y = the pixel under the top vertex", ops=_evaluate(options))
    code.add("rows", "    while y >= ymin:")
    # A side test looks at up to two edges; each visit also steps x and the
    # edge values, and tests the grid's edge.
    visit = _sum({"compare": 3, "pixels_tested": 1}, LOOP_OPS, _step(options))
    code.add("back", "        while not outsideLeft(x, y): x -= 1   (backtrack, e_k -= a_k)", VISIT,
             ops=visit)
    code.add("right", "        x += 1;  while not outsideRight(x, y):   (e_k += a_k)")
    pixel = _sum(visit, {"compare": 3})
    code.add("test", "            if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT,
             ops=pixel)
    code.add("plot", "            else: " + plot_text(options), PLOT, ops=_sum(pixel, _shade(options)))
    code.add("stop", "        outside to the right: y -= 1   (e_k -= b_k; the next row starts "
                     "under this pixel)", VISIT, ops=visit)
    footer(code)
    return code


def backtrack_code(points, options):
    return tuple(_backtrack_code(options).lines)


def _left_right(edges: Edges):
    """Edge indices whose outside is to the left (a > 0) and to the right (a < 0)."""
    a = [edges.sign * v for v in edges.a]
    return [k for k in range(3) if a[k] > 0], [k for k in range(3) if a[k] < 0]


def _backtrack_traversal(run, tri, edges, attrs, at):
    x, y, i_lo, i_hi, j_lo = top_start(run, tri)
    if x < i_lo or y < j_lo:
        return
    left, right = _left_right(edges)
    wx0, _, wx1, _ = run.window
    es = edges.at(x, y)
    yield run.calc(at["start"], (x, y), es, edges)
    a, b = edges.a, edges.b
    while y >= j_lo:
        while x >= wx0:
            out = any(edges.outside(es, k) for k in left)
            run.tested += 1
            yield run.lean(at["back"], x, y, es, edges, attrs=attrs)
            if out:
                break
            x -= 1
            es = [e - d for e, d in zip(es, a)]
        x += 1
        es = [e + d for e, d in zip(es, a)]
        while x < wx1:
            if any(edges.outside(es, k) for k in right):
                run.tested += 1
                yield run.lean(at["stop"], x, y, es, edges, attrs=attrs)
                break
            yield _test_frame(run, at, x, y, es, edges, attrs)
            x += 1
            es = [e + d for e, d in zip(es, a)]
        if x >= wx1:  # stopped by the grid's right edge: come back inside it
            x -= 1
            es = [e - d for e, d in zip(es, a)]
        y -= 1
        es = [e - d for e, d in zip(es, b)]


def backtrack(points, options, grid=None):
    run = Run(points, options, grid, BASE)
    return _drive(run, _backtrack_code(options), _backtrack_traversal)


# ------------------------------------------------------------- pineda
def _pineda_code(options):
    code = Code()
    header(code, options)
    code.add("sides", "    outside on the left: not inside(e_k) for an edge with a_k > 0; "
                      "on the right: for one with a_k < 0   (the grid's edges count as outside)")
    code.add("start", "    x, y = the pixel under the top vertex;  dir = left",
             ops=_evaluate(options))
    code.add("rows", "    for each row from the top down   (y -= 1: e_k -= b_k)")
    # Every visit tests the pixel, the side it walks towards (up to two
    # edges) and the grid's edge, then steps x and the edge values.
    visit = _sum(TEST_OPS, {"compare": 2}, LOOP_OPS, _step(options))
    code.add("ahead", "        from x, walk on in dir until outside on that side   "
                      "(e_k += dir * a_k)", VISIT, ops=visit)
    code.add("turn", "        from the pixel beside x, walk against dir until outside on that "
                     "side", VISIT, ops=visit)
    code.add("plot", "            a visited pixel with inside(e0), inside(e1), inside(e2): "
             + plot_text(options), PLOT, ops=_sum(visit, _shade(options)))
    code.add("flip", "        dir = -dir; the next row starts under the last pixel visited   "
                     "(zig-zag: no pixel is visited twice)")
    footer(code)
    return code


def pineda_code(points, options):
    return tuple(_pineda_code(options).lines)


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

    def outside(values, d):
        return any(edges.outside(values, k) for k in sides[0 if d < 0 else 1])

    def walk(cx, ces, d, line, frames):
        """Visit from (cx, ces) in direction d until outside on that side; the last visit."""
        last = None
        while wx0 <= cx < wx1:
            covered, tie = edges.test(ces)
            run.count(cx, y, covered)
            frame_line = at["plot"] if covered else at[line]
            frames.append(run.lean(frame_line, cx, y, ces, edges, tie, covered, attrs=attrs))
            last = (cx, ces)
            if outside(ces, d):
                break
            cx += d
            ces = [e + d * v for e, v in zip(ces, a)]
        return last

    while y >= j_lo:
        frames = []
        walk(x, es, direction, "ahead", frames)
        beside = [e - direction * v for e, v in zip(es, a)]
        back = walk(x - direction, beside, -direction, "turn", frames)
        yield from frames
        if back is not None:
            x, es = back
        direction = -direction
        y -= 1
        es = [e - v for e, v in zip(es, b)]


def pineda(points, options, grid=None):
    run = Run(points, options, grid, BASE)
    return _drive(run, _pineda_code(options), _pineda_traversal)


# ------------------------------------------------------------ linewise
LINEWISE = ("x_left", "x_right") + BASE
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
                     + ROW_TEXT[options["fill_rule"]], ops=_sum(row, LOOP_OPS))
    code.add("cols", "        for x with " + BOUNDS_TEXT[options["fill_rule"]] + ":")
    # A pixel of the span is decided by the bounds alone: no test of its
    # own (the run's counters still call it tested, as it is visited).
    code.add("plot", "            " + plot_text(options), PLOT,
             ops=_sum(LOOP_OPS, {"pixels_tested": 1}, _shade(options)))
    footer(code)
    return code


def linewise_code(points, options):
    return tuple(_linewise_code(options).lines)


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
    view = _ExactView(tri)
    yield run.calc(at["sort"])
    for j, xl, xr, first, last in linewise_rows(tri, run.rule, run.precision, run.window):
        yield run.calc(at["span"], None, extra=(xl, xr))
        for i in range(first, last + 1):
            es = tri.at(i, j)
            _, tie = view.test(es)
            run.count(i, j, True)
            yield run.lean(at["plot"], i, j, es, view, tie, True, extra=(xl, xr), attrs=attrs)


class _ExactView(Edges):
    """Exact edge values of a triangle for display, whatever the run's precision."""

    def __init__(self, tri):  # noqa: D401 - a light view, not a full setup
        self.tri, self.sign, self.include = tri, tri.sign, tri.include
        self.kind, self.unit, self.area2 = int, 2 * tri.S * tri.S, 2 * tri.area2
        self.a, self.b, self.c = tri.A, tri.B, tri.C


def linewise(points, options, grid=None):
    run = Run(points, options, grid, LINEWISE)
    return _drive(run, _linewise_code(options), _linewise_traversal)


# ----------------------------------------------------------- half-plane
def _halfplane_code(options):
    code = Code()
    header(code, options, winding="keep")
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("cols", "        for x = xmin .. xmax:")
    # Three side products (V - U) x (P - U): five additions and two
    # products each (exactly the expanded a x + b y + c in fixed precision).
    if options["precision"] == "fixed":
        sides = _evaluate(options)
    else:
        sides = {"float_add": 17, "mul": 6}
    pixel = _sum(sides, TEST_OPS, LOOP_OPS)
    code.add("test", "            P = (x + 1/2, y + 1/2);  side(P, U, V) = (V - U) x (P - U);  "
                     "if not (P on the winding's side of A->B, B->C, C->A, or on a kept edge): skip",
             VISIT, ops=pixel)
    code.add("plot", "            else: " + plot_text(options), PLOT, ops=_sum(pixel, _shade(options)))
    footer(code)
    return code


def halfplane_code(points, options):
    return tuple(_halfplane_code(options).lines)


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
    for j in range(j_lo, j_hi + 1):
        for i in range(i_lo, i_hi + 1):
            yield _test_frame(run, at, i, j, sides.at(i, j), sides, attrs)


def halfplane(points, options, grid=None):
    run = Run(points, options, grid, BASE, keep_winding=True)
    return _drive(run, _halfplane_code(options), _halfplane_traversal)


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
    pixel = _sum(_evaluate(options), {"div": 3}, TEST_OPS, LOOP_OPS)
    code.add("test", "            if not (alpha, beta, gamma >= 0, a zero one kept only by the "
                     "fill rule on its edge): skip   (each is then <= 1 too)", VISIT, ops=pixel)
    code.add("plot", "            else: " + plot_text(options), PLOT,
             ops=_sum(pixel, _shade(options, weighted=True)))
    footer(code)
    return code


def barycentric_code(points, options):
    return tuple(_barycentric_code(options).lines)


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


def barycentric(points, options, grid=None):
    run = Run(points, options, grid, BASE, weights_always=True)
    return _drive(run, _barycentric_code(options), _barycentric_traversal)


# ============================================================ kernels
def snap_array(points, scale: int) -> np.ndarray:
    """(n, 2) int64 vertex coordinates in 1/scale px (|x| <= 1e15 px keeps them below 2^58)."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    if pts.size and not np.all(np.abs(pts) <= MAX_COORDINATE):
        raise InputError(f"a coordinate is beyond +-{MAX_COORDINATE:g} px")
    return np.rint(pts * scale).astype(np.int64)  # exact scaling; rint is half-to-even


def oriented(points, options):
    """Snapped triangles, counter-clockwise, degenerate and culled ones dropped.

    Returns (vertices (T, 3, 2) int64, input triangle numbers).
    """
    scale = 1 << options.get("subpixel_bits", 8)
    ox, oy = offset_of(options)
    tris = snap_array(points, scale).reshape(-1, 3, 2) + np.array([ox, oy], np.int64) * scale
    d1 = tris[:, 1] - tris[:, 0]
    d2 = tris[:, 2] - tris[:, 0]
    if tris.size and np.abs(tris).max() >= 1 << 30:
        # the area products could overflow; only Python integers are safe
        area = np.array([int(a[0]) * int(b[1]) - int(b[0]) * int(a[1]) for a, b in zip(d1, d2)],
                        dtype=object)
        sign = np.array([(a > 0) - (a < 0) for a in area], dtype=np.int64)
    else:
        sign = np.sign(d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1])
    keep = sign != 0
    if options.get("cull", False):
        keep &= sign > 0
    numbers = np.flatnonzero(keep)
    tris = tris[keep].copy()
    cw = sign[keep] < 0
    tris[cw, 1], tris[cw, 2] = tris[cw, 2].copy(), tris[cw, 1].copy()
    return tris, numbers


def span_arrays(tris, scale: int, rule: str, window=None, top_down=False):
    """Covered runs of counter-clockwise triangles, vertices in 1/scale px.

    ``tris`` is an int64 array (T, 3, 2) or a list of vertex triples of
    Python integers. Returns (triangle, y, x_start, x_end) int64 arrays,
    x_end excluded, one entry per non-empty row, ordered by triangle and
    then by row (upwards, or downwards with ``top_down``). Per row and
    edge, A i + R > 0 with R = B j + C (+1 where the rule keeps ties) bounds
    i by one floor division, so no pixel is tested. Triangles too large for
    int64 go through the same steps in Python integers.
    """
    if len(tris) == 0:
        empty = np.zeros(0, np.int64)
        return empty, empty, empty, empty
    if isinstance(tris, np.ndarray):
        fits = _fits_int64_array(tris, scale)
        small, big = np.flatnonzero(fits), np.flatnonzero(~fits)
        arrays = tris if len(big) == 0 else tris[small]
    else:
        fits = [_fits_int64(t, scale) for t in tris]
        small = np.flatnonzero(fits)
        big = np.flatnonzero(~np.array(fits, bool))
        arrays = np.array([tris[n] for n in small], dtype=np.int64).reshape(-1, 3, 2)
    parts = [_spans_numpy(arrays, small, scale, rule, window)] if len(small) else []
    parts += [_spans_python(tris[n], n, scale, rule, window) for n in big]
    t, y, x0, x1 = (np.concatenate([p[k] for p in parts]) for k in range(4))
    if len(big) or top_down:
        order = np.lexsort((-y if top_down else y, t))
        t, y, x0, x1 = t[order], y[order], x0[order], x1[order]
    return t, y, x0, x1


def _fits_int64(tri, scale) -> bool:
    """Do the edge terms of this triangle, relative to its first vertex's pixel, fit int64?"""
    xs = [int(p[0]) for p in tri]
    ys = [int(p[1]) for p in tri]
    ox, oy = (xs[0] // scale) * scale, (ys[0] // scale) * scale
    m = max(max(abs(v - ox) for v in xs), max(abs(v - oy) for v in ys))
    return 12 * m * m + 32 * scale * m + 64 < 2 ** 63


def _fits_int64_array(tris, scale) -> np.ndarray:
    # The same bound in float64, with room to spare for its rounding.
    f = tris.astype(np.float64)
    origin = np.floor(f[:, 0:1, :] / scale) * scale
    d = np.abs(f - origin).reshape(-1, 6)
    m = d[:, 0]
    for column in range(1, 6):
        m = np.maximum(m, d[:, column])
    return 12 * m * m + 32 * scale * m + 64 < 0.9 * 2.0 ** 63


def _edge_terms(X, Y, scale, rule):
    """A, B, C (relative to the first vertex's pixel) and the tie bias, per edge: (T, 3) each."""
    Xi, Yi = np.roll(X, -1, axis=1), np.roll(Y, -1, axis=1)   # P_(k+1)
    Xj, Yj = np.roll(X, -2, axis=1), np.roll(Y, -2, axis=1)   # P_(k+2)
    A = -2 * scale * (Yj - Yi)
    B = 2 * scale * (Xj - Xi)
    C = scale * (Xj - Xi) - scale * (Yj - Yi) + 2 * (Xi * Yj - Yi * Xj)
    if rule == "inclusive":
        bias = np.ones_like(A)
    elif rule == "strict":
        bias = np.zeros_like(A)
    else:
        bias = ((A > 0) | ((A == 0) & (B > 0))).astype(A.dtype)
    return A, B, C, bias


def _spans_numpy(tris, numbers, scale, rule, window):
    X, Y = tris[:, :, 0], tris[:, :, 1]
    ox, oy = X[:, 0] // scale, Y[:, 0] // scale
    X = X - (ox * scale)[:, None]
    Y = Y - (oy * scale)[:, None]
    A, B, C, bias = _edge_terms(X, Y, scale, rule)
    x_min = np.minimum(np.minimum(X[:, 0], X[:, 1]), X[:, 2])
    x_max = np.maximum(np.maximum(X[:, 0], X[:, 1]), X[:, 2])
    y_min = np.minimum(np.minimum(Y[:, 0], Y[:, 1]), Y[:, 2])
    y_max = np.maximum(np.maximum(Y[:, 0], Y[:, 1]), Y[:, 2])
    i_lo = -((scale - 2 * x_min) // (2 * scale))
    i_hi = (2 * x_max - scale) // (2 * scale)
    j_lo = -((scale - 2 * y_min) // (2 * scale))
    j_hi = (2 * y_max - scale) // (2 * scale)
    if window is not None:
        wx0, wy0, wx1, wy1 = window
        i_lo, i_hi = np.maximum(i_lo, wx0 - ox), np.minimum(i_hi, wx1 - 1 - ox)
        j_lo, j_hi = np.maximum(j_lo, wy0 - oy), np.minimum(j_hi, wy1 - 1 - oy)
    rows = np.maximum(j_hi - j_lo + 1, 0)
    total = int(rows.sum())
    if total > MAX_KERNEL_PIXELS:
        raise InputError("the triangles span too many rows; give a grid to clip them")
    which = np.repeat(np.arange(len(tris)), rows)
    first = np.cumsum(rows) - rows
    j = np.repeat(j_lo - first, rows) + np.arange(total)
    lo, hi = i_lo[which], i_hi[which]
    empty = np.zeros(total, bool)
    for k in range(3):  # one edge at a time: short reductions are slow in numpy
        a = A[:, k][which]
        r = B[:, k][which] * j + (C[:, k] + bias[:, k])[which]  # the test is A i + r > 0
        q = np.floor_divide(-r, np.where(a == 0, 1, np.abs(a)))
        np.maximum(lo, np.where(a > 0, q + 1, lo), out=lo)
        np.minimum(hi, np.where(a < 0, -q - 1, hi), out=hi)
        empty |= (a == 0) & (r <= 0)
    keep = (hi >= lo) & ~empty
    w = which[keep]
    return (np.asarray(numbers, np.int64)[w], j[keep] + oy[w], lo[keep] + ox[w],
            hi[keep] + 1 + ox[w])


def _spans_python(tri, number, scale, rule, window):
    """The same bounds as _spans_numpy, one row at a time in Python integers."""
    vertices = [(int(x), int(y)) for x, y in tri]
    t = Triangle(number, vertices, (0, 1, 2), scale, rule)
    i_lo, i_hi, j_lo, j_hi = t.box()
    if window is not None:
        wx0, wy0, wx1, wy1 = window
        i_lo, i_hi, j_lo, j_hi = max(i_lo, wx0), min(i_hi, wx1 - 1), max(j_lo, wy0), min(j_hi, wy1 - 1)
    if j_hi - j_lo + 1 > MAX_KERNEL_PIXELS:
        raise InputError("the triangles span too many rows; give a grid to clip them")
    out = ([], [], [], [])
    for j in range(j_lo, j_hi + 1):
        lo, hi = i_lo, i_hi
        for k in range(3):
            a = t.A[k]
            r = t.B[k] * j + t.C[k] + (1 if t.include[k] else 0)
            if a > 0:
                lo = max(lo, floor_div(-r, a) + 1)
            elif a < 0:
                hi = min(hi, -floor_div(-r, -a) - 1)
            elif r <= 0:
                hi = lo - 1
        if hi >= lo:
            for column, value in zip(out, (number, j, lo, hi + 1)):
                column.append(value)
    return tuple(np.array(c, dtype=np.int64) for c in out)


def span_mask(tris, scale, rule, window) -> np.ndarray:
    """Boolean (rows, columns) of the window: centres covered by any of ``tris``."""
    x0, y0, x1, y1 = window
    mask = np.zeros((y1 - y0, x1 - x0), bool)
    _, y, s, e = span_arrays(list(tris), scale, rule, window)
    for row, start, end in zip(y - y0, s - x0, e - x0):
        mask[row, start:end] = True
    return mask


def pixels_from_spans(y, x_start, x_end) -> np.ndarray:
    """(n, 2) pixels of the runs, in order."""
    keep = x_end > x_start
    y, x_start, x_end = y[keep], x_start[keep], x_end[keep]
    lengths = x_end - x_start
    total = int(lengths.sum())
    if total > MAX_KERNEL_PIXELS:
        raise InputError("too many pixels; give a grid to clip the triangles")
    out = np.empty((total, 2), np.int64)
    if total == 0:
        return out
    # x climbs by one along a run and jumps at the start of the next: a cumsum of steps.
    step = np.ones(total, np.int64)
    step[np.cumsum(lengths) - lengths] = x_start - np.concatenate(([0], x_end[:-1] - 1))
    np.cumsum(step, out=out[:, 0])
    out[:, 1] = np.repeat(y, lengths)
    return out


def counts_from_spans(y, x_start, x_end, width: int, height: int) -> np.ndarray:
    """Coverage counts (height, width) int32 of runs, clipped to the grid."""
    keep = (y >= 0) & (y < height)
    y, s, e = y[keep], np.clip(x_start[keep], 0, width), np.clip(x_end[keep], 0, width)
    counts = np.zeros((height, width), np.int32)
    if len(y) <= 4096:  # few, long runs: one slice each
        for row, start, end in zip(y.tolist(), s.tolist(), e.tolist()):
            counts[row, start:end] += 1
        return counts
    lengths = e - s
    long = lengths >= 32
    if long.any():
        # Long runs: +1 where each starts, -1 where it ends, summed along the rows.
        stride = width + 1
        marks = np.bincount(y[long] * stride + s[long], minlength=height * stride)
        marks -= np.bincount(y[long] * stride + e[long], minlength=height * stride)
        counts += np.cumsum(marks.reshape(height, stride), axis=1)[:, :width].astype(np.int32)
    y, s, lengths = y[~long], s[~long], lengths[~long]
    # Short runs: every pixel's flat index, counted by bincount, in chunks
    # of at most 2^24 pixels so memory stays bounded.
    ends = np.cumsum(lengths)
    flat_counts = counts.reshape(-1)
    lo = 0
    while lo < len(y):
        hi = int(np.searchsorted(ends, ends[lo] - lengths[lo] + (1 << 24), side="right"))
        hi = max(hi, lo + 1)
        part = lengths[lo:hi]
        first = np.cumsum(part) - part
        flat = np.repeat(y[lo:hi] * width + s[lo:hi] - first, part) + np.arange(int(part.sum()))
        flat_counts += np.bincount(flat, minlength=width * height).astype(np.int32)
        lo = hi
    return counts


def fill(points, grid, rule: str = "top-left", subpixel_bits: int = 8, cull: bool = False):
    """Coverage counts of k triangles (3k points) on a W x H grid, exact: the fast path."""
    options = {"subpixel_bits": subpixel_bits, "cull": cull}
    width, height = grid
    tris, _ = oriented(points, options)
    _, y, s, e = span_arrays(tris, 1 << subpixel_bits, rule, (0, 0, width, height))
    return counts_from_spans(y, s, e, width, height)


def kernel_pixels(points, options, grid=None, top_down=False) -> np.ndarray:
    """Fast kernel (precision fixed): covered pixels, per triangle, row by row, left to right."""
    offset = offset_of(options)
    window = None if grid is None else window_of(grid, (), offset)
    scale = 1 << options.get("subpixel_bits", 8)
    rule = options.get("fill_rule", "top-left")
    tris, _ = oriented(points, options)
    _, y, s, e = span_arrays(tris, scale, rule, window, top_down)
    return pixels_from_spans(y, s, e) - np.array(offset, np.int64)


def _float_box_pixels(points, options, grid, whole):
    """Dense float evaluation of a*x + b*y + c, as triangle-scan / triangle-bbox do it."""
    full = dict(options)
    setups = prepare(points, full)
    offset = offset_of(full)
    window = window_of(grid, setups, offset)
    t = np.float64 if options["precision"] == "float64" else np.float32
    out = []
    for setup in setups:
        if setup.tri is None:
            continue
        edges = Edges(setup.tri, options["precision"])
        if whole:
            i_lo, j_lo, i_hi, j_hi = window[0], window[1], window[2] - 1, window[3] - 1
        else:
            x0, y0, x1, y1 = window
            b = setup.tri.box()
            i_lo, i_hi, j_lo, j_hi = max(b[0], x0), min(b[1], x1 - 1), max(b[2], y0), min(b[3], y1 - 1)
        if i_lo > i_hi or j_lo > j_hi:
            continue
        xs = (np.arange(i_lo, i_hi + 1, dtype=np.float64) + 0.5).astype(t)[None, :]
        ys = (np.arange(j_lo, j_hi + 1, dtype=np.float64) + 0.5).astype(t)[:, None]
        ok = np.ones((len(ys), xs.shape[1]), bool)
        for k in range(3):
            a, b, c = t(edges.a[k]), t(edges.b[k]), t(edges.c[k])
            e = (a * xs + b * ys) + c
            e = edges.sign * e
            ok &= (e > 0) | ((e == 0) & edges.include[k])
        rows, cols = np.nonzero(ok)
        out.append(np.stack([cols + i_lo - offset[0], rows + j_lo - offset[1]], axis=1))
    return np.concatenate(out).astype(np.int64) if out else np.zeros((0, 2), np.int64)


def make_kernel(name: str, generator, code, top_down=False, box=None):
    """The spec's kernel: exact spans for fixed precision; floats as the generator does them."""
    def kernel(points, options, grid=None):
        options = {**{o.name: o.default for o in OPTIONS}, **options}
        if options.get("near", 0) > 0:  # the pieces left by the near plane are drawn
            points, _ = clip_near(points, PerspectiveColumns(options, len(points)),
                                  options["near"])
        if options["precision"] == "fixed":
            return kernel_pixels(points, options, grid, top_down)
        if box is not None:
            return _float_box_pixels(points, options, grid, whole=box == "whole")
        lines = code(points, options)
        plotted = []
        for frame in generator(points, options, grid):
            if type(frame) is tuple and lines[frame[0]].kind == PLOT and frame[1] != NO_PIXEL:
                plotted.append((frame[1], frame[2]))
        return np.array(plotted, dtype=np.int64).reshape(-1, 2)
    kernel.__name__ = f"{name.replace('-', '_')}_kernel"
    return kernel


# ====================================================== interpolation
def _plane_code(options):
    code = Code()
    header(code, options)
    # Operation counts per attribute q (colour channels, z, s). The row
    # step (step_y) yields no frame and is not counted; the column step
    # (step_x) follows every pixel's frame and is counted with it.
    n = 3 * bool(options.get("colors")) + bool(options.get("z")) + bool(options.get("s"))
    code.add("setup", "    det = (x1-x0)(y2-y0) - (x2-x0)(y1-y0);  for each attribute q:  "
                      "c_x = ((q1-q0)(y2-y0) - (q2-q0)(y1-y0)) / det;  "
                      "c_y = ((q2-q0)(x1-x0) - (q1-q0)(x2-x0)) / det   (Cramer's rule)",
             ops={"mul": 2 + 4 * n, "float_add": 5 + 6 * n, "div": 2 * n})
    code.add("first", "    q_row = q0 + c_x (xmin + 1/2 - x0) + c_y (ymin + 1/2 - y0);  "
                      "e_row_k = e_k(xmin + 1/2, ymin + 1/2)",
             ops=_sum(_evaluate(options), {"mul": 2 * n, "float_add": 4 * n}))
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("copy", "        q = q_row;  e_k = e_row_k")
    code.add("cols", "        for x = xmin .. xmax:")
    pixel = _sum(TEST_OPS, LOOP_OPS, _step(options), {"float_add": n})
    code.add("test", "            if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT,
             ops=pixel)
    code.add("plot", "            else: output(x, y, q)", PLOT,
             ops=_sum(pixel, {"round": 3} if options.get("colors") else {}))
    code.add("step_x", "            q += c_x;  e_k += a_k")
    code.add("step_y", "        q_row += c_y;  e_row_k += b_k")
    footer(code)
    return code


def plane_code(points, options):
    return tuple(_plane_code(options).lines)


class PlaneAttributes:
    """Which attributes the plane walk carries: colour channels, z and s."""

    def __init__(self, options, count):
        colors = per_vertex(options, "colors", count)
        self.colors = [unpack(c) for c in colors] if colors else None
        self.z = per_vertex(options, "z", count)
        self.s = per_vertex(options, "s", count)
        if self.colors is None and self.z is None and self.s is None:
            raise InputError("triangle-plane interpolates an attribute: set colors, z or s")
        names = []
        if self.colors is not None:
            names += ["r", "g", "b"]
        if self.z is not None:
            names.append("z")
        if self.s is not None:
            names.append("s")
        if self.colors is not None:
            names.append("rgb")
        self.names = tuple(names)
        self.nothing = (NAN,) * len(names)
        self.pixel_value = "rgb" if self.colors is not None else None

    def vertex_values(self, order):
        """Per attribute: the three vertex values of a triangle."""
        values = []
        if self.colors is not None:
            values += [[self.colors[k][n] for k in order] for n in range(3)]
        for attr in (self.z, self.s):
            if attr is not None:
                values.append([attr[k] for k in order])
        return values


def _plane_traversal(run, tri, edges, attrs, at):
    plane = run.plane
    values = plane.vertex_values(tri.order)
    corners = [tri.px(k) for k in range(3)]
    slopes = [plane_coefficients(corners, q) for q in values]
    yield Vars(at["setup"], {f"c_x[{n}]": cx for n, (cx, _) in zip(plane.names, slopes)}
               | {f"c_y[{n}]": cy for n, (_, cy) in zip(plane.names, slopes)})
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    if i_lo > i_hi or j_lo > j_hi:
        return
    x0, y0 = corners[0]
    q_row = [q[0] + cx * (i_lo + 0.5 - x0) + cy * (j_lo + 0.5 - y0)
             for q, (cx, cy) in zip(values, slopes)]
    e_row = edges.at(i_lo, j_lo)
    yield run.calc(at["first"], (i_lo, j_lo), e_row, edges)
    a, b = edges.a, edges.b
    for j in range(j_lo, j_hi + 1):
        q, es = list(q_row), list(e_row)
        for i in range(i_lo, i_hi + 1):
            covered, tie = edges.test(es)
            run.count(i, j, covered)
            shown = edges.shown(es)
            if covered:
                extra = list(q)
                if plane.colors is not None:
                    extra.append(float(pack(q[:3])))
                yield (at["plot"], i, j, *shown, 1.0 if tie else 0.0, *map(float, extra))
            else:
                yield (at["test"], i, j, *shown, 1.0 if tie else 0.0, *plane.nothing)
            q = [v + cx for v, (cx, _) in zip(q, slopes)]
            es = [e + d for e, d in zip(es, a)]
        q_row = [v + cy for v, (_, cy) in zip(q_row, slopes)]
        e_row = [e + d for e, d in zip(e_row, b)]


class _NoAttributes:
    names = ()
    nothing = ()
    pixel_value = None
    active = False

    def for_triangle(self, order):
        return None


def plane(points, options, grid=None):
    attributes = PlaneAttributes(options, len(points))
    run = Run(points, options, grid, BASE, attributes=_PlaneColumns(attributes))
    run.plane = attributes
    return _drive(run, _plane_code(options), _plane_traversal)


class _PlaneColumns(_NoAttributes):
    def __init__(self, plane_attributes):
        self.names = plane_attributes.names
        self.nothing = plane_attributes.nothing
        self.pixel_value = plane_attributes.pixel_value


PERSPECTIVE_COLUMNS = BASE + ("alpha", "beta", "gamma", "1/w", "s/w", "s_affine", "s_persp",
                              "alpha_p", "beta_p", "gamma_p")


def _perspective_code(options):
    code = Code()
    if options.get("near", 0) > 0:
        # Runs once, before the triangles: the pieces are what is drawn.
        code.add("clip", "cut each triangle by the near plane w >= near in (x w, y w, w) space: "
                         "an edge crossing it gets the corner H_a + t (H_b - H_a), "
                         "t = (w_a - near) / (w_a - w_b); draw the 3 or 4 corners left as a fan "
                         "of triangles")
    header(code, options)
    code.add("setup", "    setup: a_k, b_k, c_k of the edges;  1 / 2A;  1 / w_k for each vertex",
             ops={"div": 4})
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("cols", "        for x = xmin .. xmax:")
    pixel = _sum(_evaluate(options), TEST_OPS, LOOP_OPS)
    # A covered pixel: weights (3 products by 1/2A), s_affine, f_k = e_k / w_k
    # (3 products by 1/w_k), their sum and one division, the corrected
    # weights (3 products) and s (a blend); z and a colour where given.
    covered = _sum(pixel, {"mul": 15, "float_add": 6, "div": 1},
                   {"mul": 3, "float_add": 2} if options.get("z") else {},
                   {"mul": 9, "float_add": 6, "round": 3} if options.get("colors") else {})
    code.add("test", "            e_k at the centre;  if not (inside(e0), inside(e1), inside(e2)): "
                     "skip", VISIT, ops=pixel)
    code.add("plot", "            alpha, beta, gamma = e_k / 2A;  s_affine = alpha s0 + beta s1 + "
                     "gamma s2;  f_k = e_k / w_k;  alpha_p = f0 / (f0 + f1 + f2), ...;  "
                     "s = alpha_p s0 + beta_p s1 + gamma_p s2 = (s/w) / (1/w);  setPixel(x, y"
             + (", colour by the perspective-correct weights)" if options.get("colors")
                and options.get("perspective", True) else
                ", colour by alpha, beta, gamma)" if options.get("colors") else ")"), PLOT,
             ops=covered)
    footer(code)
    return code


def perspective_code(points, options):
    return tuple(_perspective_code(options).lines)


class PerspectiveColumns(_NoAttributes):
    def __init__(self, options, count):
        self.s = per_vertex(options, "s", count)
        self.w = per_vertex(options, "w", count)
        self.z = per_vertex(options, "z", count)
        colors = per_vertex(options, "colors", count)
        self.colors = [unpack(c) for c in colors] if colors else None
        if self.s is None or self.w is None:
            raise InputError("triangle-perspective needs s and w, one per vertex (or three)")
        if not options.get("near", 0) > 0:
            try:
                check_w(self.w)
            except InputError as error:
                raise InputError(f"{error}; or set near (e.g. near=0.05) to clip triangles "
                                 "that cross w = 0") from None
        self.perspective = options.get("perspective", True)
        names = ["z"] if self.z is not None else []
        if self.colors is not None:
            names.append("rgb")
        self.names = tuple(names)
        self.nothing = (NAN,) * len(names)
        self.pixel_value = "rgb" if self.colors is not None else None


def _perspective_traversal(run, tri, edges, attrs, at):
    cols = run.perspective
    order = tri.order
    s = [cols.s[k] for k in order]
    w = [cols.w[k] for k in order]
    yield Vars(at["setup"], {"1/2A": 1 / (tri.area2 / (tri.S * tri.S)),
                             "1/w0": 1 / w[0], "1/w1": 1 / w[1], "1/w2": 1 / w[2]})
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    empty = (NAN,) * (len(PERSPECTIVE_COLUMNS) - len(BASE)) + cols.nothing
    for j in range(j_lo, j_hi + 1):
        for i in range(i_lo, i_hi + 1):
            es = edges.at(i, j)
            covered, tie = edges.test(es)
            run.count(i, j, covered)
            shown = edges.shown(es)
            if not covered:
                yield (at["test"], i, j, *shown, 1.0 if tie else 0.0, *empty)
                continue
            weights = edges.weights(es)
            corrected = perspective_weights(weights, w)  # InputError rather than inf or NaN
            inverse = affine_value(weights, [1 / v for v in w])
            over_w = affine_value(weights, [sv / wv for sv, wv in zip(s, w)])
            extra = [*weights, inverse, over_w, affine_value(weights, s),
                     affine_value(corrected, s), *corrected]
            if cols.z is not None:
                extra.append(affine_value(weights, [cols.z[k] for k in order]))
            if cols.colors is not None:
                shade = corrected if cols.perspective else weights
                extra.append(mix(shade, [cols.colors[k] for k in order]))
            yield (at["plot"], i, j, *shown, 1.0 if tie else 0.0, *map(float, extra))


def perspective(points, options, grid=None):
    cols = PerspectiveColumns(options, len(points))
    near = options.get("near", 0)
    report = None
    if near > 0:
        points, report = clip_near(points, cols, near)
    run = Run(points, options, grid, PERSPECTIVE_COLUMNS, attributes=cols)
    run.perspective = cols
    code = _perspective_code(options)
    frames = _drive(run, code, _perspective_traversal)
    return frames if report is None else _with_clip_frames(frames, report, code.at["clip"], near)


# ------------------------------------------------------ near-plane clipping
# A vertex (x, y) with clip-space w is the homogeneous point (x w, y w, w):
# its screen position is that point divided by w. A triangle with some w
# below 0 is not the screen triangle of its projected corners: the part
# behind the eye projects through infinity to the far side. Cutting the
# triangle by the plane w = near in homogeneous space first (Sutherland-
# Hodgman against one plane) leaves a polygon whose corners all have
# w >= near, so its projection is the visible part. Attributes that are
# perspective-correct (s, colours) are linear in homogeneous space and are
# cut with the same t; z is a screen-space depth z = Z / w, so Z = z w is.
def clip_near(points, cols, near):
    """The triangles cut by w >= near, fanned into triangles.

    Replaces cols' per-vertex lists (w, s, z, colours) by the pieces' and
    returns (the pieces' points, one (triangle, w's, kept corners, pieces)
    entry per input triangle).
    """
    out_points, report = [], []
    lists = {"w": [], "s": [], "z": [] if cols.z is not None else None,
             "colors": [] if cols.colors is not None else None}
    for n in range(len(points) // 3):
        corners = [_homogeneous(points[k], cols, k) for k in range(3 * n, 3 * n + 3)]
        polygon = _cut(corners, near)
        first = len(out_points) // 3
        for k in range(1, len(polygon) - 1):
            for corner in (polygon[0], polygon[k], polygon[k + 1]):
                _append(corner, out_points, lists)
        report.append((n + 1, [c["w"] for c in corners], polygon,
                       list(range(first + 1, len(out_points) // 3 + 1))))
    cols.w, cols.s, cols.z, cols.colors = lists["w"], lists["s"], lists["z"], lists["colors"]
    return out_points, report


def _homogeneous(point, cols, k):
    w = cols.w[k]
    corner = {"X": point[0] * w, "Y": point[1] * w, "w": w, "s": cols.s[k]}
    if cols.z is not None:
        corner["Z"] = cols.z[k] * w
    if cols.colors is not None:
        corner["rgb"] = tuple(float(c) for c in cols.colors[k])
    return corner


def _cut(corners, near):
    """Sutherland-Hodgman against w >= near: 0, 3 or 4 corners, in order."""
    kept = []
    for a, b in zip(corners, corners[1:] + corners[:1]):
        if a["w"] >= near:
            kept.append(a)
        if (a["w"] >= near) != (b["w"] >= near):
            corner = _between(a, b, (a["w"] - near) / (a["w"] - b["w"]))
            corner["w"] = near  # on the plane by construction, whatever the rounding
            kept.append(corner)
    return kept


def _between(a, b, t):
    corner = {}
    for key, value in a.items():
        if key == "rgb":
            corner[key] = tuple(p + t * (q - p) for p, q in zip(value, b[key]))
        else:
            corner[key] = value + t * (b[key] - value)
    return corner


def _append(corner, out_points, lists):
    w = corner["w"]
    x, y = corner["X"] / w, corner["Y"] / w
    if not max(abs(x), abs(y)) <= MAX_COORDINATE:
        raise InputError(f"option near: a cut corner lands beyond +-{MAX_COORDINATE:g} px; "
                         "use a larger near")
    out_points.append((x, y))
    lists["w"].append(w)
    lists["s"].append(corner["s"])
    if lists["z"] is not None:
        lists["z"].append(corner["Z"] / w)
    if lists["colors"] is not None:
        lists["colors"].append(corner["rgb"])


def _with_clip_frames(frames, report, line, near):
    """The run's frames with what the clipping did, right after Start."""
    yield next(frames)
    rows = []
    for number, ws, polygon, pieces in report:
        shown = ", ".join(f"{w:g}" for w in ws)
        names = " and ".join(str(p) for p in pieces)
        if not pieces:
            text = f"Triangle {number} (w = {shown}) lies wholly behind w = {near:g}: nothing drawn."
        elif min(ws) >= near:
            text = f"Triangle {number} (w = {shown}) lies in front of w = {near:g}: drawn as {names}."
        else:
            text = (f"Triangle {number} (w = {shown}) crosses w = {near:g}: cut to "
                    f"{len(polygon)} corners, drawn as triangle{'s' if len(pieces) > 1 else ''} "
                    f"{names}.")
        yield Note(line, text)
        for corner in polygon:
            w = corner["w"]
            rows.append((number, round(corner["X"] / w, 6), round(corner["Y"] / w, 6),
                         round(w, 6), round(corner["s"], 6)))
    yield Table(line, "near clip", ("triangle", "x", "y", "w", "s"), tuple(rows))
    yield from frames


# ========================================================= registering
# The families before this one register first, whichever module a caller
# imported first: the order of algorithms (as lists and pickers show it)
# then follows FAMILIES.
registry_module.all_specs()

NOTES = (
    "A pixel is covered when its centre (x + 1/2, y + 1/2) is inside; ties on an edge "
    "follow the fill rule.",
    "Top-left rule, y up: a centre on an edge counts when the triangle lies to the right "
    "of that edge (a > 0: a left edge) or, for a horizontal edge, above it (b > 0: a "
    "bottom edge). With counter-clockwise vertices a > 0 means the edge runs downwards.",
    "Vertices snap to the sub-pixel grid first; with precision fixed every decision is "
    "exact integer arithmetic. e values are shown in px^2; the panel's exact value is "
    "recomputed from the snapped vertices.",
    "tie = 1 marks a pixel whose verdict rested on the fill rule: no edge value below "
    "zero and at least one exactly zero.",
    "overlaps: pixels filled more than once. cracks: pixels whose centre lies in the "
    "interior of the union of the drawn triangles but that no triangle filled.",
)


def _spec(name, title, summary, code, generator, notes=(), options=OPTIONS, top_down=False,
          box=None, kernel=True):
    register(AlgorithmSpec(
        name=name, title=title, family="triangles", summary=summary, inputs=TRIANGLES,
        options=options, code=code, generator=generator,
        kernel=make_kernel(name, generator, code, top_down, box) if kernel else None,
        notes=NOTES + tuple(notes), explain=explain, uses_grid=True))


_spec("triangle-scan", "Every pixel (naive)", "test every pixel of the grid against the three "
      "edge functions", scan_code, scan, box="whole",
      notes=("The simplest traversal: correct, but it tests every pixel of the grid for "
             "every triangle.",))
_spec("triangle-bbox", "Bounding box", "test the pixels of the triangle's bounding box",
      bbox_code, bbox, box="box",
      notes=("Only rows and columns whose centres fall between the extreme vertices are "
             "tested; any order would do.",))
_spec("triangle-incremental", "Incremental edge functions", "bounding box, edge values "
      "updated by e += a per pixel and e += b per row", incremental_code, incremental,
      notes=("One full evaluation per triangle; then one addition per edge and pixel. Exact "
             "in fixed precision; in floating point the additions accumulate rounding.",))
_spec("triangle-backtrack", "Backtracking", "from the top vertex down: back up left until "
      "outside, then right until outside", backtrack_code, backtrack, top_down=True,
      notes=("Outside to the left: failing an edge with a > 0; outside to the right: one with "
             "a < 0. Pixels backtracked over are visited again going right.",
             "The walk never leaves the grid: its edges count as outside."))
_spec("triangle-pineda", "Pineda pixel walk", "zig-zag from the top vertex, visiting a "
      "superset of the covered pixels, each once", pineda_code, pineda, kernel=False,
      notes=("Each row first carries on in the last direction, then turns and walks back; "
             "edge values follow each step (e += a, e -= b).",
             "No fast kernel: the pixels equal triangle-bbox's, in the walk's order."))
_spec("triangle-linewise", "Linewise (explicit form)", "per row, the span between the long "
      "edge and a short edge", linewise_code, linewise,
      notes=("The span's ends are rational; in fixed precision they are compared with the "
             "centres exactly, so the fill rule holds at both ends.",
             "The e values shown are computed for display; the algorithm needs only the spans."))
_spec("triangle-halfplane", "Half-plane (implicit form)", "a centre is inside when it lies "
      "on the inner side of all three edges, by the winding order", halfplane_code, halfplane,
      notes=("Clockwise triangles keep their order: the inside is then to the right of every "
             "edge, and the fill rule is mirrored to match.",
             "Floating-point side tests use (V - U) x (P - U), relative to a vertex."))
_spec("triangle-barycentric", "Barycentric (parametric form)", "inside when alpha, beta, gamma "
      "= e_k / 2A are all in range", barycentric_code, barycentric,
      notes=("alpha, beta, gamma are shown rounded; the test uses their exact signs in fixed "
             "precision.",))
_spec("triangle-plane", "Parameter plane (Cramer's rule)", "fit q = c_x x + c_y y + c_k "
      "through the vertex values; walk it with q += c_x", plane_code, plane,
      options=BASE_OPTIONS + (Option("colors", "colors", ("#ff0000", "#00ff00", "#0000ff"),
                                     VERTEX_COLORS.help), Z_OPTION, S_OPTION),
      notes=("The plane's value at each pixel equals the barycentric interpolation "
             "alpha q0 + beta q1 + gamma q2 (tests check it exactly).",))
_spec("triangle-perspective", "Perspective-correct interpolation", "interpolate s/w and 1/w "
      "in screen space and divide per pixel", perspective_code, perspective,
      options=BASE_OPTIONS + (VERTEX_COLORS, Z_OPTION,
                              Option("w", "numbers", (1.0, 3.0, 3.0), W_OPTION.help),
                              Option("s", "numbers", (4.0, 6.0, 6.0), S_OPTION.help),
                              Option("perspective", "bool", True, PERSPECTIVE.help),
                              Option("near", "float", 0.0, "clip each triangle against the "
                                     "plane w = near before the divide, so triangles crossing "
                                     "w = 0 draw only their visible part (0: no clipping; "
                                     "every w must then be > 0)", minimum=0.0, maximum=1e6)),
      notes=("Defaults follow the classic example: s = 4 at w = 1 and s = 6 at w = 3; half way "
             "along P0 -> P1 the affine value is 5, the perspective-correct one 4.5.",))
