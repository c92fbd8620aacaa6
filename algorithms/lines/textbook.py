"""Line code as the lecture notes print it, beside the corrected forms.

Each variant reproduces one printed listing or rule on purpose, faults
included, so a class can see what the fault does: the DDA that truncates,
that always steps in x, that adds the slope before it writes, or that steps
in x and truncates, Bresenham with ties sent to NE, the sign-reversed
formulation (with the printed initial value and with the corrected one), and
the midpoint line derived from the implicit form. The plain, corrected
algorithms are line-dda and line-bresenham.
"""
from __future__ import annotations

import math
from itertools import chain

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Start, Vars
from .bresenham import bresenham_pixels
from .common import COLORS, NAN, SEGMENT, Octant, color_ramp, colored, round_half_up, with_color


# ------------------------------------------------------- DDA as printed
DDA_VARIANTS = ("truncate", "x-only", "add-first", "x-truncate")


def dda_printed_listing(points, options) -> Code:
    code = Code()
    if options["variant"] == "truncate":
        code.add("setup", "dx = x2 - x1;  dy = y2 - y1;  steps = max(|dx|, |dy|);  "
                          "x_inc = dx / steps;  y_inc = dy / steps",
                 ops={"int_add": 2, "compare": 3, "div": 2})
        code.add("plot_first", "x = x1;  y = y1;  DisplayPixel(x1, y1)", PLOT)
        code.add("loop", "for k = 1 .. steps:")
        code.add("plot_step", "    x += x_inc;  y += y_inc;  DisplayPixel((int) x, (int) y)   "
                              "(the cast truncates toward zero)", PLOT,
                 ops={"float_add": 2, "round": 2, "int_add": 1, "compare": 1})
    elif options["variant"] == "x-only":
        code.add("setup", "m = (y2 - y1) / (x2 - x1)  (0 when x1 = x2);  y = y1",
                 ops={"int_add": 2, "div": 1})
        code.add("loop", "for i = x1 .. x2:   (always along x, whatever the slope)")
        code.add("plot_step", "    write_pixel(i, round(y));  y += m", PLOT,
                 ops={"float_add": 1, "round": 1, "int_add": 1, "compare": 1})
    elif options["variant"] == "add-first":
        code.add("setup", "m = (y2 - y1) / (x2 - x1)  (0 when x1 = x2);  y = y1",
                 ops={"int_add": 2, "div": 1})
        code.add("loop", "for (i = x1; i <= x2; i++)   (counts up only: nothing when x2 < x1)")
        code.add("plot_step", "    y += m;  write_pixel(i, round(y))   (as printed: adds before "
                              "it writes, so every pixel is one step of m late)", PLOT,
                 ops={"float_add": 1, "round": 1, "int_add": 1, "compare": 1})
    else:
        code.add("setup", "dx = x2 - x1;  dy = y2 - y1;  m = dy / (float) dx;  x = x1;  y = y1",
                 ops={"int_add": 2, "div": 1})
        code.add("plot_first", "DisplayPixel(x1, y1)", PLOT)
        code.add("loop", "for k = 1 .. dx:   (counts up only: P alone when x2 <= x1)")
        code.add("plot_step", "    x += 1;  y += m;  DisplayPixel(x, y)   (the float y is cut "
                              "to an int: truncated toward zero; x-only for every slope)", PLOT,
                 ops={"float_add": 1, "round": 1, "int_add": 2, "compare": 1})
    code.add("done", "done")
    return code


def dda_printed(points, options):
    """Start, then one frame per pixel with the real accumulators x, y."""
    ramp = color_ramp(options)
    at = dda_printed_listing(points, options).at
    (x1, y1), (x2, y2) = points
    if options["variant"] == "truncate":
        steps = max(abs(x2 - x1), abs(y2 - y1))
        frames = _truncate_frames(points, steps, at)
        constants = {"dx": x2 - x1, "dy": y2 - y1, "steps": steps}
    else:
        steps = abs(x2 - x1) if options["variant"] == "x-only" else max(0, x2 - x1)
        m = (y2 - y1) / (x2 - x1) if x2 != x1 else 0.0
        frames = _X_FRAMES[options["variant"]](points, m, at)
        constants = {"dx": x2 - x1, "dy": y2 - y1, "m": m, "rows_missed": _rows_missed(points)}
    constants["variant"] = options["variant"]
    start = Start(line=at["setup"], values=with_color(ramp, ("x", "y")), constants=constants,
                  pixel_value="rgb" if ramp else None)
    return chain((start,), colored(frames, ramp, steps) if ramp else frames)


