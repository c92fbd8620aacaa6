"""More circles from integer centres: Bresenham's circle (d = 3 - 2R), the
polar circle stepped in the angle t, and the midpoint circle exactly as one
lecture prints it.

Like algorithms/circles/midpoint.py these work on whole-number offsets (x, y) from an
integer centre and plot pixel (xc + x, yc + y).
"""
from __future__ import annotations

import math

from algorithms.circles.midpoint import CENTRE, E_SE, PLOT_OPS, RADIUS, ArcWatch, _centre, mirrors8
from algorithms.core.code import Code, listing
from algorithms.exact.circles import midpoint_circle as exact_midpoint_circle
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import PLOT, Start, Vars

NAN = math.nan


# ------------------------------------------------------ Bresenham circle
def bresenham_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "x = 0;  y = R;  d = 3 - 2R   (d = F(E) + F(SE) with F = x^2 + y^2 - R^2)",
             ops={"int_add": 1, "mul": 1})
    code.add("loop", "while x <= y:", ops={"compare": 1})
    code.add("plot_mirrors", "    plot the eight mirrors of (x, y)   (four on the axes and the "
                             "diagonal)", PLOT, ops=PLOT_OPS)
    code.add("east", "    if d < 0:  d += 4x + 6;  x += 1          (E is nearer the circle)",
             branch="E", ops={"compare": 1, "mul": 1, "int_add": 3})
    code.add("south_east", "    else:  d += 4(x - y) + 10;  x += 1;  y -= 1   (SE is nearer)",
             branch="SE", ops={"compare": 1, "mul": 1, "int_add": 5})
    code.add("done", "done")
    return code


def bresenham_circle(points, options):
    xc, yc = _centre(points)
    r = options["radius"]
    at = bresenham_listing(points, options).at
    yield Start(line=at["setup"], values=("d", "x", "y"),
                constants={"xc": xc, "yc": yc, "R": r, "d0": 3 - 2 * r},
                candidates=E_SE, decision="d")
    x, y, d = 0, r, 3 - 2 * r
    plotted = 0
    loop, mirror, east, south_east = at["loop"], at["plot_mirrors"], at["east"], at["south_east"]
    while True:
        yield (loop, xc + x, yc + y, d, x, y)
        if x > y:
            break
        for dx, dy in mirrors8(x, y):
            plotted += 1
            yield (mirror, xc + dx, yc + dy, d, x, y)
        tested = d
        if d < 0:
            line, d = east, d + 4 * x + 6
        else:
            line, d, y = south_east, d + 4 * (x - y) + 10, y - 1
        x += 1
        yield (line, xc + x, yc + y, tested, x, y)
    yield Vars(line=at["done"], values={"pixels": plotted})


def bresenham_explain(trace, i):
    step = trace.step(i)
    if not step.branch or "d" not in step.values:
        return []
    d = int(step.values["d"])
    if step.branch == "E":
        return [("decision", f"d = {d} < 0: F(E) + F(SE) < 0, so E is nearer the circle")]
    return [("decision", f"d = {d} >= 0: F(E) + F(SE) >= 0, so SE is nearer the circle")]


CIRCLE_BRESENHAM = AlgorithmSpec(
    name="circle-bresenham",
    title="Bresenham circle",
    family="circles",
    summary="d = 3 - 2R: the sum of the two candidates' residuals picks E or SE, mirrored 8 ways",
    inputs=CENTRE,
    options=(RADIUS,),
    code=listing(bresenham_listing),
    generator=bresenham_circle,
    explain=bresenham_explain,
    notes=("d is F(E) + F(SE), the residuals x^2 + y^2 - R^2 of the two candidates added: "
           "E when the sum is negative, so the candidate with the smaller residual wins.",
           "d is always odd, so it is never 0: no ties.",
           "It chooses the same pixels as the midpoint circle for every whole radius: the "
           "two tests could only disagree if R^2 - x^2 - (y - 1/2)^2, a whole number less "
           "1/4, lay in (0, 1/4]."),
    oracle=Oracle(
        "exact",
        "Per column the candidate with the smaller integer residual |x^2 + y^2 - R^2|, mirrored 8 "
        "ways, written in the test: the exact midpoint circle's pixels "
        "(algorithms/exact/circles.py); d is the sum of the two residuals.",
        ("algorithms/circles/test_circle_variants.py", "algorithms/test_stability.py"),
        check="bresenham-circle"),
)


