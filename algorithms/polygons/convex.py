"""polygon-convex: one run per row between the left and the right chain."""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, InputError, Oracle
from algorithms.core.steps import NO_PIXEL, PER_PIXEL, PER_ROW, PLOT, Note, Span, Start, Table, Vars
from .common import (HALF_PIXEL, NAN, ONE, POLYGON, as_pixels, cross, first_column, first_index,
                     signed_area2, single_contour, snap_contours, table_number, without_repeats)
from .scanline import scanline_pixels


# ---------------------------------------------------------- convex polygon
def convexity_problem(contour) -> str:
    """Why a contour (snapped, without repeats) is not convex, or ''."""
    n = len(contour)
    if n < 3:
        return ""
    edges = [(contour[(k + 1) % n][0] - contour[k][0], contour[(k + 1) % n][1] - contour[k][1])
             for k in range(n)]
    if all(cross(contour[k - 2], contour[k - 1], contour[k]) == 0 for k in range(n)):
        return ""  # flat: a degenerate convex polygon, with no area to fill
    turns = set()
    for k in range(n):
        (ax, ay), (bx, by) = edges[k - 1], edges[k]
        turn = ax * by - ay * bx
        if turn == 0 and ax * bx + ay * by < 0:
            return f"it turns back on itself at P{k + 1}"
        if turn:
            turns.add(turn > 0)
    if len(turns) > 1:
        return "it turns left at some vertices and right at others"
    for axis, name in ((0, "x"), (1, "y")):
        signs = [d[axis] > 0 for d in edges if d[axis]]
        changes = sum(signs[k] != signs[k - 1] for k in range(len(signs)))
        if changes > 2:
            return f"it winds around more than once ({name} changes direction {changes} times)"
    return ""


def _chains(contour):
    """Left and right chains from the lowest vertex up to the highest, as edge lists."""
    n = len(contour)
    bottom = min(range(n), key=lambda k: (contour[k][1], contour[k][0]))
    top = max(range(n), key=lambda k: (contour[k][1], -contour[k][0]))
    forward, backward = [], []
    k = bottom
    while k != top:
        forward.append((k, (k + 1) % n))
        k = (k + 1) % n
    k = bottom
    while k != top:
        backward.append((k, (k - 1) % n))
        k = (k - 1) % n
    # Going forward from the bottom of a counter-clockwise polygon runs up its right side.
    if signed_area2(contour) >= 0:
        return bottom, top, backward, forward
    return bottom, top, forward, backward


class ChainWalker:
    """Walks one chain upward, giving x where it meets each row's centre line."""

    def __init__(self, contour, edges):
        self.contour, self.edges, self.k = contour, edges, -1
        self.x = self.inv_m = None

    def at(self, row: int) -> bool:
        """Move to the edge that meets the row's centre line; True if it moved."""
        centre = ONE * row + HALF_PIXEL
        moved = False
        while self.k < 0 or self.contour[self.edges[self.k][1]][1] <= centre:
            self.k += 1
            moved = True
        if moved:
            (x0, y0), (x1, y1) = (self.contour[v] for v in self.edges[self.k])
            self.inv_m = Fraction(x1 - x0, y1 - y0)
            self.x = as_pixels(x0) + as_pixels(centre - y0) * self.inv_m
        return moved

    def step(self) -> None:
        self.x += self.inv_m


def convex_listing(points, options) -> Code:
    # Operation counts: per vertex, snapping and the turn test (a cross
    # product); per chain edge (a row of the chains table) the search for
    # B and T; x is exact, a whole part and a remainder (two additions and
    # a carry test per step), as in polygon-scanline.
    code = Code()
    code.add("snap", "snap the vertices; check convexity: all turns one way, and x and y "
                     "each change direction at most twice",
             per={"vertices": {"mul": 4, "round": 2, "int_add": 5, "compare": 4}})
    code.add("chains", "B = lowest vertex, T = highest; the left and right chains of edges run "
                       "from B up to T", per={PER_ROW: {"compare": 2}})
    code.add("rows", "for each row y whose centre line B.y <= y + 1/2 < T.y:",
             ops={"int_add": 2, "div": 2})
    code.add("next_edge", "    on each chain, while the edge's top is at or below y + 1/2: take "
                          "the next edge, x = its x at y + 1/2",
             ops={"compare": 2, "int_add": 4, "mul": 1, "div": 1})
    code.add("plot_span", "    fill pixels i with x_left <= i + 1/2 < x_right", PLOT,
             ops={"round": 2, "compare": 3}, per={PER_PIXEL: {"int_add": 1, "compare": 1}})
    code.add("step_x", "    x_left += 1/m_left;  x_right += 1/m_right",
             ops={"int_add": 5, "compare": 3})
    code.add("done", "done")
    return code


