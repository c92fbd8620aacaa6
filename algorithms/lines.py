"""The line family: step generators (and fast kernels) for segments P -> Q.

Points are integer pixel coordinates; pixel (i, j) is the ideal line's
sample point at (i + 1/2, j + 1/2), so the ideal segment runs between the
centres of the two end pixels. Every algorithm plots both end pixels.
"""
from __future__ import annotations

import math

import numpy as np

from .registry import AlgorithmSpec, InputError, Inputs, Option, register
from .steps import NO_PIXEL, PLOT, CodeLine, Start

NAN = math.nan

COLORS = Option("colors", "colors", (), "endpoint colours #rrggbb,#rrggbb; the colour "
                "of each pixel is interpolated linearly in t along the segment")
SEGMENT = Inputs(2, integer=True, names=("P", "Q"))


# ------------------------------------------------------------- shared parts
class ColorRamp:
    """Linear interpolation between two colours, packed as 0xRRGGBB."""

    def __init__(self, first: str, last: str):
        self.first = _unpack_hex(first)
        self.last = _unpack_hex(last)

    def at(self, t: float) -> int:
        channels = [round(a + (b - a) * t) for a, b in zip(self.first, self.last)]
        return (channels[0] << 16) | (channels[1] << 8) | channels[2]


def _unpack_hex(text: str) -> tuple[int, int, int]:
    value = int(text[1:], 16)
    return (value >> 16) & 255, (value >> 8) & 255, value & 255


def color_ramp(options: dict) -> ColorRamp | None:
    colors = options.get("colors") or ()
    if not colors:
        return None
    if len(colors) != 2:
        raise InputError("option colors: give two colours, one for each endpoint")
    return ColorRamp(*colors)


def hex_color(packed: float) -> str:
    return f"#{int(packed):06x}"


def round_half_up(value: float) -> int:
    """Nearest integer, halves rounded up (floor(v + 1/2))."""
    return math.floor(value + 0.5)


class Octant:
    """How a segment maps into the first octant (0 <= slope <= 1, left to right).

    The major axis is the one with the larger extent. ``major`` and
    ``minor`` are unit steps in the original grid; the mapped segment runs
    from (0, 0) to (dx, dy) with 0 <= dy <= dx.
    """

    def __init__(self, p, q):
        ddx, ddy = q[0] - p[0], q[1] - p[1]
        self.steep = abs(ddy) > abs(ddx)
        sx = 1 if ddx >= 0 else -1
        sy = 1 if ddy >= 0 else -1
        if self.steep:
            self.dx, self.dy = abs(ddy), abs(ddx)
            self.major, self.minor = (0, sy), (sx, 0)
        else:
            self.dx, self.dy = abs(ddx), abs(ddy)
            self.major, self.minor = (sx, 0), (0, sy)
        # +1 when the minor coordinate grows from P towards Q.
        self.minor_sign = self.minor[0] + self.minor[1]
        self.number = _octant_number(ddx, ddy)

    def to_grid(self, p, u, v):
        """Mapped (u, v) back to the original grid, from P."""
        return (p[0] + u * self.major[0] + v * self.minor[0],
                p[1] + u * self.major[1] + v * self.minor[1])