def _truncate_frames(points, steps, at):
    (x1, y1), (x2, y2) = points
    x_inc = (x2 - x1) / steps if steps else 0.0
    y_inc = (y2 - y1) / steps if steps else 0.0
    x, y = float(x1), float(y1)
    yield (at["plot_first"], x1, y1, x, y)
    step = at["plot_step"]
    for _ in range(steps):
        x += x_inc
        y += y_inc
        yield (step, math.trunc(x), math.trunc(y), x, y)
    yield (at["done"], NO_PIXEL, NO_PIXEL, x, y)


def _x_only_frames(points, m, at):
    (x1, y1), (x2, _) = points
    direction = 1 if x2 >= x1 else -1
    y = float(y1)
    step = at["plot_step"]
    for i in range(x1, x2 + direction, direction):
        yield (step, i, round_half_up(y), float(i), y)
        y += m * direction
    yield (at["done"], NO_PIXEL, NO_PIXEL, float(x2), y)


def _add_first_frames(points, m, at):
    """002's loop as printed: for i = x1 .. x2 (upward only), y += m, then write."""
    (x1, y1), (x2, _) = points
    y = float(y1)
    step = at["plot_step"]
    for i in range(x1, x2 + 1):
        y += m
        yield (step, i, round_half_away(y), float(i), y)
    yield (at["done"], NO_PIXEL, NO_PIXEL, float(max(x1, x2)), y)


def _x_truncate_frames(points, m, at):
    """000's LineDDA as printed: P, then dx steps of x += 1, y += m, the
    float y cut to an int (toward zero); no steps when x2 <= x1."""
    (x1, y1), (x2, _) = points
    x, y = x1, float(y1)
    yield (at["plot_first"], x1, y1, float(x), y)
    step = at["plot_step"]
    for _ in range(x2 - x1):
        x += 1
        y += m
        yield (step, x, math.trunc(y), float(x), y)
    yield (at["done"], NO_PIXEL, NO_PIXEL, float(x), y)


def round_half_away(value: float) -> int:
    """C's round(): the nearest integer, halves away from zero."""
    return int(math.copysign(math.floor(abs(value) + 0.5), value))


_X_FRAMES = {"x-only": _x_only_frames, "add-first": _add_first_frames,
             "x-truncate": _x_truncate_frames}


def _rows_missed(points) -> int:
    """Rows the ideal segment crosses that an x-stepping loop leaves empty
    (one pixel per column cannot fill more rows than there are columns)."""
    (x1, y1), (x2, y2) = points
    return max(0, abs(y2 - y1) - abs(x2 - x1))


def dda_printed_pixels(points, options) -> np.ndarray:
    """Fast kernel: the same float additions, in order."""
    frames = dda_printed(points, options)
    next(frames)
    return np.array([f[1:3] for f in frames if f[1] != NO_PIXEL], dtype=np.int64).reshape(-1, 2)


