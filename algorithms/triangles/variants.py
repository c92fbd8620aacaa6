"""Two more ways to look at a triangle: barycentric coordinates solved from
the 3x3 linear system by Cramer's rule (shown beside the edge functions and
the sub-triangle areas they equal), and the triangle drawn as three lines.

Vertices are real; pixel (i, j) has its sample point at (i + 1/2, j + 1/2).
Both take 3k points (k triangles) and stay inside the grid.
"""
from __future__ import annotations

import math
from fractions import Fraction

from algorithms.core.code import Code, listing
from algorithms.core.errors import InputError
from algorithms.lines.common import Octant
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Note, Start, Vars
from algorithms.triangles.edges import MAX_COORDINATE, TRIANGLES

NAN = math.nan
HALF = Fraction(1, 2)


def triangles_of(points):
    return [tuple(points[k:k + 3]) for k in range(0, len(points) - 2, 3)]


def cramer(triangle, p) -> tuple[Fraction, Fraction, Fraction, Fraction]:
    """D and D_alpha, D_beta, D_gamma of the system
    alpha P0 + beta P1 + gamma P2 = p, alpha + beta + gamma = 1, exactly.

    D = det [[x0, x1, x2], [y0, y1, y2], [1, 1, 1]]; D_alpha replaces the first
    column by (x, y, 1), and so on. Each determinant is twice a signed area:
    D of the triangle, D_alpha of (p, P1, P2), which is also the edge function
    e_0(p) of the edge P1 P2.
    """
    def det(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
    p0, p1, p2 = triangle
    return det(p0, p1, p2), det(p, p1, p2), det(p0, p, p2), det(p0, p1, p)


def check_coordinates(number: int, vertices) -> None:
    """The triangle family's bound on coordinates, for the same inputs."""
    if not all(abs(c) <= MAX_COORDINATE for v in vertices for c in v):
        raise InputError(f"triangle {number}: a coordinate is beyond +-{MAX_COORDINATE:g} px")


def box_of(triangle, grid):
    """Columns and rows of the grid whose centres lie in the triangle's bounding box."""
    xs, ys = [v[0] for v in triangle], [v[1] for v in triangle]
    width, height = grid
    return (range(max(0, math.ceil(min(xs) - HALF)), min(width, math.floor(max(xs) - HALF) + 1)),
            range(max(0, math.ceil(min(ys) - HALF)), min(height, math.floor(max(ys) - HALF) + 1)))


# -------------------------------------------------- Cramer's rule
def cramer_listing(points, options) -> Code:
    det = {"mul": 2, "float_add": 5}
    code = Code()
    code.add("setup", "for each triangle:  M = [[x0, x1, x2], [y0, y1, y2], [1, 1, 1]];  "
                      "D = det M = 2A", ops=det)
    code.add("degenerate", "    if D = 0:  skip (the three points are on a line)")
    code.add("visit", "    for each pixel centre p of the bounding box:  solve M (alpha, beta, "
                      "gamma) = (x, y, 1):  D_alpha = det M with column 0 replaced by p, ...",
             VISIT, ops={"mul": 6, "float_add": 15, "div": 3, "compare": 3,
                         "pixels_tested": 1})
    code.add("plot_inside", "        if alpha, beta, gamma >= 0:  plot p   (alpha = D_alpha / D "
                            "= area(p, P1, P2) / area = e0(p) / 2A)", PLOT)
    code.add("done", "done")
    return code


def cramer_run(points, options, grid):
    at = cramer_listing(points, options).at
    yield Start(line=at["setup"], values=("D", "D_alpha", "D_beta", "D_gamma", "alpha", "beta",
                                          "gamma", "area_check"),
                constants={"triangles": len(points) // 3})
    tested = filled = degenerate = 0
    for number, vertices in enumerate(triangles_of(points)):
        check_coordinates(number, vertices)
        triangle = tuple((Fraction(x), Fraction(y)) for x, y in vertices)
        d = cramer(triangle, triangle[0])[0]
        yield Vars(line=at["setup"], values={"triangle": number, "D": float(d), "2A": float(d),
                                             **{f"P{k}": tuple(float(c) for c in vertices[k])
                                                for k in range(3)}})
        if d == 0:
            degenerate += 1
            yield Note(line=at["degenerate"], text=f"triangle {number}: D = 0, nothing to solve")
            continue
        columns, rows = box_of(triangle, grid)
        for j in rows:
            for i in columns:
                tested += 1
                _, da, db, dg = cramer(triangle, (i + HALF, j + HALF))
                weights = (da / d, db / d, dg / d)
                # The three sub-triangles' areas add up to the triangle's: 1 exactly.
                frame = (i, j, float(d), float(da), float(db), float(dg),
                         *(float(w) for w in weights), float(sum(weights)))
                yield (at["visit"], *frame)
                if min(weights) >= 0:
                    filled += 1
                    yield (at["plot_inside"], *frame)
    yield Vars(line=at["done"], values={"tested": tested, "filled": filled,
                                        "degenerate": degenerate})


def cramer_explain(trace, i):
    values = trace.step(i).values
    if "D_alpha" not in values or values.get("D") != values.get("D"):
        return []
    d = values["D"]
    return [("alpha", f"D_alpha / D = {values['D_alpha']:g} / {d:g} = e0(p) / 2A"),
            ("areas", "alpha, beta, gamma = area(p P1 P2), area(P0 p P2), area(P0 P1 p) "
                      "over area(P0 P1 P2)")]


TRIANGLE_CRAMER = AlgorithmSpec(
    name="triangle-cramer",
    title="Barycentric by Cramer's rule",
    family="triangles",
    summary="solve the 3x3 system for alpha, beta, gamma at each centre; inside when all >= 0",
    inputs=TRIANGLES,
    options=(),
    code=listing(cramer_listing),
    generator=cramer_run,
    explain=cramer_explain,
    uses_grid=True,
    step_seconds=1.5e-4,  # three exact determinants a pixel: 60-120 us a step
    notes=("Each determinant of Cramer's rule is twice a signed area: D of the triangle, "
           "D_alpha of (p, P1, P2), which is the edge function e0 at p. So the weights from "
           "the linear system, from the edge functions and from the areas are one and the "
           "same, and add up to 1 (area_check).",
           "Exact rational arithmetic on the vertices as given (no sub-pixel snapping). A "
           "centre on an edge counts as inside (alpha, beta or gamma = 0), so two triangles "
           "sharing an edge both fill its centres; triangle-barycentric applies the fill rule.",
           "Clockwise triangles work too: D and the three D's change sign together."),
    oracle=Oracle(
        "exact",
        "Per pixel, how many of the closed triangles hold its centre, by exact side tests in "
        "Fractions (tests/support/triangle_variant_oracles.py); the weights are the edge functions "
        "over 2A and add up to 1.",
        ("algorithms/triangles/test_triangle_variants.py", "algorithms/test_stability.py"),
        check="closed-triangle"),
)


# -------------------------------------------------- trilinear coordinates
def trilinear_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "for each triangle:  side lengths L_k = |P_(k+2) - P_(k+1)| (the side "
                      "opposite P_k);  2A = (P1 - P0) x (P2 - P0)",
             ops={"mul": 8, "float_add": 8, "sqrt": 3})
    code.add("degenerate", "    if 2A = 0:  skip (the three points are on a line)")
    code.add("visit", "    for each pixel centre p of the bounding box:  trilinear d_k = e_k(p) / "
                      "L_k, the signed distance from p to side k (positive inside)", VISIT,
             ops={"mul": 6, "float_add": 9, "div": 3, "pixels_tested": 1})
    code.add("plot_inside", "        if d_0, d_1, d_2 >= 0:  plot p   (to barycentric: alpha = "
                            "L_0 d_0 / |2A|, beta = L_1 d_1 / |2A|, gamma = L_2 d_2 / |2A|)",
             PLOT, ops={"mul": 3, "div": 3, "compare": 3})
    code.add("done", "done")
    return code


def trilinear_run(points, options, grid):
    at = trilinear_listing(points, options).at
    yield Start(line=at["setup"], values=("d0", "d1", "d2", "alpha", "beta", "gamma"),
                constants={"triangles": len(points) // 3})
    tested = filled = degenerate = 0
    for number, vertices in enumerate(triangles_of(points)):
        check_coordinates(number, vertices)
        triangle = tuple((Fraction(x), Fraction(y)) for x, y in vertices)
        two_a = cramer(triangle, triangle[0])[0]
        sides = [math.dist(vertices[(k + 1) % 3], vertices[(k + 2) % 3]) for k in range(3)]
        yield Vars(line=at["setup"], values={"triangle": number, "2A": float(two_a),
                                             "L0": sides[0], "L1": sides[1], "L2": sides[2],
                                             **{f"P{k}": tuple(float(c) for c in vertices[k])
                                                for k in range(3)}})
        if two_a == 0:
            degenerate += 1
            yield Note(line=at["degenerate"], text=f"triangle {number}: 2A = 0, no inside")
            continue
        sign = 1 if two_a > 0 else -1
        columns, rows = box_of(triangle, grid)
        for j in rows:
            for i in columns:
                tested += 1
                # e_k exact, turned positive inside (a clockwise triangle's are
                # negative there), so d_k has its exact sign; the division rounds once.
                e = [sign * v for v in cramer(triangle, (i + HALF, j + HALF))[1:]]
                d = [float(e[k]) / sides[k] for k in range(3)]
                weights = [sides[k] * d[k] / abs(float(two_a)) for k in range(3)]
                frame = (i, j, *d, *weights)
                yield (at["visit"], *frame)
                if min(e) >= 0:
                    filled += 1
                    yield (at["plot_inside"], *frame)
    yield Vars(line=at["done"], values={"tested": tested, "filled": filled,
                                        "degenerate": degenerate})


TRIANGLE_TRILINEAR = AlgorithmSpec(
    name="triangle-trilinear",
    title="Trilinear coordinates",
    family="triangles",
    summary="the signed distances to the three sides; inside when all >= 0; converted to "
            "barycentric by alpha = L_0 d_0 / |2A|",
    inputs=TRIANGLES,
    options=(),
    code=listing(trilinear_listing),
    generator=trilinear_run,
    uses_grid=True,
    step_seconds=1.5e-4,  # exact distances and side lengths: 60-120 us a step
    notes=("Trilinear coordinates (d_0, d_1, d_2) are p's signed distances to the sides "
           "opposite P0, P1, P2, positive inside whatever the winding. Times the side lengths "
           "they are twice the sub-triangles' "
           "areas, so (L_0 d_0, L_1 d_1, L_2 d_2) / |2A| is (alpha, beta, gamma); the other way, "
           "d_k = |2A| alpha / L_k.",
           "The inside test uses the exact sign of each edge function (a centre on a side "
           "counts as inside), as triangle-cramer does; the distances themselves involve a "
           "square root and are rounded."),
    oracle=Oracle(
        "exact",
        "Per pixel, how many of the closed triangles hold its centre, by exact side tests in "
        "Fractions (tests/support/triangle_variant_oracles.py); the distances convert to the "
        "barycentric weights.",
        ("algorithms/triangles/test_triangle_variants.py", "algorithms/test_stability.py"),
        check="closed-triangle"),
)


# -------------------------------------------------- explicit form by columns
SWAP = Option("swap", "choice", "correct",
              "correct: if y_min > y_max swap them, for each column of the whole triangle; "
              "printed: the lecture's code as printed, columns A..B only and the test reversed "
              "(if y_min < y_max swap), which empties every column it swaps",
              choices=("correct", "printed"))


def column_span(triangle, cx):
    """(y_min, y_max) of the closed triangle on the vertical line x = cx, or None."""
    ys = []
    for k in range(3):
        (x0, y0), (x1, y1) = triangle[k], triangle[(k + 1) % 3]
        if x0 == x1 == cx:
            ys += [y0, y1]
        elif min(x0, x1) <= cx <= max(x0, x1) and x0 != x1:
            ys.append(y0 + (y1 - y0) * (cx - x0) / (x1 - x0))
    return (min(ys), max(ys)) if ys else None


def centre_range(low, high, size: int) -> range:
    """Pixels 0 .. size - 1 whose centres k + 1/2 lie in [low, high]."""
    return range(max(0, math.ceil(low - HALF)), min(size, math.floor(high - HALF) + 1))


def _line_y(p, q, cx):
    return p[1] + (q[1] - p[1]) * (cx - p[0]) / (q[0] - p[0])


def columns_listing(points, options) -> Code:
    printed = options["swap"] == "printed"
    code = Code()
    code.add("setup", "for each triangle:  sort A, B, C so that A_x <= B_x <= C_x")
    if printed:
        code.add("column", "    for x = A_x .. B_x   (as printed: the columns B..C are missing):  "
                           "y_min = y_AC(x);  y_max = y_AB(x)", ops={"mul": 2, "float_add": 4})
        code.add("swap", "        if y_min < y_max:  swap(y_min, y_max)   (as printed: reversed)",
                 ops={"compare": 1})
    else:
        code.add("column", "    for x = A_x .. C_x:  y_min = y_AC(x);  y_max = y_AB(x) while "
                           "x <= B_x, else y_BC(x)", ops={"mul": 2, "float_add": 4})
        code.add("swap", "        if y_min > y_max:  swap(y_min, y_max)   (B below AC)",
                 ops={"compare": 1})
    code.add("plot_span", "        for y = y_min .. y_max:  setPixel(x, y)   (pixel centres, "
                          "ends included)", PLOT, ops={"compare": 1})
    code.add("done", "done")
    return code


def columns_run(points, options, grid):
    printed = options["swap"] == "printed"
    at = columns_listing(points, options).at
    yield Start(line=at["setup"], values=("y_min", "y_max", "swapped"),
                constants={"triangles": len(points) // 3, "swap": options["swap"]})
    filled = 0
    for number, vertices in enumerate(triangles_of(points)):
        check_coordinates(number, vertices)
        a, b, c = sorted(tuple(Fraction(v) for v in p) for p in vertices)
        yield Vars(line=at["setup"], values={"triangle": number, **{
            name: tuple(float(v) for v in p) for name, p in zip("ABC", (a, b, c))}})
        if not printed and cramer((a, b, c), a)[0] == 0:
            yield Note(line=at["setup"], text=f"triangle {number}: no area, nothing to fill")
            continue
        last = b[0] if printed else c[0]
        for x in centre_range(a[0], last, grid[0]):
            cx = x + HALF
            if printed:
                if a[0] == b[0] or a[0] == c[0]:
                    continue  # a vertical AB or AC: the printed slopes divide by zero
                low, high = _line_y(a, c, cx), _line_y(a, b, cx)
                swapped = low < high
            else:
                low, high = column_span((a, b, c), cx)
                swapped = False
            if swapped:
                low, high = high, low
            yield (at["swap"], NO_PIXEL, NO_PIXEL, float(low), float(high), float(swapped))
            for y in centre_range(low, high, grid[1]):
                filled += 1
                yield (at["plot_span"], x, y, float(low), float(high), float(swapped))
    yield Vars(line=at["done"], values={"filled": filled,
                                        "missing": exact_column_count(points, grid) - filled})


def exact_column_count(points, grid) -> int:
    """Pixels of the grid the closed triangles cover, counted column by column."""
    total = 0
    for vertices in triangles_of(points):
        triangle = tuple(tuple(Fraction(v) for v in p) for p in vertices)
        if cramer(triangle, triangle[0])[0] == 0:
            continue
        xs = [p[0] for p in triangle]
        for x in centre_range(min(xs), max(xs), grid[0]):
            total += len(centre_range(*column_span(triangle, x + HALF), grid[1]))
    return total


TRIANGLE_COLUMNS = AlgorithmSpec(
    name="triangle-columns",
    title="Explicit form by columns",
    family="triangles",
    summary="sort the vertices by x; per column, fill between the lower and upper edge",
    inputs=TRIANGLES,
    options=(SWAP,),
    code=listing(columns_listing),
    generator=columns_run,
    uses_grid=True,
    notes=("The explicit form y = m x + c scanned column by column, as one lecture writes "
           "it; triangle-linewise scans rows. Exact rational arithmetic; a centre on an "
           "edge is filled; a triangle without area fills nothing.",
           "swap=printed runs the printed code: its test 'if (y_min < y_max) swap' is the "
           "wrong way round: with B above AC it swaps y_min and y_max into an empty range, "
           "with B below it leaves them reversed, so every column comes out empty (a pixel "
           "only where the two edges meet); its loop also stops at B. missing counts the "
           "pixels the closed triangle has and the run did not fill."),
    oracle=Oracle(
        "exact",
        "correct: the centres of the closed triangles, by exact side tests; printed: the lecture's "
        "loop with its reversed swap test, transcribed in Fractions "
        "(tests/support/triangle_variant_oracles.py).",
        ("algorithms/triangles/test_triangle_variants.py", "algorithms/test_stability.py"),
        check="columns"),
)


# -------------------------------------------------- wireframe
def line_in_grid(p, q, grid):
    """The textbook Bresenham line's pixels from P towards Q, Q left out, only
    those inside the grid: the closed form of algorithms/lines/bresenham.py
    (ties to E), evaluated for the steps that land in the grid's columns (or
    rows), so a line far longer than the grid costs no more than the grid."""
    octant = Octant(p, q)
    dx, dy = octant.dx, octant.dy
    axis = 1 if octant.steep else 0
    sign = octant.major[axis]
    size = grid[axis]
    # The steps u whose major coordinate p + sign u lies in [0, size).
    lo, hi = (-p[axis], size - 1 - p[axis]) if sign > 0 else (p[axis] - size + 1, p[axis])
    for u in range(max(0, lo), min(dx - 1, hi) + 1):
        v = -((dx - 2 * dy * u) // (2 * dx))
        x, y = octant.to_grid(p, u, v)
        if 0 <= x < grid[0] and 0 <= y < grid[1]:
            yield x, y


def wireframe_listing(points, options) -> Code:
    code = Code()
    code.add("setup", "for each triangle:  Q_k = the pixel holding P_k  (floor x, floor y)",
             ops={"round": 6})
    code.add("plot_edge", "    draw the lines Q0 Q1, Q1 Q2, Q2 Q0 with Bresenham (each "
                          "corner once)", PLOT, ops={"int_add": 2})
    code.add("done", "done")
    return code


def wireframe_run(points, options, grid):
    at = wireframe_listing(points, options).at
    yield Start(line=at["setup"], values=("triangle", "edge"),
                constants={"triangles": len(points) // 3})
    width, height = grid
    written = 0
    for number, vertices in enumerate(triangles_of(points)):
        check_coordinates(number, vertices)
        corners = [(math.floor(x), math.floor(y)) for x, y in vertices]
        yield Vars(line=at["setup"], values={"triangle": number, "Q0": corners[0],
                                             "Q1": corners[1], "Q2": corners[2]})
        edges = [(corners[k], corners[(k + 1) % 3]) for k in range(3)]
        if corners[0] == corners[1] == corners[2]:
            edges = [(corners[0], (corners[0][0] + 1, corners[0][1]))]  # one pixel
        for edge, (p, q) in enumerate(edges):
            for x, y in line_in_grid(p, q, grid):
                written += 1
                yield (at["plot_edge"], x, y, number, edge)
    yield Vars(line=at["done"], values={"pixels": written})


TRIANGLE_WIREFRAME = AlgorithmSpec(
    name="triangle-wireframe",
    title="Triangle as three lines",
    family="triangles",
    summary="the outline only: Bresenham lines between the pixels holding the vertices",
    inputs=TRIANGLES,
    options=(),
    code=listing(wireframe_listing),
    generator=wireframe_run,
    uses_grid=True,
    notes=("Compare with a fill (triangle-bbox): the lines' pixels are the nearest to the "
           "edges, so some lie outside the filled triangle and some filled pixels on the "
           "edge are not on a line.",
           "Each line is drawn without its last pixel, which the next line starts from, so "
           "every corner is plotted once."),
    oracle=Oracle(
        "exact",
        "The three nearest-pixel lines between the pixels holding the vertices, ties toward P, "
        "from exact line values (algorithms/exact/lines.py), clipped to the grid, pixel for pixel "
        "in order.",
        ("algorithms/triangles/test_triangle_variants.py", "algorithms/test_stability.py"),
        check="wireframe"),
)

# The module's algorithms, in the order they are listed.
SPECS = (TRIANGLE_CRAMER, TRIANGLE_TRILINEAR, TRIANGLE_COLUMNS, TRIANGLE_WIREFRAME)
