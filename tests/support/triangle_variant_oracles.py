"""Hard cases and independent oracles for triangle-cramer and triangle-wireframe
(algorithms/triangles/variants.py), shared by their tests and the stability suite."""
from __future__ import annotations

import functools
import math
from collections import Counter
from fractions import Fraction

from algorithms.exact import lines as exact_lines


def _side(a, b, p) -> int:
    cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    return (cross > 0) - (cross < 0)


def closed_triangle_pixels(vertices, grid) -> frozenset:
    """See _closed_pixels; remembered, as several algorithms share the cases."""
    return _closed_pixels(tuple(tuple(v) for v in vertices), tuple(grid))


@functools.lru_cache(maxsize=256)
def _closed_pixels(vertices, grid) -> frozenset:
    """Grid pixels whose centres lie in the closed triangle: for each edge, the
    centre is not strictly on the other side from the third vertex. Exact;
    a triangle of zero area covers nothing."""
    tri = [tuple(Fraction(c) for c in v) for v in vertices]
    if _side(*tri) == 0:
        return frozenset()
    found = set()
    # Only centres inside the bounding box can be inside.
    xs, ys = [v[0] for v in tri], [v[1] for v in tri]
    columns = range(max(0, math.floor(min(xs))), min(grid[0], math.ceil(max(xs)) + 1))
    rows = range(max(0, math.floor(min(ys))), min(grid[1], math.ceil(max(ys)) + 1))
    for i in columns:
        for j in rows:
            p = (i + Fraction(1, 2), j + Fraction(1, 2))
            if all(_side(tri[k], tri[(k + 1) % 3], p) * _side(tri[k], tri[(k + 1) % 3],
                                                              tri[(k + 2) % 3]) >= 0
                   for k in range(3)):
                found.add((i, j))
    return frozenset(found)


def cramer_oracle(points, grid) -> Counter:
    """Per pixel, how many of the closed triangles hold its centre."""
    counts = Counter()
    for k in range(0, len(points) - 2, 3):
        counts.update(closed_triangle_pixels(points[k:k + 3], grid))
    return counts


def line_pixels_in_grid(p, q, grid) -> list:
    """The nearest-pixel line from P towards Q (ties toward P, Q left out), only
    the major-axis columns inside the grid, from exact line values."""
    x_major = exact_lines.x_is_major(p, q)
    a0, a1 = (p[0], q[0]) if x_major else (p[1], q[1])
    size = grid[0] if x_major else grid[1]
    step = 1 if a1 >= a0 else -1
    if step > 0:
        majors = range(max(a0, 0), min(a1 - 1, size - 1) + 1)
    else:
        majors = range(min(a0, size - 1), max(a1 + 1, 0) - 1, -1)
    toward = p[1] if x_major else p[0]
    pixels = []
    for a in majors:
        b = exact_lines.nearest_minor(exact_lines.line_value(p, q, a), "toward-P", toward)
        pixel = (a, b) if x_major else (b, a)
        if 0 <= pixel[0] < grid[0] and 0 <= pixel[1] < grid[1]:
            pixels.append(pixel)
    return pixels


def wireframe_oracle(points, grid) -> list:
    pixels = []
    for k in range(0, len(points) - 2, 3):
        corners = [(math.floor(x), math.floor(y)) for x, y in points[k:k + 3]]
        if corners[0] == corners[1] == corners[2]:
            x, y = corners[0]
            pixels += [(x, y)] if 0 <= x < grid[0] and 0 <= y < grid[1] else []
            continue
        for e in range(3):
            pixels += line_pixels_in_grid(corners[e], corners[(e + 1) % 3], grid)
    return pixels


def check_cramer(case, options, trace, pixels):
    assert Counter(pixels) == cramer_oracle(case.points, case.grid), f"{case}: unlike the oracle"


def check_wireframe(case, options, trace, pixels):
    assert pixels == wireframe_oracle(case.points, case.grid), f"{case}: unlike the lines"


def printed_columns(points, grid) -> list:
    """The lecture's explicit-form loop as printed, pixel centres for x and y:
    sorted by x, columns A..B, y_min on AC, y_max on AB, the swap test reversed."""
    pixels = []
    for k in range(0, len(points) - 2, 3):
        a, b, c = sorted(tuple(Fraction(v) for v in p) for p in points[k:k + 3])
        if a[0] == b[0] or a[0] == c[0]:
            continue
        for x in range(grid[0]):
            cx = x + Fraction(1, 2)
            if not a[0] <= cx <= b[0]:
                continue
            y_min = a[1] + (c[1] - a[1]) / (c[0] - a[0]) * (cx - a[0])
            y_max = a[1] + (b[1] - a[1]) / (b[0] - a[0]) * (cx - a[0])
            if y_min < y_max:
                y_min, y_max = y_max, y_min
            pixels += [(x, y) for y in range(grid[1]) if y_min <= y + Fraction(1, 2) <= y_max]
    return pixels


def check_columns(case, options, trace, pixels):
    if options["swap"] == "printed":
        assert pixels == printed_columns(case.points, case.grid), f"{case}: not as printed"
    else:
        check_cramer(case, options, trace, pixels)


def plane_value(vertices, values, pixel) -> Fraction:
    """alpha s0 + beta s1 + gamma s2 at the pixel's centre, from the signed areas."""
    (ax, ay), (bx, by), (cx, cy) = [tuple(Fraction(v) for v in p) for p in vertices]
    px, py = pixel[0] + Fraction(1, 2), pixel[1] + Fraction(1, 2)
    two_a = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
    alpha = ((bx - px) * (cy - py) - (cx - px) * (by - py)) / two_a
    beta = ((cx - px) * (ay - py) - (ax - px) * (cy - py)) / two_a
    s0, s1, s2 = (Fraction(v) for v in values)
    return alpha * s0 + beta * s1 + (1 - alpha - beta) * s2


def check_span(case, options, trace, pixels):
    check_cramer(case, options, trace, pixels)
    values = options["s"] or (0.0,)
    f = trace.series("f")[trace.writes()]
    count = 0
    for k in range(0, len(case.points) - 2, 3):
        tri = case.points[k:k + 3]
        owned = [p for p in closed_triangle_pixels(tri, case.grid)]
        s = [values[(k + j) % len(values)] for j in range(3)]
        for pixel in sorted(owned, key=lambda p: (p[1], p[0])):
            assert f[count] == float(plane_value(tri, s, pixel)) or \
                abs(f[count] - float(plane_value(tri, s, pixel))) < 1e-9, f"{case}: f off the plane"
            count += 1


# The stability suite's checks, by the name an algorithm's oracle declares.
CHECKS = {"closed-triangle": check_cramer, "columns": check_columns, "wireframe": check_wireframe,
          "span-plane": check_span}


def edge(a, b, p):
    """Twice the signed area of a, b, p (exact for Fractions and integers)."""
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def strictly_inside(tri, p) -> bool | None:
    """Whether p lies strictly inside the triangle (either winding); None
    when p lies on one of its edge lines (a tie the fill rule decides)."""
    values = [edge(tri[k], tri[(k + 1) % 3], p) for k in range(3)]
    if any(v == 0 for v in values):
        return None
    return all(v > 0 for v in values) or all(v < 0 for v in values)
