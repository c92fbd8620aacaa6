"""polygon-tessellate: ear clipping into triangles, each filled by edge functions."""
from __future__ import annotations

import numpy as np

from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec, InputError, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PER_PIXEL, PER_ROW, PLOT, VISIT, Note, Span, Start, Table, Vars
from .common import (HALF_PIXEL, NAN, ONE, POLYGON, cross, first_index, pixel_of, signed_area2,
                     single_contour, snap_contours, without_repeats)


# ------------------------------------------------------------ tessellation
def _segments_meet(p, q, r, s) -> bool:
    """Do the closed segments pq and rs share a point? (exact)"""
    d1, d2 = cross(p, q, r), cross(p, q, s)
    d3, d4 = cross(r, s, p), cross(r, s, q)
    if ((d1 > 0 and d2 < 0) or (d1 < 0 and d2 > 0)) and ((d3 > 0 and d4 < 0) or (d3 < 0 and d4 > 0)):
        return True

    def on(a, b, c):  # c on the closed segment ab, given that a, b, c are collinear
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(a[1], b[1])
    return ((d1 == 0 and on(p, q, r)) or (d2 == 0 and on(p, q, s))
            or (d3 == 0 and on(r, s, p)) or (d4 == 0 and on(r, s, q)))


def simplicity_problem(contour) -> str:
    """Why a contour (snapped, without repeats) is not a simple polygon, or ''."""
    n = len(contour)
    for k in range(n):
        before, here, after = contour[k - 1], contour[k], contour[(k + 1) % n]
        if cross(before, here, after) == 0 and (
                (here[0] - before[0]) * (after[0] - here[0])
                + (here[1] - before[1]) * (after[1] - here[1])) < 0:
            return f"it folds back on itself at P{k + 1} (two edges overlap)"
    # Every pair of edges that are not neighbours, tested one edge against all
    # later ones at once: the same pairs in the same order as a double loop,
    # in whole numbers (exact while the products fit in 64 bits).
    points = np.array(contour, dtype=object if _too_large(contour) else np.int64)
    ends = np.roll(points, -1, axis=0)
    for a in range(n - 2):
        meets = _meets(points[a], ends[a], points[a + 2:], ends[a + 2:])
        if a == 0:
            meets[-1] = False  # neighbours through the closing edge
        hits = np.flatnonzero(meets)
        if len(hits):
            b = a + 2 + int(hits[0])
            return (f"edges P{a + 1}P{(a + 1) % n + 1} and P{b + 1}P{(b + 1) % n + 1} "
                    "cross or touch")
    return ""


def _too_large(contour) -> bool:
    # cross products of coordinates below 2**30 stay below 2**62
    return max((abs(v) for point in contour for v in point), default=0) >= 1 << 30


def _cross_many(o, a, b):
    """cross(o, a, b) with any of o, a, b an array of points."""
    return ((a[..., 0] - o[..., 0]) * (b[..., 1] - o[..., 1])
            - (a[..., 1] - o[..., 1]) * (b[..., 0] - o[..., 0]))


def _on_many(a, b, c):
    """c on the closed segment ab, given that they are collinear (arrays allowed)."""
    return ((np.minimum(a[..., 0], b[..., 0]) <= c[..., 0])
            & (c[..., 0] <= np.maximum(a[..., 0], b[..., 0]))
            & (np.minimum(a[..., 1], b[..., 1]) <= c[..., 1])
            & (c[..., 1] <= np.maximum(a[..., 1], b[..., 1])))


def _meets(p, q, r, s):
    """_segments_meet(p, q, r[i], s[i]) for every i, as a bool array."""
    d1, d2 = _cross_many(p, q, r), _cross_many(p, q, s)
    d3, d4 = _cross_many(r, s, p), _cross_many(r, s, q)
    proper = (((d1 > 0) & (d2 < 0)) | ((d1 < 0) & (d2 > 0))) \
        & (((d3 > 0) & (d4 < 0)) | ((d3 < 0) & (d4 > 0)))
    touch = (((d1 == 0) & _on_many(p, q, r)) | ((d2 == 0) & _on_many(p, q, s))
             | ((d3 == 0) & _on_many(r, s, p)) | ((d4 == 0) & _on_many(r, s, q)))
    return np.asarray(proper | touch, dtype=bool)