# ------------------------------------------------------ polar circle
DT = Option("dt", "float", "auto",
            "step in the angle t, in radians; auto takes 1/R, the largest step without gaps",
            minimum=1e-3, maximum=2 * math.pi, choices=("auto",))


def polar_step(options) -> float:
    if options["dt"] == "auto":
        return 1.0 / max(options["radius"], 1)
    return float(options["dt"])


def polar_listing(points, options) -> Code:
    dt = "1/R" if options["dt"] == "auto" else f"{options['dt']:g}"
    code = Code()
    code.add("setup", f"dt = {dt};  n = ceil(2 pi / dt)", ops={"div": 1, "round": 1})
    code.add("loop", "for k = 0 .. n - 1:  t = k dt", ops={"mul": 1, "int_add": 1, "compare": 1})
    code.add("plot_point", "    plot (round(xc + R cos t), round(yc + R sin t))", PLOT,
             ops={"mul": 2, "float_add": 4, "round": 2})
    code.add("done", "done   (gaps: steps to a pixel that is not an 8-neighbour)")
    return code


def polar_circle(points, options):
    xc, yc = _centre(points)
    r = options["radius"]
    dt = polar_step(options)
    n = math.ceil(2 * math.pi / dt)
    at = polar_listing(points, options).at
    yield Start(line=at["setup"], values=("t", "x", "y", "gaps", "duplicates"),
                constants={"xc": xc, "yc": yc, "R": r, "dt": dt, "n": n})
    watch = ArcWatch()
    loop, plot = at["loop"], at["plot_point"]
    first = before = None
    for k in range(n):
        t = k * dt
        x, y = r * math.cos(t), r * math.sin(t)
        # floor(v + 1/2) rounds halves up, as the line family does.
        pixel = (math.floor(x + 0.5), math.floor(y + 0.5))
        yield (loop, xc + pixel[0], yc + pixel[1], t, x, y, watch.gaps, watch.duplicates)
        if before is not None:
            watch.step(before, pixel, 1)
        watch.plot(pixel)
        yield (plot, xc + pixel[0], yc + pixel[1], t, x, y, watch.gaps, watch.duplicates)
        first = first or pixel
        before = pixel
    watch.step(before, first, 1)  # the arc closes back to t = 0
    summary = watch.summary()
    del summary["gap_columns"]
    yield Vars(line=at["done"], values=summary)


CIRCLE_POLAR = AlgorithmSpec(
    name="circle-polar",
    title="Circle, polar form",
    family="circles",
    summary="x = xc + R cos t, y = yc + R sin t for t = 0, dt, 2dt, ..., each point rounded",
    inputs=CENTRE,
    options=(RADIUS, DT),
    code=listing(polar_listing),
    generator=polar_circle,
    notes=("A step of dt moves the point along a chord shorter than R dt, so with dt <= 1/R "
           "neither coordinate moves a whole pixel and there are no gaps; a larger step "
           "leaves gaps, a smaller one plots pixels again (duplicates).",
           "Two cosines and two sines a point: far dearer than the midpoint circle's "
           "additions."),
    oracle=Oracle(
        "reference",
        "A bound: every pixel's square meets the ideal circle (an exact integer test), in "
        "ceil(2 pi / dt) plots; gaps and duplicates recounted from the pixels, no gap with "
        "dt = 1/R. Which pixel near the circle is not fixed.",
        ("algorithms/circles/test_circle_variants.py", "algorithms/test_stability.py"),
        check="polar-circle"),
)


# ----------------------------------------- midpoint circle as printed
def printed_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "x = 0;  y = r;  d = 5 / 4 - r   (integer division: 5 / 4 is 1.  The "
                      "summary slide calls this F(0, R), which is 0: started there, d < 0 fails "
                      "and the first step goes SE; 5/4 - R is F(1, R - 1/2), the first midpoint)",
             ops={"int_add": 1, "div": 1})
    code.add("plot_axes", "DisplayPixel (0, r), (0, -r), (r, 0), (-r, 0)", PLOT, ops=PLOT_OPS)
    code.add("loop", "while y > x:", ops={"compare": 1})
    code.add("east", "    if d < 0:  d = d + 2x + 3;  x = x + 1", branch="E",
             ops={"compare": 1, "int_add": 3})
    code.add("south_east", "    else:  d = d + 2(x - y) +   <- the 5 is missing;  x = x + 1;  "
                           "y = y - 1   (the slides write SE as (x_{i+1}, y_{i-1}): read as "
                           "indices, y_{i-1} is the row before, which would climb back; "
                           "y_i - 1 is meant)", branch="SE", ops={"compare": 1, "int_add": 4})
    code.add("plot_mirrors", "    DisplayCirclePoints: all eight mirrors of (x, y)", PLOT,
             ops=PLOT_OPS)
    code.add("done", "done")
    return code