def _convex_contour(points):
    single_contour(points, "polygon-convex", "use polygon-scanline for several contours or holes")
    contour = without_repeats(snap_contours(points)[0])
    problem = convexity_problem(contour)
    if problem:
        raise InputError(f"polygon-convex needs a convex polygon, but {problem}; "
                         "use polygon-scanline or polygon-tessellate")
    return contour


def convex(points, options):
    contour = _convex_contour(points)
    at = convex_listing(points, options).at
    yield Start(line=at["snap"], values=("y", "x_left", "x_right"),
                constants={"vertices": len(contour), "subpixel": ONE})
    if len(contour) < 3 or signed_area2(contour) == 0 and all(
            cross(contour[k - 2], contour[k - 1], contour[k]) == 0 for k in range(len(contour))):
        yield Note(line=at["snap"], text="all the vertices lie on one line: the polygon has no area")
        yield (at["done"], NO_PIXEL, NO_PIXEL, NAN, NAN, NAN)
        return
    bottom, top, left_edges, right_edges = _chains(contour)
    rows = []
    for side, chain in (("left", left_edges), ("right", right_edges)):
        for a, b in chain:
            (x0, y0), (x1, y1) = contour[a], contour[b]
            slope = Fraction(x1 - x0, y1 - y0) if y1 != y0 else "horizontal"
            rows.append((side, f"P{a + 1}P{b + 1}", as_pixels(y0), as_pixels(y1), slope))
    yield Vars(line=at["chains"], values={"B": f"P{bottom + 1}", "T": f"P{top + 1}"})
    yield Table(line=at["chains"], name="chains", columns=("side", "edge", "from y", "to y", "1/m"),
                rows=tuple(tuple(table_number(c) if not isinstance(c, str) else c for c in row)
                           for row in rows))
    left, right = ChainWalker(contour, left_edges), ChainWalker(contour, right_edges)
    y, top_row = first_index(contour[bottom][1]), first_index(contour[top][1])
    yield (at["rows"], NO_PIXEL, NO_PIXEL, y, NAN, NAN)
    pixels = 0
    next_edge, plot, step_x = at["next_edge"], at["plot_span"], at["step_x"]
    while y < top_row:
        moved = left.at(y)
        moved = right.at(y) or moved
        if moved:
            yield (next_edge, NO_PIXEL, NO_PIXEL, y, float(left.x), float(right.x))
        start, end = first_column(left.x), first_column(right.x)
        pixels += max(0, end - start)
        yield Span(line=plot, y=y, x_start=start, x_end=max(start, end))
        left.step()
        right.step()
        y += 1
        yield (step_x, NO_PIXEL, NO_PIXEL, y, float(left.x), float(right.x))
    yield Vars(line=at["done"], values={"pixels": pixels})


def convex_pixels(points, options=None) -> np.ndarray:
    """Fast kernel: after the convexity check, the scan-line kernel's pixels."""
    _convex_contour(points)
    return scanline_pixels(points, {"fill_rule": "evenodd", "arithmetic": "exact"})


CONVEX = AlgorithmSpec(
    name="polygon-convex",
    title="Convex polygon",
    family="polygons",
    summary="left and right edge chains from the bottom vertex to the top: one run per row",
    inputs=POLYGON,
    options=(),
    code=listing(convex_listing),
    generator=convex,
    kernel=convex_pixels,
    notes=("A convex polygon meets every scan line in one run, so no edge table or "
           "sorting is needed: each side is one chain of edges, walked upward.",
           "Refuses a polygon that is not convex, or more than one contour.",
           "Same fill rule as polygon-scanline: a centre on the left chain is filled, "
           "one on the right chain is not."),
    oracle=Oracle(
        "exact",
        "The pixel centres the polygon covers, from exact integer arithmetic "
        "(algorithms/exact/polygons.py), on the hard cases; on random convex polygons the same "
        "runs, row for row, as polygon-scanline.",
        ("algorithms/polygons/test_polygons_convex_tessellate.py", "algorithms/test_stability.py"),
        check="covered-polygon"),
)

# The module's algorithms, in the order they are listed.
SPECS = (CONVEX,)
