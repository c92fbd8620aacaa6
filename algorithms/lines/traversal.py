"""Grid traversal: the cells a segment with real end points meets.

Unlike the pixel-centre lines, these take real points in the plane, where
pixel (i, j) is the unit square [i, i+1) x [j, j+1), as triangles do (the
supercover can take closed cells [i, i+1] x [j, j+1] instead). All
tests are exact: the points are turned into Fractions (a float is a
fraction), so a segment through a cell corner is seen to pass through it.
"""
from __future__ import annotations

import math
from fractions import Fraction

from algorithms.core.code import Code, listing
from algorithms.core.registry import (MAX_INTEGER_COORDINATE, AlgorithmSpec, InputError, Inputs,
                                     Option, Oracle)
from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Note, Start

REAL_SEGMENT = Inputs(2, integer=False, names=("P", "Q"))
NOTHING = (math.nan, math.nan)


def _exact_points(points):
    """The end points as Fractions, refused beyond the frames' 32-bit cells."""
    exact = []
    for n, (x, y) in enumerate(points):
        if max(abs(x), abs(y)) > MAX_INTEGER_COORDINATE:
            raise InputError(f"point {n + 1}: beyond +-{MAX_INTEGER_COORDINATE:,} px")
        exact.append((Fraction(x), Fraction(y)))
    return exact


def _floor(value: Fraction) -> int:
    return value.numerator // value.denominator


# ------------------------------------------------------------- supercover
CELLS = Option("cells", "choice", "half-open",
               "half-open: pixel (i, j) is [i, i+1) x [j, j+1), so a point on a grid line "
               "belongs to the cell above or right of it; closed: [i, i+1] x [j, j+1], so "
               "every cell the segment touches, corners and edges included",
               choices=("half-open", "closed"))


def supercover_listing(points, options) -> Code:
    closed = options["cells"] == "closed"
    strip, cell = ("[c, c+1]", "[r, r+1]") if closed else ("[c, c+1)", "[r, r+1)")
    code = Code()
    code.add("setup", "dx = x1 - x0;  dy = y1 - y0   (exact fractions)", ops={"int_add": 2})
    code.add("column", f"for each column c whose strip {strip} the segment meets, P to Q:",
             ops={"compare": 2})
    code.add("range", "    [y_lo, y_hi] = the segment's y over that strip"
             + ("" if closed else "   (an end at x = c+1 left out)"),
             ops={"mul": 2, "div": 2, "float_add": 2, "compare": 2})
    code.add("plot_cell", f"    plot every row r with {cell} meeting [y_lo, y_hi]", PLOT,
             ops={"compare": 1})
    code.add("done", "done   (cells outside the grid are not plotted; a note counts them)")
    return code


def supercover(points, options, grid):
    """Column by column from P to Q: the segment's y-range over the column's
    strip, then every cell of the column that range meets. Cells are closed
    or half-open as the option says; cells outside the grid are counted and
    named in a note instead of plotted."""
    (x0, y0), (x1, y1) = _exact_points(points)
    at = supercover_listing(points, options).at
    closed = options["cells"] == "closed"
    yield Start(line=at["setup"], values=("y_lo", "y_hi"),
                constants={"dx": float(x1 - x0), "dy": float(y1 - y0), "cells": options["cells"]})
    outside = []
    for c, rows, y_lo, y_hi in _supercover_columns(x0, y0, x1, y1, closed):
        yield (at["column"], NO_PIXEL, NO_PIXEL, *NOTHING)
        yield (at["range"], NO_PIXEL, NO_PIXEL, float(y_lo), float(y_hi))
        for r in rows:
            if 0 <= c < grid[0] and 0 <= r < grid[1]:
                yield (at["plot_cell"], c, r, float(y_lo), float(y_hi))
            else:
                outside.append((c, r))
    if outside:
        yield Note(line=at["done"], text=_outside_note(outside, grid))
    yield (at["done"], NO_PIXEL, NO_PIXEL, *NOTHING)


def _outside_note(cells, grid) -> str:
    shown = ", ".join(f"({c}, {r})" for c, r in cells[:4]) + (", ..." if len(cells) > 4 else "")
    noun = "cell" if len(cells) == 1 else "cells"
    return (f"{len(cells)} {noun} the segment meets lie outside the {grid[0]} x {grid[1]} grid "
            f"and are not plotted: {shown}")


