"""The line from its equations: basic incremental, explicit, implicit and parametric forms."""
from __future__ import annotations

import math

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, InputError, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Start, Vars
from .common import (COLORS, NAN, SEGMENT, color_ramp, fraction_of, major_axis, pixel_at,
                     round_half_up, sign, with_color)


# ------------------------------------------------------ basic incremental
ROUNDING = Option("rounding", "choice", "floor",
                  "floor, as the lecture's loop does, or round: floor(v + 1/2), "
                  "the nearest pixel", choices=("floor", "round"))


Q_AS_GIVEN = ("plot(x1, y1)   (the loop stops one short of Q, as in the notes; "
              "Q is plotted as given)")


def incremental_listing(points, options) -> Code:
    steep, *_ = major_axis(points)
    a, b = ("y", "x") if steep else ("x", "y")
    slope, ratio = ("1/m", "dx / dy") if steep else ("m", "dy / dx")
    rounding = options["rounding"]
    # Operation counts: the loop's step and test are counted on the loop
    # body's line, whose frame every iteration yields.
    code = Code()
    code.add("setup", f"dx = x1 - x0;  dy = y1 - y0;  {a} is the major axis "
                      f"(|d{a}| {'>' if steep else '>='} |d{b}|)", ops={"int_add": 2, "compare": 3})
    code.add("slope", f"{slope} = {ratio}  (a float);  s = sign(d{a})", ops={"div": 1, "compare": 1})
    code.add("loop", f"for {a} = {a}0, {a}0 + s, ... while {a} != {a}1:")
    code.add("plot_step", f"    {b}_real = {slope} * ({a} - {a}0) + {b}0;  "
                          f"plot({rounding}({b}_real)) in {'row' if steep else 'column'} {a}", PLOT,
             ops={"int_add": 2, "mul": 1, "float_add": 1, "round": 1, "compare": 1})
    code.add("plot_q", Q_AS_GIVEN, PLOT)
    code.add("done", "done")
    return code


def _incremental_setup(points):
    steep, a0, b0, a1, b1 = major_axis(points)
    n = abs(a1 - a0)
    slope = (b1 - b0) / (a1 - a0) if n else 0.0
    return steep, a0, b0, a1, b1, n, sign(a1 - a0), slope


def incremental(points, options):
    steep, a0, b0, a1, b1, n, s, slope = _incremental_setup(points)
    rounder = math.floor if options["rounding"] == "floor" else round_half_up
    ramp = color_ramp(options)
    at = incremental_listing(points, options).at
    real_name = "x_real" if steep else "y_real"
    (x0, y0), (x1, y1) = points
    nothing = (NAN, NAN) if ramp else (NAN,)
    yield Start(line=at["setup"], values=with_color(ramp, (real_name,)),
                constants={"dx": x1 - x0, "dy": y1 - y0, ("1/m" if steep else "m"): slope,
                           "major": "y" if steep else "x", "rounding": options["rounding"]},
                pixel_value="rgb" if ramp else None)
    yield (at["slope"], NO_PIXEL, NO_PIXEL, *nothing)
    step = at["plot_step"]
    for k in range(n):
        a = a0 + s * k
        # Evaluated anew from the line equation in every column (not added up).
        real = slope * (a - a0) + b0
        color = (ramp.at(k / n),) if ramp else ()
        yield (step, *pixel_at(steep, a, rounder(real)), real, *color)
    # Floor of a float m*dx + y0 can land one below y1 (1/49 * 49 is
    # 0.999...), so Q is plotted as given, not from the formula.
    yield (at["plot_q"], x1, y1, float(b1), *((ramp.at(fraction_of(n, n)),) if ramp else ()))
    yield (at["done"], NO_PIXEL, NO_PIXEL, *nothing)


def incremental_pixels(points, options) -> np.ndarray:
    """Fast kernel: the same float evaluation per column, vectorised."""
    steep, a0, b0, a1, b1, n, s, slope = _incremental_setup(points)
    offsets = s * np.arange(n, dtype=np.int64)
    real = slope * offsets.astype(np.float64) + b0
    if options["rounding"] == "round":
        real = real + 0.5
    major = np.append(a0 + offsets, a1)
    minor = np.append(np.floor(real).astype(np.int64), b1)
    columns = (minor, major) if steep else (major, minor)
    return np.stack(columns, axis=1)


