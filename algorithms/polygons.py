"""The polygon family: scan-line fill with edge tables, convex fill, tessellation.

Points are real pixel coordinates, snapped to a sub-pixel grid of 1/256 px
(8 fractional bits) and evaluated exactly from there on: a snapped
coordinate is the integer ``X = round(x * 256)``, and pixel (i, j) has its
sample point, its centre, at ``(256 i + 128, 256 j + 128)`` in those units.

Fill rule: a pixel is covered when its centre is strictly inside, or lies
exactly on a left edge or on a bottom horizontal edge. Scan line j (the row
of centres at y = j + 1/2) meets the edges with ``ymin <= j + 1/2 < ymax``,
and a run between crossings x_left and x_right covers the centres with
``x_left <= i + 1/2 < x_right``. Equivalently: a centre is covered when the
point a hair to its right and a far smaller hair above it is inside; that
point lies on no edge, so polygons that share an edge share no pixel and
leave no gap between them.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from .registry import AlgorithmSpec, InputError, Inputs, Option, register
from .steps import (NO_PIXEL, PER_PIXEL, PER_ROW, PLOT, VISIT, CodeLine, Note, Span, Start,
                    Table, Vars)

NAN = math.nan
SUBPIXEL_BITS = 8
ONE = 1 << SUBPIXEL_BITS  # one pixel in snapped units
HALF_PIXEL = ONE // 2
HALF = Fraction(1, 2)
# Keeps every product of the fast kernel inside int64 (see _crossing_columns).
MAX_COORDINATE = 1 << 20

POLYGON = Inputs(3, integer=False, contours=True)
FILL_RULE = Option("fill_rule", "choice", "evenodd",
                   "evenodd: inside after an odd number of crossings; nonzero: inside "
                   "where the winding number is not 0", choices=("evenodd", "nonzero"))
ARITHMETIC = Option("arithmetic", "choice", "exact",
                    "how x is kept and stepped along each edge: exact fractions, or "
                    "float64 / float32 to watch rounding move a span end",
                    choices=("exact", "float64", "float32"))
FLOATS = {"float64": np.float64, "float32": np.float32}


# ------------------------------------------------------------- shared parts
def snap(value: float) -> int:
    """A coordinate in 1/256 px, rounded to nearest (halves to even)."""
    return round(value * ONE)


def snap_contours(points) -> list[list[tuple[int, int]]]:
    """Every contour with its vertices on the 1/256 grid."""
    contours = []
    for contour in points:
        for x, y in contour:
            if abs(x) > MAX_COORDINATE or abs(y) > MAX_COORDINATE:
                raise InputError(f"polygon coordinates must lie within +-{MAX_COORDINATE} px, "
                                 f"got ({x:g}, {y:g})")
        contours.append([(snap(x), snap(y)) for x, y in contour])
    return contours


def first_index(v: int) -> int:
    """The first pixel index (row or column) whose centre is at or beyond v (snapped units)."""
    return -((HALF_PIXEL - v) // ONE)


def first_column(x) -> int:
    """The leftmost pixel whose centre is at or right of x (in pixels)."""
    if isinstance(x, (int, Fraction)):
        return math.ceil(x - HALF)
    # Float arithmetic: the same test done in float64, as the fast kernel does.
    return math.ceil(float(x) - 0.5)


def pixel_of(vertex) -> tuple[int, int]:
    """The pixel whose square holds a snapped vertex."""
    return vertex[0] // ONE, vertex[1] // ONE


def as_pixels(value: int) -> Fraction:
    return Fraction(value, ONE)


def _edge_label(contours, contour: int, index: int) -> str:
    after = (index + 1) % len(contours[contour])
    if len(contours) > 1:
        return f"C{contour + 1}.P{index + 1}P{after + 1}"
    return f"P{index + 1}P{after + 1}"


def _number(value):
    """A table cell: exact fractions stay exact, floats become plain floats."""
    if isinstance(value, (int, Fraction)):
        return value.numerator if isinstance(value, Fraction) and value.denominator == 1 else value
    return float(value)


def cross(o, a, b) -> int:
    """(a - o) x (b - o): positive when o -> a -> b turns left."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def signed_area2(contour) -> int:
    """Twice the signed area (snapped units): positive counter-clockwise."""
    return sum(contour[k - 1][0] * contour[k][1] - contour[k][0] * contour[k - 1][1]
               for k in range(len(contour)))


def _without_repeats(contour):
    """The vertices with repeated neighbours (and a repeated first/last) merged."""
    kept = []
    for vertex in contour:
        if not kept or kept[-1] != vertex:
            kept.append(vertex)
    while len(kept) > 1 and kept[0] == kept[-1]:
        kept.pop()
    return kept