LINE_DDA_PRINTED = AlgorithmSpec(
    name="line-dda-printed",
    title="DDA as printed",
    family="lines",
    summary="the lecture listings: a DDA that truncates, steps only in x, or adds before it writes",
    inputs=SEGMENT,
    options=(Option("variant", "choice", "truncate",
                    "truncate: the C cast (int) y instead of rounding; x-only: y += m along x "
                    "for every slope, so steep lines have gaps; add-first: that loop exactly as "
                    "printed, adding m before it writes; x-truncate: the LineDDA listing, "
                    "x-only steps and the cast together", choices=DDA_VARIANTS), COLORS),
    code=listing(dda_printed_listing),
    generator=dda_printed,
    kernel=dda_printed_pixels,
    notes=("truncate differs from line-dda only in the conversion: (int) drops the fraction, "
           "so the line sits up to a whole pixel below (or, left of zero, above) the ideal one.",
           "x-only is the slide's loop without the slope cases: one pixel per column, so a line "
           "steeper than 45 degrees leaves rows empty (rows_missed counts them). It writes y "
           "before it adds m, so P is plotted, and it runs right to left as well.",
           "add-first is that slide's loop exactly as printed: y += m comes before write_pixel, "
           "so column i gets the height of column i + 1 (0,0 -> 10,7 gives (0, 1) ... (10, 8)), "
           "and the loop counts up only, so a line with x2 < x1 draws nothing.",
           "x-truncate is the other lecture's LineDDA: x-only stepping for every slope and the "
           "float y truncated when it is passed as an int, so a steep line has gaps and sits "
           "low; it also counts up only (P alone when x2 <= x1).",
           "Float additions can land just under a whole number, which the cast then drops."),
    oracle=Oracle(
        "exact",
        "truncate: the exact truncation of P + k (Q - P) / n in Fractions, on slopes whose float "
        "sums are exact; x-only: one pixel per column at the rounded exact y, and the rows it "
        "misses counted; add-first and x-truncate: the two listings ported in the tests in "
        "Fractions.",
        ("algorithms/lines/test_line_textbook.py",)),
)


# ------------------------------------------- Bresenham as the notes state it
BRESENHAM_VARIANTS = ("ties-ne", "sign-reversed", "as-printed")
_TESTS = {"ties-ne": ("d < 0", "E"), "sign-reversed": ("D > 0", "E"), "as-printed": ("D > 0", "E")}


def bresenham_textbook_listing(points, options) -> Code:
    variant = options["variant"]
    code = Code()
    code.add("map", "map P, Q into octant 1 (swap x and y if steep, mirror negative steps)")
    if variant == "ties-ne":
        code.add("setup", "dx = x2 - x1;  dy = y2 - y1;  incrE = 2*dy;  incrNE = 2*(dy - dx)",
                 ops={"int_add": 5, "compare": 3})
        code.add("plot_first", "d = 2*dy - dx;  x, y = x1, y1;  plot(x, y)", PLOT,
                 ops={"int_add": 2})
        code.add("loop", "while x < x2:     (d = dx*(s - n): s below the line, n above)")
        code.add("plot_e", "    if d < 0:  d += incrE;  x += 1;  plot(x, y)   (the printed "
                           "code tests d <= 0, ties to E, and sets x = x + 1 after the closing "
                           "brace, before else: C refuses that else; x = x + 1 belongs inside)",
                 PLOT, "E", ops={"int_add": 2, "compare": 2})
        code.add("plot_ne", "    else (d >= 0, ties too):  d += incrNE;  x += 1;  y += 1;  "
                            "plot(x, y)", PLOT, "NE", ops={"int_add": 3, "compare": 2})
    else:
        first = "D = (dy - dx) / 2   (as printed)" if variant == "as-printed" else \
            "D = dx/2 - dy   (= Dx*(a - b) at the first column)"
        code.add("setup", "dx = 2*(x2 - x1);  dy = 2*(y2 - y1);  dydx = dy - dx",
                 ops={"int_add": 5, "compare": 3})
        start = "y = y1   (printed: y = y0, which is no parameter of draw_line(x1, y1, x2, "\
            "y2): C refuses it, and a y0 from elsewhere would put the line on y0's row)" \
            if variant == "as-printed" else "y = y1"
        code.add("plot_first", f"{first};  x = x1;  {start};  write_pixel(x, y)", PLOT,
                 ops={"int_add": 2})
        code.add("loop", "for x = x1 + 1 .. x2:   (D = Dx*(a - b): a above the line, b below)")
        code.add("plot_e", "    if D > 0:  D -= dy;  write_pixel(x, y)", PLOT, "E",
                 ops={"int_add": 2, "compare": 2})
        code.add("plot_ne", "    else (D <= 0):  y += 1;  D -= dydx;  write_pixel(x, y)", PLOT,
                 "NE", ops={"int_add": 3, "compare": 2})
    code.add("done", "done")
    return code


