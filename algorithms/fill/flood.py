"""The fill family: seed fill inside an outline drawn on the grid.

The outline is one or more closed polygons of integer points (the last
point joins the first), each segment drawn with integer rounding as
Bresenham draws it, or a midpoint circle around one centre
(``flood-fill-circle``); it is drawn in the boundary colour. Then the region
around a seed pixel is filled in the fill colour, bounded by the grid's
edges and, by the ``mode`` option, either by the boundary colour (boundary
fill: every pixel the seed reaches without crossing the outline) or by any
change of colour (flood fill of a region of one colour: the pixels joined to
the seed that have the seed's colour, so a seed on the outline recolours the
outline).
The seed pixel grows by 4- or 8-neighbours, in one of three orders: a stack
(depth first, the order of the recursive textbook fill), a queue (breadth
first) or spans (the scan-line seed fill, a run of a row at a time).

No Python recursion is used, so regions of millions of pixels fill without
a recursion limit.
"""
from __future__ import annotations

import math
from array import array
from collections import deque

from algorithms.circles.midpoint import CENTRE, RADIUS
from algorithms.core.code import Code, listing
from algorithms.fill.kernel import circle_fill_state, flood_fill_state
from algorithms.fill.seed import (BOUNDARY, FILLED, FREE, WALL, circle_outline, circle_seed, inside_pixel,
                        seed_pixel)
from algorithms.core.registry import AlgorithmSpec, InputError, Inputs, Option, Oracle
from algorithms.core.steps import PER_PIXEL, PLOT, VISIT, Note, Span, Start, Vars
from algorithms.core.trace import checkpoint, work_allowance

NAN = math.nan

OUTLINE = Inputs(3, integer=True, contours=True)

NEIGHBOURS = {
    "4": ((1, 0), (-1, 0), (0, 1), (0, -1)),
    "8": ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, 1), (-1, -1), (1, -1)),
}
NEIGHBOUR_NAMES = "E, W, N, S"
DIAGONAL_NAMES = ", NE, NW, SW, SE"

# Pops up to this many show the stack's first entries in the panel; past it
# only its size is kept, so a million-pixel fill stays small. Wherever the
# size changes, the listing changes with it (or says once that it is no
# longer kept): the two are never shown out of step.
DETAIL_POPS = 10_000
SHOWN_ENTRIES = 5
NOT_LISTED = "(not listed past the first pops)"  # "next" once DETAIL_POPS is passed

SEED = Option("seed", "point", "auto",
              "the pixel X,Y the fill starts from; auto takes a free pixel inside the outlines "
              "(even-odd), near the middle of the first",
              choices=("auto",))
CONNECTIVITY = Option("connectivity", "choice", "4",
                      "4: grow to edge neighbours; 8: to corner neighbours too", choices=("4", "8"))
ORDER = Option("order", "choice", "stack",
               "stack: depth first, as the recursive fill; queue: breadth first; "
               "span: a run of a row at a time", choices=("stack", "queue", "span"))
OUTLINE_STEPS = Option("outline", "choice", "8",
                       "8: outline segments as Bresenham draws them (8-connected); 4: a corner "
                       "pixel added at each diagonal step, which holds an 8-connected fill",
                       choices=("8", "4"))
MODE = Option("mode", "choice", "boundary",
              "boundary: fill everything the seed reaches without crossing the boundary "
              "colour; region: recolour the pixels joined to the seed that have the seed's "
              "colour (a seed on the outline recolours the outline)",
              choices=("boundary", "region"))
COLORS = Option("colors", "colors", ("#c0392b", "#2e86de"), "boundary colour, fill colour")