def _rounding_explain(trace, i, rounding):
    """How the real minor coordinate of step i became a pixel coordinate."""
    step = trace.step(i)
    name = trace.value_names[0]  # "y_real", or "x_real" when y is the major axis
    if step.pixel is None or name not in step.values:
        return []
    real = step.values[name]
    result = step.pixel[0] if name == "x_real" else step.pixel[1]
    # repr keeps every digit that matters: floor(0.9999999999999999) = 0
    # must not read as floor(1) = 0.
    if rounding == "floor":
        return [("rounding", f"floor({real!r}) = {result}")]
    return [("rounding", f"round({real!r}) = floor({real + 0.5!r}) = {result}")]


def incremental_explain(trace, i):
    if trace.code[int(trace.line[i])].text == Q_AS_GIVEN:
        return [("rounding", "none: Q is plotted as given")]
    return _rounding_explain(trace, i, trace.start.constants["rounding"])


LINE_INCREMENTAL = AlgorithmSpec(
    name="line-incremental",
    title="Basic incremental",
    family="lines",
    summary="evaluate y = m*x + b anew in every column and round it",
    inputs=SEGMENT,
    options=(ROUNDING, COLORS),
    code=listing(incremental_listing),
    generator=incremental,
    kernel=incremental_pixels,
    explain=incremental_explain,
    notes=("When |m| > 1 the roles of x and y swap: x = (1/m) * (y - y0) + x0 "
           "row by row, so no row is skipped.",
           "The loop walks from P towards Q in either direction.",
           "m is a float, so m * (x - x0) + y0 can miss an exact whole number by "
           "a rounding error, which floor then turns into the pixel below.",
           "round(v) is floor(v + 1/2): halves round up."),
    oracle=Oracle(
        "exact",
        "In every column, the floor or the rounding (by the option) of the exact line value, "
        "either neighbour where that value is whole or an exact half. With rounding round, the "
        "pixel nearest the ideal line in every column.",
        ("algorithms/lines/test_line_float_forms.py", "algorithms/test_stability.py"),
        check="incremental-line"),
)


# ---------------------------------------------------------- explicit form
def explicit_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "run = x1 - x0;  rise = y1 - y0", ops={"int_add": 2})
    code.add("x_major", "if |run| >= |rise|:       (x is the major axis; also a point or a flat line)",
             branch="x major", ops={"compare": 3})
    code.add("x_setup", "    m = rise / run  (0 when run = 0);  c = y0 - m*x0",
             ops={"compare": 1, "div": 1, "mul": 1, "float_add": 1})
    code.add("x_up", "    if run >= 0:  for x = x0, x0 + 1, ..., x1   (up to x1 itself, so Q is plotted)",
             branch="ascending", ops={"compare": 1})
    code.add("x_down", "    else:         for x = x0, x0 - 1, ..., x1   (descending loop)",
             branch="descending", ops={"compare": 1})
    # The loop's step and test are counted with the body's frame.
    plot = {"mul": 1, "float_add": 1, "round": 1, "int_add": 1, "compare": 1}
    code.add("plot_x", "        y = m*x + c;  setPixel(x, round(y))", PLOT, ops=plot)
    code.add("y_major", "else:                     (y is the major axis: x = n*y + d)",
             branch="y major", ops={"compare": 3})
    code.add("y_setup", "    n = run / rise;  d = x0 - n*y0", ops={"div": 1, "mul": 1, "float_add": 1})
    code.add("y_up", "    if rise > 0:  for y = y0, y0 + 1, ..., y1   (up to y1 itself)",
             branch="ascending", ops={"compare": 1})
    code.add("y_down", "    else:         for y = y0, y0 - 1, ..., y1   (descending loop)",
             branch="descending", ops={"compare": 1})
    code.add("plot_y", "        x = n*y + d;  setPixel(round(x), y)", PLOT, ops=plot)
    code.add("done", "done")
    return code