def bresenham_textbook(points, options):
    """Start, then a frame per column with the decision value and the two
    distances of the derivation: s (line above the lower pixel centre) and
    n (upper pixel centre above the line), the slides' b and a."""
    p, q = points
    octant = Octant(p, q)
    variant = options["variant"]
    at = bresenham_textbook_listing(points, options).at
    ramp = color_ramp(options)
    name = "d" if variant == "ties-ne" else "D"
    constants = {"dx": octant.dx, "dy": octant.dy, "octant": octant.number,
                 "steep": octant.steep, "variant": variant}
    if variant == "as-printed":
        constants["first_difference"] = _first_difference(p, q, octant)
    start = Start(line=at["setup"], values=with_color(ramp, (name, "s", "n")),
                  constants=constants, pixel_value="rgb" if ramp else None,
                  candidates=(octant.major, (octant.major[0] + octant.minor[0],
                                             octant.major[1] + octant.minor[1])),
                  decision=name)
    frames = _textbook_frames(p, octant, variant, at)
    return chain((start,), colored(frames, ramp, octant.dx) if ramp else frames)


def _decisions(octant, variant):
    """(goes_ne, value) per column u = 1..dx in octant 1. Corrected, the
    sign-reversed D is exactly -d."""
    dx, dy = octant.dx, octant.dy
    if variant == "ties-ne":
        d = 2 * dy - dx
        for _ in range(dx):
            ne = d >= 0
            yield ne, d
            d += 2 * (dy - dx) if ne else 2 * dy
        return
    big_dx, big_dy = 2 * dx, 2 * dy
    # The slides' (dy - dx)/2 with doubled dx, dy is dy - dx in plain units.
    d = (big_dy - big_dx) // 2 if variant == "as-printed" else dx - big_dy
    for _ in range(dx):
        ne = d <= 0
        yield ne, d
        d -= (big_dy - big_dx) if ne else big_dy


def _textbook_frames(p, octant, variant, at):
    east, north_east = at["plot_e"], at["plot_ne"]
    x, y = p
    v = 0
    yield (at["plot_first"], x, y, NAN, NAN, NAN)
    for u, (ne, value) in enumerate(_decisions(octant, variant), start=1):
        # The ideal line at column u, above the pixel row v the loop stands on.
        # Whole numerators, one division each: s and n carry no float drift.
        above = octant.dy * u - v * octant.dx
        if ne:
            v += 1
        x, y = octant.to_grid(p, u, v)
        yield (north_east if ne else east, x, y, value, above / octant.dx,
               (octant.dx - above) / octant.dx)
    yield (at["done"], NO_PIXEL, NO_PIXEL, NAN, NAN, NAN)


def textbook_pixels(points, options) -> np.ndarray:
    """Fast kernel: the decision sequence without the frames."""
    p, q = points
    octant = Octant(p, q)
    v, cells = 0, [tuple(p)]
    for u, (ne, _) in enumerate(_decisions(octant, options["variant"]), start=1):
        v += ne
        cells.append(octant.to_grid(p, u, v))
    return np.array(cells, dtype=np.int64).reshape(-1, 2)


def _first_difference(p, q, octant) -> str:
    """Where the printed initial value first sends the line off the corrected one."""
    printed = textbook_pixels((p, q), {"variant": "as-printed"})
    corrected = textbook_pixels((p, q), {"variant": "sign-reversed"})
    for a, b in zip(printed.tolist(), corrected.tolist()):
        if a != b:
            return f"({a[0]}, {a[1]}) instead of ({b[0]}, {b[1]})"
    return "none"


