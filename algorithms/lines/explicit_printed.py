"""The explicit form as one lecture prints it under Bresenham's name.

The listing splits on the signs of rise and run and on which is larger, and
evaluates y = (rise/run) x + c (or x = (run/rise) y + b) in each column (or
row). Ported as printed, in C's integers: rise/run divides in integers and
truncates toward zero, so a shallow line's slope is 0 and it comes out flat,
and a steep one's is 0 too (a vertical line) unless run = rise. The loops
count up with '<', so Q is never drawn, and the branch for rise < 0 with a
steep line counts y up from y0 to y1 < y0 and never runs. The slide ends with
"&c." where run <= 0 would be: nothing is drawn there. The corrected form is
line-explicit.
"""
from __future__ import annotations

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, Start, Vars
from .common import NAN, SEGMENT
from .forms import explicit_pixels


def c_divide(a: int, b: int) -> int:
    """a / b on C's ints: the quotient truncated toward zero."""
    quotient = abs(a) // abs(b)
    return quotient if (a >= 0) == (b > 0) else -quotient


def explicit_printed_listing(points, options) -> Code:
    body = {"mul": 1, "int_add": 2, "div": 1, "compare": 1}
    code = Code()
    code.add("setup", "rise = y1 - y0;  run = x1 - x0   (ints: rise/run divides in integers)",
             ops={"int_add": 2})
    code.add("shallow_up", "if run > 0, rise > 0, run > rise:", branch="shallow, rising",
             ops={"compare": 3})
    code.add("plot_shallow_up", "    for (x = x0; x < x1; x++)  y = (rise/run)*x + c;  "
                                "setPixel(x, y)   (rise/run is 0 here: flat; x < x1 leaves Q out)",
             PLOT, ops=body)
    code.add("steep_up", "if run > 0, rise > 0, run <= rise:", branch="steep, rising",
             ops={"compare": 3})
    code.add("plot_steep_up", "    for (y = y0; y < y1; y++)  x = (run/rise)*y + b;  "
                              "setPixel(x, y)   (run/rise is 0 unless run = rise: vertical)",
             PLOT, ops=body)
    code.add("shallow_down", "if run > 0, rise <= 0, run > -rise:", branch="shallow, falling",
             ops={"compare": 3})
    code.add("plot_shallow_down", "    for (x = x0; x < x1; x++)  y = (rise/run)*x + c;  "
                                  "setPixel(x, y)   (rise/run is 0 here too: flat)", PLOT, ops=body)
    code.add("steep_down", "if run > 0, rise <= 0, run <= -rise:   (as printed: the loop below "
                           "counts y up to y1 < y0, so it never runs)", branch="steep, falling",
             ops={"compare": 3})
    code.add("plot_steep_down", "    for (y = y0; y < y1; y++)  x = (run/rise)*y + b;  "
                                "setPixel(x, y)", PLOT, ops=body)
    code.add("other", "run <= 0:  '&c.'   (not printed: nothing is drawn)", branch="not printed")
    code.add("done", "done   (c and b are not given: taken as y0 - (rise/run)*x0 and "
                     "x0 - (run/rise)*y0, so the line starts at P)")
    return code


def _branch(rise: int, run: int) -> str:
    if run <= 0:
        return "other"
    if rise > 0:
        return "shallow_up" if run > rise else "steep_up"
    return "shallow_down" if run > -rise else "steep_down"


def _pixels(points, branch):
    """(x, y, quotient, intercept) of each setPixel the printed branch runs."""
    (x0, y0), (x1, y1) = points
    rise, run = y1 - y0, x1 - x0
    if branch in ("shallow_up", "shallow_down"):
        m = c_divide(rise, run)
        c = y0 - m * x0
        return [(x, m * x + c, m, c) for x in range(x0, x1)]
    if branch in ("steep_up", "steep_down"):
        n = c_divide(run, rise)
        b = x0 - n * y0
        return [(n * y + b, y, n, b) for y in range(y0, y1)]
    return []


def explicit_printed(points, options):
    """Start, the branch taken, then one frame per setPixel with the
    integer quotient and the intercept."""
    (x0, y0), (x1, y1) = points
    branch = _branch(y1 - y0, x1 - x0)
    at = explicit_printed_listing(points, options).at
    yield Start(line=at["setup"], values=("quotient", "intercept"),
                constants={"rise": y1 - y0, "run": x1 - x0, "branch": branch})
    yield (at[branch], NO_PIXEL, NO_PIXEL, NAN, NAN)
    written = _pixels(points, branch)
    for x, y, quotient, intercept in written:
        yield (at["plot_" + branch], x, y, float(quotient), float(intercept))
    corrected = {tuple(p) for p in explicit_pixels(points, {}).tolist()}
    drawn = {(x, y) for x, y, _, _ in written}
    yield Vars(line=at["done"], values={
        "pixels": len(written), "Q_plotted": "yes" if (x1, y1) in drawn else "no",
        "off_corrected": len(drawn - corrected), "missing": len(corrected - drawn)})


LINE_EXPLICIT_PRINTED = AlgorithmSpec(
    name="line-explicit-printed",
    title="Explicit form, as printed",
    family="lines",
    summary="the slide titled Bresenham: y = (rise/run) x + c in C's integers, so shallow "
            "lines come out flat",
    inputs=SEGMENT,
    options=(),
    code=listing(explicit_printed_listing),
    generator=explicit_printed,
    notes=("The slide's title says Bresenham, but its code is the explicit form split into "
           "cases; line-explicit is the corrected form.",
           "rise and run are ints, so rise/run truncates: below 45 degrees it is 0 and the line "
           "is drawn flat along P's row; above, run/rise is 0 and the line is vertical; only "
           "exact diagonals come out right.",
           "The loops stop before x1 (or y1), so Q is never drawn; with rise < 0 and a steep "
           "line the loop counts y up from y0 towards a smaller y1 and never runs; for "
           "run <= 0 the slide says only '&c.', and nothing is drawn.",
           "off_corrected and missing compare the pixels with line-explicit's."),
    oracle=Oracle(
        "exact",
        "The slide's listing ported in the test with C's truncating integer division, on "
        "random and hard segments; its pixels against the nearest-pixel line counted.",
        ("algorithms/lines/test_line_explicit_printed.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (LINE_EXPLICIT_PRINTED,)
