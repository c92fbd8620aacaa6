"""Circles and curves beyond the integer-centre circles: the distance test in
a bounding box (real centre and radius; a disk or its outline), Wu's
antialiased circle, and a cubic Bezier curve drawn as N short lines.

Real coordinates follow the triangles' convention: pixel (i, j) has its
sample point at (i + 1/2, j + 1/2).
"""
from __future__ import annotations

import math
from fractions import Fraction

from algorithms.circles.midpoint import CENTRE, PLOT_OPS, RADIUS, _centre, mirrors8
from algorithms.core.code import Code, listing
from algorithms.lines.bresenham import bresenham_pixels
from algorithms.core.registry import AlgorithmSpec, Inputs, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Start, Vars

NAN = math.nan


# --------------------------------------- circle by distance, real centre
REAL_CENTRE = Inputs(1, integer=False, names=("C",))
MAX_REAL_RADIUS = 256  # the box holds (2R + 1)^2 pixels, each one step or two
REAL_RADIUS = Option("radius", "float", 6.5, "radius in pixels (any real number)",
                     minimum=0, maximum=MAX_REAL_RADIUS)
SHAPE = Option("shape", "choice", "disk",
               "disk: every pixel whose centre is within R; outline: those of them with a "
               "4-neighbour outside", choices=("disk", "outline"))


class DistanceTest:
    """Inside tests of pixel centres in exact integers.

    The centre and radius are binary fractions (floats), so scaled by a
    common power of two they are whole numbers: 2D(i + 1/2) - 2D cx is then
    a whole number too, and the test (2D dx)^2 + (2D dy)^2 <= (2D R)^2 is exact.
    """

    def __init__(self, centre, radius):
        parts = [Fraction(v) for v in (*centre, radius)]
        self.scale = 2 * math.lcm(*(p.denominator for p in parts))
        self.cx, self.cy, r = (int(p * self.scale) for p in parts)
        self.r2 = r * r
        half = self.scale // 2
        self.half = half

    def d2(self, i: int, j: int) -> int:
        """Squared distance of pixel (i, j)'s centre from the centre, scaled by scale^2."""
        dx = i * self.scale + self.half - self.cx
        dy = j * self.scale + self.half - self.cy
        return dx * dx + dy * dy

    def inside(self, i: int, j: int) -> bool:
        return self.d2(i, j) <= self.r2

    def box(self, centre, radius) -> tuple[range, range]:
        """Columns and rows whose centres can be within the radius."""
        (cx, cy), r = centre, radius
        return (range(math.ceil(cx - r - 0.5) - 1, math.floor(cx + r - 0.5) + 2),
                range(math.ceil(cy - r - 0.5) - 1, math.floor(cy + r - 0.5) + 2))


def distance_listing(points, options) -> Code:
    outline = options["shape"] == "outline"
    code = Code()
    code.add("setup", "box = the pixels whose centres can lie within R of C",
             ops={"float_add": 4, "round": 4})
    code.add("visit", "for each pixel (i, j) of the box:  d2 = (i + 1/2 - cx)^2 + (j + 1/2 - cy)^2",
             VISIT, ops={"float_add": 4, "mul": 2, "pixels_tested": 1})
    if outline:
        code.add("plot_inside", "    if d2 <= R^2 and a 4-neighbour's d2 > R^2:  plot (i, j)",
                 PLOT, ops={"compare": 5, "float_add": 16, "mul": 8})
    else:
        code.add("plot_inside", "    if d2 <= R^2:  plot (i, j)", PLOT, ops={"compare": 1})
    code.add("done", "done")
    return code


def distance_circle(points, options):
    centre = tuple(points[0])
    radius = options["radius"]
    outline = options["shape"] == "outline"
    test = DistanceTest(centre, radius)
    at = distance_listing(points, options).at
    scale2 = test.scale * test.scale
    yield Start(line=at["setup"], values=("d2", "inside"),
                constants={"cx": centre[0], "cy": centre[1], "R": radius, "R2": radius * radius,
                           "shape": options["shape"]})
    columns, rows = test.box(centre, radius)
    visit, plot = at["visit"], at["plot_inside"]
    written = 0
    for j in rows:
        for i in columns:
            d2 = test.d2(i, j)
            inside = d2 <= test.r2
            yield (visit, i, j, d2 / scale2, float(inside))
            if inside and (not outline or not all(test.inside(i + a, j + b) for a, b in
                                                   ((1, 0), (-1, 0), (0, 1), (0, -1)))):
                written += 1
                yield (plot, i, j, d2 / scale2, 1.0)
    yield Vars(line=at["done"], values={"pixels": written,
                                        "box": len(columns) * len(rows)})


