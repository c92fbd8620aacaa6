"""What every traversal shares: the pseudo-code around it, the run's state and its frames.

A traversal is one function ``traverse(run, tri, edges, attrs, at)`` that
yields the frames of one triangle, and one function writing its
pseudo-code; ``Traversal`` joins the two with the shared header (snapping,
edges, fill rule) and footer (totals, overlaps, cracks) into what the
registry takes.
"""
from __future__ import annotations

import numpy as np

from algorithms.core.code import Code, nonzero
from algorithms.exact import triangles as exact_triangles
from algorithms.triangles.interpolate import VertexAttributes
from algorithms.core.registry import InputError
from algorithms.core.steps import NO_PIXEL, PER_ROW, Note, Start, Table, Vars

from .edges import NAN, PRECISIONS, Edges, Setup, edge_table, offset_of, prepare, window_of
from .kernels import span_mask

# ------------------------------------------------- operation counts
# The operations each line performs (CodeLine.ops), for the report's
# counts. Edge values are integers in fixed precision and floats otherwise,
# so their additions count as int_add or float_add by the precision. Work
# of a loop header or an update that yields no frame of its own (the
# column loop, e += a after a pixel) is counted with the frame of the
# pixel it belongs to; per-row work without a frame (the row loop, the
# pixel walks' row steps) is not counted. The three sign tests of a
# pixel are counted in full, as hardware does them side by side.
def ops_sum(*parts, times: int = 1) -> dict:
    """Operation counts of the parts added up (each ``times`` over), zero entries dropped."""
    total = {}
    for part in parts:
        for name, count in part.items():
            total[name] = total.get(name, 0) + count * times
    return nonzero(total)


def add_op(options) -> str:
    return "int_add" if options["precision"] == "fixed" else "float_add"


def evaluate_ops(options) -> dict:
    """e_k = a_k x + b_k y + c_k for three edges, at a centre."""
    centre = {} if options["precision"] == "fixed" else {"float_add": 2}
    return ops_sum({"mul": 6, add_op(options): 6}, centre)


def step_ops(options) -> dict:
    """e_k += a_k (or b_k) for three edges."""
    return {add_op(options): 3}


TEST_OPS = {"compare": 3, "pixels_tested": 1}
LOOP_OPS = {"int_add": 1, "compare": 1}


def shade_ops(options, weighted: bool = False) -> dict:
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
    return ops_sum(*parts)


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
             per={PER_ROW: {"mul": 2, add_op(options): 3}})
    code.add("inside", "    " + INSIDE_TEXT[options["fill_rule"]])


def footer(code: Code) -> None:
    code.add("done", "count pixels tested and filled, overlaps (pixels filled more than once) "
                     "and cracks (centres inside the mesh that no triangle fills)")


def plot_text(options, what: str = "setPixel(x, y)") -> str:
    if options.get("colors"):
        return what[:-1] + ", alpha c0 + beta c1 + gamma c2)"
    return what


BASE = ("e0", "e1", "e2", "tie")


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
        self.outside_box = 0  # the backtracking walk's visits outside a triangle's box

    # ------------------------------------------------------------ frames
    def start(self, line: int) -> Start:
        constants = {"S": self.S, "fill_rule": self.rule, "precision": self.precision,
                     "triangles": len(self.setups)}
        if any(self.offset):
            constants["offset"] = self.offset
        return Start(line=line, values=self.columns, constants=constants,
                     pixel_value=self.attributes.pixel_value)

    def setup_frames(self, setup: Setup, at: dict):
        """Vars, notes and the edge table of one triangle, as frames."""
        n = setup.number + 1
        snapped = [(x / self.S, y / self.S) for x, y in setup.snapped]
        values = {"triangle": n}
        if setup.tri is None:
            values.update({f"P{k}": snapped[k] for k in range(3)})
            values["2A"] = 0.0 if setup.status == "degenerate" else _area(setup.snapped, self.S)
            yield Vars(line=at["snap"], values=values)
            if setup.status == "degenerate":
                yield Note(line=at["degenerate"], text=f"Triangle {n} has no area (its vertices "
                                                       "are collinear once snapped): no pixels.")
            else:
                yield Note(line=at["winding"],
                           text=f"Triangle {n} is clockwise, a back face: culled.")
            return
        tri = setup.tri
        values.update({f"P{k}": tri.px(k) for k in range(3)})
        values["2A"] = tri.area2 / (self.S * self.S)
        values["winding"] = {"ccw": "counter-clockwise", "swapped": "clockwise: P1, P2 swapped",
                             "cw": "clockwise"}[setup.status]
        yield Vars(line=at["snap"], values=values)
        if setup.status == "swapped":
            yield Note(line=at["winding"], text=f"Triangle {n} was clockwise: P1 and P2 swapped, "
                                                "so the inside is where all e_k > 0.")
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

    def test(self, i: int, j: int, es, edges: Edges, attrs, plot: int, skip: int):
        """The frame of a pixel tested against the three edges: on ``plot`` when covered."""
        covered, tie = edges.test(es)
        self.count(i, j, covered)
        return self.lean(plot if covered else skip, i, j, es, edges, tie, covered, attrs=attrs)

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
        yield Vars(line=line, values=values)
        if crack_cells:
            # The cracks themselves, so that a view can mark them on the grid.
            yield Table(line=line, name="cracks", columns=("x", "y"), rows=tuple(crack_cells))

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


def drive(run: Run, code: Code, traverse):
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
            frame = Table(line=frame.line, name=frame.name, columns=frame.columns,
                          rows=tuple((x - ox, y - oy) for x, y in frame.rows))
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


class Traversal:
    """One traversal as the registry takes it: its pseudo-code and its generator.

    ``build_code(options)`` returns the traversal's ``Code`` (the header and
    footer included); ``traverse(run, tri, edges, attrs, at)`` yields one
    triangle's frames. ``columns`` name the values of a lean frame before
    the attributes'; ``attributes(options, count)``, when given, makes the
    columns of the attributes the traversal carries itself.
    """

    def __init__(self, build_code, traverse, columns=BASE, keep_winding=False,
                 weights_always=False, attributes=None):
        self.build_code = build_code
        self.traverse = traverse
        self.columns = columns
        self.keep_winding = keep_winding
        self.weights_always = weights_always
        self.attributes = attributes

    def code(self, points, options) -> tuple:
        return tuple(self.build_code(options).lines)

    def generator(self, points, options, grid=None):
        return self.frames(points, options, grid, self.build_code(options))

    def frames(self, points, options, grid, code: Code, attributes=None):
        """The run's frames with this pseudo-code (``attributes``: already made)."""
        if attributes is None and self.attributes is not None:
            attributes = self.attributes(options, len(points))
        run = Run(points, options, grid, self.columns, self.keep_winding, self.weights_always,
                  attributes)
        return drive(run, code, self.traverse)
