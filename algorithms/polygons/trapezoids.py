"""polygon-tessellate-any: triangles for any polygon, holes and self-crossings too.

Ear clipping needs one simple contour. This cuts the plane into horizontal
slabs at every vertex and every point where two edges cross; inside a slab
no two edges cross, so the edges there are ordered left to right, the fill
rule picks the spans between them, and each span is a trapezoid: two
triangles. Every coordinate stays exact (Fractions of the 1/256 px grid),
and each triangle is filled by edge functions with the left-bottom tie
rule, so the pixels are polygon-scanline's.
"""
from __future__ import annotations

from fractions import Fraction

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Oracle
from algorithms.core.steps import NO_PIXEL, PER_PIXEL, PER_ROW, PLOT, Span, Start, Table, Vars
from .common import ONE, POLYGON, cross, snap_contours
from .scanline import FILL_RULE
from .tessellate import triangle_runs


def _edges(contours):
    """(low, high, direction) of every edge that is not horizontal."""
    for contour in contours:
        for k, start in enumerate(contour):
            end = contour[(k + 1) % len(contour)]
            if start[1] != end[1]:
                up = end[1] > start[1]
                yield (start, end, 1) if up else (end, start, -1)


def _crossing_ys(edges) -> set:
    """The y of every point where two edges cross (exact)."""
    ys = set()
    for n, (a, b, _) in enumerate(edges):
        for c, d, _ in edges[n + 1:]:
            denominator = (b[0] - a[0]) * (d[1] - c[1]) - (b[1] - a[1]) * (d[0] - c[0])
            if denominator == 0:
                continue  # parallel: their ends are vertices, already cut at
            # a + t (b - a) = c + u (d - c), by cross products with (c - a).
            t = Fraction((c[0] - a[0]) * (d[1] - c[1]) - (c[1] - a[1]) * (d[0] - c[0]), denominator)
            u = Fraction((c[0] - a[0]) * (b[1] - a[1]) - (c[1] - a[1]) * (b[0] - a[0]), denominator)
            if 0 < t < 1 and 0 < u < 1:
                ys.add(a[1] + t * (b[1] - a[1]))
    return ys


def _x_at(edge, y):
    (x0, y0), (x1, y1), _ = edge
    return x0 + Fraction((x1 - x0) * (y - y0)) / (y1 - y0)


def _spans(edges, y0, y1, rule):
    """(left, right) edge pairs the fill rule fills in the slab y0..y1."""
    middle = Fraction(y0 + y1) / 2
    crossing = sorted((e for e in edges if e[0][1] <= y0 and e[1][1] >= y1),
                      key=lambda e: _x_at(e, middle))
    if rule == "evenodd":
        return [(crossing[k], crossing[k + 1]) for k in range(0, len(crossing) - 1, 2)]
    found, winding, left = [], 0, None
    for edge in crossing:
        before, winding = winding, winding + edge[2]
        if before == 0:
            left = edge
        elif winding == 0:
            found.append((left, edge))
    return found


def trapezoids_listing(points, options) -> Code:
    code = Code()
    code.add("snap", "snap the vertices to the 1/256 px grid", per={"vertices": {"mul": 2, "round": 2}})
    code.add("cuts", "cut at every vertex y and every y where two edges cross (exact)",
             per={"edges": {"mul": 4, "int_add": 6, "div": 2, "compare": 4}})
    code.add("slab", "for each slab between two cuts: sort the edges that span it on x; the "
                     f"{options['fill_rule']} rule picks the pairs (left, right)",
             per={PER_ROW: {"compare": 2, "mul": 1, "div": 1}})
    code.add("trapezoid", "    each pair is a trapezoid: triangles (l0, r0, r1) and (l0, r1, l1)",
             ops={"int_add": 4, "mul": 2, "div": 2})
    code.add("plot_rows", "    fill each triangle: centres with E > 0, or E = 0 on a left or "
                          "bottom edge", PLOT,
             per={PER_PIXEL: {"mul": 6, "int_add": 8, "compare": 4, "pixels_tested": 1}})
    code.add("done", "done")
    return code


def tessellate_any(points, options):
    rule = options["fill_rule"]
    contours = snap_contours(points)
    edges = list(_edges(contours))
    at = trapezoids_listing(points, options).at
    cuts = sorted({v[1] for contour in contours for v in contour} | _crossing_ys(edges))
    yield Start(line=at["snap"], values=("y0", "y1", "triangles"),
                constants={"edges": len(edges), "vertices": sum(map(len, contours)),
                           "fill_rule": rule, "subpixel": ONE})
    yield Table(line=at["cuts"], name="cuts", columns=("y",),
                rows=tuple((Fraction(y, ONE),) for y in cuts))
    triangles = pixels = 0
    for y0, y1 in zip(cuts, cuts[1:]):
        pairs = _spans(edges, y0, y1, rule)
        yield (at["slab"], NO_PIXEL, NO_PIXEL, float(y0) / ONE, float(y1) / ONE, triangles)
        for left, right in pairs:
            l0, l1 = (_x_at(left, y0), y0), (_x_at(left, y1), y1)
            r0, r1 = (_x_at(right, y0), y0), (_x_at(right, y1), y1)
            yield (at["trapezoid"], NO_PIXEL, NO_PIXEL, float(y0) / ONE, float(y1) / ONE,
                   triangles)
            for triangle in ((l0, r0, r1), (l0, r1, l1)):
                if cross(*triangle) <= 0:
                    continue  # a trapezoid narrowed to a point: one triangle is flat
                triangles += 1
                for row, start, end in triangle_runs(triangle):
                    pixels += end - start
                    yield Span(line=at["plot_rows"], y=row, x_start=start, x_end=end)
    yield Vars(line=at["done"], values={"triangles": triangles, "pixels": pixels,
                                        "slabs": max(0, len(cuts) - 1)})


POLYGON_TESSELLATE_ANY = AlgorithmSpec(
    name="polygon-tessellate-any",
    title="Tessellation into trapezoids",
    family="polygons",
    summary="any polygon, holes and self-crossings too: slabs at vertices and crossings, "
            "two triangles per span",
    inputs=POLYGON,
    options=(FILL_RULE,),
    code=listing(trapezoids_listing),
    generator=tessellate_any,
    notes=("Where polygon-tessellate (ear clipping) refuses holes and crossing edges, this "
           "cuts the plane at every vertex and every crossing, so inside a slab the edges "
           "keep their order and each filled span is a trapezoid.",
           "Coordinates stay exact fractions; each triangle is filled with the left-bottom "
           "tie rule, so the pixels equal polygon-scanline's."),
    oracle=Oracle(
        "exact",
        "The pixel centres the polygon covers by either fill rule, holes and self-crossings "
        "included, each once, from exact integer arithmetic (algorithms/exact/polygons.py).",
        ("algorithms/polygons/test_polygon_textbook.py", "algorithms/test_stability.py"),
        check="covered-polygon"),
)

# The module's algorithms, in the order they are listed.
SPECS = (POLYGON_TESSELLATE_ANY,)
