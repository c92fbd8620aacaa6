"""The stencil buffer: a mask that a later primitive respects.

The input is a list of contours. All but the last make the stencil
polygon (holes and self-intersections by the fill rule, as the scan line
fills them); the last, of three points, is the triangle drawn through it.

Pass 1 writes the polygon into the stencil buffer only: S[x, y] = 1 at
every pixel whose centre the polygon covers (the scan line's pixels), and
no colour. Pass 2 rasterizes the triangle with the triangle family's fill
rule; a fragment is written only where S[x, y] = 1 (the stencil test
"equal to 1") and is dropped elsewhere. The picture is therefore the
triangle's pixels that are also the polygon's.

A single contour is a triangle with no stencil: the scene has no stencil
buffer, and every fragment is written.

Frames: a VISIT frame per stencil pixel set (value ``stencil`` 1), then
one per fragment, a PLOT frame when the test passes and a VISIT frame when
it fails. ``Start`` names ``stencil`` as its second buffer, so the window
shows the stencil at any step.
"""
from __future__ import annotations

import math

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, InputError, Inputs, Option, Oracle
from algorithms.core.steps import PLOT, VISIT, Note, Start, Vars
from algorithms.polygons.scanline import scanline_pixels
from algorithms.triangles.edges import FILL_RULE
from algorithms.triangles.kernels import kernel_pixels

NAN = math.nan
STENCIL = "stencil buffer"
POLYGON_RULE = Option("polygon_rule", "choice", "evenodd", "how the stencil polygon is "
                      "filled where it crosses itself or has holes",
                      choices=("evenodd", "nonzero"))
OPTIONS = (POLYGON_RULE, FILL_RULE)
CONTOURS = Inputs(3, integer=False, contours=True)


def split(points) -> tuple[tuple, tuple]:
    """(stencil contours, triangle) of the input; no contours: no stencil."""
    if len(points[-1]) != 3:
        raise InputError(f"the last contour is the triangle: expected 3 points, got "
                         f"{len(points[-1])}")
    return tuple(points[:-1]), tuple(points[-1])


def polygon_pixels(contours, options, grid) -> np.ndarray:
    """The stencil polygon's pixels on the grid, (n, 2), rows up."""
    if not contours:
        return np.zeros((0, 2), np.int64)
    pixels = scanline_pixels(contours, {"fill_rule": options["polygon_rule"]})
    inside = ((pixels[:, 0] >= 0) & (pixels[:, 0] < grid[0])
              & (pixels[:, 1] >= 0) & (pixels[:, 1] < grid[1]))
    return pixels[inside]


def triangle_pixels(triangle, options, grid) -> np.ndarray:
    """The triangle's fragments on the grid, (n, 2), rows up, by the fill rule."""
    return kernel_pixels(triangle, {"fill_rule": options["fill_rule"]}, grid)


def stencil_code(points, options) -> Code:
    masked = bool(points) and len(points) > 1
    code = Code()
    code.add("clear", "clear the colour buffer;  clear the stencil buffer: S = 0" if masked
             else "clear the colour buffer (no stencil buffer: nothing masks the triangle)")
    if masked:
        code.add("stencil", "pass 1, colour writes off: for each pixel whose centre the polygon "
                            "covers:  S[x, y] = 1", VISIT, ops={"compare": 1})
    code.add("fragments", "pass 2: rasterize the triangle (fill rule); for each fragment (x, y):")
    code.add("plot_pass", "    if S[x, y] == 1: write (x, y)" if masked else "    write (x, y)",
             PLOT, "pass", ops={"compare": 1} if masked else {})
    if masked:
        code.add("fail", "    else: drop the fragment (the stencil test fails)", VISIT, "fail",
                 ops={"compare": 1})
    code.add("done", "done")
    return code


def stencil(points, options, grid):
    contours, triangle = split(points)
    at = stencil_code(points, options).at
    masked = bool(contours)
    yield Start(line=at["clear"], values=("stencil",),
                constants={"mask": "polygon" if masked else "none",
                           "fill_rule": options["fill_rule"]},
                buffer_value="stencil" if masked else None, buffer_name=STENCIL if masked else "")
    mask = np.zeros((int(grid[1]), int(grid[0])), bool)
    if masked:
        yield Note(line=at["stencil"], text="Pass 1 writes only the stencil: the colour buffer "
                                            "stays empty while the polygon is drawn.")
        for x, y in polygon_pixels(contours, options, grid).tolist():
            mask[y, x] = True
            yield (at["stencil"], x, y, 1.0)
    written = dropped = 0
    for x, y in triangle_pixels(triangle, options, grid).tolist():
        if mask[y, x] or not masked:
            written += 1
            yield (at["plot_pass"], x, y, NAN)
        else:
            dropped += 1
            yield (at["fail"], x, y, NAN)
    yield Vars(line=at["done"], values={"written": written, "dropped": dropped,
                                        "stencil pixels": int(mask.sum())})


STENCIL_TRIANGLE = AlgorithmSpec(
    name="stencil-triangle", title="Stencil buffer: a triangle through a polygon mask",
    family="visibility",
    summary="write a polygon into the stencil, then draw a triangle only where S = 1",
    inputs=CONTOURS, options=OPTIONS, code=listing(stencil_code), generator=stencil,
    notes=("The contours but the last are the stencil polygon (scan-line pixels: centres "
           "covered, ties to left and bottom edges); the last contour is the triangle.",
           "Pass 1 writes no colour, only S; the stencil buffer view shows S at any step.",
           "A fragment passes where S[x, y] = 1: the picture is the triangle's pixels that "
           "are also the polygon's. With one contour there is no stencil buffer."),
    uses_grid=True,
    oracle=Oracle(
        "exact",
        "The pixels written equal the triangle's pixels (centres tested against the exact edge "
        "functions with the top-left rule) that are also the polygon's (centres by the even-odd "
        "rule, ties to left and bottom edges), both in Fractions written in the test.",
        ("algorithms/visibility/test_stencil.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (STENCIL_TRIANGLE,)