def textbook_explain(trace, i):
    step = trace.step(i)
    name = trace.start.decision
    if not step.branch or name not in step.values:
        return []
    value = int(step.values[name])
    s, n = step.values["s"], step.values["n"]
    rows = [("decision", f"{name} = {value}, so {step.branch}"),
            ("s - n", f"{s:.4g} - {n:.4g} = {s - n:.4g}")]
    if "first_difference" in trace.start.constants:
        rows.append(("parts from corrected", trace.start.constants["first_difference"]))
    return rows


LINE_BRESENHAM_TEXTBOOK = AlgorithmSpec(
    name="line-bresenham-textbook",
    title="Bresenham as the notes state it",
    family="lines",
    summary="ties to NE, the sign-reversed D, or the printed listing with its initial-value error",
    inputs=SEGMENT,
    options=(Option("variant", "choice", "ties-ne",
                    "ties-ne: d >= 0 chooses NE, as the derivation's text says; sign-reversed: "
                    "D = dx*(a - b), D > 0 chooses E; as-printed: that listing's D = (dy - dx)/2, "
                    "which sends the first step up", choices=BRESENHAM_VARIANTS), COLORS),
    code=listing(bresenham_textbook_listing),
    generator=bresenham_textbook,
    kernel=textbook_pixels,
    explain=textbook_explain,
    notes=("ties-ne differs from line-bresenham only at ties (d = 0): it takes NE, not E.",
           "sign-reversed gives the same pixels as ties-ne: D is -d, and D = 0 chooses NE.",
           "as-printed starts D at (dy - dx)/2, which is <= 0 for any slope up to 1, so the first "
           "step always goes up and every later test is shifted: it draws the corrected line "
           "for the ideal line lifted by 1 - 3m/2 rows (m = dy/dx in octant 1), a whole row when "
           "flat, none at m = 2/3 (the same pixels), half a row low at m = 1; Q is drawn only "
           "when m > 1/3. first_difference says where it leaves the corrected line.",
           "The listings' other slips are flagged in the pseudo-code: one lecture's code tests "
           "d <= 0 where its text says d < 0, and prints the E branch's x = x + 1 outside its "
           "braces; the other starts y at y0, a name draw_line does not have (y1 is meant).",
           "s and n are the distances from the ideal line to the lower and the upper candidate "
           "(the slides' b and a); d = dx*(s - n)."),
    oracle=Oracle(
        "exact",
        "ties-ne and sign-reversed: the pixel nearest the ideal line in every column, ties away "
        "from P, from exact rational arithmetic (algorithms/exact/lines.py). as-printed: the "
        "slide's listing transcribed in integers in the test, and its pixels off the nearest line "
        "counted.",
        ("algorithms/lines/test_line_textbook.py", "algorithms/test_stability.py"),
        check="textbook-line"),
)


# --------------------------------------------------------- midpoint line
def midpoint_listing(points, options) -> Code:
    code = Code()
    code.add("map", "map P, Q into octant 1 (swap x and y if steep, mirror negative steps)")
    code.add("setup", "F(x, y) = dy*x - dx*y + c   (the implicit form; F > 0 below the line)",
             ops={"int_add": 2, "compare": 3})
    code.add("plot_first", "d = 2*F(x1 + 1, y1 + 1/2) = 2*dy - dx;  plot(x1, y1)", PLOT,
             ops={"int_add": 2})
    code.add("loop", "while x < x2:   (d is twice F at the midpoint M between E and NE)")
    code.add("plot_e", "    if d <= 0 (M on or above the line):  d += 2*dy;  x += 1;  plot(x, y)",
             PLOT, "E", ops={"int_add": 2, "compare": 2})
    code.add("plot_ne", "    else (M below the line):  d += 2*(dy - dx);  x += 1;  y += 1;  "
                        "plot(x, y)", PLOT, "NE", ops={"int_add": 3, "compare": 2})
    code.add("done", "done")
    return code