# ------------------------------------------------------- scan line: edges
class ScanEdge:
    """One edge as the ET and the AET hold it."""

    __slots__ = ("label", "first", "ymax", "x", "inv_m", "direction")

    def __init__(self, label, first, ymax, x, inv_m, direction):
        self.label = label
        self.first = first        # first row whose centre the edge meets
        self.ymax = ymax          # first row above the edge: it leaves the AET there
        self.x = x                # x where the edge meets the current row's centre line
        self.inv_m = inv_m        # 1/m: change of x from one row to the next
        self.direction = direction  # +1 upward, -1 downward (for the winding number)

    def row(self, rule: str) -> tuple:
        cells = (self.label, self.ymax, _number(self.x), _number(self.inv_m))
        return cells + ((self.direction,) if rule == "nonzero" else ())


def scan_edges(contours, arithmetic: str = "exact") -> tuple[list[ScanEdge], int]:
    """The ET's entries (in polygon order) and how many edges were left out.

    Horizontal edges, and edges too short to reach any row's centre line,
    meet no scan line and are left out.
    """
    edges, skipped = [], 0
    real = FLOATS.get(arithmetic)
    for c, contour in enumerate(contours):
        for k, start in enumerate(contour):
            end = contour[(k + 1) % len(contour)]
            direction = 1 if end[1] > start[1] else -1
            low, high = (start, end) if direction > 0 else (end, start)
            first, ymax = first_index(low[1]), first_index(high[1])
            if first >= ymax:  # horizontal, or between two centre lines
                skipped += 1
                continue
            dx, dy = high[0] - low[0], high[1] - low[1]
            rise = ONE * first + HALF_PIXEL - low[1]  # from the low end to the first centre line
            if real is None:
                inv_m = Fraction(dx, dy)
                x = as_pixels(low[0]) + as_pixels(rise) * inv_m
            else:
                inv_m = real(dx) / real(dy)
                x = real(low[0] / ONE) + real(rise / ONE) * inv_m
            edges.append(ScanEdge(_edge_label(contours, c, k), first, ymax, x, inv_m, direction))
    return edges, skipped


def runs(active: list[ScanEdge], rule: str) -> list[tuple]:
    """(x_left, x_right) of every run the fill rule fills, from the sorted AET."""
    if rule == "evenodd":
        return [(active[k].x, active[k + 1].x) for k in range(0, len(active) - 1, 2)]
    found, winding, left = [], 0, None
    for edge in active:
        before, winding = winding, winding + edge.direction
        if before == 0:
            left = edge.x
        elif winding == 0:
            found.append((left, edge.x))
    return found


# ------------------------------------------------------- polygon-scanline
def scanline_code(points, options):
    rule, arithmetic = options["fill_rule"], options["arithmetic"]
    entry = "(ymax, x, 1/m, dir)" if rule == "nonzero" else "(ymax, x, 1/m)"
    if rule == "nonzero":
        fill = ("    walk the AET adding each dir to w; between an x where w leaves 0 and the "
                "x where it returns to 0: fill pixels i with x_left <= i + 1/2 < x_right")
    else:
        fill = ("    for each pair (x_left, x_right) of the AET in turn: "
                "fill pixels i with x_left <= i + 1/2 < x_right")
    number = "an exact fraction" if arithmetic == "exact" else f"a {arithmetic}"
    # Operation counts. An exact x is kept as a whole part and a remainder
    # over dy, as the integer edge walk does: x += 1/m is two integer
    # additions and a carry test. Per edge (the Start constant "edges"),
    # the ET line counts its setup and the one test that removes it from
    # the AET later; line 5 counts the test of each edge that stays (the
    # frame's "active"). The AET is nearly sorted from row to row, so the
    # sort is an insertion pass: one comparison per row of its table. A
    # span costs two roundings; each of its pixels a step and a test.
    step = ({"int_add": 2, "compare": 2} if arithmetic == "exact"
            else {"float_add": 1, "compare": 1})
    setup = {"int_add": 4, "div": 1, "mul": 1, "round": 2, "compare": 2}
    if arithmetic != "exact":
        setup["float_add"] = 1
    return (
        CodeLine("snap every vertex to the 1/256 px grid",
                 per={"vertices": {"mul": 2, "round": 2}}),
        CodeLine(f"ET: bucket each edge under the first row y whose centre line y + 1/2 it "
                 f"meets, as {entry}; skip horizontal edges", per={"edges": setup}),
        CodeLine("AET = empty;  y = the lowest bucket of the ET"),
        CodeLine("while the ET or the AET is not empty:"),
        CodeLine("    if the AET is empty: y = the lowest remaining bucket;  "
                 "move the edges of bucket ET[y] into the AET", ops={"compare": 3}),
        CodeLine("    remove from the AET the edges with ymax == y", per={"active": {"compare": 1}}),
        CodeLine("    sort the AET on x", per={PER_ROW: {"compare": 1}}),
        CodeLine(fill, PLOT, ops={"round": 2, "compare": 1},
                 per={PER_PIXEL: {"int_add": 1, "compare": 1}}),
        CodeLine("    y += 1", ops={"int_add": 1}),
        CodeLine(f"    for each edge in the AET: x += 1/m   (x is {number})", per={"active": step}),
        CodeLine("done"),
    )