def _in_closed_triangle(a, b, c, p) -> bool:
    d1, d2, d3 = cross(a, b, p), cross(b, c, p), cross(c, a, p)
    return not ((min(d1, d2, d3) < 0) and (max(d1, d2, d3) > 0))


TIES = Option("ties", "choice", "left-bottom",
              "centres exactly on a triangle's edge: left-bottom (the fill rule: left and "
              "bottom edges only), inclusive (every edge: shared edges overlap) or strict "
              "(no edge: cracks open)", choices=("left-bottom", "inclusive", "strict"))


def edge_functions(triangle):
    """(a, b, c) of E(X, Y) = a X + b Y + c for each edge, positive inside.

    In snapped units; the triangle must be counter-clockwise.
    """
    functions = []
    for k in range(3):
        (x0, y0), (x1, y1) = triangle[k], triangle[(k + 1) % 3]
        a, b = -(y1 - y0), x1 - x0
        functions.append((a, b, x0 * y1 - y0 * x1))
    return functions


def covers(functions, x: int, y: int, ties: str) -> bool:
    """The triangle's test at a snapped point, with the tie rule on its edges."""
    for a, b, c in functions:
        e = a * x + b * y + c
        if e > 0:
            continue
        if e < 0 or ties == "strict":
            return False
        # On this edge: a left edge (a > 0) or a bottom one (a == 0, b > 0) keeps it.
        if ties == "left-bottom" and not (a > 0 or (a == 0 and b > 0)):
            return False
    return True


def triangle_runs(triangle, ties: str = "left-bottom"):
    """(row, first, end) runs of the covered pixels of a counter-clockwise
    triangle, a row at a time as they are asked for: each row is a frame, so
    a triangle as large as the grid does not hold up the first of them."""
    functions = edge_functions(triangle)
    xs = [v[0] for v in triangle]
    ys = [v[1] for v in triangle]
    for row in range(first_index(min(ys)) - 1, first_index(max(ys)) + 1):
        centre_y = ONE * row + HALF_PIXEL
        covered = [i for i in range(first_index(min(xs)) - 1, first_index(max(xs)) + 1)
                   if covers(functions, ONE * i + HALF_PIXEL, centre_y, ties)]
        if covered:
            # A triangle is convex, so one row's pixels are one run.
            assert covered[-1] - covered[0] + 1 == len(covered)
            yield row, covered[0], covered[-1] + 1


def tessellate_listing(points, options) -> Code:
    ties = {"left-bottom": "E > 0, or E = 0 on a left edge (a > 0) or a bottom edge (a = 0, b > 0)",
            "inclusive": "E >= 0 for every edge", "strict": "E > 0 for every edge"}[options["ties"]]
    # Operation counts, with two lower bounds: the simplicity check (every
    # pair of edges) and the search for a vertex inside the candidate ear
    # (every other vertex against it) are counted as one test each; and a
    # row's fill counts its covered pixels, not the other centres of the
    # bounding box row that were tested and left out.
    cross_ops = {"mul": 2, "int_add": 5}
    inside = {"mul": 6, "int_add": 15, "compare": 3}
    code = Code()
    code.add("snap", "snap the vertices; check the polygon is simple (no two edges cross or touch)",
             per={"vertices": {"mul": 2, "round": 2}})
    code.add("drop_flat", "drop every vertex that lies on the straight line between its neighbours")
    code.add("loop", "while more than 3 vertices remain:")
    code.add("candidate", "    candidate ear: the triangle (prev, v, next) at the next vertex v",
             VISIT, ops={**cross_ops, "compare": 2})
    code.add("reflex", "    if the turn prev -> v -> next is not convex: not an ear", branch="reflex")
    code.add("blocked", "    elif another vertex lies in the triangle (edges included): not an ear",
             VISIT, branch="blocked", ops=inside)
    code.add("ear", "    else: it is an ear: output the triangle, remove v", branch="ear", ops=inside)
    code.add("drop_new_flat", "    drop prev or next if it now lies on a straight line between "
                              "its neighbours")
    code.add("last", "output the last 3 vertices as a triangle")
    code.add("edges", "for each triangle: E_k(p) = a_k x + b_k y + c_k for its 3 edges, "
                      "positive inside (1/256 px units)", per={PER_ROW: {"mul": 2, "int_add": 3}})
    code.add("plot_rows", f"    for each row of its bounding box: fill the pixels whose centre has "
                          f"{ties}", PLOT,
             per={PER_PIXEL: {"mul": 6, "int_add": 8, "compare": 4, "pixels_tested": 1}})
    code.add("done", "done")
    return code


