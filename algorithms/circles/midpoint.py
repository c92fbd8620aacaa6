"""The circle family: circles by 4- and 8-way symmetry, the midpoint circle
and the two-region midpoint ellipse.

The centre is an integer point. Pixel (i, j) has its sample point at
(i + 1/2, j + 1/2), and so has the centre's pixel, so with an integer centre
every pixel sits at a whole-number offset (x, y) from the centre: the
algorithms work on offsets and plot pixel (xc + x, yc + y). Pixels past the
grid's edge are clipped by the raster (``written_pixels`` keeps them).
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Inputs, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, Start, Vars

NAN = math.nan
MAX_RADIUS = 4096

CENTRE = Inputs(1, integer=True, names=("C",))
RADIUS = Option("radius", "int", 8, "radius in pixels", minimum=0, maximum=MAX_RADIUS)

E_SE = ((1, 0), (1, -1))  # offsets of E and SE from the current pixel
# Operations of one plot at an offset: centre + offset, two additions.
PLOT_OPS = {"int_add": 2}
S_SW = ((0, -1), (1, -1))


# ------------------------------------------------------------- shared parts
def mirrors8(x: int, y: int) -> tuple:
    """The distinct images of offset (x, y) under the circle's 8 symmetries.

    In drawing order, (x, y) first. On the axes (x == 0) and on the diagonal
    (x == y) two images coincide, so only four are left; at (0, 0) one.
    """
    return tuple(dict.fromkeys(((x, y), (y, x), (y, -x), (x, -y),
                                (-x, -y), (-y, -x), (-y, x), (-x, y))))


def mirrors4(x: int, y: int) -> tuple:
    """The distinct images of (x, y) under the 4 axis symmetries."""
    return tuple(dict.fromkeys(((x, y), (x, -y), (-x, y), (-x, -y))))


def root_floor(n: int) -> int:
    """floor(sqrt(n)) of a whole number, exactly.

    For n up to 4096^2 a float sqrt (even single precision, as the C code's
    cast uses) floors to the same integer, so this is what the cast gives.
    """
    return math.isqrt(n)


def _centre(points):
    (xc, yc), = points
    return xc, yc


class ArcWatch:
    """Counts gaps and repeats of a circle drawn arc by arc.

    A gap is a step along one mirrored arc between two consecutive pixels
    that are not 8-neighbours; ``missing`` adds up the pixels such a step
    skips (the longer coordinate difference minus one). A duplicate is a
    plot of a pixel plotted before.
    """

    def __init__(self):
        self.gaps = self.missing = self.duplicates = 0
        self.columns = []  # first-arc columns where a gap ends
        self.seen = set()

    def step(self, before, after, images: int, first: bool = True) -> None:
        """One step from ``before`` to ``after`` on ``images`` mirrored arcs.

        ``first`` marks the image whose column goes into gap_columns.
        """
        jump = max(abs(after[0] - before[0]), abs(after[1] - before[1]))
        if jump > 1:
            self.gaps += images
            self.missing += images * (jump - 1)
            if first:
                self.columns.append(after[0])

    def plot(self, offset) -> None:
        if offset in self.seen:
            self.duplicates += 1
        self.seen.add(offset)

    def summary(self) -> dict:
        return {"gaps": self.gaps, "missing": self.missing, "duplicates": self.duplicates,
                "pixels": len(self.seen), "gap_columns": tuple(self.columns)}


# -------------------------------------------------- 4-way symmetry (sqrt)
def sqrt4_listing(points, options) -> Code:
    # Operation counts: a plot adds the offset to the centre (two
    # additions); the loop's step and test are counted on the root's line.
    code = Code()
    code.add("setup", "r2 = r*r   (offsets (x, y) from the centre)", ops={"mul": 1})
    code.add("plot_poles", "plot (0, r) and (0, -r)", PLOT, ops=PLOT_OPS)
    code.add("loop", "for x = 1 .. r:")
    code.add("root", "    y = floor(sqrt(r2 - x*x))      (the cast to int)",
             ops={"mul": 1, "int_add": 2, "sqrt": 1, "round": 1, "compare": 1})
    code.add("plot_mirrors", "    plot (x, y), (x, -y), (-x, y), (-x, -y)", PLOT, ops=PLOT_OPS)
    code.add("done", "done")
    return code


def sqrt4(points, options):
    xc, yc = _centre(points)
    r = options["radius"]
    watch = ArcWatch()
    at = sqrt4_listing(points, options).at
    yield Start(line=at["setup"], values=("x", "y", "gaps", "duplicates"),
                constants={"xc": xc, "yc": yc, "r": r, "r2": r * r})
    for offset in ((0, r), (0, -r)):
        watch.plot(offset)
        yield (at["plot_poles"], xc + offset[0], yc + offset[1], 0, r, 0, watch.duplicates)
    before = (0, r)
    root, mirror = at["root"], at["plot_mirrors"]
    for x in range(1, r + 1):
        y = root_floor(r * r - x * x)
        yield (root, xc + x, yc + y, x, y, watch.gaps, watch.duplicates)
        # Each of the four arcs makes the same step, mirrored.
        for k, offset in enumerate(((x, y), (x, -y), (-x, y), (-x, -y))):
            watch.step(before, (x, y), 1, k == 0)
            watch.plot(offset)
            yield (mirror, xc + offset[0], yc + offset[1], x, y, watch.gaps, watch.duplicates)
        before = (x, y)
    yield Vars(line=at["done"], values=watch.summary())


def sqrt4_pixels(points, options) -> np.ndarray:
    """Fast kernel: the same pixels in the same order, (n, 2) int64."""
    xc, yc = _centre(points)
    r = options["radius"]
    x = np.arange(1, r + 1, dtype=np.int64)
    y = _root_floor_array(r * r - x * x)
    steps = np.stack([np.stack([x, y], 1), np.stack([x, -y], 1),
                      np.stack([-x, y], 1), np.stack([-x, -y], 1)], axis=1).reshape(-1, 2)
    pixels = np.concatenate([np.array([[0, r], [0, -r]], dtype=np.int64), steps])
    return pixels + np.array([xc, yc], dtype=np.int64)


def _root_floor_array(n: np.ndarray) -> np.ndarray:
    """floor(sqrt(n)) elementwise, exact for n < 2^52."""
    root = np.floor(np.sqrt(n.astype(np.float64))).astype(np.int64)
    root -= root * root > n
    root += (root + 1) * (root + 1) <= n
    return root


def sqrt_explain(trace, i):
    step = trace.step(i)
    if "x" not in step.values:
        return []
    r2 = trace.start.constants["r2"]
    x, y = int(step.values["x"]), int(step.values["y"])
    rows = []
    if r2 - x * x >= 0:
        rows.append(("sqrt", f"sqrt({r2} - {x * x}) = {math.sqrt(r2 - x * x):.6g}, floor {y}"))
    if step.pixel is not None and step.kind == PLOT:
        c = trace.start.constants
        rows.append(("offset", f"({step.pixel[0] - c['xc']}, {step.pixel[1] - c['yc']})"))
    if i > 0 and step.values.get("gaps", 0) > trace.step(i - 1).values.get("gaps", 0):
        rows.append(("gap", "this pixel is not an 8-neighbour of the one before it on its arc"))
    return rows


CIRCLE_SQRT4 = AlgorithmSpec(
    name="circle-sqrt4",
    title="Circle, 4-way symmetry",
    family="circles",
    summary="y = floor(sqrt(r^2 - x^2)) for x = 0..r, mirrored into the four quadrants",
    inputs=CENTRE,
    options=(RADIUS,),
    code=listing(sqrt4_listing),
    generator=sqrt4,
    kernel=sqrt4_pixels,
    explain=sqrt_explain,
    notes=("One pixel per column: where the arc is steeper than 45 degrees "
           "(x > r / sqrt 2) y drops by more than one from column to column and the "
           "arc has gaps. gaps counts those steps on all four arcs, missing the "
           "pixels they skip, gap_columns the columns x where they land.",
           "At x = r, y is 0, so (x, y) and (x, -y) are one pixel: it is plotted "
           "twice on each side (duplicates).",
           "For radii up to 4096 a float square root floors to the exact integer "
           "root, so the cast loses nothing here."),
    oracle=Oracle(
        "exact",
        "y = floor(sqrt(R^2 - x^2)) mirrored four ways, from integer square roots "
        "(algorithms/exact/circles.py), with its duplicates and gap columns counted exactly.",
        ("algorithms/circles/test_circles.py", "algorithms/test_stability.py"),
        check="sqrt4-circle"),
)


# -------------------------------------------------- 8-way symmetry (sqrt)
def sqrt8_listing(points, options) -> Code:
    root = {"mul": 1, "int_add": 1, "sqrt": 1, "round": 1}
    code = Code()
    code.add("setup", "r2 = r*r   (offsets (x, y) from the centre)", ops={"mul": 1})
    code.add("plot_axes", "plot (0, r), (0, -r), (r, 0), (-r, 0)", PLOT, ops=PLOT_OPS)
    code.add("first", "x = 1;  y = floor(sqrt(r2 - x*x))", ops=root)
    code.add("loop", "while x < y:", ops={"compare": 1})
    code.add("plot_mirrors", "    plot (x, y), (x, -y), (-x, y), (-x, -y), (y, x), (y, -x), (-y, x), "
                             "(-y, -x)", PLOT, ops=PLOT_OPS)
    code.add("next", "    x += 1;  y = floor(sqrt(r2 - x*x))", ops={**root, "int_add": 2})
    code.add("plot_diagonal", "if x == y:  plot (x, y), (x, -y), (-x, y), (-x, -y)", PLOT,
             ops=PLOT_OPS)
    code.add("done", "done")
    return code


def _sqrt8_y(r: int, x: int) -> int:
    # r = 0 asks for sqrt(-1) at x = 1; taking 0 runs neither the loop nor
    # the x == y case, which is what the plots above already cover.
    return root_floor(max(r * r - x * x, 0))


def sqrt8(points, options):
    xc, yc = _centre(points)
    r = options["radius"]
    watch = ArcWatch()
    at = sqrt8_listing(points, options).at
    yield Start(line=at["setup"], values=("x", "y", "gaps", "duplicates"),
                constants={"xc": xc, "yc": yc, "r": r, "r2": r * r})
    for offset in ((0, r), (0, -r), (r, 0), (-r, 0)):
        watch.plot(offset)
        yield (at["plot_axes"], xc + offset[0], yc + offset[1], 0, r, 0, watch.duplicates)
    x, before = 1, (0, r)
    y = _sqrt8_y(r, x)
    yield (at["first"], xc + x, yc + y, x, y, 0, watch.duplicates)
    loop, mirror, step = at["loop"], at["plot_mirrors"], at["next"]
    while True:
        yield (loop, xc + x, yc + y, x, y, watch.gaps, watch.duplicates)
        if not x < y:
            break
        for k, offset in enumerate(((x, y), (x, -y), (-x, y), (-x, -y),
                                    (y, x), (y, -x), (-y, x), (-y, -x))):
            watch.step(before, (x, y), 1, k == 0)
            watch.plot(offset)
            yield (mirror, xc + offset[0], yc + offset[1], x, y, watch.gaps, watch.duplicates)
        before = (x, y)
        x += 1
        y = _sqrt8_y(r, x)
        yield (step, xc + x, yc + y, x, y, watch.gaps, watch.duplicates)
    if x == y:
        for k, offset in enumerate(((x, y), (x, -y), (-x, y), (-x, -y))):
            # The diagonal pixel ends two arcs, one from each side.
            watch.step(before, (x, y), 2, k == 0)
            watch.plot(offset)
            yield (at["plot_diagonal"], xc + offset[0], yc + offset[1], x, y, watch.gaps,
                   watch.duplicates)
    elif r > 0:
        # The last pixel of the arc and its mirror across the diagonal meet
        # (or fail to) on each of the four diagonals.
        watch.step(before, before[::-1], 4)
    yield Vars(line=at["done"], values=watch.summary())


def sqrt8_pixels(points, options) -> np.ndarray:
    """Fast kernel: the same pixels in the same order, (n, 2) int64."""
    xc, yc = _centre(points)
    r = options["radius"]
    x = np.arange(1, r + 2, dtype=np.int64)
    y = _root_floor_array(np.maximum(r * r - x * x, 0))
    loop = int(np.argmin(x < y))  # x < y holds for a prefix of the columns
    xs, ys = x[:loop], y[:loop]
    parts = [np.array([[0, r], [0, -r], [r, 0], [-r, 0]], dtype=np.int64),
             np.stack([np.stack(pair, 1) for pair in ((xs, ys), (xs, -ys), (-xs, ys), (-xs, -ys),
                                                      (ys, xs), (ys, -xs), (-ys, xs), (-ys, -xs))],
                      axis=1).reshape(-1, 2)]
    if x[loop] == y[loop]:
        a = int(x[loop])
        parts.append(np.array([[a, a], [a, -a], [-a, a], [-a, -a]], dtype=np.int64))
    return np.concatenate(parts) + np.array([xc, yc], dtype=np.int64)


CIRCLE_SQRT8 = AlgorithmSpec(
    name="circle-sqrt8",
    title="Circle, 8-way symmetry",
    family="circles",
    summary="y = floor(sqrt(r^2 - x^2)) while x < y, mirrored into all eight octants",
    inputs=CENTRE,
    options=(RADIUS,),
    code=listing(sqrt8_listing),
    generator=sqrt8,
    kernel=sqrt8_pixels,
    explain=sqrt_explain,
    notes=("Only the octant where the arc is flatter than 45 degrees is computed, "
           "so y never drops by more than one per column: no gaps for r >= 1.",
           "For r = 0 the four axis plots are one pixel (three duplicates).",
           "For radii up to 4096 a float square root floors to the exact integer "
           "root, so the cast loses nothing here."),
    oracle=Oracle(
        "exact",
        "The integer-root octant mirrored eight ways (algorithms/exact/circles.py): a closed curve "
        "without gaps.",
        ("algorithms/circles/test_circles.py", "algorithms/test_stability.py"),
        check="sqrt8-circle"),
)


# ------------------------------------------------------- midpoint circle
START = Option("start", "choice", "integer",
               "the first decision value: integer, 1 - R, or fraction, 5/4 - R exactly; "
               "both choose the same pixels", choices=("integer", "fraction"))


def midpoint_listing(points, options) -> Code:
    if options["start"] == "fraction":
        first = "d = 5/4 - R   (F at the first midpoint (1, R - 1/2), kept exact)"
    else:
        first = ("d = 1 - R   (5/4 - R less 1/4: d then stays a whole number and "
                 "has the same sign test)")
    # Operation counts: 2x is an addition; the diagonal test runs every
    # iteration and is counted on the E and SE lines (its own line has a
    # frame only when it stops the loop).
    code = Code()
    code.add("setup", f"x = 0;  y = R;  {first}", ops={"int_add": 1})
    code.add("plot_axes", "plot (0, R), (0, -R), (R, 0), (-R, 0)   (offsets; one pixel when R = 0)",
             PLOT, ops=PLOT_OPS)
    code.add("loop", "while y > x:", ops={"compare": 1})
    code.add("east", "    if d < 0:  d += 2x + 3;  x += 1            (midpoint inside: E)",
             branch="E", ops={"compare": 2, "int_add": 4})
    code.add("south_east", "    else:  d += 2(x - y) + 5;  x += 1;  y -= 1   (on or outside: SE)",
             branch="SE", ops={"compare": 2, "int_add": 6})
    code.add("crossed", "    if x > y:  stop   (SE crossed the diagonal: these pixels are "
                        "mirrors of the last ones)")
    code.add("plot_mirrors", "    plot (x, y), (y, x), (y, -x), (x, -y), (-x, -y), (-y, -x), "
                             "(-y, x), (-x, y)   (four when x == y)", PLOT, ops=PLOT_OPS)
    code.add("done", "done")
    return code


def _number(value):
    """A panel value: a Fraction as its exact float (quarters are exact)."""
    return float(value) if isinstance(value, Fraction) else value


def midpoint_circle(points, options):
    xc, yc = _centre(points)
    r = options["radius"]
    fraction = options["start"] == "fraction"
    d = Fraction(5, 4) - r if fraction else 1 - r
    at = midpoint_listing(points, options).at
    yield Start(line=at["setup"], values=("d", "x", "y"),
                constants={"xc": xc, "yc": yc, "R": r, "start": "5/4 - R" if fraction else "1 - R",
                           "d0": _number(d)},
                candidates=E_SE, decision="d")
    x, y = 0, r
    plotted = 0
    for dx, dy in mirrors8(0, r):
        plotted += 1
        yield (at["plot_axes"], xc + dx, yc + dy, _number(d), x, y)
    loop, east, south_east, mirror = at["loop"], at["east"], at["south_east"], at["plot_mirrors"]
    while True:
        # The loop test sits on the current pixel, so that E and SE are
        # offsets from it at the decision that follows.
        yield (loop, xc + x, yc + y, _number(d), x, y)
        if not y > x:
            break
        tested = d
        if d < 0:
            line, d, x = east, d + 2 * x + 3, x + 1
        else:
            line, d, x, y = south_east, d + 2 * (x - y) + 5, x + 1, y - 1
        yield (line, xc + x, yc + y, _number(tested), x, y)
        if x > y:
            yield (at["crossed"], NO_PIXEL, NO_PIXEL, _number(d), x, y)
            break
        for dx, dy in mirrors8(x, y):
            plotted += 1
            yield (mirror, xc + dx, yc + dy, _number(d), x, y)
    yield Vars(line=at["done"], values={"pixels": plotted})


def midpoint_circle_pixels(points, options) -> np.ndarray:
    """Fast kernel: each octant column's y in closed form, same order as the loop.

    In the octant the loop picks, for column x, the y whose cell holds the
    circle: (2y - 1)^2 < 4(R^2 - x^2) < (2y + 1)^2 (see exact_circles).
    """
    xc, yc = _centre(points)
    r = options["radius"]
    x = np.arange(0, r + 1, dtype=np.int64)
    y = (_root_floor_array(4 * (r * r - x * x)) + 1) // 2
    x, y = x[x <= y], y[x <= y]
    parts = [np.array(mirrors8(0, r), dtype=np.int64).reshape(-1, 2)]
    if len(x) > 1:
        xs, ys = x[1:], y[1:]
        eight = np.stack([np.stack(pair, 1) for pair in
                          ((xs, ys), (ys, xs), (ys, -xs), (xs, -ys),
                           (-xs, -ys), (-ys, -xs), (-ys, xs), (-xs, ys))], axis=1)
        # On the diagonal every other image repeats the one before it.
        keep = np.ones(eight.shape[:2], dtype=bool)
        keep[xs == ys, 1::2] = False
        parts.append(eight[keep])
    return np.concatenate(parts) + np.array([xc, yc], dtype=np.int64)


def midpoint_explain(trace, i):
    step = trace.step(i)
    rows = []
    if step.branch and "d" in step.values:
        d = step.values["d"]
        x, y = int(step.values["x"]) - 1, int(step.values["y"])  # x_i, y_i before the move
        if step.branch == "E":
            rows.append(("decision", f"d_i = {_text(d)} < 0: the midpoint (x+1, y-1/2) is "
                                     f"inside the circle, so E"))
            rows.append(("update", f"d_i+1 = d_i + 2x_i + 3 = {_text(d)} + {2 * x + 3} "
                                   f"= {_text(d + 2 * x + 3)}"))
        else:
            y += 1
            rows.append(("decision", f"d_i = {_text(d)} >= 0: the midpoint is on or outside "
                                     f"the circle, so SE"))
            rows.append(("update", f"d_i+1 = d_i + 2(x_i - y_i) + 5 = {_text(d)} + "
                                   f"{2 * (x - y) + 5} = {_text(d + 2 * (x - y) + 5)}"))
    if step.kind == PLOT and step.pixel is not None and "x" in step.values:
        c = trace.start.constants
        ox, oy = step.pixel[0] - c["xc"], step.pixel[1] - c["yc"]
        rows.append(("mirror", f"({ox}, {oy}) is {_image_name(ox, oy, int(step.values['x']))}"))
    return rows


def _text(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else f"{value:g}"


def _image_name(ox: int, oy: int, x: int) -> str:
    """Which symmetry of the octant pixel (x, y) the offset (ox, oy) is."""
    first = "x" if abs(ox) == x else "y"
    second = "y" if first == "x" else "x"
    return f"({'-' if ox < 0 else ''}{first}, {'-' if oy < 0 else ''}{second})"


CIRCLE_MIDPOINT = AlgorithmSpec(
    name="circle-midpoint",
    title="Midpoint circle",
    family="circles",
    summary="integer decision variable d = F(midpoint); E or SE, mirrored 8 ways",
    inputs=CENTRE,
    options=(RADIUS, START),
    code=listing(midpoint_listing),
    generator=midpoint_circle,
    kernel=midpoint_circle_pixels,
    explain=midpoint_explain,
    notes=("F(x, y) = x^2 + y^2 - R^2 is negative inside the circle. d is F at the "
           "midpoint (x + 1, y - 1/2) between the two candidates E and SE.",
           "With the fraction start d is always the integer start's d plus 1/4, so "
           "d < 0 holds for both or for neither: the same pixels.",
           "The midpoint never lies exactly on the circle (4F there is odd), so the "
           "choice is never a tie: each column's pixel is the one whose cell the "
           "circle crosses.",
           "Each pixel is plotted once: on the axes and on the diagonal only four "
           "mirrors are distinct, and a step that crosses the diagonal stops the loop."),
    oracle=Oracle(
        "exact",
        "The midpoint circle's pixels from integer square roots (algorithms/exact/circles.py), for "
        "both starts, each once; each decision is F at the midpoint, exactly.",
        ("algorithms/circles/test_circles.py", "algorithms/test_stability.py"),
        check="midpoint-circle"),
)


# ------------------------------------------------------ midpoint ellipse
RX = Option("rx", "int", 10, "half width in pixels (0: a vertical segment)",
            minimum=0, maximum=MAX_RADIUS)
RY = Option("ry", "int", 6, "half height in pixels (0: a horizontal segment)",
            minimum=0, maximum=MAX_RADIUS)


def ellipse_listing(points, options) -> Code:
    # Operation counts: rx^2, ry^2 and their multiples 4ry^2, 8rx^2, ...
    # are computed once, on the first line; doubling is an addition. The
    # tail loop plots two pixels per step and counts plotting only.
    code = Code()
    code.add("setup", "x = 0;  y = ry;  d = 4F(x + 1, y - 1/2) = 4ry^2 - 4rx^2*ry + rx^2   "
                      "(F = ry^2 x^2 + rx^2 y^2 - rx^2 ry^2; 4F keeps d whole)",
             ops={"mul": 6, "int_add": 2})
    code.add("plot_poles", "plot (0, ry), (0, -ry)", PLOT, ops=PLOT_OPS)
    code.add("region1", "while ry^2 * x < rx^2 * y:     (region 1: slope above -1, one pixel per "
                        "column)", ops={"mul": 2, "compare": 1})
    code.add("east", "    if d < 0:  d += 4ry^2(2x + 3);  x += 1", branch="E",
             ops={"compare": 1, "mul": 1, "int_add": 4})
    code.add("south_east", "    else:  d += 4ry^2(2x + 3) - 8rx^2(y - 1);  x += 1;  y -= 1",
             branch="SE", ops={"compare": 1, "mul": 2, "int_add": 7})
    code.add("plot_region1", "    plot (x, y), (x, -y), (-x, y), (-x, -y)", PLOT, ops=PLOT_OPS)
    code.add("switch", "d = 4F(x + 1/2, y - 1)         (region 2: one pixel per row)",
             ops={"mul": 4, "int_add": 5})
    code.add("region2", "while y > 0:", ops={"compare": 1})
    code.add("south", "    if d > 0:  d += 4rx^2(3 - 2y);  y -= 1", branch="S", candidates=S_SW,
             ops={"compare": 1, "mul": 1, "int_add": 4})
    code.add("south_west", "    else:  d += 8ry^2(x + 1) + 4rx^2(3 - 2y);  x += 1;  y -= 1",
             branch="SW", candidates=S_SW, ops={"compare": 1, "mul": 2, "int_add": 7})
    code.add("plot_region2", "    plot (x, y), (x, -y), (-x, y), (-x, -y)", PLOT, ops=PLOT_OPS)
    code.add("plot_tail", "while x < rx:  x += 1;  plot (x, 0), (-x, 0)   (a flat ellipse reaches "
                          "y = 0 before x = rx)", PLOT, ops=PLOT_OPS)
    code.add("done", "done")
    return code


def ellipse_f4(rx: int, ry: int, x2: int, y2: int) -> int:
    """4 F at the point (x2 / 2, y2 / 2): whole numbers for half-integer points."""
    return ry * ry * x2 * x2 + rx * rx * y2 * y2 - 4 * rx * rx * ry * ry


def midpoint_ellipse(points, options):
    xc, yc = _centre(points)
    rx, ry = options["rx"], options["ry"]
    a2, b2 = rx * rx, ry * ry
    x, y = 0, ry
    d = ellipse_f4(rx, ry, 2 * x + 2, 2 * y - 1)
    at = ellipse_listing(points, options).at
    yield Start(line=at["setup"], values=("d", "x", "y"),
                constants={"xc": xc, "yc": yc, "rx": rx, "ry": ry, "region": 1},
                candidates=E_SE, decision="d")
    plotted = 0
    for dx, dy in mirrors4(x, y):
        plotted += 1
        yield (at["plot_poles"], xc + dx, yc + dy, d, x, y)
    loop, east, south_east, mirror = at["region1"], at["east"], at["south_east"], at["plot_region1"]
    while True:
        yield (loop, xc + x, yc + y, d, x, y)
        if not b2 * x < a2 * y:
            break
        tested = d
        if d < 0:
            line, d = east, d + 4 * b2 * (2 * x + 3)
        else:
            line, d = south_east, d + 4 * b2 * (2 * x + 3) - 8 * a2 * (y - 1)
            y -= 1
        x += 1
        yield (line, xc + x, yc + y, tested, x, y)
        for dx, dy in mirrors4(x, y):
            plotted += 1
            yield (mirror, xc + dx, yc + dy, d, x, y)
    d = ellipse_f4(rx, ry, 2 * x + 1, 2 * y - 2)
    yield Vars(line=at["switch"], values={"region": 2, "d": d, "x": x, "y": y},
               pixel=(xc + x, yc + y))
    loop, south, south_west, mirror = at["region2"], at["south"], at["south_west"], at["plot_region2"]
    while True:
        yield (loop, xc + x, yc + y, d, x, y)
        if not y > 0:
            break
        tested = d
        if d > 0:
            line, d = south, d + 4 * a2 * (3 - 2 * y)
        else:
            line, d = south_west, d + 8 * b2 * (x + 1) + 4 * a2 * (3 - 2 * y)
            x += 1
        y -= 1
        yield (line, xc + x, yc + y, tested, x, y)
        for dx, dy in mirrors4(x, y):
            plotted += 1
            yield (mirror, xc + dx, yc + dy, d, x, y)
    tail = at["plot_tail"]
    while x < rx:
        x += 1
        for dx, dy in mirrors4(x, 0):
            plotted += 1
            yield (tail, xc + dx, yc + dy, d, x, 0)
    yield Vars(line=at["done"], values={"pixels": plotted})


def ellipse_explain(trace, i):
    step = trace.step(i)
    if not step.branch or "d" not in step.values:
        return []
    d = int(step.values["d"])
    relation = "<" if d < 0 else (">" if d > 0 else "=")
    where = {"E": "inside: E", "SE": "on or outside: SE",
             "S": "outside: S", "SW": "on or inside: SW"}[step.branch]
    return [("decision", f"d_i = {d} {relation} 0, the midpoint is {where}")]


ELLIPSE_MIDPOINT = AlgorithmSpec(
    name="ellipse-midpoint",
    title="Midpoint ellipse",
    family="circles",
    summary="two regions: a pixel per column while the slope is above -1, then one per row",
    inputs=CENTRE,
    options=(RX, RY),
    code=listing(ellipse_listing),
    generator=midpoint_ellipse,
    explain=ellipse_explain,
    notes=("Axis-aligned, mirrored four ways; each pixel is plotted once (on the axes "
           "the mirrors coincide).",
           "Region 1 ends where the gradient's x part reaches its y part "
           "(ry^2 x >= rx^2 y), i.e. where the slope passes -1.",
           "Ties go to SE in region 1 and to SW in region 2.",
           "With rx == ry the pixels are exactly those of the midpoint circle "
           "(drawn in another order).",
           "rx = 0 or ry = 0 gives a segment along an axis; both 0, one pixel."),
    oracle=Oracle(
        "reference",
        "A bound: every pixel within one pixel of the ellipse along its column or row (exact "
        "Fractions), 4-way symmetric and unbroken, decisions 4F at the midpoints. The exact pixels "
        "only when rx = ry (the midpoint circle) or an axis is 0.",
        ("algorithms/circles/test_circles_ellipse.py", "algorithms/test_stability.py"),
        check="midpoint-ellipse"),
)

# The module's algorithms, in the order they are listed.
SPECS = (CIRCLE_SQRT4, CIRCLE_SQRT8, CIRCLE_MIDPOINT, ELLIPSE_MIDPOINT)