def _explicit_setup(points):
    """(steep, slope, intercept, first, last, step) of the case the split picks."""
    (x0, y0), (x1, y1) = points
    run, rise = x1 - x0, y1 - y0
    if abs(run) >= abs(rise):
        m = rise / run if run else 0.0
        return False, m, y0 - m * x0, x0, x1, sign(run)
    n = run / rise
    return True, n, x0 - n * y0, y0, y1, sign(rise)


def explicit(points, options):
    steep, slope, intercept, first, last, step = _explicit_setup(points)
    (x0, y0), (x1, y1) = points
    ramp = color_ramp(options)
    nothing = (NAN, NAN) if ramp else (NAN,)
    at = explicit_listing(points, options).at
    if steep:
        constants = {"run": x1 - x0, "rise": y1 - y0, "n": slope, "d": intercept}
        case, setup, plot = at["y_major"], at["y_setup"], at["plot_y"]
        loop = at["y_up"] if step > 0 else at["y_down"]
    else:
        constants = {"run": x1 - x0, "rise": y1 - y0, "m": slope, "c": intercept}
        case, setup, plot = at["x_major"], at["x_setup"], at["plot_x"]
        loop = at["x_up"] if step > 0 else at["x_down"]
    yield Start(line=at["setup"], values=with_color(ramp, ("x_real" if steep else "y_real",)),
                constants=constants, pixel_value="rgb" if ramp else None)
    yield (case, NO_PIXEL, NO_PIXEL, *nothing)
    yield (setup, NO_PIXEL, NO_PIXEL, *nothing)
    yield (loop, NO_PIXEL, NO_PIXEL, *nothing)
    n = abs(last - first)
    for k in range(n + 1):
        a = first + step * k
        # The line equation in absolute coordinates, as the notes write it.
        real = slope * a + intercept
        color = (ramp.at(fraction_of(k, n)),) if ramp else ()
        yield (plot, *pixel_at(steep, a, round_half_up(real)), real, *color)
    yield (at["done"], NO_PIXEL, NO_PIXEL, *nothing)


def explicit_pixels(points, options) -> np.ndarray:
    """Fast kernel: y = m*x + c over the whole loop at once."""
    steep, slope, intercept, first, last, step = _explicit_setup(points)
    major = np.arange(first, last + step, step, dtype=np.int64)
    minor = np.floor(slope * major.astype(np.float64) + intercept + 0.5).astype(np.int64)
    columns = (minor, major) if steep else (major, minor)
    return np.stack(columns, axis=1)


def explicit_explain(trace, i):
    return _rounding_explain(trace, i, "round")


LINE_EXPLICIT = AlgorithmSpec(
    name="line-explicit",
    title="Explicit form",
    family="lines",
    summary="y = m*x + c with a case for each slope and direction",
    inputs=SEGMENT,
    options=(COLORS,),
    code=listing(explicit_listing),
    generator=explicit,
    kernel=explicit_pixels,
    explain=explicit_explain,
    notes=("The loops include their last value, so both endpoints are plotted; "
           "a loop written with '<' would stop one pixel short of Q.",
           "round(v) is floor(v + 1/2): halves round up."),
    oracle=Oracle(
        "exact",
        "The pixel nearest the ideal line in every column of the major axis, from exact rational "
        "line values (algorithms/exact/lines.py); either neighbour at an exact half.",
        ("algorithms/lines/test_line_float_forms.py", "algorithms/test_stability.py"),
        check="nearest-line"),
)


# ---------------------------------------------------------- implicit form
def implicit_listing(points, options) -> Code:
    # Operation counts: every pixel of the box yields one frame, on the skip
    # or the plot line, so each of them carries the whole test: the inner
    # loop's step and condition, and the distance as the exact integer test
    # does it (w = X - P; along = w.D; two range tests; cross = D x w;
    # 4 cross^2 against |PQ|^2). No square root is needed for the verdict.
    test = {"int_add": 5, "mul": 6, "compare": 4, "pixels_tested": 1}
    code = Code()
    code.add("box", "the bounding box of P and Q, edges included (a loop with '<' would miss "
                    "Q's column and row); walk it from P's corner to Q's",
             ops={"int_add": 3, "mul": 2, "compare": 2})
    code.add("columns", "for x = x0 .. x1:")
    code.add("rows", "    for y = y0 .. y1:")
    code.add("distance", "        dist = distance from (x, y) to the segment PQ  "
                         "(to P or Q where (x, y) lies beyond an end)")
    code.add("skip", "        if dist >= 1/2:  skip", VISIT, ops=test)
    code.add("plot", "        else:  setPixel(x, y)", PLOT, ops=test)
    code.add("done", "done")
    return code