def printed_circle(points, options):
    xc, yc = _centre(points)
    r = options["radius"]
    at = printed_listing(points, options).at
    yield Start(line=at["setup"], values=("d", "x", "y"),
                constants={"xc": xc, "yc": yc, "R": r, "d0": 1 - r},
                candidates=E_SE, decision="d")
    x, y, d = 0, r, 5 // 4 - r
    drawn = []
    for dx, dy in ((0, r), (0, -r), (r, 0), (-r, 0)):
        drawn.append((dx, dy))
        yield (at["plot_axes"], xc + dx, yc + dy, d, x, y)
    loop, east, south_east, mirror = at["loop"], at["east"], at["south_east"], at["plot_mirrors"]
    while True:
        yield (loop, xc + x, yc + y, d, x, y)
        if not y > x:
            break
        tested = d
        if d < 0:
            line, d = east, d + 2 * x + 3
        else:
            line, d, y = south_east, d + 2 * (x - y), y - 1
        x += 1
        yield (line, xc + x, yc + y, tested, x, y)
        for dx, dy in ((x, y), (x, -y), (-x, y), (-x, -y), (y, x), (y, -x), (-y, x), (-y, -x)):
            drawn.append((dx, dy))
            yield (mirror, xc + dx, yc + dy, d, x, y)
    yield Vars(line=at["done"], values=printed_summary(r, drawn))


def printed_summary(r: int, drawn: list) -> dict:
    """How the printed loop's pixels differ from the exact midpoint circle."""
    exact = exact_midpoint_circle(r)
    got = set(drawn)
    first = min((abs(x) for x, y in got - exact if abs(x) <= abs(y)), default=-1)
    return {"pixels": len(drawn), "duplicates": len(drawn) - len(got),
            "off_circle": len(got - exact), "missing": len(exact - got),
            "first_wrong_column": first}


CIRCLE_MIDPOINT_PRINTED = AlgorithmSpec(
    name="circle-midpoint-printed",
    title="Midpoint circle, as printed",
    family="circles",
    summary="the lecture's MidpointCircle code as printed: the SE update lacks its + 5",
    inputs=CENTRE,
    options=(RADIUS,),
    code=listing(printed_listing),
    generator=printed_circle,
    notes=("The printed SE line breaks after '+' and the 5 of d += 2(x - y) + 5 is lost "
           "(as C the two lines do not even compile; this runs the evident reading). After "
           "each SE step d is 5 too small, so the next tests choose E too often: the arc "
           "stays outside the circle and the outline turns square-ish.",
           "Two slips of the slides before the code are flagged in the listing: the summary's "
           "d0 = F(0, R) (which is 0, not 5/4 - R, and would send the first step SE) and SE "
           "written as (x_{i+1}, y_{i-1}) (y_{i-1} is the previous row; y_i - 1 is meant).",
           "The loop also plots after a step that crossed the diagonal and plots all eight "
           "mirrors on the axes and the diagonal, so pixels repeat (duplicates).",
           "off_circle and missing count the pixels unlike circle-midpoint's; "
           "first_wrong_column is the first octant column where they part (-1: none)."),
    oracle=Oracle(
        "exact",
        "The lecture's code as printed, transcribed in integers (tests/support/curve_oracles.py), "
        "pixel for pixel in order; its pixels off the exact midpoint circle and those it misses "
        "are counted.",
        ("algorithms/circles/test_circle_variants.py", "algorithms/test_stability.py"),
        check="printed-midpoint-circle"),
)

# The module's algorithms, in the order they are listed.
SPECS = (CIRCLE_BRESENHAM, CIRCLE_POLAR, CIRCLE_MIDPOINT_PRINTED)
