"""The shapes an antialiasing run draws, their exact inside tests, and what every method shares.

Triangles, one polygon or thick lines, snapped to 1/256 px and tested on
the 1/512 px sample lattice in integers (see the package's notes); the
exact coverage they aim at; the ink blended over white; the operation
counts of an inside test; the frames naming the shapes; the panel rows
explaining a sample or a pixel.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms.exact import coverage as exact_coverage
from algorithms.triangles.interpolate import unpack
from algorithms.core.registry import InputError, Inputs, Option
from algorithms.core.steps import PLOT, VISIT, Note, Vars
from algorithms.core.trace import checkpoint
from algorithms.triangles import ops_sum

NAN = math.nan
UNIT = 512          # sample lattice: 1/512 px
SNAP = 256          # vertices: 1/256 px
MAX_COORDINATE = 2.0 ** 20
BACKGROUND = (255, 255, 255)
WHITE = 0xFFFFFF
INK = "#000000"

SHAPES = ("triangles", "polygon", "thick-line")
# A shape with more edges than this tests a sample through its row's
# crossing table; at most this many tables are kept (each holds the edges
# across one sample row).
TABLE_EDGES = 32
TABLE_ROWS = 16
RULES = ("evenodd", "nonzero")

POINTS = Inputs(1, integer=False, multiple=True)
SEGMENT = Inputs(2, integer=True, names=("P", "Q"))

SHAPE = Option("shape", "choice", "triangles", "what the points draw: triangles (3k points), "
               "one polygon (all points) or thick lines (2k points, one segment each)",
               choices=SHAPES)
WIDTH = Option("width", "float", 1.0, "width of a thick line, in px", minimum=0.01, maximum=256)
CAPS = Option("caps", "choice", "butt", "ends of a thick line: butt (the rectangle ends at "
              "the endpoints) or square (it goes on for width/2)", choices=exact_coverage.CAPS)
POLYGON_RULE = Option("fill_rule", "choice", "evenodd", "which points a polygon covers: "
                      "evenodd or nonzero winding", choices=RULES)
COLORS = Option("colors", "colors", (), "a colour per shape (repeated when fewer); "
                "black ink when none")

SHAPE_OPTIONS = (SHAPE, WIDTH, CAPS, POLYGON_RULE, COLORS)


# ============================================================ shapes
def _snap(value: float) -> int:
    """A coordinate in 1/512 px units, snapped to the 1/256 px grid (halves to even)."""
    if not abs(value) <= MAX_COORDINATE:
        raise InputError(f"coordinate {value} is beyond +-{MAX_COORDINATE:g} px")
    return 2 * round(value * SNAP)


class Shape:
    """One shape in lattice units: a counter-clockwise triangle, or contours with a rule."""

    def __init__(self, contours, rule: str, color, triangle: bool):
        self.contours = contours            # lists of (X, Y) integer vertices
        self.rule = rule
        self.color = color                  # (r, g, b)
        self.triangle = triangle
        xs = [p[0] for c in contours for p in c]
        ys = [p[1] for c in contours for p in c]
        self.box = (min(xs), min(ys), max(xs), max(ys))
        edges = [(c[k], c[(k + 1) % len(c)]) for c in contours for k in range(len(c))]
        self.edges = [(a[0], a[1], b[0], b[1]) for a, b in edges if a != b]
        self._rows: dict = {}  # crossing tables of sample rows, for many edges
        if triangle:
            # The fill rule's tie: a sample on edge k counts on a left edge
            # (a > 0) or a bottom one (a == 0, b > 0), as for pixel centres.
            self.keep = []
            for k in range(3):
                (xi, yi), (xj, yj) = contours[0][(k + 1) % 3], contours[0][(k + 2) % 3]
                a, b = yi - yj, xj - xi
                self.keep.append(a > 0 or (a == 0 and b > 0))

    def outline_px(self):
        """The contours in px (exact binary fractions), for the exact reference."""
        return [[(x / UNIT, y / UNIT) for x, y in c] for c in self.contours]

    # ------------------------------------------------------------ tests
    def hit(self, sx: int, sy: int) -> bool:
        """Is the sample (in lattice units) inside? Python integers."""
        if self.triangle:
            tri = self.contours[0]
            for k in range(3):
                (xi, yi), (xj, yj) = tri[(k + 1) % 3], tri[(k + 2) % 3]
                e = (xj - xi) * (sy - yi) - (yj - yi) * (sx - xi)
                if e < 0 or (e == 0 and not self.keep[k]):
                    return False
            return True
        if len(self.edges) > TABLE_EDGES:
            winding = self._winding(sx, sy)
        else:
            winding = 0
            for ax, ay, bx, by in self.edges:
                if ay <= sy < by and (bx - ax) * (sy - ay) - (by - ay) * (sx - ax) > 0:
                    winding += 1
                elif by <= sy < ay and (ax - bx) * (sy - by) - (ay - by) * (sx - bx) > 0:
                    winding -= 1
        return winding % 2 == 1 if self.rule == "evenodd" else winding != 0

    def _winding(self, sx: int, sy: int) -> int:
        """The winding number of a sample from its row's crossing table.

        An upward edge across row sy adds 1 where sx < its crossing (the
        cross product test above), that is sx < c with c the crossing's
        ceiling; a downward one takes 1. With the edges' c sorted and the
        signs summed from the right, one binary search answers a sample, so
        a sample costs the same with 10 edges or 100,000 (the table is made
        once per sample row, in numpy).
        """
        row = self._rows.get(sy)
        if row is None:
            row = self._rows[sy] = self._crossing_table(sy)
        ceilings, windings = row
        return int(windings[np.searchsorted(ceilings, sx, side="right")])

    def _crossing_table(self, sy: int):
        checkpoint()  # each table is O(edges): a cancel need not wait for the frame
        if len(self._rows) >= TABLE_ROWS:
            self._rows.clear()
        if not hasattr(self, "_edge_arrays"):
            self._edge_arrays = np.array(self.edges, np.int64).T
        ax, ay, bx, by = self._edge_arrays
        up = (ay <= sy) & (sy < by)
        down = (by <= sy) & (sy < ay)
        # c = a + ceil((b - a)_x (sy - a_y) / (b - a)_y), from the lower end a
        lx = np.where(up, ax, bx)[up | down]
        ly = np.where(up, ay, by)[up | down]
        hx = np.where(up, bx, ax)[up | down]
        hy = np.where(up, by, ay)[up | down]
        ceilings = lx - ((-(hx - lx) * (sy - ly)) // (hy - ly))
        signs = np.where(up[up | down], 1, -1)
        order = np.argsort(ceilings, kind="stable")
        windings = np.zeros(len(order) + 1, np.int64)
        windings[:-1] = np.cumsum(signs[order][::-1])[::-1]
        return ceilings[order], windings

    def hits(self, sx: np.ndarray, sy: np.ndarray) -> np.ndarray:
        """The same test on int64 arrays of samples."""
        if self.triangle:
            tri = self.contours[0]
            inside = np.ones(sx.shape, bool)
            for k in range(3):
                (xi, yi), (xj, yj) = tri[(k + 1) % 3], tri[(k + 2) % 3]
                e = (xj - xi) * (sy - yi) - (yj - yi) * (sx - xi)
                inside &= (e > 0) | ((e == 0) & self.keep[k])
            return inside
        winding = np.zeros(sx.shape, np.int64)
        for ax, ay, bx, by in self.edges:
            if ay < by:
                band = (sy >= ay) & (sy < by)
                winding += band & ((bx - ax) * (sy - ay) - (by - ay) * (sx - ax) > 0)
            elif by < ay:
                band = (sy >= by) & (sy < ay)
                winding -= band & ((ax - bx) * (sy - by) - (ay - by) * (sx - bx) > 0)
        return (winding % 2 == 1) if self.rule == "evenodd" else (winding != 0)


class Shapes:
    """The shapes a run draws, from its points and shape options."""

    def __init__(self, points, options):
        kind = options.get("shape", "triangles")
        colors = [unpack(c) for c in (options.get("colors") or ())] or [unpack(INK)]
        self.kind = kind
        self.items: list[Shape] = []
        self.degenerate = 0
        points = [(float(x), float(y)) for x, y in points]
        if kind == "triangles":
            if len(points) % 3:
                raise InputError(f"shape triangles: expected a multiple of 3 points, got "
                                 f"{len(points)}")
            for k in range(len(points) // 3):
                if not k & 1023:
                    checkpoint()  # 33,333 triangles take seconds to make
                tri = [(_snap(x), _snap(y)) for x, y in points[3 * k:3 * k + 3]]
                area = exact_coverage.twice_signed_area(tri)
                if area == 0:
                    self.degenerate += 1
                    continue
                if area < 0:
                    tri = [tri[0], tri[2], tri[1]]
                self.items.append(Shape([tri], "nonzero", colors[k % len(colors)], True))
        elif kind == "polygon":
            if len(points) < 3:
                raise InputError(f"shape polygon: expected at least 3 points, got {len(points)}")
            contour = []
            for k, (x, y) in enumerate(points):
                if not k & 4095:
                    checkpoint()  # 100,000 vertices take a good part of a second
                contour.append((_snap(x), _snap(y)))
            self.items.append(Shape([contour], options.get("fill_rule", "evenodd"),
                                    colors[0], False))
        elif kind == "thick-line":
            if len(points) % 2:
                raise InputError(f"shape thick-line: expected 2 points per segment, got "
                                 f"{len(points)}")
            for k in range(len(points) // 2):
                if not k & 1023:
                    checkpoint()
                corners = exact_coverage.segment_rectangle(
                    points[2 * k], points[2 * k + 1], options.get("width", 1.0),
                    options.get("caps", "butt"))
                rect = [(_snap(x), _snap(y)) for x, y in corners]
                if exact_coverage.twice_signed_area(rect) == 0:
                    self.degenerate += 1
                    continue
                self.items.append(Shape([rect], "nonzero", colors[k % len(colors)], False))
        else:
            raise InputError(f"option shape: unknown shape {kind!r}")

    def window(self, grid) -> tuple[int, int, int, int]:
        """Pixels (x0, y0, x1, y1; x1, y1 excluded) the shapes' boxes reach, within the grid."""
        width, height = int(grid[0]), int(grid[1])
        if not self.items:
            return (0, 0, 0, 0)
        x0 = min(s.box[0] for s in self.items) // UNIT
        y0 = min(s.box[1] for s in self.items) // UNIT
        x1 = max(s.box[2] for s in self.items) // UNIT + 1
        y1 = max(s.box[3] for s in self.items) // UNIT + 1
        x0, y0 = max(x0, 0), max(y0, 0)
        x1, y1 = min(x1, width), min(y1, height)
        return (x0, y0, max(x0, x1), max(y0, y1))

    def mask(self, window) -> np.ndarray:
        """Pixels of the window that some shape's box reaches."""
        x0, y0, x1, y1 = window
        boxes = [(max(s.box[0] // UNIT, x0) - x0, min(s.box[2] // UNIT + 1, x1) - x0,
                  max(s.box[1] // UNIT, y0) - y0, min(s.box[3] // UNIT + 1, y1) - y0)
                 for s in self.items]
        boxes = [box for box in boxes if box[0] < box[1] and box[2] < box[3]]
        if len(boxes) <= TABLE_EDGES:
            mask = np.zeros((y1 - y0, x1 - x0), bool)
            for a, b, c, d in boxes:
                mask[c:d, a:b] = True
            return mask
        boxes = np.array(boxes, np.int64)
        # Each box adds 1 inside it to a difference table whose running sums
        # over both axes count the boxes over each pixel: one pass over the
        # window however many boxes there are (painting each box in turn took
        # half a minute for 33,333 triangles across a 4096 grid).
        counts = np.zeros((y1 - y0 + 1, x1 - x0 + 1), np.int32)
        a, b, c, d = boxes.T
        for rows, columns, sign in ((c, a, 1), (c, b, -1), (d, a, -1), (d, b, 1)):
            np.add.at(counts, (rows, columns), sign)
        return (counts.cumsum(axis=0).cumsum(axis=1) > 0)[:-1, :-1]

    def owner(self, sx: int, sy: int) -> int:
        """The last shape containing the sample, or -1."""
        for index in range(len(self.items) - 1, -1, -1):
            if self.items[index].hit(sx, sy):
                return index
        return -1

    def owners(self, sx: np.ndarray, sy: np.ndarray) -> np.ndarray:
        result = np.full(sx.shape, -1, np.int64)
        for index, shape in enumerate(self.items):
            result[shape.hits(sx, sy)] = index
        return result

    def outlines_px(self):
        return [shape.outline_px() for shape in self.items]


def reference_coverage(points, options, grid, exact: bool = False) -> np.ndarray:
    """Exact coverage of the snapped shapes a run draws: what the estimates aim at."""
    options = {**{o.name: o.default for o in SHAPE_OPTIONS}, **options}
    shapes = Shapes(points, options)
    if not shapes.items:
        window = exact_coverage.window_of(grid)
        return np.zeros((window[3] - window[1], window[2] - window[0]))
    contours = [c for outline in shapes.outlines_px() for c in outline]
    if shapes.kind == "polygon":
        return exact_coverage.polygon_coverage(contours, grid, shapes.items[0].rule, exact)
    if len(contours) == 1:
        return exact_coverage.polygon_coverage(contours, grid, "signed", exact)
    return exact_coverage.polygon_coverage(contours, grid, "nonzero", exact)


def blend(weighted_channels, total: int) -> int:
    """Packed colour from per-channel sums of weight * channel, rounded half up."""
    r, g, b = ((2 * c + total) // (2 * total) for c in weighted_channels)
    return (int(r) << 16) | (int(g) << 8) | int(b)


def ink_blend(ink, coverage: float) -> int:
    """Ink over the white background by the coverage."""
    channels = [min(255, max(0, math.floor(255 + (c - 255) * coverage + 0.5))) for c in ink]
    return (channels[0] << 16) | (channels[1] << 8) | channels[2]


# ------------------------------------------------- operation counts
# CodeLine.ops of the antialiasing family. Inside tests are exact integer
# arithmetic on the 1/512 px lattice, so their additions are int_add.
# Conventions:
# * One shape's inside test, in full as the vectorised kernel (Shape.hits)
#   does it: a triangle evaluates three edges e = (xj - xi)(sy - yi) -
#   (yj - yi)(sx - xi) (2 mul, 3 int_add each; the vertex differences are
#   setup) with the sign and the tie test (2 compares each); a polygon or a
#   thick line's rectangle takes, per edge, the band test (2 compares), the
#   cross product and its sign (2 mul, 5 int_add, 1 compare) and the
#   winding step (1 int_add), then the fill rule's test (1 compare).
# * A sample that misses tests every shape. The generators look for the
#   last shape containing a sample, from the last one back, and stop
#   there: a hit counts that one shape's test only (exact with one shape, a
#   lower bound with more).
# * A sample's position x * 512 + offset, per axis: 1 mul, 1 int_add.
# * Setup lines (snapping, weights tables) and loops that yield no frame
#   of their own are not counted; a pixel loop's step and test (1 int_add,
#   1 compare) and its bounding-box mask test (1 compare) go with the
#   pixel's frame. The display colour (the ink blended over white for the
#   colour buffer) is not counted where the pseudo-code writes a coverage.
LOOP = {"int_add": 1, "compare": 1}
POSITION = {"mul": 2, "int_add": 2}


def _shape_test_ops(shape: Shape) -> dict:
    if shape.triangle:
        return {"mul": 6, "int_add": 9, "compare": 6}
    edges = len(shape.edges)
    return {"mul": 2 * edges, "int_add": 6 * edges, "compare": 3 * edges + 1}


def test_ops(shapes: Shapes | None) -> tuple[dict, dict]:
    """(one hit's test, one miss's test): the last shape's, and every shape's."""
    if shapes is None or not shapes.items:
        return {}, {}
    every = ops_sum(*(_shape_test_ops(s) for s in shapes.items))
    return _shape_test_ops(shapes.items[-1]), every


def code_shapes(points, options) -> Shapes | None:
    try:
        return Shapes(points, options)
    except (InputError, ValueError, TypeError):
        return None


def sample_ops(hit: bool, test: dict, extra: dict | None = None) -> dict:
    """One sample frame: the position, the test, the hit/miss compare, the loop."""
    return ops_sum({"samples": 1, "compare": 1}, POSITION, test, LOOP, extra or {})


def shape_vars(shapes: Shapes, line: int):
    """The snapped outline of every shape, and a note on those with no area."""
    values = {}
    prefix = {"triangles": "T", "polygon": "polygon", "thick-line": "line"}[shapes.kind]
    for number, outline in enumerate(shapes.outlines_px()):
        name = prefix if shapes.kind == "polygon" else f"{prefix}{number + 1}"
        values[name] = tuple(outline[0])
    yield Vars(line=line, values=values)
    if shapes.degenerate:
        yield Note(line=line, text=f"{shapes.degenerate} shape(s) have no area once snapped "
                                   "and cover nothing.")


def _outline_vars(variables) -> list:
    outlines = []
    for name, value in variables.items():
        if (name.startswith("T") or name.startswith("line") or name == "polygon") \
                and isinstance(value, tuple) and value and isinstance(value[0], tuple):
            outlines.append(list(value))
    return outlines


def _exact_pixel(variables, x: int, y: int):
    """Exact coverage of pixel (x, y) by the shapes named in the run's variables."""
    outlines = _outline_vars(variables)
    if not outlines:
        return None
    window = (x, y, x + 1, y + 1)
    shape = variables.get("shape")
    if shape == "polygon":
        rule = variables.get("fill_rule", "evenodd")
        return float(exact_coverage.polygon_coverage(outlines, window, rule)[0, 0])
    rule = "signed" if len(outlines) == 1 else "nonzero"
    return float(exact_coverage.polygon_coverage(outlines, window, rule)[0, 0])


def explain_samples(trace, i):
    """Where the sample lies in its pixel; for a pixel, the exact coverage and the error."""
    step = trace.step(i)
    if step.pixel is None:
        return []
    x, y = step.pixel
    rows = []
    if "sx" in step.values:
        u, v = step.values["sx"] - x, step.values["sy"] - y
        rows.append(("in the pixel", f"u = {Fraction(u).limit_denominator(UNIT)}, "
                                     f"v = {Fraction(v).limit_denominator(UNIT)}"))
        if "weight" in step.values:
            rows.append(("w_s / W", f"{step.values['weight']:.6g}"))
        return rows
    if "coverage" in step.values and step.kind in (PLOT, VISIT):
        exact = _exact_pixel(trace.variables_at(i), x, y)
        if exact is not None:
            estimate = step.values["coverage"]
            rows.append(("exact coverage", f"{exact:.6f}"))
            rows.append(("error", f"{estimate - exact:+.6f}"))
    if "rgb" in step.values:
        rows.append(("colour", f"#{int(step.values['rgb']):06x}"))
    return rows