CIRCLE_DISTANCE = AlgorithmSpec(
    name="circle-distance",
    title="Circle by distance, real centre",
    family="circles",
    summary="every pixel of the bounding box whose centre lies within R: a disk or its outline",
    inputs=REAL_CENTRE,
    options=(REAL_RADIUS, SHAPE),
    code=listing(distance_listing),
    generator=distance_circle,
    notes=("Centre and radius may be fractions of a pixel, unlike the midpoint circle's. "
           "The test is exact: the centre and radius are scaled to whole numbers first.",
           "A pixel centre exactly on the circle counts as inside.",
           "The outline is the disk's pixels with a 4-neighbour outside: 8-connected and "
           "one pixel thin."),
    oracle=Oracle(
        "exact",
        "The pixels whose centres lie within R of the real centre (disk), or those of them with a "
        "4-neighbour outside (outline), in exact Fractions.",
        ("algorithms/circles/test_curves.py", "algorithms/test_stability.py"),
        check="disk"),
)


# ------------------------------------------------------- Wu's circle
def wu_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "x = 0   (offsets from the centre; the octant from (0, R) to the diagonal)")
    code.add("loop", "while x <= h:   h = sqrt(R^2 - x^2);  y = floor(h);  f = h - y",
             ops={"mul": 1, "int_add": 1, "sqrt": 1, "round": 1, "float_add": 1, "compare": 1})
    code.add("plot_near", "    plot the mirrors of (x, y) with intensity 1 - f", PLOT,
             ops={**PLOT_OPS, "float_add": 1})
    code.add("plot_far", "    plot the mirrors of (x, y + 1) with intensity f", PLOT, ops=PLOT_OPS)
    code.add("zero", "    (f = 0: the circle passes through the centre of (x, y); nothing for "
                     "y + 1)", VISIT)
    code.add("next", "    x += 1", ops={"int_add": 1})
    code.add("done", "done")
    return code


def wu_circle(points, options):
    xc, yc = _centre(points)
    r = options["radius"]
    at = wu_listing(points, options).at
    yield Start(line=at["setup"], values=("x", "h", "f", "intensity", "rgb"),
                constants={"xc": xc, "yc": yc, "R": r},
                pixel_value="intensity", color_value="rgb")
    x = written = 0
    while True:
        h = math.sqrt(max(r * r - x * x, 0))  # R = 0 reaches x = 1
        yield (at["loop"], xc + x, yc + math.floor(h), x, h, NAN, NAN, NAN)
        if x > h:
            break
        y = math.isqrt(r * r - x * x)  # floor(h), exactly
        f = h - y
        for line, offset, intensity in ((at["plot_near"], 0, 1 - f), (at["plot_far"], 1, f)):
            if intensity <= 0:
                yield (at["zero"], xc + x, yc + y + offset, x, h, f, 0.0, NAN)
                continue
            for dx, dy in mirrors8(x, y + offset):
                written += 1
                yield (line, xc + dx, yc + dy, x, h, f, intensity, grey_ink(intensity))
        x += 1
        yield (at["next"], NO_PIXEL, NO_PIXEL, x, NAN, NAN, NAN, NAN)
    yield Vars(line=at["done"], values={"pixels": written})


def grey_ink(intensity: float) -> float:
    """Black ink over white by the intensity, packed 0xRRGGBB."""
    level = round(255 * (1 - intensity))
    return float(level * 0x10101)


