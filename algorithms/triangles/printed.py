"""Two triangle listings as the lecture notes print them, beside their corrected forms.

triangle-barycentric-printed: the parametric (barycentric) loop with alpha
and gamma as ratios of distances. With an unsigned distance() neither can be
negative, so only beta = 1 - alpha - gamma rejects a pixel and the test fills
a region larger than the triangle (in the unit triangle, (0.6, 0.6) passes).
Signed distances (positive on the vertex's side) give the triangle.

triangle-lininterp: the incremental evaluation q += c_x, q += c_y of a
linear function over the bounding box, with the printed slips: q starts at
vertex 1 instead of at the box's corner, the loops start at vertex 1 instead
of at xl, yl, and a stray qRow += c_y follows the loops.

Vertices are real; pixel (i, j) has its sample point at (i + 1/2, j + 1/2);
both stay inside the grid and work in exact rational arithmetic.
"""
from __future__ import annotations

import math
from fractions import Fraction

from algorithms.circles.curves import grey_ink
from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Note, Start, Vars
from algorithms.triangles.edges import TRIANGLES
from algorithms.triangles.span_interpolation import VALUES
from algorithms.triangles.variants import HALF, box_of, centre_range, check_coordinates, triangles_of

NAN = math.nan


def edge(a, b, p) -> Fraction:
    """Twice the signed area of (a, b, p): p's distance to the line ab times |ab|."""
    return (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1])


def exact_triangle(vertices):
    return tuple(tuple(Fraction(c) for c in p) for p in vertices)


# -------------------------------------------- barycentric test as printed
DISTANCE = Option("distance", "choice", "unsigned",
                  "unsigned: distance() as printed, never negative, so the test overfills; "
                  "signed: positive on the vertex's side of the edge, the corrected form",
                  choices=("unsigned", "signed"))


def barycentric_listing(points, options) -> Code:
    ratio = {"mul": 4, "float_add": 5, "div": 1}
    unsigned = options["distance"] == "unsigned"
    code = Code()
    code.add("setup", "for each triangle A, B, C:  for each pixel (x, y) of its bounding box "
                      "(its centre):")
    code.add("alpha", "    alpha = distance((x, y), BC) / distance(A, BC);  gamma = "
                      "distance((x, y), AB) / distance(C, AB)" +
             ("   (as printed: unsigned, so never negative)" if unsigned else
              "   (signed: negative across the edge from the vertex)"), ops=ratio)
    code.add("beta", "    beta = 1 - alpha - gamma", ops={"float_add": 2})
    code.add("skip", "    if alpha < 0 or beta < 0 or gamma < 0:  continue" +
             ("   (only beta can be)" if unsigned else ""), VISIT,
             ops={"compare": 3, "pixels_tested": 1})
    code.add("plot", "    setPixel(x, y)   (the listing also mixes the vertex colours by "
                     "alpha, beta, gamma)", PLOT, ops={"compare": 3, "pixels_tested": 1})
    code.add("done", "done")
    return code