def scanline(points, options):
    rule, arithmetic = options["fill_rule"], options["arithmetic"]
    contours = snap_contours(points)
    edges, skipped = scan_edges(contours, arithmetic)
    yield Start(0, ("y", "active"),
                {"contours": len(contours), "vertices": sum(map(len, contours)),
                 "edges": len(edges), "fill_rule": rule, "arithmetic": arithmetic,
                 "subpixel": ONE})
    if skipped:
        yield Note(1, f"{skipped} edge(s) left out: horizontal, or between two centre lines, "
                      "so no scan line meets them")
    table = {}
    for edge in sorted(edges, key=lambda e: (e.first, e.x, e.inv_m)):
        table.setdefault(edge.first, []).append(edge)
    columns = ("ymin", "edge", "ymax", "x", "1/m") + (("dir",) if rule == "nonzero" else ())
    yield Table(1, "ET", columns,
                tuple((y,) + edge.row(rule) for y in sorted(table) for edge in table[y]))
    aet_columns = columns[1:]
    y = min(table, default=0)
    active: list[ScanEdge] = []
    yield (2, NO_PIXEL, NO_PIXEL, y, 0)
    spans = pixels = 0
    while table or active:
        if not active:
            y = min(table)
        active.extend(table.pop(y, ()))
        yield (4, NO_PIXEL, NO_PIXEL, y, len(active))
        active = [edge for edge in active if edge.ymax != y]
        yield (5, NO_PIXEL, NO_PIXEL, y, len(active))
        # Ties on x are broken by 1/m, so the table reads in the order the
        # edges will be met on the rows just above.
        active.sort(key=lambda e: (e.x, e.inv_m))
        yield Table(6, "AET", aet_columns, tuple(edge.row(rule) for edge in active))
        for left, right in runs(active, rule):
            start, end = first_column(left), first_column(right)
            spans += 1
            pixels += max(0, end - start)
            yield Span(7, y, start, max(start, end))
        y += 1
        yield (8, NO_PIXEL, NO_PIXEL, y, len(active))
        for edge in active:
            edge.x = edge.x + edge.inv_m
        yield (9, NO_PIXEL, NO_PIXEL, y, len(active))
    yield Vars(10, {"spans": spans, "pixels": pixels})


def scanline_explain(trace, i):
    """For a span: the pair of crossings it lies between and its pixels."""
    record = trace.step(i).record
    if not isinstance(record, Span):
        if isinstance(record, Table) and record.name == "AET":
            return [("scan line", f"centre line y + 1/2 = {trace.step(i - 1).values.get('y', 0) + 0.5:g}")]
        return []
    tables = [(k, table) for k, table in trace.records_of(Table, hi=i) if table.name == "AET"]
    if not tables:
        return []
    k, table = tables[-1]
    ordinal = len(trace.steps_of(Span, lo=k + 1, hi=i))
    rule = trace.start.constants["fill_rule"]
    active = [ScanEdge(row[0], 0, row[1], row[2], row[3], row[4] if rule == "nonzero" else 1)
              for row in table.rows]
    found = runs(active, rule)
    if ordinal >= len(found):
        return []
    left, right = found[ordinal]
    covered = (f"i = {record.x_start} .. {record.x_end - 1}" if record.x_end > record.x_start
               else "none: no centre lies between them")
    return [("run", f"x_left = {_show(left)}, x_right = {_show(right)}"),
            ("pixels", f"x_left <= i + 1/2 < x_right: {covered}")]


def _show(value) -> str:
    if isinstance(value, Fraction) and value.denominator != 1:
        return f"{value} ({float(value):.6g})"
    return f"{float(value):.9g}" if isinstance(value, float) else str(value)


