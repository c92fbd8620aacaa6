"""polygon-scanline: the edge table and the active edge table, and its fast kernel."""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PER_PIXEL, PER_ROW, PLOT, Note, Span, Start, Table, Vars
from .common import (FLOATS, HALF_PIXEL, ONE, POLYGON, WholeAndError, as_pixels, edge_label,
                     first_column, first_index, snap_contours, table_number)

FILL_RULE = Option("fill_rule", "choice", "evenodd",
                   "evenodd: inside after an odd number of crossings; nonzero: inside "
                   "where the winding number is not 0", choices=("evenodd", "nonzero"))
ARITHMETIC = Option("arithmetic", "choice", "exact",
                    "how x is kept and stepped along each edge: exact fractions, or "
                    "float64 / float32 to watch rounding move a span end",
                    choices=("exact", "float64", "float32"))


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
        cells = (self.label, self.ymax, table_number(self.x), table_number(self.inv_m))
        return cells + ((self.direction,) if rule == "nonzero" else ())


def scan_edges(contours, arithmetic: str = "exact",
               sample: int = HALF_PIXEL) -> tuple[list[ScanEdge], int]:
    """The ET's entries (in polygon order) and how many edges were left out.

    Horizontal edges, and edges too short to reach any row's centre line,
    meet no scan line and are left out. ``sample`` is the height of row y's
    scan line above y, in snapped units: the centre, or 0 for the textbook's
    X_low table, whose scan lines run along the rows' lower edges.
    """
    edges, skipped = [], 0
    real = FLOATS.get(arithmetic)
    for c, contour in enumerate(contours):
        for k, start in enumerate(contour):
            end = contour[(k + 1) % len(contour)]
            direction = 1 if end[1] > start[1] else -1
            low, high = (start, end) if direction > 0 else (end, start)
            first, ymax = first_row(low[1], sample), first_row(high[1], sample)
            if first >= ymax:  # horizontal, or between two centre lines
                skipped += 1
                continue
            dx, dy = high[0] - low[0], high[1] - low[1]
            rise = ONE * first + sample - low[1]  # from the low end to the first scan line
            if real is None:
                inv_m = Fraction(dx, dy)
                x = as_pixels(low[0]) + as_pixels(rise) * inv_m
                if arithmetic == "integer":  # x in 1/(256 dy) px: a whole part and an error
                    x, inv_m = WholeAndError.of(x, ONE * dy), WholeAndError.of(inv_m, ONE * dy)
            else:
                inv_m = real(dx) / real(dy)
                x = real(low[0] / ONE) + real(rise / ONE) * inv_m
            edges.append(ScanEdge(edge_label(contours, c, k), first, ymax, x, inv_m, direction))
    return edges, skipped


