"""Bresenham's integer line and the DDA: incremental steps along the major axis."""
from __future__ import annotations

from itertools import chain

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, Start
from .common import COLORS, SEGMENT, Octant, color_ramp, colored, round_half_up, with_color


# ---------------------------------------------------------------- Bresenham
def bresenham_listing(points, options) -> Code:
    ties_to_e = _bresenham_ties_to_e(points, options)
    test = "d <= 0" if ties_to_e else "d < 0"
    # Operation counts (CodeLine.ops): the first frame stands on the setup
    # line, so the octant mapping (two subtractions, three tests) is counted
    # there; doubling is an addition. The loop test is counted on the E and
    # NE lines, one of which every iteration runs.
    code = Code()
    code.add("map", "map P, Q into octant 1 (swap x and y if steep, mirror negative steps)")
    code.add("setup", "dx = x1 - x0;  dy = y1 - y0;  incrE = 2*dy;  incrNE = 2*(dy - dx)",
             ops={"int_add": 5, "compare": 3})
    code.add("plot_first", "d = 2*dy - dx;  x, y = x0, y0;  plot(x, y)", PLOT, ops={"int_add": 2})
    code.add("loop", "while x < x1:        (the loop runs to x1, so Q is plotted)")
    code.add("plot_e", f"    if {test}:  d += incrE;  x += 1;  plot(x, y)", PLOT, "E",
             ops={"int_add": 2, "compare": 2})
    code.add("plot_ne", "    else:  d += incrNE;  x += 1;  y += 1;  plot(x, y)", PLOT, "NE",
             ops={"int_add": 3, "compare": 2})
    code.add("done", "done")
    return code


bresenham_code = listing(bresenham_listing)


def _bresenham_ties_to_e(points, options) -> bool:
    # The textbook sends a tie (d = 0) to E. Mirrored back, that rounds the
    # minor coordinate towards P's side, so P->Q and Q->P can differ. With
    # `symmetric`, ties always round the minor coordinate down instead.
    if not options.get("symmetric"):
        return True
    return Octant(*points).minor_sign > 0


def bresenham(points, options):
    """The Start record, then the loop's frames (each plot with its colour
    when colours are given). Chained, not yielded from a generator, so a
    million-step line pays nothing per frame for the two parts."""
    p, q = points
    octant = Octant(p, q)
    dx, dy = octant.dx, octant.dy
    at = bresenham_listing(points, options).at
    ramp = color_ramp(options)
    start = Start(line=at["setup"], values=with_color(ramp, ("d",)),
                  constants={"dx": dx, "dy": dy, "incrE": 2 * dy, "incrNE": 2 * (dy - dx),
                             "octant": octant.number, "steep": octant.steep},
                  pixel_value="rgb" if ramp else None,
                  candidates=(octant.major, (octant.major[0] + octant.minor[0],
                                             octant.major[1] + octant.minor[1])),
                  decision="d")
    # d is an integer, so "d < 0" is "d <= -1".
    limit = 0 if _bresenham_ties_to_e(points, options) else -1
    frames = _bresenham_frames(p, octant, limit, at)
    return chain((start,), colored(frames, ramp, dx) if ramp else frames)


def _bresenham_frames(p, octant, limit, at):
    """The textbook loop in octant 1, each pixel mapped back as it is plotted."""
    dx, dy = octant.dx, octant.dy
    incr_e, incr_ne = 2 * dy, 2 * (dy - dx)
    (ex, ey), (nx, ny) = octant.major, octant.minor
    nx, ny = nx + ex, ny + ey
    east, north_east = at["plot_e"], at["plot_ne"]
    x, y = p
    d = 2 * dy - dx
    yield (at["plot_first"], x, y, d)
    # Each frame carries the d that decided it (d_i); d_i+1 is the next frame's.
    for _ in range(dx):
        if d <= limit:
            x += ex
            y += ey
            yield (east, x, y, d)
            d += incr_e
        else:
            x += nx
            y += ny
            yield (north_east, x, y, d)
            d += incr_ne
    yield (at["done"], NO_PIXEL, NO_PIXEL, d)