CIRCLE_WU = AlgorithmSpec(
    name="circle-wu",
    title="Wu's antialiased circle",
    family="circles",
    summary="two pixels per column, y and y + 1, sharing the intensity by where the arc passes",
    inputs=CENTRE,
    options=(RADIUS,),
    code=listing(wu_listing),
    generator=wu_circle,
    notes=("In each column of the octant the arc's height h lies between the centres of "
           "y = floor(h) and y + 1; they get 1 - f and f, so a column's intensities add up "
           "to 1.",
           "Near the diagonal the octant's pixels and their mirrors meet: a pixel written "
           "twice keeps the last intensity, as the raster keeps the last write."),
    oracle=Oracle(
        "exact",
        "The pixels floor(h) and floor(h) + 1 of each octant column, h = sqrt(R^2 - x^2), from "
        "integer square roots, mirrored 8 ways; the intensities give h to within 1e-9 and add up "
        "to 1 per column.",
        ("algorithms/circles/test_curves.py", "algorithms/test_stability.py"),
        check="wu-circle"),
)


# ------------------------------------------ a cubic Bezier as N lines
SEGMENTS = Option("segments", "int", 8, "number of short lines the curve is cut into",
                  minimum=1, maximum=1024)
BEZIER = Inputs(4, integer=True, names=("P0", "P1", "P2", "P3"))


def bezier_point(points, t: Fraction) -> tuple[Fraction, Fraction]:
    """B(t) = (1-t)^3 P0 + 3(1-t)^2 t P1 + 3(1-t) t^2 P2 + t^3 P3, exactly."""
    s = 1 - t
    weights = (s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t)
    return (sum(w * p[0] for w, p in zip(weights, points)),
            sum(w * p[1] for w, p in zip(weights, points)))


def _round(value: Fraction) -> int:
    return math.floor(value + Fraction(1, 2))  # halves up, as the line family rounds


def bezier_listing(points, options) -> Code:
    code = Code()
    code.add("setup", f"N = {options['segments']};  Q0 = round(B(0)) = P0")
    code.add("loop", "for k = 1 .. N:  Q_k = round(B(k / N))   (B(t) = sum of the Bernstein "
                     "weights times P0..P3)", ops={"mul": 14, "float_add": 8, "round": 2})
    code.add("plot_segment", "    draw the line Q_k-1 Q_k with Bresenham (its first pixel is "
                             "the last one's end)", PLOT, ops=PLOT_OPS)
    code.add("done", "done")
    return code


def bezier_curve(points, options):
    n = options["segments"]
    at = bezier_listing(points, options).at
    yield Start(line=at["setup"], values=("k", "t", "bx", "by"),
                constants={"N": n, "P0": points[0], "P3": points[3]})
    before = tuple(points[0])
    yield (at["plot_segment"], before[0], before[1], 0, 0.0, float(before[0]), float(before[1]))
    written = 1
    for k in range(1, n + 1):
        t = Fraction(k, n)
        bx, by = bezier_point(points, t)
        here = (_round(bx), _round(by))
        values = (k, float(t), float(bx), float(by))
        yield (at["loop"], here[0], here[1], *values)
        for x, y in bresenham_pixels((before, here), {}).tolist()[1:]:
            written += 1
            yield (at["plot_segment"], x, y, *values)
        before = here
    yield Vars(line=at["done"], values={"pixels": written, "segments": n})


CURVE_BEZIER = AlgorithmSpec(
    name="curve-bezier",
    title="Cubic Bezier as N lines",
    family="circles",
    summary="the curve's points at t = k/N, rounded, joined by Bresenham lines",
    inputs=BEZIER,
    options=(SEGMENTS,),
    code=listing(bezier_listing),
    generator=bezier_curve,
    notes=("Few segments show the polygon under the curve: its corners sit on the curve, "
           "its sides cut across the bends. More segments follow the curve closer, until a "
           "segment is shorter than a pixel and plots nothing new.",
           "B(k/N) is computed exactly and rounded halves up."),
    oracle=Oracle(
        "exact",
        "The curve's points B(k/N) by de Casteljau in Fractions, rounded, joined by the exact "
        "nearest-pixel lines (algorithms/exact/lines.py), pixel for pixel in order.",
        ("algorithms/circles/test_curves.py", "algorithms/test_stability.py"),
        check="bezier-polyline"),
)

# The module's algorithms, in the order they are listed.
SPECS = (CIRCLE_DISTANCE, CIRCLE_WU, CURVE_BEZIER)