def _segment_test(p, dx, dy, length_sq, x, y):
    """(4 * squared distance as a fraction num/den, where the nearest point lies).

    Integers only: the pixel is plotted when num < den, i.e. distance < 1/2.
    """
    wx, wy = x - p[0], y - p[1]
    along = wx * dx + wy * dy
    if along <= 0:
        return 4 * (wx * wx + wy * wy), 1, "P"
    if along >= length_sq:
        ux, uy = wx - dx, wy - dy
        return 4 * (ux * ux + uy * uy), 1, "Q"
    cross = dx * wy - dy * wx
    return 4 * cross * cross, length_sq, "inside"


def implicit(points, options):
    p, q = points
    dx, dy = q[0] - p[0], q[1] - p[1]
    length_sq = dx * dx + dy * dy
    sx, sy = sign(dx), sign(dy)
    ramp = color_ramp(options)
    at = implicit_listing(points, options).at
    yield Start(line=at["box"], values=with_color(ramp, ("dist",)),
                constants={"x0": p[0], "y0": p[1], "x1": q[0], "y1": q[1], "|PQ|^2": length_sq},
                pixel_value="rgb" if ramp else None)
    skip, plot = at["skip"], at["plot"]
    for x in range(p[0], q[0] + sx, sx):
        for y in range(p[1], q[1] + sy, sy):
            num, den, _ = _segment_test(p, dx, dy, length_sq, x, y)
            dist = math.sqrt(num / den) / 2
            if num >= den:
                yield (skip, x, y, dist, *((NAN,) if ramp else ()))
                continue
            color = (ramp.at(_projection(p, dx, dy, length_sq, x, y)),) if ramp else ()
            yield (plot, x, y, dist, *color)
    yield (at["done"], NO_PIXEL, NO_PIXEL, NAN, *((NAN,) if ramp else ()))


def _projection(p, dx, dy, length_sq, x, y) -> float:
    """Where (x, y) projects onto PQ, clamped to [0, 1]: the pixel's t for colour."""
    if not length_sq:
        return 0.0
    along = (x - p[0]) * dx + (y - p[1]) * dy
    return min(max(along, 0), length_sq) / length_sq


IMPLICIT_MAX_SIDE = 1 << 15  # keeps 4 * cross**2 well inside int64


def implicit_pixels(points, options) -> np.ndarray:
    """Fast kernel: the same integer test on the whole box, in the same order."""
    p, q = points
    dx, dy = q[0] - p[0], q[1] - p[1]
    if max(abs(dx), abs(dy)) >= IMPLICIT_MAX_SIDE:
        raise InputError(f"line-implicit: the bounding box is larger than "
                         f"{IMPLICIT_MAX_SIDE} pixels on a side")
    length_sq = dx * dx + dy * dy
    wx = (sign(dx) * np.arange(abs(dx) + 1, dtype=np.int64))[:, None]
    wy = (sign(dy) * np.arange(abs(dy) + 1, dtype=np.int64))[None, :]
    along = wx * dx + wy * dy
    to_p = 4 * (wx * wx + wy * wy)
    to_q = 4 * ((wx - dx) ** 2 + (wy - dy) ** 2)
    cross = dx * wy - dy * wx
    inside = np.where(along <= 0, to_p < 1,
                      np.where(along >= length_sq, to_q < 1, 4 * cross * cross < length_sq))
    # Row-major order of the (x, y) box is x outer, y inner, as the loops.
    xs, ys = np.nonzero(inside)
    return np.stack([p[0] + sign(dx) * xs, p[1] + sign(dy) * ys], axis=1).astype(np.int64)


