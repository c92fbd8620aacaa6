"""Snapping, the integer edge functions and the fill rule: what every traversal decides with.

See the package's notes for the arithmetic: vertices snap to 1/S px, edge k
is E_k(i, j) = A_k i + B_k j + C_k in units where every pixel centre's
value is an integer, and the fill rule settles a centre exactly on an edge.
"""
from __future__ import annotations

import math
from decimal import Decimal, localcontext

import numpy as np

from algorithms.triangles.interpolate import ATTRIBUTE_OPTIONS, barycentric_weights
from algorithms.core.registry import InputError, Inputs, Option
from algorithms.core.steps import PLOT, VISIT, Table

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


def dyadic_text(numerator: int, denominator: int) -> str:
    """numerator / denominator exactly in decimal (the denominator a power of two)."""
    with localcontext() as context:
        context.prec = max(40, len(str(abs(numerator))) + 2 * denominator.bit_length())
        value = Decimal(numerator) / Decimal(denominator)
    text = format(value.normalize(), "f")
    return text


def edge_table(tri: Triangle, line: int) -> Table:
    """The edges' a, b, c and sides, as the table shown with each triangle's setup."""
    rows = []
    unit = 2 * tri.S * tri.S
    for k in range(3):
        c_px = tri.C[k] - (tri.A[k] + tri.B[k]) // 2  # c at the pixel origin, not the centre
        rows.append((f"e{k}", f"P{(k + 1) % 3} -> P{(k + 2) % 3}", dyadic_text(tri.A[k], unit),
                     dyadic_text(tri.B[k], unit), dyadic_text(c_px, unit),
                     f"{tri.side(k)} ({'kept' if tri.include[k] else 'left out'} on a tie)"))
    return Table(line=line, name="edges", columns=("edge", "from -> to", "a", "b", "c", "side"),
                 rows=tuple(rows))


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


class ExactView(Edges):
    """Exact edge values of a triangle for display, whatever the run's precision."""

    def __init__(self, tri):  # a light view, not a full setup
        self.tri, self.sign, self.include = tri, tri.sign, tri.include
        self.kind, self.unit, self.area2 = int, 2 * tri.S * tri.S, 2 * tri.area2
        self.a, self.b, self.c = tri.A, tri.B, tri.C