# ----------------------------------------------- polygon-scanline: kernel
def _edge_arrays(contours):
    """Per edge that meets a scan line: low end, deltas, rows and direction."""
    starts, ends = [], []
    for contour in contours:
        vertices = np.asarray(contour, dtype=np.int64).reshape(-1, 2)
        starts.append(vertices)
        ends.append(np.roll(vertices, -1, axis=0))
    start = np.concatenate(starts) if starts else np.zeros((0, 2), np.int64)
    end = np.concatenate(ends) if ends else np.zeros((0, 2), np.int64)
    up = end[:, 1] > start[:, 1]
    low = np.where(up[:, None], start, end)
    high = np.where(up[:, None], end, start)
    first = -((HALF_PIXEL - low[:, 1]) // ONE)
    stop = -((HALF_PIXEL - high[:, 1]) // ONE)
    keep = stop > first
    return (low[keep], high[keep] - low[keep], first[keep], (stop - first)[keep],
            np.where(up, 1, -1)[keep])


def _crossing_columns(contours, arithmetic: str):
    """Row, first covered column and direction of every edge/scan-line crossing."""
    low, delta, first, count, direction = _edge_arrays(contours)
    total = int(count.sum())
    edge = np.repeat(np.arange(len(count)), count)
    step = np.arange(total, dtype=np.int64) - np.repeat(np.cumsum(count) - count, count)
    rows = first[edge] + step
    dx, dy = delta[:, 0], delta[:, 1]
    rise = ONE * first + HALF_PIXEL - low[:, 1]
    if arithmetic == "exact":
        # The first covered column is ceil((x - 1/2 px) / 1 px) with
        # x = low.x + rise * dx / dy; times 256 * dy it is an integer quotient.
        # |coordinates| <= 2^28 keeps every term below 2^60.
        numerator = rise * dx + (low[:, 0] - HALF_PIXEL) * dy
        numerator = numerator[edge] + step * (ONE * dx)[edge]
        columns = -((-numerator) // (ONE * dy)[edge])
        return rows, columns, direction[edge]
    real = FLOATS[arithmetic]
    inv_m = dx.astype(real) / dy.astype(real)
    x_first = (low[:, 0] / ONE).astype(real) + (rise / ONE).astype(real) * inv_m
    xs = np.empty(total, dtype=real)
    offsets = np.cumsum(count) - count
    for e in range(len(count)):
        # Added one row at a time, left to right, exactly as the generator does.
        terms = np.full(count[e], inv_m[e], dtype=real)
        terms[0] = x_first[e]
        xs[offsets[e]:offsets[e] + count[e]] = np.add.accumulate(terms, dtype=real)
    columns = np.ceil(xs.astype(np.float64) - 0.5).astype(np.int64)
    return rows, columns, direction[edge]


def _options(options):
    options = dict(options or {})
    rule = options.get("fill_rule", "evenodd")
    arithmetic = options.get("arithmetic", "exact")
    return rule, arithmetic


def scanline_mask(points, options=None, grid=None, origin=(0, 0)) -> np.ndarray:
    """The covered pixels as a boolean (H, W) array, row 0 at y = origin[1].

    ``grid`` is (W, H); pixels outside it are clipped. Exact, and equal to
    the generator's pixels. Each crossing switches the fill state from its
    first covered column on, so the whole grid is one run-length decode:
    sort the crossings by (row, column), carry the parity (or the winding
    number) along, and repeat each state over the run it holds for.
    """
    rule, arithmetic = _options(options)
    width, height = grid
    rows, columns, direction = _crossing_columns(snap_contours(points), arithmetic)
    rows = rows - origin[1]
    inside = (rows >= 0) & (rows < height)
    # A crossing left of the grid switches the whole row, one right of it
    # none; every row has as many crossings up as down, so whole rows may go.
    keys = rows[inside] * width + np.clip(columns[inside] - origin[0], 0, width)
    if rule == "evenodd":
        keys.sort()
        state = np.zeros(len(keys) + 1, dtype=bool)
        state[1::2] = True
    else:
        order = np.sort(2 * keys + (direction[inside] > 0))
        keys = order >> 1
        winding = np.cumsum(2 * (order & 1) - 1)
        state = np.concatenate(([False], winding != 0))
    lengths = np.diff(keys, prepend=0, append=width * height)
    return np.repeat(state, lengths).reshape(height, width)


def pixel_box(points) -> tuple[int, int, int, int]:
    """(x0, y0, W, H): the smallest block of pixels the polygon can cover."""
    snapped = [v for contour in snap_contours(points) for v in contour]
    xs = [x for x, _ in snapped]
    ys = [y for _, y in snapped]
    x0, y0 = first_index(min(xs)), first_index(min(ys))
    return x0, y0, first_index(max(xs)) - x0, first_index(max(ys)) - y0


def scanline_pixels(points, options=None) -> np.ndarray:
    """Fast kernel: (n, 2) pixels in the generator's order (rows up, x right)."""
    x0, y0, width, height = pixel_box(points)
    if width <= 0 or height <= 0:
        return np.zeros((0, 2), dtype=np.int64)
    flat = np.flatnonzero(scanline_mask(points, options, (width, height), (x0, y0)))
    pixels = np.empty((len(flat), 2), dtype=np.int64)
    np.divmod(flat, width, out=(pixels[:, 1], pixels[:, 0]))
    pixels += (x0, y0)
    return pixels


SCANLINE = register(AlgorithmSpec(
    name="polygon-scanline",
    title="Scan line (ET/AET)",
    family="polygons",
    summary="edge table and active edge table: fill the runs between crossings row by row",
    inputs=POLYGON,
    options=(FILL_RULE, ARITHMETIC),
    code=scanline_code,
    generator=scanline,
    kernel=scanline_pixels,
    explain=scanline_explain,
    notes=("Vertices are snapped to 1/256 px. Row y is the scan line through the pixel "
           "centres at y + 1/2; an edge is in the AET for the rows ymin <= y < ymax, "
           "ymax being the first row above it, so a vertex on a scan line counts once.",
           "x is where an edge meets the row's centre line, in pixels; 1/m is how far "
           "it moves from one row to the next.",
           "A centre exactly on a left edge is filled, one on a right edge is not; the "
           "same for bottom and top horizontal edges. Polygons sharing an edge never "
           "share a pixel.",
           "Any number of contours: holes are contours inside others; self-intersecting "
           "polygons are filled by the fill rule."),
))


# ---------------------------------------------------------- convex polygon
def convexity_problem(contour) -> str:
    """Why a contour (snapped, without repeats) is not convex, or ''."""
    n = len(contour)
    if n < 3:
        return ""
    edges = [(contour[(k + 1) % n][0] - contour[k][0], contour[(k + 1) % n][1] - contour[k][1])
             for k in range(n)]
    if all(cross(contour[k - 2], contour[k - 1], contour[k]) == 0 for k in range(n)):
        return ""  # flat: a degenerate convex polygon, with no area to fill
    turns = set()
    for k in range(n):
        (ax, ay), (bx, by) = edges[k - 1], edges[k]
        turn = ax * by - ay * bx
        if turn == 0 and ax * bx + ay * by < 0:
            return f"it turns back on itself at P{k + 1}"
        if turn:
            turns.add(turn > 0)
    if len(turns) > 1:
        return "it turns left at some vertices and right at others"
    for axis, name in ((0, "x"), (1, "y")):
        signs = [d[axis] > 0 for d in edges if d[axis]]
        changes = sum(signs[k] != signs[k - 1] for k in range(len(signs)))
        if changes > 2:
            return f"it winds around more than once ({name} changes direction {changes} times)"
    return ""


def _single_contour(points, name: str, alternative: str):
    if len(points) != 1:
        raise InputError(f"{name} fills one contour, got {len(points)}; {alternative}")


def _chains(contour):
    """Left and right chains from the lowest vertex up to the highest, as edge lists."""
    n = len(contour)
    bottom = min(range(n), key=lambda k: (contour[k][1], contour[k][0]))
    top = max(range(n), key=lambda k: (contour[k][1], -contour[k][0]))
    forward, backward = [], []
    k = bottom
    while k != top:
        forward.append((k, (k + 1) % n))
        k = (k + 1) % n
    k = bottom
    while k != top:
        backward.append((k, (k - 1) % n))
        k = (k - 1) % n
    # Going forward from the bottom of a counter-clockwise polygon runs up its right side.
    if signed_area2(contour) >= 0:
        return bottom, top, backward, forward
    return bottom, top, forward, backward


class ChainWalker:
    """Walks one chain upward, giving x where it meets each row's centre line."""

    def __init__(self, contour, edges):
        self.contour, self.edges, self.k = contour, edges, -1
        self.x = self.inv_m = None

    def at(self, row: int) -> bool:
        """Move to the edge that meets the row's centre line; True if it moved."""
        centre = ONE * row + HALF_PIXEL
        moved = False
        while self.k < 0 or self.contour[self.edges[self.k][1]][1] <= centre:
            self.k += 1
            moved = True
        if moved:
            (x0, y0), (x1, y1) = (self.contour[v] for v in self.edges[self.k])
            self.inv_m = Fraction(x1 - x0, y1 - y0)
            self.x = as_pixels(x0) + as_pixels(centre - y0) * self.inv_m
        return moved

    def step(self) -> None:
        self.x += self.inv_m


def convex_code(points, options):
    # Operation counts: per vertex, snapping and the turn test (a cross
    # product); per chain edge (a row of the chains table) the search for
    # B and T; x is exact, a whole part and a remainder (two additions and
    # a carry test per step), as in polygon-scanline.
    return (
        CodeLine("snap the vertices; check convexity: all turns one way, and x and y "
                 "each change direction at most twice",
                 per={"vertices": {"mul": 4, "round": 2, "int_add": 5, "compare": 4}}),
        CodeLine("B = lowest vertex, T = highest; the left and right chains of edges run "
                 "from B up to T", per={PER_ROW: {"compare": 2}}),
        CodeLine("for each row y whose centre line B.y <= y + 1/2 < T.y:",
                 ops={"int_add": 2, "div": 2}),
        CodeLine("    on each chain, while the edge's top is at or below y + 1/2: take the "
                 "next edge, x = its x at y + 1/2",
                 ops={"compare": 2, "int_add": 4, "mul": 1, "div": 1}),
        CodeLine("    fill pixels i with x_left <= i + 1/2 < x_right", PLOT,
                 ops={"round": 2, "compare": 3}, per={PER_PIXEL: {"int_add": 1, "compare": 1}}),
        CodeLine("    x_left += 1/m_left;  x_right += 1/m_right",
                 ops={"int_add": 5, "compare": 3}),
        CodeLine("done"),
    )


def _convex_contour(points):
    _single_contour(points, "polygon-convex", "use polygon-scanline for several contours or holes")
    contour = _without_repeats(snap_contours(points)[0])
    problem = convexity_problem(contour)
    if problem:
        raise InputError(f"polygon-convex needs a convex polygon, but {problem}; "
                         "use polygon-scanline or polygon-tessellate")
    return contour


def convex(points, options):
    contour = _convex_contour(points)
    yield Start(0, ("y", "x_left", "x_right"),
                {"vertices": len(contour), "subpixel": ONE})
    if len(contour) < 3 or signed_area2(contour) == 0 and all(
            cross(contour[k - 2], contour[k - 1], contour[k]) == 0 for k in range(len(contour))):
        yield Note(0, "all the vertices lie on one line: the polygon has no area")
        yield (6, NO_PIXEL, NO_PIXEL, NAN, NAN, NAN)
        return
    bottom, top, left_edges, right_edges = _chains(contour)
    rows = []
    for side, chain in (("left", left_edges), ("right", right_edges)):
        for a, b in chain:
            (x0, y0), (x1, y1) = contour[a], contour[b]
            slope = Fraction(x1 - x0, y1 - y0) if y1 != y0 else "horizontal"
            rows.append((side, f"P{a + 1}P{b + 1}", as_pixels(y0), as_pixels(y1), slope))
    yield Vars(1, {"B": f"P{bottom + 1}", "T": f"P{top + 1}"})
    yield Table(1, "chains", ("side", "edge", "from y", "to y", "1/m"),
                tuple(tuple(_number(c) if not isinstance(c, str) else c for c in row)
                      for row in rows))
    left, right = ChainWalker(contour, left_edges), ChainWalker(contour, right_edges)
    y, top_row = first_index(contour[bottom][1]), first_index(contour[top][1])
    yield (2, NO_PIXEL, NO_PIXEL, y, NAN, NAN)
    pixels = 0
    while y < top_row:
        moved = left.at(y)
        moved = right.at(y) or moved
        if moved:
            yield (3, NO_PIXEL, NO_PIXEL, y, float(left.x), float(right.x))
        start, end = first_column(left.x), first_column(right.x)
        pixels += max(0, end - start)
        yield Span(4, y, start, max(start, end))
        left.step()
        right.step()
        y += 1
        yield (5, NO_PIXEL, NO_PIXEL, y, float(left.x), float(right.x))
    yield Vars(6, {"pixels": pixels})


def convex_pixels(points, options=None) -> np.ndarray:
    """Fast kernel: after the convexity check, the scan-line kernel's pixels."""
    _convex_contour(points)
    return scanline_pixels(points, {"fill_rule": "evenodd", "arithmetic": "exact"})


CONVEX = register(AlgorithmSpec(
    name="polygon-convex",
    title="Convex polygon",
    family="polygons",
    summary="left and right edge chains from the bottom vertex to the top: one run per row",
    inputs=POLYGON,
    options=(),
    code=convex_code,
    generator=convex,
    kernel=convex_pixels,
    notes=("A convex polygon meets every scan line in one run, so no edge table or "
           "sorting is needed: each side is one chain of edges, walked upward.",
           "Refuses a polygon that is not convex, or more than one contour.",
           "Same fill rule as polygon-scanline: a centre on the left chain is filled, "
           "one on the right chain is not."),
))


# ------------------------------------------------------------ tessellation
def _segments_meet(p, q, r, s) -> bool:
    """Do the closed segments pq and rs share a point? (exact)"""
    d1, d2 = cross(p, q, r), cross(p, q, s)
    d3, d4 = cross(r, s, p), cross(r, s, q)
    if ((d1 > 0 and d2 < 0) or (d1 < 0 and d2 > 0)) and ((d3 > 0 and d4 < 0) or (d3 < 0 and d4 > 0)):
        return True

    def on(a, b, c):  # c on the closed segment ab, given that a, b, c are collinear
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(a[1], b[1])
    return ((d1 == 0 and on(p, q, r)) or (d2 == 0 and on(p, q, s))
            or (d3 == 0 and on(r, s, p)) or (d4 == 0 and on(r, s, q)))


def simplicity_problem(contour) -> str:
    """Why a contour (snapped, without repeats) is not a simple polygon, or ''."""
    n = len(contour)
    for k in range(n):
        before, here, after = contour[k - 1], contour[k], contour[(k + 1) % n]
        if cross(before, here, after) == 0 and (
                (here[0] - before[0]) * (after[0] - here[0])
                + (here[1] - before[1]) * (after[1] - here[1])) < 0:
            return f"it folds back on itself at P{k + 1} (two edges overlap)"
    for a in range(n):
        for b in range(a + 2, n):
            if a == 0 and b == n - 1:
                continue  # neighbours through the closing edge
            p, q = contour[a], contour[(a + 1) % n]
            r, s = contour[b], contour[(b + 1) % n]
            if _segments_meet(p, q, r, s):
                return (f"edges P{a + 1}P{(a + 1) % n + 1} and P{b + 1}P{(b + 1) % n + 1} "
                        "cross or touch")
    return ""


def _in_closed_triangle(a, b, c, p) -> bool:
    d1, d2, d3 = cross(a, b, p), cross(b, c, p), cross(c, a, p)
    return not ((min(d1, d2, d3) < 0) and (max(d1, d2, d3) > 0))


TIES = Option("ties", "choice", "left-bottom",
              "centres exactly on a triangle's edge: left-bottom (the fill rule: left and "
              "bottom edges only), inclusive (every edge: shared edges overlap) or strict "
              "(no edge: cracks open)", choices=("left-bottom", "inclusive", "strict"))


def edge_functions(triangle):
    """(a, b, c) of E(X, Y) = a X + b Y + c for each edge, positive inside.

    In snapped units; the triangle must be counter-clockwise.
    """
    functions = []
    for k in range(3):
        (x0, y0), (x1, y1) = triangle[k], triangle[(k + 1) % 3]
        a, b = -(y1 - y0), x1 - x0
        functions.append((a, b, x0 * y1 - y0 * x1))
    return functions


def covers(functions, x: int, y: int, ties: str) -> bool:
    """The triangle's test at a snapped point, with the tie rule on its edges."""
    for a, b, c in functions:
        e = a * x + b * y + c
        if e > 0:
            continue
        if e < 0 or ties == "strict":
            return False
        # On this edge: a left edge (a > 0) or a bottom one (a == 0, b > 0) keeps it.
        if ties == "left-bottom" and not (a > 0 or (a == 0 and b > 0)):
            return False
    return True


def triangle_runs(triangle, ties: str = "left-bottom"):
    """(row, first, end) runs of the covered pixels of a counter-clockwise triangle."""
    functions = edge_functions(triangle)
    xs = [v[0] for v in triangle]
    ys = [v[1] for v in triangle]
    found = []
    for row in range(first_index(min(ys)) - 1, first_index(max(ys)) + 1):
        centre_y = ONE * row + HALF_PIXEL
        covered = [i for i in range(first_index(min(xs)) - 1, first_index(max(xs)) + 1)
                   if covers(functions, ONE * i + HALF_PIXEL, centre_y, ties)]
        if covered:
            # A triangle is convex, so one row's pixels are one run.
            assert covered[-1] - covered[0] + 1 == len(covered)
            found.append((row, covered[0], covered[-1] + 1))
    return found


def tessellate_code(points, options):
    ties = {"left-bottom": "E > 0, or E = 0 on a left edge (a > 0) or a bottom edge (a = 0, b > 0)",
            "inclusive": "E >= 0 for every edge", "strict": "E > 0 for every edge"}[options["ties"]]
    # Operation counts, with two lower bounds: the simplicity check of
    # line 0 (every pair of edges) and the search of lines 5 and 6 (every
    # other vertex against the candidate) are counted as one test each;
    # and a row's fill counts its covered pixels, not the other centres of
    # the bounding box row that were tested and left out.
    cross = {"mul": 2, "int_add": 5}
    inside = {"mul": 6, "int_add": 15, "compare": 3}
    return (
        CodeLine("snap the vertices; check the polygon is simple (no two edges cross or touch)",
                 per={"vertices": {"mul": 2, "round": 2}}),
        CodeLine("drop every vertex that lies on the straight line between its neighbours"),
        CodeLine("while more than 3 vertices remain:"),
        CodeLine("    candidate ear: the triangle (prev, v, next) at the next vertex v", VISIT,
                 ops={**cross, "compare": 2}),
        CodeLine("    if the turn prev -> v -> next is not convex: not an ear", branch="reflex"),
        CodeLine("    elif another vertex lies in the triangle (edges included): not an ear",
                 VISIT, branch="blocked", ops=inside),
        CodeLine("    else: it is an ear: output the triangle, remove v", branch="ear", ops=inside),
        CodeLine("    drop prev or next if it now lies on a straight line between its neighbours"),
        CodeLine("output the last 3 vertices as a triangle"),
        CodeLine("for each triangle: E_k(p) = a_k x + b_k y + c_k for its 3 edges, "
                 "positive inside (1/256 px units)", per={PER_ROW: {"mul": 2, "int_add": 3}}),
        CodeLine(f"    for each row of its bounding box: fill the pixels whose centre has {ties}",
                 PLOT, per={PER_PIXEL: {"mul": 6, "int_add": 8, "compare": 4,
                                        "pixels_tested": 1}}),
        CodeLine("done"),
    )


def _simple_contour(points):
    _single_contour(points, "polygon-tessellate",
                    "use polygon-scanline for several contours or holes")
    contour = _without_repeats(snap_contours(points)[0])
    problem = simplicity_problem(contour) if len(contour) >= 3 else ""
    if problem:
        raise InputError(f"polygon-tessellate needs a simple polygon, but {problem}; "
                         "use polygon-scanline, which fills any polygon")
    return contour


def _flat(ring, k) -> bool:
    n = len(ring)
    return cross(ring[(k - 1) % n][1], ring[k][1], ring[(k + 1) % n][1]) == 0


def tessellate(points, options):
    contour = _simple_contour(points)
    ties = options["ties"]
    yield Start(0, ("vertex", "turn", "triangles"),
                {"vertices": len(contour), "ties": ties, "subpixel": ONE})
    # The ring keeps each vertex's original number for the tables.
    ring = list(enumerate(contour))
    k = 0
    while len(ring) >= 3 and k < len(ring):
        if _flat(ring, k):
            yield Note(1, f"P{ring[k][0] + 1} lies on the line between its neighbours: dropped")
            ring.pop(k)
            k = max(0, k - 1)
        else:
            k += 1
    if len(ring) < 3:
        yield Note(1, "all the vertices lie on one line: the polygon has no area")
        yield Vars(11, {"triangles": 0, "pixels": 0})
        return
    orientation = 1 if signed_area2([v for _, v in ring]) > 0 else -1
    triangles = []
    k, misses = 0, 0
    while len(ring) > 3:
        n = len(ring)
        k %= n
        (pi, prev), (vi, here), (ni, after) = ring[k - 1], ring[k], ring[(k + 1) % n]
        turn = cross(prev, here, after)
        ear_value = (vi + 1, turn / ONE ** 2, len(triangles))
        yield (3, *pixel_of(here), *ear_value)
        if turn * orientation <= 0:
            yield (4, NO_PIXEL, NO_PIXEL, *ear_value)
            k, misses = k + 1, misses + 1
        else:
            blocker = next((v for j, (_, v) in enumerate(ring)
                            if j not in (k - 1 if k else n - 1, k, (k + 1) % n)
                            and _in_closed_triangle(prev, here, after, v)), None)
            if blocker is not None:
                yield (5, *pixel_of(blocker), *ear_value)
                k, misses = k + 1, misses + 1
            else:
                triangles.append(((pi, prev), (vi, here), (ni, after)))
                ring.pop(k)
                misses = 0
                yield (6, NO_PIXEL, NO_PIXEL, vi + 1, turn / ONE ** 2, len(triangles))
                k = (k - 1) % len(ring)  # back to prev, whose ear just changed
                # Only prev and next got new neighbours; dropping one of them
                # leaves the other's flatness as it was (all four are collinear).
                for entry in (ring[k], ring[(k + 1) % len(ring)]):
                    j = ring.index(entry)
                    if len(ring) > 3 and _flat(ring, j):
                        yield Note(7, f"P{entry[0] + 1} now lies on a straight line "
                                      "between its neighbours: dropped")
                        ring.pop(j)
                        k -= j < k
                k %= len(ring)
        if misses > 2 * len(ring):
            raise RuntimeError("ear clipping found no ear in a simple polygon")
    triangles.append(tuple(ring))
    yield (8, NO_PIXEL, NO_PIXEL, NAN, NAN, len(triangles))
    yield Table(8, "triangles", ("triangle", "A", "B", "C"),
                tuple((t + 1, *(f"P{index + 1}" for index, _ in tri))
                      for t, tri in enumerate(triangles)))
    pixels = 0
    for t, tri in enumerate(triangles):
        vertices = [v for _, v in tri]
        if orientation < 0:
            vertices.reverse()
        functions = edge_functions(vertices)
        names = [f"P{index + 1}" for index, _ in (tri if orientation > 0 else tri[::-1])]
        yield Table(9, f"edge functions of triangle {t + 1}", ("edge", "a", "b", "c", "side"),
                    tuple((names[e] + names[(e + 1) % 3], a, b, c, _side(a, b))
                          for e, (a, b, c) in enumerate(functions)))
        for row, start, end in triangle_runs(vertices, ties):
            pixels += end - start
            yield Span(10, row, start, end)
    yield Vars(11, {"triangles": len(triangles), "pixels": pixels})


def _side(a: int, b: int) -> str:
    if a > 0:
        return "left"
    if a < 0:
        return "right"
    return "bottom" if b > 0 else "top"


TESSELLATE = register(AlgorithmSpec(
    name="polygon-tessellate",
    title="Tessellation (ear clipping)",
    family="polygons",
    summary="cut a simple polygon into triangles by clipping ears; fill each by edge functions",
    inputs=POLYGON,
    options=(TIES,),
    code=tessellate_code,
    generator=tessellate,
    notes=("An ear is a convex corner whose triangle holds no other vertex; every simple "
           "polygon with more than 3 vertices has one, so clipping ears always ends in "
           "n - 2 triangles.",
           "Each triangle is tested at every pixel centre of its bounding box with three "
           "edge functions in exact integers. With ties = left-bottom, a centre on a "
           "shared diagonal goes to exactly one triangle, so the result equals "
           "polygon-scanline's; inclusive shows the overlaps, strict the cracks.",
           "Refuses a self-intersecting polygon or more than one contour."),
))