def _supercover_columns(x0, y0, x1, y1, closed):
    """(column, rows in order P to Q, y_lo, y_hi) for each column the segment meets."""
    lo, hi = min(x0, x1), max(x0, x1)
    first = math.ceil(lo) - 1 if closed else _floor(lo)
    columns = range(first, _floor(hi) + 1)
    for c in (reversed(columns) if x1 < x0 else columns):
        a, b = max(lo, Fraction(c)), min(hi, Fraction(c + 1))
        y_lo, y_hi = _strip_range(x0, y0, x1, y1, a, b)
        if closed:
            rows = range(math.ceil(y_lo) - 1, _floor(y_hi) + 1)
        else:
            rows = _half_open_rows(x0, y0, x1, y1, a, b, c + 1 <= hi)
        yield c, (rows if y1 >= y0 else reversed(rows)), y_lo, y_hi


def _half_open_rows(x0, y0, x1, y1, a, b, b_left_out):
    """The rows r whose [r, r+1) meets the segment's y over x in [a, b],
    or [a, b) when the point at x = b lies in the next column."""
    if x1 == x0:
        return range(_floor(min(y0, y1)), _floor(max(y0, y1)) + 1)
    ya, yb = (y0 + (y1 - y0) * (x - x0) / (x1 - x0) for x in (a, b))
    top = max(ya, yb)
    # The top y is not reached when it is the left-out end (and the y's differ).
    top_left_out = b_left_out and yb > ya
    last = math.ceil(top) - 1 if top_left_out else _floor(top)
    return range(_floor(min(ya, yb)), last + 1)


def _strip_range(x0, y0, x1, y1, a, b):
    """The segment's y from x = a to x = b (the whole y extent when vertical)."""
    if x1 == x0:
        return min(y0, y1), max(y0, y1)
    ya = y0 + (y1 - y0) * (a - x0) / (x1 - x0)
    yb = y0 + (y1 - y0) * (b - x0) / (x1 - x0)
    return min(ya, yb), max(ya, yb)


LINE_SUPERCOVER = AlgorithmSpec(
    name="line-supercover",
    title="Supercover",
    family="lines",
    summary="every cell the segment meets (real end points); cells half-open or closed",
    inputs=REAL_SEGMENT,
    options=(CELLS,),
    code=listing(supercover_listing),
    generator=supercover,
    uses_grid=True,
    notes=("Points are real. With cells half-open (the default, the convention of the "
           "triangles), pixel (i, j) is the square [i, i+1) x [j, j+1): a segment through a "
           "cell corner takes the cells it passes into, and one along a grid line takes the "
           "row above it only.",
           "With cells closed, [i, i+1] x [j, j+1], a segment through a corner takes all four "
           "cells around it and one along a grid line takes both rows beside it, so a segment "
           "from the grid's corner (0, 0) also touches cells at -1.",
           "Cells outside the grid are not plotted: a note at the end names and counts them."),
    oracle=Oracle(
        "exact",
        "Every cell the segment meets, each once, half-open or closed as the option says: exact "
        "Liang-Barsky clipping of the segment against each cell (open faces strict), in "
        "Fractions written in the test; cells outside the grid left out and counted.",
        ("algorithms/lines/test_line_traversal.py",)),
)


# -------------------------------------------------------- Amanatides-Woo
def woo_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "cell = floor(P);  step = sign(Q - P);  tDelta = 1 / |Q - P| per axis",
             ops={"int_add": 2, "round": 2, "div": 2, "compare": 2})
    code.add("plot_first", "tMaxX, tMaxY = t at the first vertical, horizontal grid line;  "
                           "plot(cell)", PLOT, ops={"div": 2, "float_add": 2})
    code.add("loop", "repeat |floor(Q) - floor(P)| (x plus y) times:   (an axis is done at "
                     "floor(Q))")
    code.add("plot_x", "    if y is done or (x is not done and tMaxX < tMaxY):  cell.x += step.x;  tMaxX += tDeltaX;  plot(cell)",
             PLOT, "x", ops={"compare": 2, "float_add": 1, "int_add": 1})
    code.add("plot_y", "    else:  cell.y += step.y;  tMaxY += tDeltaY;  plot(cell)   "
                       "(a corner: y first)", PLOT, "y", ops={"compare": 2, "float_add": 1,
                                                               "int_add": 1})
    code.add("done", "done")
    return code