def midpoint(points, options):
    """The midpoint test on the implicit form: each frame carries d and the
    midpoint M = (Mx, My) it tested, in the grid's own coordinates."""
    p, q = points
    octant = Octant(p, q)
    at = midpoint_listing(points, options).at
    ramp = color_ramp(options)
    start = Start(line=at["setup"], values=with_color(ramp, ("d", "Mx", "My")),
                  constants={"dx": octant.dx, "dy": octant.dy, "octant": octant.number},
                  pixel_value="rgb" if ramp else None,
                  candidates=(octant.major, (octant.major[0] + octant.minor[0],
                                             octant.major[1] + octant.minor[1])),
                  decision="d")
    frames = _midpoint_frames(p, octant, at)
    return chain((start,), colored(frames, ramp, octant.dx) if ramp else frames)


def _midpoint_frames(p, octant, at):
    dx, dy = octant.dx, octant.dy
    x, y = p
    yield (at["plot_first"], x, y, NAN, NAN, NAN)
    d, v = 2 * dy - dx, 0
    for u in range(1, dx + 1):
        mx, my = octant.to_grid(p, u, v + 0.5)
        ne = d > 0
        tested = d
        d += 2 * (dy - dx) if ne else 2 * dy
        v += ne
        x, y = octant.to_grid(p, u, v)
        yield (at["plot_ne"] if ne else at["plot_e"], x, y, tested, float(mx), float(my))
    yield (at["done"], NO_PIXEL, NO_PIXEL, NAN, NAN, NAN)


LINE_MIDPOINT = AlgorithmSpec(
    name="line-midpoint",
    title="Midpoint line",
    family="lines",
    summary="the sign of the implicit form at the midpoint between E and NE",
    inputs=SEGMENT,
    options=(COLORS,),
    code=listing(midpoint_listing),
    generator=midpoint,
    kernel=bresenham_pixels,
    notes=("The same pixels as line-bresenham: d is twice F(M), the implicit form at the "
           "midpoint, which is Bresenham's decision value derived another way.",
           "A midpoint exactly on the line (d = 0) goes to E, as line-bresenham's ties do."),
    oracle=Oracle(
        "exact",
        "The pixel nearest the ideal line in every column, from exact rational arithmetic "
        "(algorithms/exact/lines.py; ties either way), and each decision d is twice the implicit "
        "form at the midpoint, in Fractions.",
        ("algorithms/lines/test_line_textbook.py", "algorithms/test_stability.py"),
        check="nearest-line"),
)


# ------------------------------------------- the implicit form, unbounded
def implicit_line_listing(points, options) -> Code:
    test = {"int_add": 3, "mul": 4, "compare": 2, "pixels_tested": 1}
    code = Code()
    code.add("setup", "a = y0 - y1;  b = x1 - x0;  c = x0*y1 - x1*y0   (F(x, y) = a*x + b*y + c)",
             ops={"int_add": 3, "mul": 2})
    code.add("rows", "for every pixel (x, y) of the grid (no bounding box):")
    code.add("skip", "    if |F(x, y)| / sqrt(a^2 + b^2) >= 1/2:  skip", VISIT, ops=test)
    code.add("plot", "    else:  setPixel(x, y)   (near the line, wherever P and Q are)", PLOT,
             ops=test)
    code.add("done", "done")
    return code


def implicit_line(points, options, grid):
    """Every pixel of the grid whose centre lies within 1/2 of the infinite
    line through P and Q (of P itself when P = Q), tested exactly:
    4 * F^2 < a^2 + b^2 in integers."""
    (x0, y0), (x1, y1) = points
    a, b, c = y0 - y1, x1 - x0, x0 * y1 - x1 * y0
    norm = a * a + b * b
    at = implicit_line_listing(points, options).at
    yield Start(line=at["setup"], values=("F",), constants={"a": a, "b": b, "c": c})
    width, height = grid
    for y in range(height):
        for x in range(width):
            f = a * x + b * y + c
            near = 4 * f * f < norm if norm else 4 * ((x - x0) ** 2 + (y - y0) ** 2) < 1
            yield (at["plot"] if near else at["skip"], x, y, float(f))
    yield (at["done"], NO_PIXEL, NO_PIXEL, NAN)