def _simple_contour(points):
    single_contour(points, "polygon-tessellate",
                    "use polygon-scanline for several contours or holes")
    contour = without_repeats(snap_contours(points)[0])
    problem = simplicity_problem(contour) if len(contour) >= 3 else ""
    if problem:
        raise InputError(f"polygon-tessellate needs a simple polygon, but {problem}; "
                         "use polygon-scanline, which fills any polygon")
    return contour


def _flat(ring, k) -> bool:
    n = len(ring)
    return cross(ring[(k - 1) % n][1], ring[k][1], ring[(k + 1) % n][1]) == 0


def tessellate(points, options):
    contour = _simple_contour(points)
    at = tessellate_listing(points, options).at
    yield Start(line=at["snap"], values=("vertex", "turn", "triangles"),
                constants={"vertices": len(contour), "ties": options["ties"], "subpixel": ONE})
    # The ring keeps each vertex's original number for the tables.
    ring = list(enumerate(contour))
    k = 0
    while len(ring) >= 3 and k < len(ring):
        if _flat(ring, k):
            yield Note(line=at["drop_flat"],
                       text=f"P{ring[k][0] + 1} lies on the line between its neighbours: dropped")
            ring.pop(k)
            k = max(0, k - 1)
        else:
            k += 1
    if len(ring) < 3:
        yield Note(line=at["drop_flat"], text="all the vertices lie on one line: the polygon has "
                                              "no area")
        yield Vars(line=at["done"], values={"triangles": 0, "pixels": 0})
        return
    orientation = 1 if signed_area2([v for _, v in ring]) > 0 else -1
    triangles = yield from _clip_ears(ring, orientation, at)
    triangles.append(tuple(ring))
    yield (at["last"], NO_PIXEL, NO_PIXEL, NAN, NAN, len(triangles))
    yield Table(line=at["last"], name="triangles", columns=("triangle", "A", "B", "C"),
                rows=tuple((t + 1, *(f"P{index + 1}" for index, _ in tri))
                           for t, tri in enumerate(triangles)))
    pixels = yield from _fill_triangles(triangles, orientation, options["ties"], at)
    yield Vars(line=at["done"], values={"triangles": len(triangles), "pixels": pixels})