def first_row(v: int, sample: int = HALF_PIXEL) -> int:
    """The first row whose scan line (``sample`` above its bottom) is at or above v."""
    return -((sample - v) // ONE)


def sample_of(options) -> int:
    """Where a row's scan line runs: through the centres, or (x-low) along the bottom."""
    return 0 if options.get("edge_x") == "x-low" else HALF_PIXEL


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
def scanline_listing(points, options) -> Code:
    rule, arithmetic = options["fill_rule"], options["arithmetic"]
    entry = "(ymax, x, 1/m, dir)" if rule == "nonzero" else "(ymax, x, 1/m)"
    if rule == "nonzero":
        fill = ("    walk the AET adding each dir to w; between an x where w leaves 0 and the "
                "x where it returns to 0: fill pixels i with x_left <= i + 1/2 < x_right")
    else:
        fill = ("    for each pair (x_left, x_right) of the AET in turn: "
                "fill pixels i with x_left <= i + 1/2 < x_right")
    number = {"exact": "an exact fraction",
              "integer": "whole + e/dy: x += q;  e += r;  if e >= dy: x += 1, e -= dy"
              }.get(arithmetic, f"a {arithmetic}")
    # Operation counts. An exact x is kept as a whole part and a remainder
    # over dy, as the integer edge walk does: x += 1/m is two integer
    # additions and a carry test. Per edge (the Start constant "edges"),
    # the ET line counts its setup and the one test that removes it from
    # the AET later; line 5 counts the test of each edge that stays (the
    # frame's "active"). The AET is nearly sorted from row to row, so the
    # sort is an insertion pass: one comparison per row of its table; the
    # x += 1/m step shows the AET it has just stepped, one row per edge. A
    # span costs two roundings; each of its pixels a step and a test.
    step = ({"int_add": 2, "compare": 2} if arithmetic in ("exact", "integer")
            else {"float_add": 1, "compare": 1})
    setup = {"int_add": 4, "div": 1, "mul": 1, "round": 2, "compare": 2}
    if arithmetic != "exact":
        setup["float_add"] = 1
    code = Code()
    code.add("snap", "snap every vertex to the 1/256 px grid",
             per={"vertices": {"mul": 2, "round": 2}})
    where = "the first row y whose centre line y + 1/2 it meets"
    if options.get("edge_x") == "x-low":
        # The textbook's table: x at the lower end, scan lines along whole y.
        entry, where = entry.replace(", x,", ", X_low,"), "the first whole y at or above its lower end"
    code.add("edge_table", f"ET: bucket each edge under {where}, as {entry}; skip horizontal "
                           "edges", per={"edges": setup})
    code.add("start", "AET = empty;  y = the lowest bucket of the ET")
    code.add("loop", "while the ET or the AET is not empty:")
    code.add("enter", "    if the AET is empty: y = the lowest remaining bucket;  "
                      "move the edges of bucket ET[y] into the AET", ops={"compare": 3})
    code.add("leave", "    remove from the AET the edges with ymax == y",
             per={"active": {"compare": 1}})
    code.add("sort", "    sort the AET on x", per={PER_ROW: {"compare": 1}})
    code.add("plot_spans", fill, PLOT, ops={"round": 2, "compare": 1},
             per={PER_PIXEL: {"int_add": 1, "compare": 1}})
    code.add("next_row", "    y += 1", ops={"int_add": 1})
    code.add("step_x", f"    for each edge in the AET: x += 1/m   (x is {number})",
             per={PER_ROW: step})
    code.add("done", "done")
    return code


def scanline(points, options):
    rule, arithmetic = options["fill_rule"], options["arithmetic"]
    contours = snap_contours(points)
    edges, skipped = scan_edges(contours, arithmetic, sample_of(options))
    at = scanline_listing(points, options).at
    # y and the AET's size are Vars, not frame values: they then hold on the
    # table and span steps between their updates instead of vanishing there.
    yield Start(line=at["snap"],
                constants={"contours": len(contours), "vertices": sum(map(len, contours)),
                           "edges": len(edges), "fill_rule": rule, "arithmetic": arithmetic,
                           "subpixel": ONE})
    if skipped:
        yield Note(line=at["edge_table"], brief=True,
                   text=f"{skipped} edge(s) left out: horizontal, or between two centre lines, "
                        "so no scan line meets them")
    table = {}
    for edge in sorted(edges, key=lambda e: (e.first, e.x, e.inv_m)):
        table.setdefault(edge.first, []).append(edge)
    columns = ("ymin", "edge", "ymax", "x", "1/m") + (("dir",) if rule == "nonzero" else ())
    yield _edge_table(table, rule, columns, at["edge_table"])
    y = min(table, default=0)
    yield Vars(line=at["start"], values={"y": y, "active": 0})
    spans, pixels = yield from _rows(table, y, rule, columns, at)
    yield Vars(line=at["done"], values={"spans": spans, "pixels": pixels})


def _edge_table(table, rule, columns, line) -> Table:
    """The ET as it stands: the buckets not yet moved into the AET."""
    return Table(line=line, name="ET", columns=columns,
                 rows=tuple((y,) + edge.row(rule) for y in sorted(table) for edge in table[y]))


def _aet(active, rule, columns, line) -> Table:
    return Table(line=line, name="AET", columns=columns[1:],
                 rows=tuple(edge.row(rule) for edge in active))


def _rows(table, y, rule, columns, at):
    """The scan-line loop, from row y up; returns (spans, pixels) filled.

    Every table shows what its line has just done: the ET loses a bucket
    at the line that moves it into the AET, and the AET's x values change
    at the line x += 1/m."""
    active: list[ScanEdge] = []
    plot = at["plot_spans"]
    spans = pixels = 0
    while table or active:
        if not active:
            y = min(table)
        yield Vars(line=at["loop"], values={"y": y, "active": len(active)})
        active.extend(table.pop(y, ()))
        yield _edge_table(table, rule, columns, at["enter"])
        active = [edge for edge in active if edge.ymax != y]
        yield Vars(line=at["leave"], values={"active": len(active)})
        # Ties on x are broken by 1/m, so the table reads in the order the
        # edges will be met on the rows just above.
        active.sort(key=lambda e: (e.x, e.inv_m))
        yield _aet(active, rule, columns, at["sort"])
        for left, right in runs(active, rule):
            start, end = first_column(left), first_column(right)
            spans += 1
            pixels += max(0, end - start)
            yield Span(line=plot, y=y, x_start=start, x_end=max(start, end))
        y += 1
        yield Vars(line=at["next_row"], values={"y": y})
        for edge in active:
            edge.x = edge.x + edge.inv_m
        yield _aet(active, rule, columns, at["step_x"])
    return spans, pixels


def scanline_explain(trace, i):
    """For a span: the pair of crossings it lies between and its pixels."""
    record = trace.step(i).record
    if not isinstance(record, Span):
        if isinstance(record, Table) and record.name == "AET":
            return [("scan line", f"centre line y + 1/2 = {trace.variables_at(i).get('y', 0) + 0.5:g}")]
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
def _edge_arrays(contours, sample=HALF_PIXEL):
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
    first = -((sample - low[:, 1]) // ONE)
    stop = -((sample - high[:, 1]) // ONE)
    keep = stop > first
    return (low[keep], high[keep] - low[keep], first[keep], (stop - first)[keep],
            np.where(up, 1, -1)[keep])


def _crossing_columns(contours, arithmetic: str, sample=HALF_PIXEL):
    """Row, first covered column and direction of every edge/scan-line crossing."""
    low, delta, first, count, direction = _edge_arrays(contours, sample)
    total = int(count.sum())
    edge = np.repeat(np.arange(len(count)), count)
    step = np.arange(total, dtype=np.int64) - np.repeat(np.cumsum(count) - count, count)
    rows = first[edge] + step
    dx, dy = delta[:, 0], delta[:, 1]
    rise = ONE * first + sample - low[:, 1]
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
    rows, columns, direction = _crossing_columns(snap_contours(points), arithmetic,
                                                 sample_of(options or {}))
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


def pixel_box(points, sample=HALF_PIXEL) -> tuple[int, int, int, int]:
    """(x0, y0, W, H): the smallest block of pixels the polygon can cover."""
    snapped = [v for contour in snap_contours(points) for v in contour]
    xs = [x for x, _ in snapped]
    ys = [y for _, y in snapped]
    x0, y0 = first_index(min(xs)), first_row(min(ys), sample)
    return x0, y0, first_index(max(xs)) - x0, first_row(max(ys), sample) - y0


def scanline_pixels(points, options=None) -> np.ndarray:
    """Fast kernel: (n, 2) pixels in the generator's order (rows up, x right)."""
    x0, y0, width, height = pixel_box(points, sample_of(options or {}))
    if width <= 0 or height <= 0:
        return np.zeros((0, 2), dtype=np.int64)
    flat = np.flatnonzero(scanline_mask(points, options, (width, height), (x0, y0)))
    pixels = np.empty((len(flat), 2), dtype=np.int64)
    np.divmod(flat, width, out=(pixels[:, 1], pixels[:, 0]))
    pixels += (x0, y0)
    return pixels


SCANLINE = AlgorithmSpec(
    name="polygon-scanline",
    title="Scan line (ET/AET)",
    family="polygons",
    summary="edge table and active edge table: fill the runs between crossings row by row",
    inputs=POLYGON,
    options=(FILL_RULE, ARITHMETIC),
    code=listing(scanline_listing),
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
    oracle=Oracle(
        "exact",
        "The pixel centres the polygon covers by either fill rule, ties to left and bottom edges, "
        "from exact integer arithmetic (algorithms/exact/polygons.py); float64 differs only at "
        "centres within 1e-9 px of an edge. scikit-image's polygon agrees off the outline.",
        ("algorithms/polygons/test_polygons_scanline.py",
         "algorithms/polygons/test_polygons_skimage.py", "algorithms/test_stability.py"),
        check="covered-polygon"),
)

# The module's algorithms, in the order they are listed.
SPECS = (SCANLINE,)