def _axis(a0, a1):
    """(cell, step, tMax, tDelta) along one axis; tMax None when it never moves."""
    cell = _floor(a0)
    if a1 == a0:
        return cell, 0, None, None
    step = 1 if a1 > a0 else -1
    boundary = cell + 1 if step > 0 else cell
    return cell, step, (boundary - a0) / (a1 - a0), 1 / abs(a1 - a0)


def _shown(t) -> float:
    """An exact tMax as the panel shows it: NaN for an axis never crossed,
    infinity for one beyond any float (a sub-normal step along the axis)."""
    if t is None:
        return math.nan
    try:
        return float(t)
    except OverflowError:
        return math.inf


def woo(points, options):
    """Amanatides and Woo's traversal: always cross the nearer grid line.
    Each frame carries tMaxX and tMaxY, the t of the next crossings (NaN on
    an axis the segment never crosses)."""
    (x0, y0), (x1, y1) = _exact_points(points)
    at = woo_listing(points, options).at
    cx, sx, tx, dtx = _axis(x0, x1)
    cy, sy, ty, dty = _axis(y0, y1)
    count = abs(_floor(x1) - cx) + abs(_floor(y1) - cy)
    yield Start(line=at["setup"], values=("tMaxX", "tMaxY"),
                constants={"steps": count, "stepX": sx, "stepY": sy})

    def values():
        return _shown(tx), _shown(ty)

    yield (at["plot_first"], cx, cy, *values())
    end_x, end_y = _floor(x1), _floor(y1)
    for _ in range(count):
        # An axis already at Q's cell stops: an end point on a grid line
        # belongs to the cell above or right of it, so a crossing at t = 1
        # is taken only towards that cell.
        if cy == end_y or (cx != end_x and tx < ty):
            cx, tx = cx + sx, tx + dtx
            yield (at["plot_x"], cx, cy, *values())
        else:
            cy, ty = cy + sy, ty + dty
            yield (at["plot_y"], cx, cy, *values())
    yield (at["done"], NO_PIXEL, NO_PIXEL, *values())


LINE_AMANATIDES_WOO = AlgorithmSpec(
    name="line-amanatides-woo",
    title="Amanatides-Woo traversal",
    family="lines",
    summary="walk the cells a ray passes through, crossing the nearer grid line each time",
    inputs=REAL_SEGMENT,
    options=(),
    code=listing(woo_listing),
    generator=woo,
    notes=("A 4-connected walk: where the segment passes exactly through a corner it steps "
           "in y first, so it takes one of the two side cells the supercover takes both of.",
           "Points are real; pixel (i, j) is the square [i, i+1) x [j, j+1)."),
    oracle=Oracle(
        "exact",
        "A 4-connected walk from P's cell to Q's, one step per grid line crossed, holding every "
        "cell whose inside the segment crosses and none it misses (exact clipping in Fractions "
        "written in the test); at a corner, either side cell.",
        ("algorithms/lines/test_line_traversal.py",)),
)


# ------------------------------------------------------ diamond exit rule
def diamond_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "the diamond of pixel (i, j): |x - (i + 1/2)| + |y - (j + 1/2)| < 1/2, "
                      "and its lower-left edge")
    code.add("visit", "for each cell the segment touches, P to Q:  L1 = the segment's least "
                      "|x - cx| + |y - cy|", VISIT, ops={"float_add": 4, "compare": 4})
    code.add("plot_exit", "    if (L1 < 1/2 or the segment meets the lower-left edge) and Q is "
                          "not in the diamond:  plot   (it leaves the diamond)", PLOT,
             ops={"compare": 2})
    code.add("done", "done")
    return code