def _clip_ears(ring, orientation, at):
    """Clip ears off the ring until 3 vertices are left; returns the triangles."""
    triangles = []
    k, misses = 0, 0
    while len(ring) > 3:
        n = len(ring)
        k %= n
        (pi, prev), (vi, here), (ni, after) = ring[k - 1], ring[k], ring[(k + 1) % n]
        turn = cross(prev, here, after)
        ear_value = (vi + 1, turn / ONE ** 2, len(triangles))
        yield (at["candidate"], *pixel_of(here), *ear_value)
        if turn * orientation <= 0:
            yield (at["reflex"], NO_PIXEL, NO_PIXEL, *ear_value)
            k, misses = k + 1, misses + 1
        else:
            blocker = next((v for j, (_, v) in enumerate(ring)
                            if j not in (k - 1 if k else n - 1, k, (k + 1) % n)
                            and _in_closed_triangle(prev, here, after, v)), None)
            if blocker is not None:
                yield (at["blocked"], *pixel_of(blocker), *ear_value)
                k, misses = k + 1, misses + 1
            else:
                triangles.append(((pi, prev), (vi, here), (ni, after)))
                ring.pop(k)
                misses = 0
                yield (at["ear"], NO_PIXEL, NO_PIXEL, vi + 1, turn / ONE ** 2, len(triangles))
                k = (k - 1) % len(ring)  # back to prev, whose ear just changed
                k = yield from _drop_new_flat(ring, k, at)
        if misses > 2 * len(ring):
            raise RuntimeError("ear clipping found no ear in a simple polygon")
    return triangles


def _drop_new_flat(ring, k, at):
    """Drop prev or next (at k, k + 1) where they now lie on a straight line;
    returns k, still at prev or where it was."""
    # Only prev and next got new neighbours; dropping one of them leaves the
    # other's flatness as it was (all four are collinear).
    for entry in (ring[k], ring[(k + 1) % len(ring)]):
        j = ring.index(entry)
        if len(ring) > 3 and _flat(ring, j):
            yield Note(line=at["drop_new_flat"], text=f"P{entry[0] + 1} now lies on a straight "
                                                      "line between its neighbours: dropped")
            ring.pop(j)
            k -= j < k
    return k % len(ring)


def _fill_triangles(triangles, orientation, ties, at):
    """Each triangle's edge functions, then its rows; returns the pixels filled."""
    pixels = 0
    plot = at["plot_rows"]
    for t, tri in enumerate(triangles):
        vertices = [v for _, v in tri]
        if orientation < 0:
            vertices.reverse()
        functions = edge_functions(vertices)
        names = [f"P{index + 1}" for index, _ in (tri if orientation > 0 else tri[::-1])]
        yield Table(line=at["edges"], name=f"edge functions of triangle {t + 1}",
                    columns=("edge", "a", "b", "c", "side"),
                    rows=tuple((names[e] + names[(e + 1) % 3], a, b, c, _side(a, b))
                               for e, (a, b, c) in enumerate(functions)))
        for row, start, end in triangle_runs(vertices, ties):
            pixels += end - start
            yield Span(line=plot, y=row, x_start=start, x_end=end)
    return pixels


def _side(a: int, b: int) -> str:
    if a > 0:
        return "left"
    if a < 0:
        return "right"
    return "bottom" if b > 0 else "top"


TESSELLATE = AlgorithmSpec(
    name="polygon-tessellate",
    title="Tessellation (ear clipping)",
    family="polygons",
    summary="cut a simple polygon into triangles by clipping ears; fill each by edge functions",
    inputs=POLYGON,
    options=(TIES,),
    code=listing(tessellate_listing),
    generator=tessellate,
    notes=("An ear is a convex corner whose triangle holds no other vertex; every simple "
           "polygon with more than 3 vertices has one, so clipping ears always ends in "
           "n - 2 triangles.",
           "Each triangle is tested at every pixel centre of its bounding box with three "
           "edge functions in exact integers. With ties = left-bottom, a centre on a "
           "shared diagonal goes to exactly one triangle, so the result equals "
           "polygon-scanline's; inclusive shows the overlaps, strict the cracks.",
           "Refuses a self-intersecting polygon or more than one contour."),
    oracle=Oracle(
        "exact",
        "With ties left-bottom, the pixel centres the polygon covers, each once, from exact "
        "integer arithmetic (algorithms/exact/polygons.py); inclusive and strict are only checked "
        "to nest around it.",
        ("algorithms/polygons/test_polygons_convex_tessellate.py", "algorithms/test_stability.py"),
        check="covered-polygon"),
)

# The module's algorithms, in the order they are listed.
SPECS = (TESSELLATE,)