def barycentric_run(points, options, grid):
    unsigned = options["distance"] == "unsigned"
    at = barycentric_listing(points, options).at
    yield Start(line=at["setup"], values=("alpha", "beta", "gamma"),
                constants={"triangles": len(points) // 3, "distance": options["distance"]})
    filled = outside = 0
    for number, vertices in enumerate(triangles_of(points)):
        check_coordinates(number, vertices)
        a, b, c = exact_triangle(vertices)
        to_a, to_c = edge(b, c, a), edge(a, b, c)
        if to_a == 0:
            yield Note(line=at["setup"], text=f"triangle {number}: no area, so distance(A, BC) "
                                              "is 0 and alpha divides by it: nothing to fill")
            continue
        columns, rows = box_of((a, b, c), grid)
        for y in rows:
            for x in columns:
                p = (x + HALF, y + HALF)
                alpha, gamma = edge(b, c, p) / to_a, edge(a, b, p) / to_c
                if unsigned:
                    alpha, gamma = abs(alpha), abs(gamma)
                beta = 1 - alpha - gamma
                yield (at["alpha"], x, y, float(alpha), NAN, float(gamma))
                passes = min(alpha, beta, gamma) >= 0
                if passes:
                    filled += 1
                    outside += not closed_inside((a, b, c), p)
                yield (at["plot"] if passes else at["skip"], x, y, float(alpha), float(beta),
                       float(gamma))
    yield Vars(line=at["done"], values={"filled": filled, "outside_triangle": outside})


def closed_inside(triangle, p) -> bool:
    """p in the closed triangle: the three edge functions share a sign (or are 0)."""
    a, b, c = triangle
    signs = [edge(a, b, p), edge(b, c, p), edge(c, a, p)]
    return all(s >= 0 for s in signs) or all(s <= 0 for s in signs)


TRIANGLE_BARYCENTRIC_PRINTED = AlgorithmSpec(
    name="triangle-barycentric-printed",
    title="Barycentric test, as printed",
    family="triangles",
    summary="alpha and gamma as ratios of distances: with an unsigned distance() the test "
            "fills more than the triangle",
    inputs=TRIANGLES,
    options=(DISTANCE,),
    code=listing(barycentric_listing),
    generator=barycentric_run,
    uses_grid=True,
    step_seconds=1e-4,  # three distances a pixel: 35-75 us a step
    notes=("As printed, distance() has no sign: alpha and gamma are never negative, so only "
           "beta = 1 - alpha - gamma can reject a pixel, and every centre with "
           "alpha + gamma <= 1 passes, across BC and AB as well. In the unit triangle "
           "(0,0), (1,0), (0,1) the point (0.6, 0.6) gets alpha 0.2, gamma 0.6, beta 0.2 "
           "and passes. outside_triangle counts the filled centres outside the closed "
           "triangle.",
           "distance=signed is the corrected form: the same ratios with signed distances, "
           "which are the barycentric coordinates (triangle-barycentric), and it fills the "
           "closed triangle. Exact rational arithmetic: the lengths of the edges cancel in "
           "each ratio."),
    oracle=Oracle(
        "exact",
        "The listing ported in the test with exact distances (Fractions), on random and hard "
        "triangles; signed: the centres of the closed triangle by exact side tests; unsigned: "
        "those with |alpha| + |gamma| <= 1, a superset, and its extra pixels counted.",
        ("algorithms/triangles/test_triangle_printed.py",)),
)


# ----------------------------------------------------- linInterp as printed
LISTING = Option("listing", "choice", "printed",
                 "printed: q starts at vertex 1 and the loops start at x1, y1, so the box's "
                 "columns left of vertex 1 and rows below it are never written; corrected: "
                 "q starts at the box's corner (xl, yl)", choices=("printed", "corrected"))


def lininterp_listing(points, options) -> Code:
    printed = options["listing"] == "printed"
    corner = "(x1, y1)" if printed else "(xl, yl)"
    code = Code()
    code.add("setup", "det = (x1 - x0)(y2 - y0) - (x2 - x0)(y1 - y0);  c_x, c_y by Cramer's rule "
                      "from q0, q1, q2", ops={"mul": 6, "float_add": 8, "div": 2})
    code.add("row_start", f"qRow = c_x (x - x0) + c_y (y - y0) + q0 at {corner}" +
             ("   (as printed: vertex 1, not the box's corner)" if printed else ""),
             ops={"mul": 2, "float_add": 3})
    code.add("row", f"for y = {'y1' if printed else 'yl'} .. yh:  qPix = qRow" +
             ("   (as printed: from vertex 1's row)" if printed else ""),
             ops={"compare": 1})
    code.add("plot", f"    for x = {'x1' if printed else 'xl'} .. xh:  output(x, y, qPix);  "
                     "qPix += c_x" + ("   (as printed: from vertex 1's column)" if printed else ""),
             PLOT, ops={"float_add": 1, "compare": 1})
    code.add("next_row", "    qRow += c_y", ops={"float_add": 1})
    code.add("done", "qRow += c_y   (as printed: a stray line after the loops; it writes "
                     "nothing)" if printed else "done")
    return code


def lininterp_run(points, options, grid):
    printed = options["listing"] == "printed"
    at = lininterp_listing(points, options).at
    values = options["s"] or (0.0,)
    low, high = min(values), max(values)
    yield Start(line=at["setup"], values=("q", "rgb"), pixel_value="rgb",
                constants={"triangles": len(points) // 3, "listing": options["listing"]})
    written = skipped = 0
    for number, vertices in enumerate(triangles_of(points)):
        check_coordinates(number, vertices)
        triangle = exact_triangle(vertices)
        q = [Fraction(values[(3 * number + k) % len(values)]) for k in range(3)]
        plane = plane_of(triangle, q)
        if plane is None:
            yield Note(line=at["setup"], text=f"triangle {number}: det is 0, so c_x and c_y "
                                              "are not defined: nothing is output")
            continue
        cx, cy = plane
        columns, rows = box_of(triangle, grid)
        first_x, first_y = columns.start, rows.start
        if printed:  # the loops start at vertex 1's pixel, with q1 there
            sx, sy = (math.ceil(c - HALF) for c in triangle[1])
            first_x, first_y = max(first_x, sx), max(first_y, sy)
            q_first = q[1] + cx * (first_x - sx) + cy * (first_y - sy)
        else:
            x0, y0 = triangle[0]
            q_first = cx * (first_x + HALF - x0) + cy * (first_y + HALF - y0) + q[0]
        yield Vars(line=at["setup"], values={"triangle": number, "c_x": float(cx),
                                             "c_y": float(cy)})
        skipped += len(columns) * len(rows)
        for x, y, value in _walk(cx, cy, q_first, range(first_x, columns.stop),
                                 range(first_y, rows.stop)):
            written += 1
            yield (at["plot"], x, y, float(value),
                   grey_ink(1 - _unit(value, low, high)))
        yield (at["done"], NO_PIXEL, NO_PIXEL, NAN, NAN)
    yield Vars(line=at["done"], values={"written": written, "missing": skipped - written})


def plane_of(triangle, q):
    """(c_x, c_y) of the plane through the vertex values, by Cramer's rule; None without area."""
    (x0, y0), (x1, y1), (x2, y2) = triangle
    det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    if det == 0:
        return None
    return (((q[1] - q[0]) * (y2 - y0) - (q[2] - q[0]) * (y1 - y0)) / det,
            ((q[2] - q[0]) * (x1 - x0) - (q[1] - q[0]) * (x2 - x0)) / det)


def _walk(cx, cy, q_first, columns, rows):
    """(x, y, qPix) over the columns and rows, qRow starting at q_first."""
    q_row = q_first
    for y in rows:
        q_pix = q_row
        for x in columns:
            yield x, y, q_pix
            q_pix += cx
        q_row += cy


def _unit(f, low, high) -> float:
    """f on 0..1 between the smallest and largest vertex value, clamped."""
    if high == low:
        return 0.0
    return min(1.0, max(0.0, float((f - Fraction(low)) / (Fraction(high) - Fraction(low)))))


TRIANGLE_LININTERP = AlgorithmSpec(
    name="triangle-lininterp",
    title="linInterp, as printed",
    family="triangles",
    summary="q += c_x along a row, qRow += c_y up the box: the printed listing starts at vertex "
            "1, not at the box's corner",
    inputs=TRIANGLES,
    options=(LISTING, VALUES),
    code=listing(lininterp_listing),
    generator=lininterp_run,
    uses_grid=True,
    notes=("The listing outputs every pixel of the triangle's bounding box (the inside test "
           "comes on a later slide), with q stepped by c_x along a row and c_y from row to row.",
           "As printed, qRow is q at vertex 1 (which is just q1) and the loops start at x1 and "
           "y1: the columns left of vertex 1 and the rows below it are never output (missing "
           "counts them), and the first pixel gets q1 although its centre is up to half a "
           "pixel from vertex 1, so every value is off by that step. The line qRow += c_y "
           "after the loops is stray and changes nothing.",
           "listing=corrected starts qRow at the centre of the box's corner pixel (xl, yl) and "
           "the loops at xl, yl: every value is the plane's at the centre. Exact rational "
           "arithmetic; pixels in grey from the smallest vertex value (black) to the largest."),
    oracle=Oracle(
        "exact",
        "The listing ported in the test in Fractions (as printed and corrected), on random and "
        "hard triangles; corrected: at every centre of the box the plane through the vertex "
        "values, alpha q0 + beta q1 + gamma q2.",
        ("algorithms/triangles/test_triangle_printed.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (TRIANGLE_BARYCENTRIC_PRINTED, TRIANGLE_LININTERP)
