"""Hard cases and independent oracles for triangle-cramer and triangle-wireframe
(algorithms/triangle_variants.py), shared by their tests and the stability suite."""
from __future__ import annotations

import math
from collections import Counter
from fractions import Fraction

from algorithms.exact import lines as exact_lines


def _side(a, b, p) -> int:
    cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    return (cross > 0) - (cross < 0)


def closed_triangle_pixels(vertices, grid) -> set:
    """Grid pixels whose centres lie in the closed triangle: for each edge, the
    centre is not strictly on the other side from the third vertex. Exact;
    a triangle of zero area covers nothing."""
    tri = [tuple(Fraction(c) for c in v) for v in vertices]
    if _side(*tri) == 0:
        return set()
    found = set()
    for i in range(grid[0]):
        for j in range(grid[1]):
            p = (i + Fraction(1, 2), j + Fraction(1, 2))
            if all(_side(tri[k], tri[(k + 1) % 3], p) * _side(tri[k], tri[(k + 1) % 3],
                                                              tri[(k + 2) % 3]) >= 0
                   for k in range(3)):
                found.add((i, j))
    return found


def cramer_oracle(points, grid) -> Counter:
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


ORACLES = {"triangle-columns": check_columns, "triangle-cramer": check_cramer, "triangle-trilinear": check_cramer,
           "triangle-wireframe": check_wireframe}
