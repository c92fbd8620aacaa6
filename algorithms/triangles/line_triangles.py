"""A line drawn as two skinny triangles, as some systems draw lines.

An algorithm of the line family that lives in the triangle package: it
fills triangles, and the line package may not import this one (the
triangle package imports the circle package, which imports the line
package).

The segment between the centres of pixels P and Q is widened into a
rectangle w px across (with square caps it also reaches w/2 beyond each
end); the rectangle is cut along a diagonal into two triangles, and each
is filled as the triangle family fills triangles: the pixels whose centres
it covers, corners snapped to 1/256 px, ties by the fill rule. With the
top-left rule the shared diagonal's pixels go to exactly one of the two,
so no pixel is written twice and the picture is the rectangle's pixels.

Unlike Bresenham's one pixel per column (or row), the rectangle takes
every centre within w/2 of the segment: at w = 1 a sloped line has two
pixels in some columns. At w = 1 with square caps, horizontal, vertical
and diagonal segments give exactly Bresenham's pixels.
"""
from __future__ import annotations

import math

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import PLOT, Note, Start, Vars
from algorithms.lines.common import SEGMENT

from .edges import FILL_RULE
from .kernels import kernel_pixels

WIDTH = Option("width", "float", 1.0, "the line's width across, in px", minimum=0.05, maximum=4)
CAPS = Option("caps", "choice", "square", "square: the rectangle reaches w/2 beyond each end "
              "centre; butt: it ends at the end centres", choices=("square", "butt"))
OPTIONS = (WIDTH, CAPS, FILL_RULE)


def corners(points, options) -> list[tuple[float, float]]:
    """The rectangle's corners c0..c3, counter-clockwise (c0, c1 on the right
    of P -> Q). A zero-length segment is a w x w square with square caps, a
    rectangle of no area with butt caps."""
    (px, py), (qx, qy) = points
    ax, ay, bx, by = px + 0.5, py + 0.5, qx + 0.5, qy + 0.5
    length = math.hypot(bx - ax, by - ay)
    ux, uy = ((bx - ax) / length, (by - ay) / length) if length else (1.0, 0.0)
    half = options["width"] / 2
    nx, ny = -uy * half, ux * half
    cap = half if options["caps"] == "square" else 0.0
    ax, ay, bx, by = ax - ux * cap, ay - uy * cap, bx + ux * cap, by + uy * cap
    return [(ax - nx, ay - ny), (bx - nx, by - ny), (bx + nx, by + ny), (ax + nx, ay + ny)]


def triangles(points, options):
    """The two triangles (c0, c1, c2) and (c0, c2, c3), sharing the diagonal c0 c2."""
    c = corners(points, options)
    return (c[0], c[1], c[2]), (c[0], c[2], c[3])


def triangle_pixels(triangle, options) -> np.ndarray:
    return kernel_pixels(triangle, {"fill_rule": options["fill_rule"]})


def two_triangles_pixels(points, options) -> np.ndarray:
    """Fast kernel: the pixels of both triangles, (n, 2), in the generator's order."""
    first, second = triangles(points, options)
    return np.concatenate([triangle_pixels(first, options), triangle_pixels(second, options)])


def two_triangles_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "a = P + (1/2, 1/2);  b = Q + (1/2, 1/2);  u = (b - a) / |b - a|;  "
                      "n = (w/2) (-u_y, u_x)", ops={"float_add": 4, "mul": 4, "div": 2, "sqrt": 1})
    code.add("caps", "square caps: a -= (w/2) u;  b += (w/2) u   (butt caps: keep a, b)",
             ops={"float_add": 4, "mul": 2})
    code.add("corners", "c0 = a - n;  c1 = b - n;  c2 = b + n;  c3 = a + n   (snapped to 1/256 px)",
             ops={"float_add": 8})
    code.add("first", "triangle (c0, c1, c2): for each pixel whose centre it covers (fill rule):")
    code.add("plot_first", "    write (x, y)", PLOT, ops={"compare": 3})
    code.add("second", "triangle (c0, c2, c3), sharing the diagonal c0 c2: for each pixel whose "
                       "centre it covers:")
    code.add("plot_second", "    write (x, y)", PLOT, ops={"compare": 3})
    code.add("done", "done")
    return code


def two_triangles(points, options):
    at = two_triangles_listing(points, options).at
    c = corners(points, options)
    yield Start(line=at["setup"], values=("triangle",),
                constants={"w": options["width"], "caps": options["caps"],
                           "fill_rule": options["fill_rule"]})
    names = ("c0", "c1", "c2", "c3")
    yield Vars(line=at["corners"], values={name: f"({x:.6g}, {y:.6g})"
                                          for name, (x, y) in zip(names, c)})
    first, second = triangles(points, options)
    count = 0
    for number, (key, triangle) in enumerate((("first", first), ("second", second)), 1):
        yield Note(line=at[key], text=f"Triangle {number} of 2: its pixels are those whose "
                                      f"centres it covers.")
        for x, y in triangle_pixels(triangle, options).tolist():
            count += 1
            yield (at["plot_" + key], x, y, float(number))
    yield Vars(line=at["done"], values={"pixels": count})


LINE_TWO_TRIANGLES = AlgorithmSpec(
    name="line-two-triangles",
    title="Line as two skinny triangles",
    family="lines",
    summary="widen the segment into a w-px rectangle and fill its two triangles",
    inputs=SEGMENT,
    options=OPTIONS,
    code=listing(two_triangles_listing),
    generator=two_triangles,
    kernel=two_triangles_pixels,
    notes=("The rectangle runs between the end pixels' centres, w px across; square caps "
           "extend it by w/2 at each end, butt caps do not (then an end pixel whose centre "
           "lies on a right or top end edge is left out).",
           "Each triangle takes the pixels whose centres it covers, as the triangle family "
           "decides it; with the top-left rule the diagonal's pixels go to one triangle only.",
           "Compare it with Bresenham (View > Compare, 'Two triangles vs Bresenham'): at "
           "w = 1 the rectangle takes every centre within 1/2 px of the segment, so a sloped "
           "line gains pixels that Bresenham's one-per-column leaves out."),
    oracle=Oracle(
        "exact",
        "The pixels whose centres lie in the rectangle of the snapped corners, edges tested "
        "exactly with the top-left rule, in Fractions written in the test; none written twice; "
        "Bresenham's pixels at w = 1 with square caps on axis and diagonal segments.",
        ("algorithms/lines/test_line_two_triangles.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (LINE_TWO_TRIANGLES,)