LINE_IMPLICIT_INFINITE = AlgorithmSpec(
    name="line-implicit-infinite",
    title="Implicit form, unbounded",
    family="lines",
    summary="F(x, y) = a*x + b*y + c tested over the whole grid: a line, not a segment",
    inputs=SEGMENT,
    options=(),
    code=listing(implicit_line_listing),
    generator=implicit_line,
    uses_grid=True,
    visits="grid",
    notes=("line-implicit limits the test to P and Q's bounding box; without that box the "
           "implicit form draws the whole line through P and Q, past both ends.",
           "The test is exact in integers: 4 * F^2 < a^2 + b^2."),
    oracle=Oracle(
        "exact",
        "Every pixel of the grid whose centre lies closer than 1/2 px to the infinite line PQ, and "
        "no other, by exact rational distances written in the test.",
        ("algorithms/lines/test_line_textbook.py",)),
)


# ------------------------------------------ the parametric loop as printed
def parametric_printed_listing(points, options) -> Code:
    step = {"float_add": 5, "mul": 3, "round": 2, "compare": 1}
    code = Code()
    code.add("setup", "D = Q - P;  t = 0.0", ops={"int_add": 2})
    code.add("loop", f"for (t = 0.0; t <= 1.0; t += {options['dt']:g})   (t adds up in floats)")
    code.add("plot", "    r = P + D*t;  colour = colour_P + (colour_Q - colour_P)*t;  "
                     "setPixel(round(r.x), round(r.y))", PLOT, ops=step)
    code.add("done", "done   (t passed 1.0; whether t = 1 was ever reached depends on the sums)")
    return code


def parametric_printed(points, options):
    """The loop exactly as printed: t grows by repeated float addition and
    the loop stops once t > 1, so the last t can fall short of 1 and Q can
    be missed."""
    (x0, y0), (x1, y1) = points
    dx, dy, dt = x1 - x0, y1 - y0, options["dt"]
    ramp = color_ramp(options)
    at = parametric_printed_listing(points, options).at
    yield Start(line=at["setup"], values=with_color(ramp, ("t",)),
                constants={"dt": dt, "dx": dx, "dy": dy}, pixel_value="rgb" if ramp else None)
    plot, t, last = at["plot"], 0.0, 0.0
    while t <= 1.0:
        color = (ramp.at(t),) if ramp else ()
        yield (plot, round_half_up(x0 + dx * t), round_half_up(y0 + dy * t), t, *color)
        last, t = t, t + dt
    reached = "yes" if (round_half_up(x0 + dx * last), round_half_up(y0 + dy * last)) == (x1, y1) \
        else "no"
    yield Vars(line=at["done"], values={"last_t": last, "Q_plotted": reached})


LINE_PARAMETRIC_PRINTED = AlgorithmSpec(
    name="line-parametric-printed",
    title="Parametric loop as printed",
    family="lines",
    summary="for (t = 0; t <= 1; t += dt): t summed in floats, so t = 1 may never come",
    inputs=SEGMENT,
    options=(Option("dt", "float", 0.001, "the loop's step in t, in (0, 1]", minimum=1e-6,
                    maximum=1.0), COLORS),
    code=listing(parametric_printed_listing),
    generator=parametric_printed,
    notes=("line-parametric counts whole steps k and ends on t = 1 exactly; the printed loop "
           "adds dt to t, and 1000 additions of 0.001 give 1.0000000000000007, so its last t "
           "is 0.999... and on a line longer than about 500 px Q is never plotted.",
           "last_t and Q_plotted say what happened."),
    oracle=Oracle(
        "reference",
        "The printed loop transcribed in the test, with the listing's own float additions of dt "
        "and rounding; at dt = 0.001 it misses just Q, which exact steps reach, and says so.",
        ("algorithms/lines/test_line_textbook.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (LINE_DDA_PRINTED, LINE_BRESENHAM_TEXTBOOK, LINE_MIDPOINT, LINE_IMPLICIT_INFINITE,
         LINE_PARAMETRIC_PRINTED)