def l1_to_segment(p, q, cx, cy) -> Fraction:
    """The least |x - cx| + |y - cy| over the segment, exactly. The sum is
    linear in t between the t where x = cx or y = cy, so its minimum is at
    an end or at one of those."""
    (x0, y0), (x1, y1) = p, q
    ts = [Fraction(0), Fraction(1)]
    if x1 != x0:
        ts.append((cx - x0) / (x1 - x0))
    if y1 != y0:
        ts.append((cy - y0) / (y1 - y0))
    return min(abs(x0 + (x1 - x0) * t - cx) + abs(y0 + (y1 - y0) * t - cy)
               for t in ts if 0 <= t <= 1)


HALF = Fraction(1, 2)


def _cross(o, a, b) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def meets_segment(p, q, a, b) -> bool:
    """Do the closed segments PQ and AB share a point? (exact)"""
    d1, d2, d3, d4 = _cross(a, b, p), _cross(a, b, q), _cross(p, q, a), _cross(p, q, b)
    if ((d1 > 0) != (d2 > 0) and d1 and d2) and ((d3 > 0) != (d4 > 0) and d3 and d4):
        return True

    def on(o, u, v, d):  # u lies on the segment o-v, given d = cross(o, v, u) = 0
        return d == 0 and min(o[0], v[0]) <= u[0] <= max(o[0], v[0]) and \
            min(o[1], v[1]) <= u[1] <= max(o[1], v[1])
    return on(a, p, b, d1) or on(a, q, b, d2) or on(p, a, q, d3) or on(p, b, q, d4)


def in_diamond(point, cx, cy) -> bool:
    """Inside the open diamond, or on its lower-left edge (corners included)."""
    dx, dy = point[0] - cx, point[1] - cy
    return abs(dx) + abs(dy) < HALF or (dx <= 0 and dy <= 0 and dx + dy == -HALF)


def diamond(points, options):
    """The hardware rule: a pixel is drawn when the segment leaves its
    diamond, so of two lines joined end to end the shared pixel is drawn once."""
    p, q = _exact_points(points)
    at = diamond_listing(points, options).at
    yield Start(line=at["setup"], values=("L1",))
    candidates = ((c, r) for c, rows, _, _ in _supercover_columns(*p, *q, closed=True) for r in rows)
    for i, j in candidates:
        cx, cy = i + HALF, j + HALF
        distance = l1_to_segment(p, q, cx, cy)
        yield (at["visit"], i, j, float(distance))
        # The lower-left edge belongs to the diamond, so a line through a
        # diamond's corner is not lost between two pixels.
        meets = distance < HALF or meets_segment(p, q, (cx - HALF, cy), (cx, cy - HALF))
        if meets and not in_diamond(q, cx, cy):
            yield (at["plot_exit"], i, j, float(distance))
    yield (at["done"], NO_PIXEL, NO_PIXEL, math.nan)


LINE_DIAMOND_EXIT = AlgorithmSpec(
    name="line-diamond-exit",
    title="Diamond-exit rule",
    family="lines",
    summary="draw a pixel when the segment leaves the diamond around its centre (GPU lines)",
    inputs=REAL_SEGMENT,
    options=(),
    code=listing(diamond_listing),
    generator=diamond,
    step_seconds=6e-4,  # exact diamond tests in Fractions: about 300 us a step
    notes=("The rule of OpenGL and Direct3D lines: the diamond |x - cx| + |y - cy| < 1/2 "
           "around each pixel centre; a pixel is drawn when the segment meets it and does not "
           "end inside it.",
           "The diamond is half-open, as the fill rule is: its lower-left edge and the two "
           "corners at its ends belong to it, the other edges and corners do not, so a line "
           "through a corner takes exactly one of the two pixels that meet there.",
           "The last pixel is left out when Q lies in its diamond, so a strip of segments "
           "draws each shared pixel once.",
           "Candidates are the closed supercover's cells, which hold every diamond the segment meets."),
    oracle=Oracle(
        "exact",
        "The cells whose diamond the segment meets, but Q's, each once: the diamond-exit rule "
        "clipped exactly in Fractions (in u = x + y, v = x - y) in the test.",
        ("algorithms/lines/test_line_traversal.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (LINE_SUPERCOVER, LINE_AMANATIDES_WOO, LINE_DIAMOND_EXIT)