# ---------------------------------------------------------------- outline
def segment_pixels(p, q) -> list[tuple[int, int]]:
    """The pixels of segment P -> Q, one per step along the longer axis.

    The other coordinate is rounded to the nearest integer (halves up), the
    pixels Bresenham's algorithm picks; consecutive pixels are 8-neighbours.
    """
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    if n == 0:
        return [(x0, y0)]
    # floor((2 i d + n) / 2n) is round(i d / n) with halves up, in integers.
    return [(x0 + (2 * i * dx + n) // (2 * n), y0 + (2 * i * dy + n) // (2 * n))
            for i in range(n + 1)]


def outline_pixels(contours, four: bool = False) -> list[tuple[int, int]]:
    """Every outline pixel once, in drawing order; each contour is closed."""
    return list(dict.fromkeys(outline_walk(contours, four)))


def outline_walk(contours, four: bool = False):
    """The outline's pixels in drawing order, made as they are asked for.

    A pixel drawn by two segments comes twice; a segment drawn before (the
    same ends in the same order) is skipped, as it adds no pixel.
    """
    drawn = set()
    for contour in contours:
        for k, p in enumerate(contour):
            q = contour[(k + 1) % len(contour)]
            if (p, q) not in drawn:
                drawn.add((p, q))
                yield from _segment_walk(p, q, four)


def _segment_walk(p, q, four: bool):
    """``segment_pixels(p, q)`` one at a time, with the corner pixel of each
    diagonal step when ``four``: a segment may be millions of pixels long,
    mostly off the grid, and the step cap stops it part way."""
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    a = (x0, y0)
    for i in range(1, n + 1):
        b = (x0 + (2 * i * dx + n) // (2 * n), y0 + (2 * i * dy + n) // (2 * n))
        yield a
        if four and a[0] != b[0] and a[1] != b[1]:
            # Step across first, then along: the corner closes the
            # diagonal that an 8-connected fill would slip through.
            yield b[0], a[1]
        if not i & 4095:
            checkpoint()
        a = b
    yield a


def outline_row(contours, y: int, four: bool = False) -> set[int]:
    """The x of every outline pixel on row y, worked out per segment without
    drawing the outline (the same pixels as ``outline_pixels``)."""
    found = set()
    for contour in contours:
        for k, p in enumerate(contour):
            q = contour[(k + 1) % len(contour)]
            if min(p[1], q[1]) - 1 <= y <= max(p[1], q[1]) + 1:
                found.update(_segment_row(p, q, y, four))
    return found


def _segment_row(p, q, y: int, four: bool) -> list[int]:
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    if n == 0:
        return [x0] if y == y0 else []
    if abs(dy) > abs(dx):
        # one pixel per row: i = |y - y0|; x rounds i dx / n (halves up)
        i = (y - y0) * (1 if dy > 0 else -1)
        if not 0 <= i <= n:
            return []
        xs = [x0 + (2 * i * dx + n) // (2 * n)]
        if four and i < n and x0 + (2 * (i + 1) * dx + n) // (2 * n) != xs[0]:
            xs.append(x0 + (2 * (i + 1) * dx + n) // (2 * n))  # the corner after it
        return xs
    # A run of pixels per row: the i with floor((2 i dy + n) / 2n) = y - y0,
    # that is 2 n k - n <= 2 i dy <= 2 n k + n - 1 for k = y - y0.
    k, step = y - y0, (1 if dx > 0 else -1)
    if dy == 0:
        lo, hi = (0, n) if k == 0 else (1, 0)
    elif dy > 0:
        lo, hi = -((n - 2 * n * k) // (2 * dy)), (2 * n * k + n - 1) // (2 * dy)
    else:
        lo, hi = -((2 * n * k + n - 1) // (-2 * dy)), (n - 2 * n * k) // (-2 * dy)
    lo, hi = max(lo, 0), min(hi, n)
    if lo > hi:
        return []
    xs = [x0 + step * i for i in range(lo, hi + 1)]
    if four and hi < n:
        xs.append(x0 + step * (hi + 1))  # the corner where the run steps to the next row
    return xs


# -------------------------------------------------------------- the region
class Region:
    """The grid as a padded byte array: free, boundary, filled, or wall.

    A one-pixel wall around the grid keeps neighbour tests free of bounds
    checks. Index of pixel (x, y): (y + 1) * stride + x + 1.
    """

    def __init__(self, width: int, height: int, boundary):
        self.width, self.height = width, height
        self.stride = width + 2
        self.cells = bytearray([WALL]) * (self.stride * (height + 2))
        row = bytes(width)
        for y in range(height):
            start = self.index(0, y)
            self.cells[start:start + width] = row
        for x, y in boundary:
            if self.inside(x, y):
                self.cells[self.index(x, y)] = BOUNDARY

    def inside(self, x: int, y: int) -> bool:
        return 0 <= x < self.width and 0 <= y < self.height

    def index(self, x: int, y: int) -> int:
        return (y + 1) * self.stride + x + 1

    def pixel(self, index: int) -> tuple[int, int]:
        y, x = divmod(index, self.stride)
        return x - 1, y - 1

    def free(self, x: int, y: int) -> bool:
        return self.inside(x, y) and self.cells[self.index(x, y)] == FREE

    def offsets(self, connectivity: str) -> tuple[int, ...]:
        return tuple(dy * self.stride + dx for dx, dy in NEIGHBOURS[connectivity])


def _packed(color: str) -> int:
    return int(color[1:], 16)


def _colors(options) -> tuple[str, str]:
    colors = options.get("colors") or COLORS.default
    if len(colors) != 2:
        raise InputError("option colors: give two colours, the boundary's and the fill's")
    return colors[0], colors[1]


def _neighbour_names(options) -> str:
    return NEIGHBOUR_NAMES + (DIAGONAL_NAMES if options["connectivity"] == "8" else "")


# ------------------------------------------------------------ pseudo-code
def fill_listing(points, options) -> Code:
    return _listing(_outline_line("draw each outline segment as Bresenham does, closing each "
                                  "outline", options), options)


def circle_fill_listing(points, options) -> Code:
    return _listing(_outline_line("draw the midpoint circle of radius R around C", options), options)


def _outline_line(what: str, options) -> str:
    if options["outline"] == "8":
        return f"{what} (8-connected)"
    return f"{what}, with a corner pixel at each diagonal step (4-connected)"


def _listing(outline, options) -> Code:
    free = ("free: inside the grid, not boundary, not filled" if options["mode"] == "boundary"
            else "free: inside the grid and still the seed's colour")
    # Operation counts. An outline pixel costs what a Bresenham step does.
    # Every pixel pushed is popped once, so a push (one addition to the
    # stack pointer) is counted with its pop; a pop is an addition and the
    # loop's emptiness test. pixels_tested counts reads of a pixel's state.
    code = Code()
    code.add("plot_outline", outline, PLOT, ops={"int_add": 3, "compare": 2})
    code.add("push", "push(seed)")
    if options["order"] == "span":
        _span_lines(code, free, options)
    else:
        _pixel_lines(code, free, options)
    code.add("done", "done")
    return code


def _span_lines(code: Code, free: str, options) -> None:
    # The "filled already" test runs at every pop; its line has a frame
    # only when it skips, so the test is counted on the pop's line.
    code.add("loop", "while the stack is not empty:")
    code.add("pop", "    (x, y) = pop()", VISIT, ops={"int_add": 2, "compare": 2, "pixels_tested": 1})
    code.add("skip", "    if (x, y) is filled already:  continue", VISIT)
    code.add("plot_run", f"    widen x to the run xl .. xr of free pixels on row y;  fill xl .. xr   "
                         f"({free})", PLOT, ops={"compare": 2, "pixels_tested": 2},
             per={PER_PIXEL: {"int_add": 1, "compare": 1, "pixels_tested": 1}})
    code.add("push_runs", "    for the rows y + 1 and y - 1, over " +
             ("xl - 1 .. xr + 1" if options["connectivity"] == "8" else "xl .. xr") +
             ":  push the leftmost pixel of each run of free pixels", VISIT, ops={"compare": 1},
             per={PER_PIXEL: {"int_add": 1, "compare": 2, "pixels_tested": 1}})


def _pixel_lines(code: Code, free: str, options) -> None:
    names = _neighbour_names(options)
    stack = options["order"] == "stack"
    take = ("pop()   (the top: last pushed, first out)" if stack
            else "take()   (the front: first pushed, first out)")
    push = (f"push the free neighbours among {names}, in reverse, so {names.split(',')[0]} "
            f"comes out first" if stack else f"push the free neighbours among {names}")
    # The pop has a frame only for the first pops (its panel detail); every
    # pop ends on the skip or the fill line, so it is counted there. A fill
    # reads each neighbour's state (an address addition and a test).
    k = len(NEIGHBOURS[options["connectivity"]])
    code.add("loop", f"while the {'stack' if stack else 'queue'} is not empty:")
    code.add("pop", f"    p = {take}", VISIT)
    code.add("skip", "    if p is filled already:  continue   (pushed twice before it was filled)",
             VISIT, ops={"int_add": 2, "compare": 2, "pixels_tested": 1})
    code.add("plot_fill", f"    fill p;  {push}   ({free})", PLOT,
             ops={"int_add": 2 + k, "compare": 2 + k, "pixels_tested": 1 + k})


# -------------------------------------------------------------- generator
def flood_fill(points, options, grid):
    """Check the inputs, then return the frame generator.

    The checks run here, before the first frame, so a bad seed is an
    InputError at once. They look at the outline a row at a time, without
    drawing it: the frames draw it a pixel at a time, so the step cap and a
    cancel stop an outline of any length part way.
    """
    four = options["outline"] == "4"
    region = Region(*grid, ())
    rows = {}

    def on_outline(x, y):
        if y not in rows:
            rows.clear()  # one row at a time: the search goes row by row
            rows[y] = outline_row(points, y, four)
        return x in rows[y]

    def free(x, y):
        return region.inside(x, y) and not on_outline(x, y)
    seed = seed_pixel("flood-fill", options, lambda: inside_pixel(points, free, grid), region,
                      on_outline)
    target = BOUNDARY if on_outline(*seed) else FREE
    outline = _Drawn(outline_walk(points, four), region)
    return _fill(outline, region, seed, target, options, {}, fill_listing(points, options).at)


def circle_fill(points, options, grid):
    """Seed fill inside a midpoint circle around the one point given."""
    (centre,) = points
    radius = options["radius"]
    # At most about 23,000 pixels (radius 4096): made at once.
    pixels = circle_outline(centre, radius, four=options["outline"] == "4")
    region = Region(*grid, ())
    ring = set(pixels)
    outline = _Drawn(pixels, region)
    shape = {"C": tuple(centre), "R": radius}
    at = circle_fill_listing(points, options).at
    if options["seed"] == "auto" and not (region.inside(*centre) and tuple(centre) not in ring):
        return _outline_only(outline, options, shape, at)
    seed = seed_pixel("flood-fill-circle", options,
                      lambda: circle_seed(centre, region, lambda x, y: (x, y) in ring), region,
                      lambda x, y: (x, y) in ring)
    target = BOUNDARY if seed in ring else FREE
    return _fill(outline, region, seed, target, options, shape, at)


class _Drawn:
    """The outline as the frames draw it: each pixel once, the first time it
    comes, marked on the region then; ``count`` is how many were drawn."""

    def __init__(self, pixels, region: Region):
        self.pixels, self.region = pixels, region
        self.count = 0

    def __iter__(self):
        region, cells, off_grid = self.region, self.region.cells, set()
        # Pixels walked again (segments that overlap) make no frame: they
        # count against the step cap, so the cap bounds that work too.
        allowance, skipped = work_allowance(), 0
        for x, y in self.pixels:
            if region.inside(x, y):
                index = region.index(x, y)
                new = cells[index] != BOUNDARY
                cells[index] = BOUNDARY
            else:
                new = (x, y) not in off_grid
                off_grid.add((x, y))
            if new:
                self.count += 1
                yield x, y
            else:
                skipped += 1
                if skipped > allowance:
                    raise InputError(f"flood-fill: the outline's segments overlap so much that "
                                     f"it walks over more than {allowance:,} pixels it has "
                                     "already drawn (the work the step cap allows); remove "
                                     "the overlapping segments")


def _outline_only(outline, options, shape, at):
    """A circle with no free pixel inside (radius 0, or its centre off the
    grid): the outline is drawn and nothing is filled."""
    boundary_color, fill_color = _colors(options)
    yield Start(line=at["plot_outline"], values=("rgb", "size"),
                constants={**shape, "seed": "none", "mode": options["mode"],
                           "boundary colour": boundary_color, "fill colour": fill_color},
                pixel_value="rgb")
    yield from _outline_frames(outline, _packed(boundary_color), at, 0)
    yield Note(line=at["plot_outline"],
               text="The circle has no free pixel inside it to start from, so nothing is "
                    "filled; give a seed outside it to fill the rest of the grid.")
    yield Vars(line=at["done"], values={"filled": 0, "boundary": outline.count, "pops": 0})


def _fill(outline, region, seed, target, options, shape: dict, at):
    """The frames; ``target`` is the state the fill spreads over: free
    pixels, or the outline's when a region fill starts on it."""
    boundary_color, fill_color = _colors(options)
    constants = {**shape, "seed": seed, "connectivity": int(options["connectivity"]),
                 "order": options["order"], "mode": options["mode"],
                 "spreads over": "the outline" if target == BOUNDARY else "free pixels",
                 "grid": f"{region.width}x{region.height}",
                 "boundary colour": boundary_color, "fill colour": fill_color}
    run = _span_frames if options["order"] == "span" else _pixel_frames
    return run(constants, outline, region, seed, options, target,
               (_packed(boundary_color), _packed(fill_color)), at)


def _outline_frames(outline, boundary_rgb, at, *size):
    line = at["plot_outline"]
    for x, y in outline:
        yield (line, x, y, boundary_rgb, *size)


def _pixel_frames(constants, outline, region, seed, options, target, rgb, at):
    """Stack or queue order: one pixel per pop."""
    boundary_rgb, fill_rgb = rgb
    yield Start(line=at["plot_outline"], values=("rgb", "size"), constants=constants,
                pixel_value="rgb")
    yield from _outline_frames(outline, boundary_rgb, at, 0)
    cells, stride = region.cells, region.stride
    offsets = region.offsets(options["connectivity"])
    stack = options["order"] == "stack"
    if stack:
        # Pushed in reverse, popped in order: the recursive fill's call order.
        offsets = offsets[::-1]
        pending = array("q")
        take = pending.pop
    else:
        pending = deque()
        take = pending.popleft
    push = pending.append
    push(region.index(*seed))
    yield (at["push"], seed[0], seed[1], NAN, 1)
    filled = skipped = 0
    largest = 1
    pop, skip, fill = at["pop"], at["skip"], at["plot_fill"]
    while pending:
        # The first pops show the next entries in the panel: the pop, the
        # fill (the stack as the pop left it) and the pushes are a step each.
        # Past them the loop stays lean for large regions: the fill's frame
        # carries the size after its pushes.
        pops = filled + skipped
        detailed = pops < DETAIL_POPS
        p = take()
        y, x = divmod(p, stride)
        x, y = x - 1, y - 1
        if detailed:
            yield Vars(line=pop, values={"size": len(pending),
                                         "next": _entries(pending, stack, region)}, pixel=(x, y))
        elif pops == DETAIL_POPS:  # the listing ends here: said once
            yield Note(line=pop, text=f"From here on the panel keeps only the size of the "
                                      f"{'stack' if stack else 'queue'}; its entries are listed "
                                      f"for the first {DETAIL_POPS:,} pops.", pixel=(x, y))
            yield Vars(line=pop, values={"size": len(pending), "next": NOT_LISTED}, pixel=(x, y))
        if cells[p] != target:
            skipped += 1
            yield (skip, x, y, NAN, len(pending))
            continue
        cells[p] = FILLED
        filled += 1
        before = len(pending)
        for offset in offsets:
            if cells[p + offset] == target:
                push(p + offset)
        size = len(pending)
        if size > largest:
            largest = size
        yield (fill, x, y, fill_rgb, before if detailed else size)
        if detailed and size > before:
            yield Vars(line=fill, values={"size": size, "next": _entries(pending, stack, region)},
                       pixel=(x, y))
    yield Vars(line=at["done"], values={"filled": filled, "boundary": outline.count,
                                        "pops": filled + skipped, "skipped": skipped,
                                        "largest": largest, "size": 0, "next": "(empty)"})


def _span_frames(constants, outline, region, seed, options, target, rgb, at):
    """Scan-line seed fill: a run of free pixels per pop.

    Frames are few here (one per run), so the stack's size goes into a Vars
    record at every pop and after the pushes of each row, rather than into
    a value of every frame.
    """
    boundary_rgb, fill_rgb = rgb
    yield Start(line=at["plot_outline"], values=("rgb",), constants=constants, pixel_value="rgb")
    yield from _outline_frames(outline, boundary_rgb, at)
    cells = region.cells
    eight = options["connectivity"] == "8"
    pending = [region.index(*seed)]
    yield Vars(line=at["push"], values={"size": 1, "next": f"({seed[0]}, {seed[1]})"}, pixel=seed)
    pops = skipped = filled = runs = 0
    largest = 1
    pop, skip, fill, push = at["pop"], at["skip"], at["plot_run"], at["push_runs"]
    while pending:
        p = pending.pop()
        pops += 1
        x, y = region.pixel(p)
        values = {"size": len(pending)}
        if pops <= DETAIL_POPS:
            values["next"] = _entries(pending, True, region)
        elif pops == DETAIL_POPS + 1:
            values["next"] = NOT_LISTED
        yield Vars(line=pop, values=values, pixel=(x, y))
        if cells[p] != target:
            skipped += 1
            yield (skip, x, y, NAN)
            continue
        left = right = p
        while cells[left - 1] == target:
            left -= 1
        while cells[right + 1] == target:
            right += 1
        cells[left:right + 1] = bytes([FILLED]) * (right - left + 1)
        filled += right - left + 1
        runs += 1
        xl, xr = x - (p - left), x + (right - p)
        yield Span(line=fill, y=y, x_start=xl, x_end=xr + 1, value=fill_rgb)
        for row in (y + 1, y - 1):
            if not 0 <= row < region.height:
                continue
            lo, hi = (max(xl - 1, 0), min(xr + 1, region.width - 1)) if eight else (xl, xr)
            base = region.index(0, row)
            # The leftmost pixel of each run of free pixels in lo .. hi.
            seeds = [base + k for k in range(lo, hi + 1)
                     if cells[base + k] == target and (k == lo or cells[base + k - 1] != target)]
            # Pushed right to left, so the leftmost run is popped first.
            pending.extend(reversed(seeds))
            largest = max(largest, len(pending))
            yield Span(line=push, y=row, x_start=lo, x_end=hi + 1)
            if seeds:  # the size and the listing change with the pushes
                values = {"size": len(pending)}
                if pops <= DETAIL_POPS:
                    values["next"] = _entries(pending, True, region)
                yield Vars(line=push, values=values, pixel=(lo, row))
    yield Vars(line=at["done"], values={"filled": filled, "boundary": outline.count, "pops": pops,
                                        "runs": runs, "skipped": skipped, "largest": largest,
                                        "size": 0, "next": "(empty)"})


def _entries(pending, stack: bool, region) -> str:
    """The next few entries to come out, as text."""
    count = min(SHOWN_ENTRIES, len(pending))
    if not count:
        return "(empty)"
    picks = [pending[-1 - k] if stack else pending[k] for k in range(count)]
    text = " ".join(f"({x}, {y})" for x, y in map(region.pixel, picks))
    more = len(pending) - count
    return text + (f" +{more} more" if more else "")


# ---------------------------------------------------------------- explain
def fill_explain(trace, i):
    step = trace.step(i)
    kind = trace.code[step.line].text.strip()
    if isinstance(step.record, Span):
        return _span_explain(trace, i, step.record, kind)
    if step.pixel is None or i == 0:
        return []
    x, y = step.pixel
    if kind.startswith("fill p"):
        unfilled = _unfilled(trace, i)
        pushed = [(x + dx, y + dy) for dx, dy in
                  NEIGHBOURS[str(trace.start.constants["connectivity"])]
                  if 0 <= x + dx < trace.width and 0 <= y + dy < trace.height
                  and unfilled[y + dy, x + dx]]
        return [("pushed", " ".join(f"({a}, {b})" for a, b in pushed) or "none: no free neighbour")]
    if kind.startswith("if"):
        return [("skipped", f"({x}, {y}) was filled after it was pushed")]
    return []


def _unfilled(trace, i):
    """Where the fill may still spread at step ``i``: unwritten pixels, or
    the outline's pixels not yet recoloured when a region fill started on it."""
    raster = trace.raster_at(i)
    if trace.start.constants.get("spreads over") != "the outline":
        return raster.counts == 0
    boundary = _packed(trace.start.constants["boundary colour"])
    return (raster.counts == 1) & (raster.colors == boundary)


def _span_explain(trace, i, span, kind):
    if kind.startswith("widen"):
        return [("run", f"row {span.y}: x = {span.x_start} .. {span.x_end - 1}")]
    row = _unfilled(trace, i)[span.y]
    seeds = [x for x in range(span.x_start, span.x_end)
             if row[x] and (x == span.x_start or not row[x - 1])]
    return [("pushed", " ".join(f"({x}, {span.y})" for x in seeds) or "none: no free pixel")]


FLOOD_FILL = AlgorithmSpec(
    name="flood-fill",
    title="Seed fill",
    family="fill",
    summary="draw the outline, then grow a region from a seed pixel: stack, queue or spans",
    inputs=OUTLINE,
    options=(SEED, CONNECTIVITY, ORDER, MODE, OUTLINE_STEPS, COLORS),
    code=listing(fill_listing),
    generator=flood_fill,
    kernel=flood_fill_state,
    explain=fill_explain,
    uses_grid=True,
    notes=("A pixel is free when it lies inside the grid and is neither boundary nor "
           "filled. Only free pixels are pushed; a pixel pushed twice before it is filled "
           "is skipped the second time.",
           "The stack fills in exactly the order of the recursive fill, which calls "
           "itself on E, W, N, S (and the diagonals) in turn; the stack holds the calls "
           "still to come, so no recursion limit applies.",
           "An 8-connected fill slips through the diagonal steps of an 8-connected "
           "outline; draw the outline 4-connected (outline=4) to hold it.",
           "All three orders fill the same pixels: those joined to the seed by a path "
           "of free pixels.",
           "mode=region fills the pixels joined to the seed that have the seed's colour. "
           "With one boundary colour that is the boundary fill's region when the seed is "
           "inside; a seed on the outline recolours the outline's connected pixels instead."),
    oracle=Oracle(
        "exact",
        "The seed's 4- or 8-connected region, by a breadth-first search written in the tests and "
        "by scikit-image's flood, within an outline of exact nearest-pixel segments; every order "
        "fills the same pixels, none twice but outline pixels a region fill recolours.",
        ("algorithms/fill/test_fill.py", "algorithms/fill/test_fill_kernel.py",
         "algorithms/fill/test_fill_circle_region.py", "algorithms/test_stability.py"),
        check="seed-fill"),
)


FLOOD_FILL_CIRCLE = AlgorithmSpec(
    name="flood-fill-circle",
    title="Seed fill in a circle",
    family="fill",
    summary="draw a midpoint circle, then grow a region from a seed pixel: stack, queue or spans",
    inputs=CENTRE,
    options=(RADIUS, SEED, CONNECTIVITY, ORDER, MODE, OUTLINE_STEPS, COLORS),
    code=listing(circle_fill_listing),
    generator=circle_fill,
    kernel=circle_fill_state,
    explain=fill_explain,
    uses_grid=True,
    notes=("The outline is the midpoint circle of radius R around C. Its pixels step "
           "diagonally, so an 8-connected fill leaks out of it unless outline=4 adds a "
           "corner pixel at each diagonal step.",
           "seed=auto starts at the centre. A circle of radius 0 is its centre alone and "
           "has no inside: with seed=auto only that pixel is drawn.",
           "mode=region fills the pixels joined to the seed that have the seed's colour: "
           "inside the circle that is the same as mode=boundary, but a seed on the circle "
           "recolours the circle itself."),
    oracle=Oracle(
        "exact",
        "The seed's region by scikit-image's flood and a breadth-first search written in the "
        "tests, within the exact midpoint circle (algorithms/exact/circles.py).",
        ("algorithms/fill/test_fill_circle_region.py", "algorithms/test_stability.py"),
        check="seed-fill"),
)

# The module's algorithms, in the order they are listed.
SPECS = (FLOOD_FILL, FLOOD_FILL_CIRCLE)
