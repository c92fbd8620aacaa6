"""Polygon scan lines as the lecture notes show them: the brute-force scan
line (every edge against every scan line) and the edge table with X_low.

polygon-brute-scanline does the same fill as polygon-scanline without the
tables: on each row it tests every edge, sorts the crossings and fills
between pairs, so its cost grows with rows x edges rather than with the
edges a row actually meets. polygon-scanline-xlow keeps the textbook's
table entry (ymax, X_low, 1/m): x at the lower end point and scan lines
along whole y, which samples each pixel at the middle of its bottom edge.
"""
from __future__ import annotations

from fractions import Fraction

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, Oracle
from algorithms.core.steps import NO_PIXEL, PER_PIXEL, PER_ROW, PLOT, Span, Start, Table, Vars
from .common import HALF_PIXEL, ONE, POLYGON, as_pixels, edge_label, first_column, snap_contours
from .scanline import (ARITHMETIC, FILL_RULE, ScanEdge, first_row, runs, scanline,
                       scanline_explain, scanline_listing, scanline_pixels)


# ------------------------------------------------- brute-force scan line
def brute_listing(points, options) -> Code:
    rule = options["fill_rule"]
    fill = ("walk the crossings adding each dir to w; fill where w is not 0" if rule == "nonzero"
            else "for each pair (x_left, x_right): fill pixels i with x_left <= i + 1/2 < x_right")
    code = Code()
    code.add("snap", "snap every vertex to the 1/256 px grid",
             per={"vertices": {"mul": 2, "round": 2}})
    code.add("rows", "for every row y from the lowest vertex to the highest:",
             ops={"int_add": 1, "compare": 1})
    code.add("test", "    for every edge (a, b): if min(a.y, b.y) <= y + 1/2 < max(a.y, b.y):",
             ops={"compare": 2})
    code.add("cross", "        x = a.x + (y + 1/2 - a.y) * (b.x - a.x) / (b.y - a.y);  "
                      "add (x, dir) to the list", ops={"int_add": 3, "mul": 1, "div": 1})
    code.add("sort", "    sort the list on x", per={PER_ROW: {"compare": 2}})
    code.add("plot_spans", f"    {fill}", PLOT, ops={"round": 2, "compare": 1},
             per={PER_PIXEL: {"int_add": 1, "compare": 1}})
    code.add("done", "done")
    return code


def _edges(contours):
    """(label, low, high, direction) of every edge, horizontal ones too:
    the brute force tests them all."""
    for c, contour in enumerate(contours):
        for k, start in enumerate(contour):
            end = contour[(k + 1) % len(contour)]
            direction = 1 if end[1] > start[1] else -1
            low, high = (start, end) if direction > 0 else (end, start)
            yield edge_label(contours, c, k), low, high, direction


def brute_scanline(points, options):
    """Every row, every edge: test, intersect, sort, fill."""
    rule = options["fill_rule"]
    contours = snap_contours(points)
    edges = list(_edges(contours))
    at = brute_listing(points, options).at
    ys = [v[1] for contour in contours for v in contour]
    bottom, top = first_row(min(ys)), first_row(max(ys))
    yield Start(line=at["snap"], values=("y", "tests", "crossings"),
                constants={"edges": len(edges), "rows": max(0, top - bottom),
                           "vertices": len(ys), "fill_rule": rule})
    tests = crossings = spans = pixels = 0
    for y in range(bottom, top):
        yield (at["rows"], NO_PIXEL, NO_PIXEL, y, tests, crossings)
        found = []
        line = ONE * y + HALF_PIXEL
        for label, low, high, direction in edges:
            tests += 1
            if not low[1] <= line < high[1]:
                yield (at["test"], NO_PIXEL, NO_PIXEL, y, tests, crossings)
                continue
            x = as_pixels(low[0]) + Fraction(line - low[1], ONE) * Fraction(high[0] - low[0],
                                                                             high[1] - low[1])
            crossings += 1
            found.append(ScanEdge(label, y, y + 1, x, 0, direction))
            yield (at["cross"], NO_PIXEL, NO_PIXEL, y, tests, crossings)
        found.sort(key=lambda e: e.x)
        yield Table(line=at["sort"], name="crossings", columns=("edge", "x", "dir"),
                    rows=tuple((e.label, e.x, e.direction) for e in found))
        for left, right in runs(found, rule):
            start, end = first_column(left), first_column(right)
            spans += 1
            pixels += max(0, end - start)
            yield Span(line=at["plot_spans"], y=y, x_start=start, x_end=max(start, end))
    yield Vars(line=at["done"], values={"tests": tests, "crossings": crossings, "spans": spans,
                                        "pixels": pixels})