def implicit_explain(trace, i):
    step = trace.step(i)
    if step.pixel is None:
        return []
    c = trace.start.constants
    p, dx, dy = (c["x0"], c["y0"]), c["x1"] - c["x0"], c["y1"] - c["y0"]
    num, den, nearest = _segment_test(p, dx, dy, c["|PQ|^2"], *step.pixel)
    verdict = "dist < 1/2: plot" if num < den else "dist >= 1/2: skip"
    if nearest == "inside":
        test = f"4*cross^2 = {num} {'<' if num < den else '>='} |PQ|^2 = {den}"
    else:
        test = f"4*|{nearest}X|^2 = {num} {'<' if num < den else '>='} 1"
    where = {"P": "P itself: the pixel projects onto P or before it",
             "Q": "Q itself: the pixel projects onto Q or beyond it",
             "inside": "a point between P and Q"}[nearest]
    return [("nearest", where), ("test", f"{test}, so {verdict}")]


LINE_IMPLICIT = AlgorithmSpec(
    name="line-implicit",
    title="Implicit form",
    family="lines",
    summary="test every pixel of the bounding box: distance to PQ below 1/2",
    inputs=SEGMENT,
    options=(COLORS,),
    code=listing(implicit_listing),
    generator=implicit,
    kernel=implicit_pixels,
    explain=implicit_explain,
    visits="box",
    notes=("The distance is to the segment, not to the infinite line. Inside the "
           "bounding box the two agree; beyond it every pixel centre is at least 1 "
           "from the segment, so the box misses nothing and the run stops at P and Q.",
           "The test is exact: 4 * cross^2 < |PQ|^2 in integers, where cross is "
           "the cross product of Q - P and X - P; the distance shown is rounded.",
           "With integer endpoints no pixel centre is ever exactly 1/2 from the "
           "segment, so the strict < never has to break a tie. Two pixels of one "
           "column can both pass, so the line is up to two pixels thick.",
           "Colours follow where each pixel projects onto PQ."),
    oracle=Oracle(
        "exact",
        "Every pixel whose centre lies closer than 1/2 px to the segment, and no other, by exact "
        "integer distances (algorithms/exact/lines.py); each pixel of the box tested once.",
        ("algorithms/lines/test_line_implicit.py", "algorithms/test_stability.py"),
        check="implicit-line"),
)


# -------------------------------------------------------- parametric form
DT = Option("dt", "float", 0.001,
            "step in t, in (0, 1]; auto takes 1/max(|dx|, |dy|), one step per pixel "
            "along the major axis", minimum=1e-6, maximum=1.0, choices=("auto",))


def parametric_listing(points, options) -> Code:
    dt = "1 / max(|dx|, |dy|)" if options["dt"] == "auto" else f"{options['dt']:g}"
    auto = options["dt"] == "auto"
    # Operation counts: each step yields one frame, on the plot line, which
    # carries the step's whole work: k += 1 and its test, t = k*dt (k/n for
    # auto), p = P + t*D and the two roundings.
    step = {"int_add": 1, "compare": 1, "mul": 2 if auto else 3, "float_add": 2, "round": 2}
    if auto:
        step["div"] = 1
    code = Code()
    code.add("setup", f"dt = {dt};  D = Q - P", ops={"int_add": 2, **({"div": 1} if auto else {})})
    code.add("loop", "for k = 0, 1, 2, ...:  t = min(k*dt, 1)   "
                     "(a whole counter k, so t does not drift; the last t is exactly 1)")
    code.add("point", "    p = P + t*D")
    code.add("plot", "    plot(round(p.x), round(p.y))", PLOT, ops=step)
    code.add("stop", "    stop after t = 1   (so Q is always plotted)")
    code.add("done", "done")
    return code


def _parametric_steps(points, options):
    """(count of t values below 1, t_k as a function of k, dt)."""
    (x0, y0), (x1, y1) = points
    if options["dt"] == "auto":
        n = max(abs(x1 - x0), abs(y1 - y0))
        # k / n rather than k * (1/n): exact at k = n, so no step lands
        # just below 1 and repeats Q.
        return (n, lambda k: k / n, 1 / n) if n else (1, lambda k: 0.0, 1.0)
    dt = options["dt"]
    below = math.ceil(1 / dt)
    while below > 1 and (below - 1) * dt >= 1:
        below -= 1
    while below * dt < 1:
        below += 1
    return below, lambda k: k * dt, dt


