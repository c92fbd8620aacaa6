"""Linewise interpolation: a value given at the three vertices, found first
where each row crosses the triangle's edges, then along the row between
them (the lecture's f(E), f(F), then f(G)).

Vertices are real; pixel (i, j) is sampled at (i + 1/2, j + 1/2); a centre
on an edge is filled. Exact rational arithmetic throughout, so the value at
each centre is exactly the plane through the three vertex values.
"""
from __future__ import annotations

import math
from fractions import Fraction

from algorithms.core.code import Code, listing
from algorithms.circles.curves import grey_ink
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, Note, Start, Vars
from algorithms.triangles.variants import HALF, centre_range, check_coordinates, cramer, triangles_of
from algorithms.triangles.edges import TRIANGLES

VALUES = Option("s", "numbers", (0.0, 0.5, 1.0),
                "the value at each vertex, one per point (greys: 0 black, 1 white)")


def row_crossings(triangle, values, cy):
    """[(x, f)] where the row y = cy meets the closed triangle's edges, f
    interpolated along each edge; empty when the row misses it."""
    found = []
    for k in range(3):
        (p, fp), (q, fq) = (triangle[k], values[k]), (triangle[(k + 1) % 3], values[(k + 1) % 3])
        if p[1] == q[1] == cy:
            found += [(p[0], fp), (q[0], fq)]
        elif min(p[1], q[1]) <= cy <= max(p[1], q[1]) and p[1] != q[1]:
            u = (cy - p[1]) / (q[1] - p[1])  # where along the edge, 0 at p
            found.append((p[0] + u * (q[0] - p[0]), fp + u * (fq - fp)))
    return found


def span_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "for each triangle (with its vertex values s0, s1, s2):")
    code.add("row", "    for each row y through the triangle:  E, F = where the row meets the "
                    "edges;  f(E), f(F) interpolated along those edges",
             ops={"div": 2, "mul": 4, "float_add": 8, "compare": 3})
    code.add("plot_span", "        for x = x_E .. x_F:  f = f(E) + (f(F) - f(E)) (x - x_E) / "
                          "(x_F - x_E);  plot (x, y) in grey f", PLOT,
             ops={"mul": 1, "div": 1, "float_add": 3})
    code.add("done", "done")
    return code


def span_run(points, options, grid):
    at = span_listing(points, options).at
    values = options["s"] or (0.0,)
    low, high = min(values, default=0), max(values, default=1)
    yield Start(line=at["setup"], values=("f_E", "f_F", "f", "rgb"),
                constants={"triangles": len(points) // 3}, pixel_value="rgb")
    filled = 0
    for number, vertices in enumerate(triangles_of(points)):
        check_coordinates(number, vertices)
        triangle = tuple(tuple(Fraction(c) for c in p) for p in vertices)
        s = [Fraction(values[(3 * number + k) % len(values)]) for k in range(3)]
        yield Vars(line=at["setup"], values={"triangle": number, "s": tuple(map(float, s)),
                                             **{f"P{k}": tuple(map(float, vertices[k]))
                                                for k in range(3)}})
        if cramer(triangle, triangle[0])[0] == 0:
            yield Note(line=at["setup"], text=f"triangle {number}: no area, nothing to fill")
            continue
        ys = [p[1] for p in triangle]
        for y in centre_range(min(ys), max(ys), grid[1]):
            crossings = row_crossings(triangle, s, y + HALF)
            (xe, fe), (xf, ff) = min(crossings), max(crossings)
            yield (at["row"], NO_PIXEL, NO_PIXEL, float(fe), float(ff), math.nan, math.nan)
            for x in centre_range(xe, xf, grid[0]):
                f = fe if xf == xe else fe + (ff - fe) * (x + HALF - xe) / (xf - xe)
                filled += 1
                yield (at["plot_span"], x, y, float(fe), float(ff), float(f),
                       grey_ink(1 - _unit(f, low, high)))
    yield Vars(line=at["done"], values={"filled": filled})


def _unit(f, low, high) -> float:
    """f on 0..1 between the smallest and largest vertex value."""
    return 0.0 if high == low else float((f - Fraction(low)) / (Fraction(high) - Fraction(low)))


TRIANGLE_SPAN_INTERPOLATE = AlgorithmSpec(
    name="triangle-span-interpolate",
    title="Linewise interpolation (edges, then spans)",
    family="triangles",
    summary="a vertex value interpolated along the edges to each row's ends, then along the "
            "row",
    inputs=TRIANGLES,
    options=(VALUES,),
    code=listing(span_listing),
    generator=span_run,
    uses_grid=True,
    notes=("Two linear interpolations in a row: along two edges to the row's ends E and F, "
           "then from E to F. The result at every centre is the plane through the three "
           "vertex values, the same as alpha s0 + beta s1 + gamma s2 (tests check it "
           "exactly).",
           "The pixels are drawn in grey from black (the smallest vertex value) to white "
           "(the largest); s takes one value per point, repeated when fewer are given."),
    oracle=Oracle(
        "exact",
        "The centres of the closed triangles by exact side tests, and at each the plane through "
        "the vertex values, alpha s0 + beta s1 + gamma s2 in Fractions, to within 1e-9.",
        ("algorithms/triangles/test_triangle_variants.py", "algorithms/test_stability.py"),
        check="span-plane"),
)

# The module's algorithms, in the order they are listed.
SPECS = (TRIANGLE_SPAN_INTERPOLATE,)