def bresenham_pixels(points, options) -> np.ndarray:
    """Fast kernel: the same pixels in closed form, (n, 2) int64."""
    p, q = points
    octant = Octant(p, q)
    dx, dy = octant.dx, octant.dy
    u = np.arange(dx + 1, dtype=np.int64)
    if dx == 0:
        v = np.zeros(1, dtype=np.int64)
    elif _bresenham_ties_to_e(points, options):
        v = -((dx - 2 * dy * u) // (2 * dx))  # ceil(dy*u/dx - 1/2): ties round down
    else:
        v = (2 * dy * u + dx) // (2 * dx)  # floor(dy*u/dx + 1/2): ties round up
    x = p[0] + u * octant.major[0] + v * octant.minor[0]
    y = p[1] + u * octant.major[1] + v * octant.minor[1]
    return np.stack([x, y], axis=1)


def bresenham_explain(trace, i):
    """The decision at step i and the update it makes to d."""
    step = trace.step(i)
    if not step.branch or "d" not in step.values:
        return []
    d = int(step.values["d"])
    constants = trace.start.constants
    name = "incrE" if step.branch == "E" else "incrNE"
    increment = constants[name]
    relation = ">" if d > 0 else ("<" if d < 0 else "=")
    return [("decision", f"d_i = {d} {relation} 0, so {step.branch}"),
            ("update", f"d_i+1 = d_i + {name} = {d} + ({increment}) = {d + increment}")]


LINE_BRESENHAM = AlgorithmSpec(
    name="line-bresenham",
    title="Bresenham",
    family="lines",
    summary="integer decision variable d; E or NE at each step",
    inputs=SEGMENT,
    options=(Option("symmetric", "bool", False,
                    "break ties so that P->Q and Q->P give the same pixels"), COLORS),
    code=bresenham_code,
    generator=bresenham,
    kernel=bresenham_pixels,
    explain=bresenham_explain,
    notes=("The textbook loop is written for octant 1; other octants are mapped "
           "there and each plotted pixel is mapped back.",),
    oracle=Oracle(
        "exact",
        "The pixel nearest the ideal line in every column, from exact rational arithmetic "
        "(algorithms/exact/lines.py): ties toward P, or down with symmetric. scikit-image's line "
        "agrees but for its other tie rule.",
        ("algorithms/lines/test_line_bresenham.py", "algorithms/lines/test_line_skimage.py",
         "algorithms/test_stability.py"),
        check="nearest-line"),
)


# ---------------------------------------------------------------------- DDA
def dda_listing(points, options) -> Code:
    # Operation counts: the first line runs before the first frame (on the
    # increments line) and is counted there; the loop's counter and test on
    # the loop body's line.
    code = Code()
    code.add("setup", "dx = x1 - x0;  dy = y1 - y0;  steps = max(|dx|, |dy|)")
    code.add("increments", "x_inc = dx / steps;  y_inc = dy / steps   (one is +-1, the other m "
                           f"or 1/m; {options['dtype']})",
             ops={"int_add": 2, "compare": 3, "div": 2})
    code.add("plot_first", "x, y = x0, y0;  plot(round(x), round(y))", PLOT, ops={"round": 2})
    code.add("loop", "repeat steps times:")
    code.add("plot_step", "    x += x_inc;  y += y_inc;  plot(round(x), round(y))", PLOT,
             ops={"float_add": 2, "round": 2, "int_add": 1, "compare": 1})
    code.add("done", "done")
    return code


def dda(points, options):
    """The Start record, then the loop's frames, chained as Bresenham's are."""
    (x0, y0), (x1, y1) = points
    real = np.float32 if options["dtype"] == "float32" else np.float64
    steps = max(abs(x1 - x0), abs(y1 - y0))
    x_inc = real(x1 - x0) / real(steps) if steps else real(0)
    y_inc = real(y1 - y0) / real(steps) if steps else real(0)
    ramp = color_ramp(options)
    at = dda_listing(points, options).at
    start = Start(line=at["increments"], values=with_color(ramp, ("x", "y")),
                  constants={"dx": x1 - x0, "dy": y1 - y0, "steps": steps, "x_inc": float(x_inc),
                             "y_inc": float(y_inc), "dtype": options["dtype"]},
                  pixel_value="rgb" if ramp else None)
    frames = _dda_frames(points, real, steps, x_inc, y_inc, at)
    return chain((start,), colored(frames, ramp, steps) if ramp else frames)


def _dda_frames(points, real, steps, x_inc, y_inc, at):
    (x0, y0), _ = points
    x, y = real(x0), real(y0)
    yield (at["plot_first"], x0, y0, float(x), float(y))
    step = at["plot_step"]
    for _ in range(steps):
        x = real(x + x_inc)
        y = real(y + y_inc)
        yield (step, round_half_up(float(x)), round_half_up(float(y)), float(x), float(y))
    yield (at["done"], NO_PIXEL, NO_PIXEL, float(x), float(y))


def dda_pixels(points, options) -> np.ndarray:
    """Fast kernel: sequential float accumulation with np.add.accumulate."""
    (x0, y0), (x1, y1) = points
    real = np.float32 if options["dtype"] == "float32" else np.float64
    steps = max(abs(x1 - x0), abs(y1 - y0))
    if steps == 0:
        return np.array([[x0, y0]], dtype=np.int64)
    columns = []
    for start, delta in ((x0, x1 - x0), (y0, y1 - y0)):
        terms = np.full(steps + 1, real(delta) / real(steps), dtype=real)
        terms[0] = real(start)
        # add.accumulate adds left to right, exactly as the loop does.
        columns.append(np.floor(np.add.accumulate(terms).astype(np.float64) + 0.5))
    return np.stack(columns, axis=1).astype(np.int64)


LINE_DDA = AlgorithmSpec(
    name="line-dda",
    title="DDA",
    family="lines",
    summary="digital differential analyser: add the slope, round each step",
    inputs=SEGMENT,
    options=(Option("dtype", "choice", "float64", "float type of the accumulators",
                    choices=("float64", "float32")), COLORS),
    code=listing(dda_listing),
    generator=dda,
    kernel=dda_pixels,
    notes=("round(v) is floor(v + 1/2): halves round up.",),
    oracle=Oracle(
        "exact",
        "With float64, each pixel is the exact point after k of n equal steps from P to Q, rounded "
        "(either neighbour at an exact half). With float32, only both end pixels, on short "
        "segments near the origin; a test shows it drifting on a long line.",
        ("algorithms/lines/test_line_float_forms.py", "algorithms/test_stability.py"),
        check="dda-line"),
)

# The module's algorithms, in the order they are listed.
SPECS = (LINE_BRESENHAM, LINE_DDA)