def _octant_number(ddx: int, ddy: int) -> int:
    """Octant 1..8 counter-clockwise from the +x axis (0 for a point)."""
    if ddx == 0 and ddy == 0:
        return 0
    angle = math.atan2(ddy, ddx) % (2 * math.pi)
    return min(8, int(angle // (math.pi / 4)) + 1)


def _with_color(ramp, names):
    return names + ("rgb",) if ramp else names


# ---------------------------------------------------------------- Bresenham
def bresenham_code(points, options):
    ties_to_e = _bresenham_ties_to_e(points, options)
    test = "d <= 0" if ties_to_e else "d < 0"
    return (
        CodeLine("map P, Q into octant 1 (swap x and y if steep, mirror negative steps)"),
        CodeLine("dx = x1 - x0;  dy = y1 - y0;  incrE = 2*dy;  incrNE = 2*(dy - dx)"),
        CodeLine("d = 2*dy - dx;  x, y = x0, y0;  plot(x, y)", PLOT),
        CodeLine("while x < x1:        (the loop runs to x1, so Q is plotted)"),
        CodeLine(f"    if {test}:  d += incrE;  x += 1;  plot(x, y)", PLOT, "E"),
        CodeLine("    else:  d += incrNE;  x += 1;  y += 1;  plot(x, y)", PLOT, "NE"),
        CodeLine("done"),
    )


def _bresenham_ties_to_e(points, options) -> bool:
    # The textbook sends a tie (d = 0) to E. Mirrored back, that rounds the
    # minor coordinate towards P's side, so P->Q and Q->P can differ. With
    # `symmetric`, ties always round the minor coordinate down instead.
    if not options.get("symmetric"):
        return True
    return Octant(*points).minor_sign > 0


def bresenham(points, options):
    p, q = points
    octant = Octant(p, q)
    dx, dy = octant.dx, octant.dy
    incr_e, incr_ne = 2 * dy, 2 * (dy - dx)
    # d is an integer, so "d < 0" is "d <= -1".
    limit = 0 if _bresenham_ties_to_e(points, options) else -1
    ramp = color_ramp(options)
    yield Start(1, _with_color(ramp, ("d",)),
                {"dx": dx, "dy": dy, "incrE": incr_e, "incrNE": incr_ne,
                 "octant": octant.number, "steep": octant.steep},
                "rgb" if ramp else None,
                (octant.major, (octant.major[0] + octant.minor[0], octant.major[1] + octant.minor[1])),
                "d")
    if ramp:
        yield from _bresenham_colored(p, octant, limit, ramp)
        return
    (ex, ey), (nx, ny) = octant.major, octant.minor
    nx, ny = nx + ex, ny + ey
    x, y = p
    d = 2 * dy - dx
    yield (2, x, y, d)
    # Each frame carries the d that decided it (d_i); d_i+1 is the next frame's.
    for _ in range(dx):
        if d <= limit:
            x += ex
            y += ey
            yield (4, x, y, d)
            d += incr_e
        else:
            x += nx
            y += ny
            yield (5, x, y, d)
            d += incr_ne
    yield (6, NO_PIXEL, NO_PIXEL, d)


def _bresenham_colored(p, octant, limit, ramp):
    dx, dy = octant.dx, octant.dy
    d = 2 * dy - dx
    v = 0
    yield (2, p[0], p[1], d, ramp.at(0.0))
    for u in range(1, dx + 1):
        before = d
        if d <= limit:
            line, d = 4, d + 2 * dy
        else:
            line, d, v = 5, d + 2 * (dy - dx), v + 1
        yield (line, *octant.to_grid(p, u, v), before, ramp.at(u / dx))
    yield (6, NO_PIXEL, NO_PIXEL, d, NAN)


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


register(AlgorithmSpec(
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
))


# ---------------------------------------------------------------------- DDA
def dda_code(points, options):
    return (
        CodeLine("dx = x1 - x0;  dy = y1 - y0;  steps = max(|dx|, |dy|)"),
        CodeLine(f"x_inc = dx / steps;  y_inc = dy / steps   (one is +-1, the other m or 1/m; {options['dtype']})"),
        CodeLine("x, y = x0, y0;  plot(round(x), round(y))", PLOT),
        CodeLine("repeat steps times:"),
        CodeLine("    x += x_inc;  y += y_inc;  plot(round(x), round(y))", PLOT),
        CodeLine("done"),
    )


def dda(points, options):
    (x0, y0), (x1, y1) = points
    real = np.float32 if options["dtype"] == "float32" else np.float64
    steps = max(abs(x1 - x0), abs(y1 - y0))
    x_inc = real(x1 - x0) / real(steps) if steps else real(0)
    y_inc = real(y1 - y0) / real(steps) if steps else real(0)
    ramp = color_ramp(options)
    yield Start(1, _with_color(ramp, ("x", "y")),
                {"dx": x1 - x0, "dy": y1 - y0, "steps": steps,
                 "x_inc": float(x_inc), "y_inc": float(y_inc), "dtype": options["dtype"]},
                "rgb" if ramp else None)
    x, y = real(x0), real(y0)
    color = (ramp.at(0.0),) if ramp else ()
    yield (2, x0, y0, float(x), float(y), *color)
    for k in range(1, steps + 1):
        x = real(x + x_inc)
        y = real(y + y_inc)
        color = (ramp.at(k / steps),) if ramp else ()
        yield (4, round_half_up(float(x)), round_half_up(float(y)), float(x), float(y), *color)
    yield (5, NO_PIXEL, NO_PIXEL, float(x), float(y), *((NAN,) if ramp else ()))


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


register(AlgorithmSpec(
    name="line-dda",
    title="DDA",
    family="lines",
    summary="digital differential analyser: add the slope, round each step",
    inputs=SEGMENT,
    options=(Option("dtype", "choice", "float64", "float type of the accumulators",
                    choices=("float64", "float32")), COLORS),
    code=dda_code,
    generator=dda,
    kernel=dda_pixels,
    notes=("round(v) is floor(v + 1/2): halves round up.",),
))
