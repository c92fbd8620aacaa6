"""The fill family: seed fill inside an outline drawn on the grid.

The input is one or more closed outlines of integer points (the last point
joins the first). Each segment is drawn with integer rounding, as Bresenham
draws it, in the boundary colour; then the region around a seed pixel is
filled in the fill colour, bounded by the outline and by the grid's edges.
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
from fractions import Fraction

from .registry import AlgorithmSpec, InputError, Inputs, Option, register
from .steps import PER_PIXEL, PLOT, VISIT, CodeLine, Note, Span, Start, Vars

NAN = math.nan

OUTLINE = Inputs(3, integer=True, contours=True)

NEIGHBOURS = {
    "4": ((1, 0), (-1, 0), (0, 1), (0, -1)),
    "8": ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, 1), (-1, -1), (1, -1)),
}
NEIGHBOUR_NAMES = "E, W, N, S"
DIAGONAL_NAMES = ", NE, NW, SW, SE"

# Pops up to this many show the stack's first entries in the panel; past it
# only its size is kept, so a million-pixel fill stays small.
DETAIL_POPS = 10_000
SHOWN_ENTRIES = 5

FREE, BOUNDARY, FILLED, WALL = 0, 1, 2, 3

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
    pixels = {}
    for contour in contours:
        for k, p in enumerate(contour):
            path = segment_pixels(p, contour[(k + 1) % len(contour)])
            for a, b in zip(path, path[1:] + path[-1:]):
                pixels[a] = True
                if four and a[0] != b[0] and a[1] != b[1]:
                    # Step across first, then along: the corner closes the
                    # diagonal that an 8-connected fill would slip through.
                    pixels[(b[0], a[1])] = True
    return list(pixels)


def inside_pixel(contours, free) -> tuple[int, int] | None:
    """A free pixel whose centre is inside the outlines (even-odd), or None.

    Inside counts crossings of all contours, so a hole is outside. Rows are
    tried from the first contour's mean row outwards, and in a row the pixel
    nearest its mean column wins; ``free(x, y)`` says whether a pixel may be
    filled.
    """
    xs, ys = [p[0] for p in contours[0]], [p[1] for p in contours[0]]
    middle_x, middle_y = sum(xs) / len(xs), round(sum(ys) / len(ys))
    for y in sorted(range(min(ys), max(ys) + 1), key=lambda y: (abs(y - middle_y), y)):
        crossings = sorted(c for contour in contours for c in _crossings(contour, y))
        # Pixel centres strictly between two crossings are inside.
        inside = [x for lo, hi in zip(crossings[::2], crossings[1::2])
                  for x in range(math.floor(lo) + 1, math.ceil(hi)) if free(x, y)]
        if inside:
            return min(inside, key=lambda x: (abs(x - middle_x), x)), y
    return None


def _crossings(contour, y):
    """x where the horizontal line through y crosses the contour's edges.

    An edge counts when one end is above y and the other is not, so a vertex
    on the line is counted once.
    """
    for k, (ax, ay) in enumerate(contour):
        bx, by = contour[(k + 1) % len(contour)]
        if (ay > y) != (by > y):
            yield ax + Fraction((y - ay) * (bx - ax), by - ay)


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


def _seed(options, contours, region) -> tuple[int, int]:
    seed = options["seed"]
    if seed == "auto":
        found = inside_pixel(contours, region.free)
        if found is None:
            raise InputError("flood-fill: no free pixel lies inside the outline; "
                             "give a seed with seed=X,Y")
        return found
    x, y = seed
    if not region.inside(x, y):
        raise InputError(f"flood-fill: the seed ({x}, {y}) lies outside the "
                         f"{region.width}x{region.height} grid")
    if region.cells[region.index(x, y)] == BOUNDARY:
        raise InputError(f"flood-fill: the seed ({x}, {y}) lies on the boundary; "
                         "pick a pixel inside the outline")
    return x, y


def _neighbour_names(options) -> str:
    return NEIGHBOUR_NAMES + (DIAGONAL_NAMES if options["connectivity"] == "8" else "")


# ------------------------------------------------------------ pseudo-code
def fill_code(points, options):
    outline = ("draw each outline segment, closing each outline (8-connected, as Bresenham)"
               if options["outline"] == "8" else
               "draw each outline segment, closing each outline, with a corner pixel at each "
               "diagonal step (4-connected)")
    names = _neighbour_names(options)
    # Operation counts. An outline pixel costs what a Bresenham step does.
    # Every pixel pushed is popped once, so a push (one addition to the
    # stack pointer) is counted with its pop; a pop is an addition and the
    # loop's emptiness test. pixels_tested counts reads of a pixel's state.
    outline_ops = {"int_add": 3, "compare": 2}
    pop = {"int_add": 2, "compare": 1}
    if options["order"] == "span":
        # The "filled already" test runs at every pop; its line has a frame
        # only when it skips, so the test is counted on the pop's line.
        return (
            CodeLine(outline, PLOT, ops=outline_ops),
            CodeLine("push(seed)"),
            CodeLine("while the stack is not empty:"),
            CodeLine("    (x, y) = pop()", VISIT,
                     ops={"int_add": 2, "compare": 2, "pixels_tested": 1}),
            CodeLine("    if (x, y) is filled already:  continue", VISIT),
            CodeLine("    widen x to the run xl .. xr of free pixels on row y;  fill xl .. xr", PLOT,
                     ops={"compare": 2, "pixels_tested": 2},
                     per={PER_PIXEL: {"int_add": 1, "compare": 1, "pixels_tested": 1}}),
            CodeLine("    for the rows y + 1 and y - 1, over " +
                     ("xl - 1 .. xr + 1" if options["connectivity"] == "8" else "xl .. xr") +
                     ":  push the leftmost pixel of each run of free pixels", VISIT,
                     ops={"compare": 1},
                     per={PER_PIXEL: {"int_add": 1, "compare": 2, "pixels_tested": 1}}),
            CodeLine("done"),
        )
    take = ("pop()   (the top: last pushed, first out)" if options["order"] == "stack"
            else "take()   (the front: first pushed, first out)")
    container = "stack" if options["order"] == "stack" else "queue"
    push = (f"push the free neighbours among {names}, in reverse, so {names.split(',')[0]} "
            f"comes out first" if options["order"] == "stack"
            else f"push the free neighbours among {names}")
    # The pop of line 3 has a frame only for the first pops (its panel
    # detail); every pop ends on line 4 or 5, so it is counted there. A
    # fill reads each neighbour's state (an address addition and a test).
    k = len(NEIGHBOURS[options["connectivity"]])
    return (
        CodeLine(outline, PLOT, ops=outline_ops),
        CodeLine("push(seed)"),
        CodeLine(f"while the {container} is not empty:"),
        CodeLine(f"    p = {take}", VISIT),
        CodeLine("    if p is filled already:  continue   (pushed twice before it was filled)", VISIT,
                 ops={"int_add": pop["int_add"], "compare": pop["compare"] + 1,
                      "pixels_tested": 1}),
        CodeLine(f"    fill p;  {push}   (free: inside the grid, not boundary, not filled)", PLOT,
                 ops={"int_add": pop["int_add"] + k, "compare": pop["compare"] + 1 + k,
                      "pixels_tested": 1 + k}),
        CodeLine("done"),
    )


# -------------------------------------------------------------- generator
def flood_fill(points, options, grid):
    """Check the inputs, then return the frame generator.

    The checks run here, before the first frame, so a bad seed is an
    InputError at once.
    """
    width, height = grid
    boundary_color, fill_color = _colors(options)
    outline = outline_pixels(points, four=options["outline"] == "4")
    region = Region(width, height, outline)
    seed = _seed(options, points, region)
    start = Start(0, ("rgb", "size"),
                  {"seed": seed, "connectivity": int(options["connectivity"]),
                   "order": options["order"], "grid": f"{width}x{height}",
                   "boundary colour": boundary_color, "fill colour": fill_color},
                  pixel_value="rgb")
    run = _span_frames if options["order"] == "span" else _pixel_frames
    return run(start, outline, region, seed, options, _packed(boundary_color), _packed(fill_color))


def _outline_frames(outline, boundary_rgb, *size):
    for x, y in outline:
        yield (0, x, y, boundary_rgb, *size)


def _pixel_frames(start, outline, region, seed, options, boundary_rgb, fill_rgb):
    """Stack or queue order: one pixel per pop."""
    yield start
    yield from _outline_frames(outline, boundary_rgb, 0)
    cells = region.cells
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
    first = region.index(*seed)
    push(first)
    yield (1, seed[0], seed[1], NAN, 1)
    filled = skipped = 0
    largest = 1
    # The first pops show the next entries in the panel.
    while pending and filled + skipped < DETAIL_POPS:
        p = take()
        x, y = region.pixel(p)
        yield Vars(3, {"size": len(pending), "next": _entries(pending, stack, region)}, (x, y))
        if cells[p] != FREE:
            skipped += 1
            yield (4, x, y, NAN, len(pending))
            continue
        cells[p] = FILLED
        filled += 1
        for offset in offsets:
            if cells[p + offset] == FREE:
                push(p + offset)
        largest = max(largest, len(pending))
        yield (5, x, y, fill_rgb, len(pending))
    if pending:
        x, y = region.pixel(pending[-1] if stack else pending[0])
        yield Note(3, f"From here on the panel keeps only the size of the "
                      f"{'stack' if stack else 'queue'}; its entries are listed for the "
                      f"first {DETAIL_POPS:,} pops.", (x, y))
    # The same loop without the panel's entries, kept lean for large regions.
    stride = region.stride
    while pending:
        p = take()
        y, x = divmod(p, stride)
        if cells[p]:  # not FREE (0)
            skipped += 1
            yield (4, x - 1, y - 1, NAN, len(pending))
            continue
        cells[p] = FILLED
        filled += 1
        for offset in offsets:
            if not cells[p + offset]:
                push(p + offset)
        size = len(pending)
        if size > largest:
            largest = size
        yield (5, x - 1, y - 1, fill_rgb, size)
    pops = filled + skipped
    yield Vars(6, {"filled": filled, "boundary": len(outline), "pops": pops,
                   "skipped": skipped, "largest": largest, "next": "(empty)"})


def _span_frames(start, outline, region, seed, options, boundary_rgb, fill_rgb):
    """Scan-line seed fill: a run of free pixels per pop.

    Frames are few here (one per run), so the stack's size goes into a Vars
    record at every pop rather than into a value of every frame.
    """
    yield Start(start.line, ("rgb",), start.constants, start.pixel_value)
    yield from _outline_frames(outline, boundary_rgb)
    cells = region.cells
    eight = options["connectivity"] == "8"
    pending = [region.index(*seed)]
    yield Vars(1, {"size": 1, "next": f"({seed[0]}, {seed[1]})"}, seed)
    pops = skipped = filled = runs = 0
    largest = 1
    while pending:
        p = pending.pop()
        pops += 1
        x, y = region.pixel(p)
        values = {"size": len(pending)}
        if pops <= DETAIL_POPS:
            values["next"] = _entries(pending, True, region)
        yield Vars(3, values, (x, y))
        if cells[p] != FREE:
            skipped += 1
            yield (4, x, y, NAN)
            continue
        left = right = p
        while cells[left - 1] == FREE:
            left -= 1
        while cells[right + 1] == FREE:
            right += 1
        cells[left:right + 1] = bytes([FILLED]) * (right - left + 1)
        filled += right - left + 1
        runs += 1
        xl, xr = x - (p - left), x + (right - p)
        yield Span(5, y, xl, xr + 1, fill_rgb)
        for row in (y + 1, y - 1):
            if not 0 <= row < region.height:
                continue
            lo, hi = (max(xl - 1, 0), min(xr + 1, region.width - 1)) if eight else (xl, xr)
            base = region.index(0, row)
            # The leftmost pixel of each run of free pixels in lo .. hi.
            seeds = [base + k for k in range(lo, hi + 1)
                     if cells[base + k] == FREE and (k == lo or cells[base + k - 1] != FREE)]
            # Pushed right to left, so the leftmost run is popped first.
            pending.extend(reversed(seeds))
            largest = max(largest, len(pending))
            yield Span(6, row, lo, hi + 1)
    yield Vars(7, {"filled": filled, "boundary": len(outline), "pops": pops, "runs": runs,
                   "skipped": skipped, "largest": largest, "size": 0, "next": "(empty)"})


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
        raster = trace.raster_at(i)
        pushed = [(x + dx, y + dy) for dx, dy in
                  NEIGHBOURS[str(trace.start.constants["connectivity"])]
                  if 0 <= x + dx < trace.width and 0 <= y + dy < trace.height
                  and raster.counts[y + dy, x + dx] == 0]
        return [("pushed", " ".join(f"({a}, {b})" for a, b in pushed) or "none: no free neighbour")]
    if kind.startswith("if"):
        return [("skipped", f"({x}, {y}) was filled after it was pushed")]
    return []


def _span_explain(trace, i, span, kind):
    if kind.startswith("widen"):
        return [("run", f"row {span.y}: x = {span.x_start} .. {span.x_end - 1}")]
    raster = trace.raster_at(i)
    row = raster.counts[span.y]
    seeds = [x for x in range(span.x_start, span.x_end)
             if row[x] == 0 and (x == span.x_start or row[x - 1] != 0)]
    return [("pushed", " ".join(f"({x}, {span.y})" for x in seeds) or "none: no free pixel")]


register(AlgorithmSpec(
    name="flood-fill",
    title="Seed fill",
    family="fill",
    summary="draw the outline, then grow a region from a seed pixel: stack, queue or spans",
    inputs=OUTLINE,
    options=(SEED, CONNECTIVITY, ORDER, OUTLINE_STEPS, COLORS),
    code=fill_code,
    generator=flood_fill,
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
           "of free pixels."),
))