POLYGON_BRUTE_SCANLINE = AlgorithmSpec(
    name="polygon-brute-scanline",
    title="Scan line, brute force",
    family="polygons",
    summary="every edge against every scan line, sort the crossings, fill between pairs",
    inputs=POLYGON,
    options=(FILL_RULE,),
    code=listing(brute_listing),
    generator=brute_scanline,
    kernel=scanline_pixels,
    notes=("The same pixels as polygon-scanline, without its tables: each row tests every edge "
           "(tests counts them: rows x edges), where the edge table only looks at the edges "
           "that reach the row.",
           "A crossing is where an edge meets the row's centre line y + 1/2, exactly."),
    oracle=Oracle(
        "exact",
        "The pixel centres the polygon covers by either fill rule, each once, from exact integer "
        "arithmetic (algorithms/exact/polygons.py); its tests counted as rows times edges.",
        ("algorithms/polygons/test_polygon_textbook.py", "algorithms/test_stability.py"),
        check="covered-polygon"),
)


# --------------------------------------------------- the X_low edge table
def _xlow(options) -> dict:
    return {**options, "edge_x": "x-low"}


def xlow_listing(points, options) -> Code:
    return scanline_listing(points, _xlow(options))


def xlow_scanline(points, options):
    return scanline(points, _xlow(options))


def xlow_pixels(points, options) -> object:
    return scanline_pixels(points, _xlow(options))


POLYGON_SCANLINE_XLOW = AlgorithmSpec(
    name="polygon-scanline-xlow",
    title="Scan line, X_low table",
    family="polygons",
    summary="the textbook's edge table (ymax, X_low, 1/m): scan lines along whole y",
    inputs=POLYGON,
    options=(FILL_RULE, ARITHMETIC),
    code=listing(xlow_listing),
    generator=xlow_scanline,
    kernel=xlow_pixels,
    explain=scanline_explain,
    notes=("The ET keeps x at the edge's lower end point, as the notes' table does, and row y "
           "is scanned along y itself rather than its centre line y + 1/2.",
           "With whole-number vertices X_low is the vertex's own x, but every pixel is then "
           "sampled at the middle of its bottom edge (i + 1/2, y): the fill sits half a pixel "
           "lower than polygon-scanline's, and a vertex on a whole y starts its edge's rows.",
           "Everything else (the AET, the fill rule, the spans) is polygon-scanline's."),
    oracle=Oracle(
        "exact",
        "With exact arithmetic, the pixels whose sample point (i + 1/2, j) the polygon covers: the "
        "exact centre rule (algorithms/exact/polygons.py) on the polygon lifted by 1/2 px. float64 "
        "and float32 are not checked against it.",
        ("algorithms/polygons/test_polygon_textbook.py", "algorithms/test_stability.py"),
        check="covered-polygon-lifted"),
)


# ----------------------------------------------- the integer edge stepper
def _integer(options) -> dict:
    return {**options, "arithmetic": "integer"}


def integer_listing(points, options) -> Code:
    return scanline_listing(points, _integer(options))


def integer_scanline(points, options):
    return scanline(points, _integer(options))


def integer_pixels(points, options) -> object:
    return scanline_pixels(points, {**options, "arithmetic": "exact"})


POLYGON_SCANLINE_INTEGER = AlgorithmSpec(
    name="polygon-scanline-integer",
    title="Scan line, integer edge walk",
    family="polygons",
    summary="the ET/AET with each edge's x stepped Bresenham-style: a whole part and an error term",
    inputs=POLYGON,
    options=(FILL_RULE,),
    code=listing(integer_listing),
    generator=integer_scanline,
    kernel=integer_pixels,
    explain=scanline_explain,
    notes=("x is kept as a whole number of 1/(256 dy) px and split into a whole part and an "
           "error e over that denominator; each row adds 1/m's whole part and remainder and "
           "carries when e reaches it, as Bresenham's line does: integers only.",
           "The same pixels as polygon-scanline's exact arithmetic; the AET shows x as "
           "(whole, e/denominator)."),
    oracle=Oracle(
        "exact",
        "The pixel centres the polygon covers, from exact integer arithmetic "
        "(algorithms/exact/polygons.py), and each active edge's whole part and error term equal to "
        "its exact crossing, in Fractions.",
        ("algorithms/polygons/test_polygon_textbook.py", "algorithms/test_stability.py"),
        check="covered-polygon"),
)

# The module's algorithms, in the order they are listed.
SPECS = (POLYGON_BRUTE_SCANLINE, POLYGON_SCANLINE_XLOW, POLYGON_SCANLINE_INTEGER)