def parametric(points, options):
    (x0, y0), (x1, y1) = points
    dx, dy = x1 - x0, y1 - y0
    below, time, dt = _parametric_steps(points, options)
    ramp = color_ramp(options)
    at = parametric_listing(points, options).at
    yield Start(line=at["setup"], values=with_color(ramp, ("t", "duplicates", "gaps")),
                constants={"x0": x0, "y0": y0, "dx": dx, "dy": dy, "dt": dt},
                pixel_value="rgb" if ramp else None)
    seen = set()
    previous = None
    duplicates = gaps = 0
    plot = at["plot"]
    for k in range(below + 1):
        t = time(k) if k < below else 1.0
        pixel = (round_half_up(x0 + t * dx), round_half_up(y0 + t * dy))
        if pixel in seen:
            duplicates += 1
        if previous is not None and max(abs(pixel[0] - previous[0]),
                                        abs(pixel[1] - previous[1])) > 1:
            gaps += 1
        seen.add(pixel)
        previous = pixel
        yield (plot, *pixel, t, duplicates, gaps, *((ramp.at(t),) if ramp else ()))
    yield Vars(line=at["done"], values={"plots": below + 1, "pixels": len(seen),
                                        "duplicates": duplicates, "gaps": gaps})


def parametric_pixels(points, options) -> np.ndarray:
    """Fast kernel: all t at once, then the same rounding."""
    (x0, y0), (x1, y1) = points
    below, _, dt = _parametric_steps(points, options)
    k = np.arange(below, dtype=np.float64)
    if options["dt"] == "auto":
        t = k / below if max(abs(x1 - x0), abs(y1 - y0)) else k * 0.0
    else:
        t = k * dt
    t = np.append(t, 1.0)
    x = np.floor(t * (x1 - x0) + x0 + 0.5)
    y = np.floor(t * (y1 - y0) + y0 + 0.5)
    return np.stack([x, y], axis=1).astype(np.int64)


def parametric_explain(trace, i):
    step = trace.step(i)
    if step.pixel is None or "t" not in step.values:
        return []
    c = trace.start.constants
    t = step.values["t"]
    rows = [("p", f"({c['x0'] + t * c['dx']:.6g}, {c['y0'] + t * c['dy']:.6g}) "
                  f"rounds to {step.pixel}")]
    if i < 2:
        return rows
    before = trace.step(i - 1)
    if step.values["duplicates"] > before.values.get("duplicates", 0):
        rows.append(("duplicate", f"{step.pixel} was plotted before"))
    elif step.values["gaps"] > before.values.get("gaps", 0):
        rows.append(("gap", f"{before.pixel} to {step.pixel} skips at least one pixel"))
    return rows


LINE_PARAMETRIC = AlgorithmSpec(
    name="line-parametric",
    title="Parametric form",
    family="lines",
    summary="p = P + t (Q - P) for t in steps of dt; plot round(p)",
    inputs=SEGMENT,
    options=(DT, COLORS),
    code=listing(parametric_listing),
    generator=parametric,
    kernel=parametric_pixels,
    explain=parametric_explain,
    notes=("round(v) is floor(v + 1/2): halves round up.",
           "A duplicate is a plot of a pixel that was already plotted, at the step "
           "before or at any earlier one; duplicates counts them.",
           "A gap is a jump between two consecutive distinct plots whose pixels are "
           "not 8-neighbours (they share no edge or corner); gaps counts the jumps, "
           "one per jump however many pixels it skips.",
           "Too small a dt wastes work on duplicates; too large a dt leaves gaps. "
           "dt = auto takes one step per pixel along the major axis and leaves no gaps."),
    oracle=Oracle(
        "exact",
        "Each pixel is P + t (Q - P) rounded, computed exactly from the run's t (which must be k/n "
        "or k dt, ending at 1), either neighbour within 1e-9 of a half; duplicates and gaps "
        "recounted from the pixels. With dt auto, the pixel nearest the ideal line in every "
        "column.",
        ("algorithms/lines/test_line_parametric.py", "algorithms/test_stability.py"),
        check="parametric-line"),
)

# The module's algorithms, in the order they are listed.
SPECS = (LINE_INCREMENTAL, LINE_EXPLICIT, LINE_IMPLICIT, LINE_PARAMETRIC)
