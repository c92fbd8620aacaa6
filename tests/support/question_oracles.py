"""Exact oracles for the triangle, visibility, antialiasing and texture
question templates (tests/app/teaching/questions/test_templates_*.py),
written from DESIGN.md and the lecture notes in Fractions: nothing here
calls the code under test.

Frame: y up, pixel (i, j) the square [i, i+1) x [j, j+1) sampled at its
centre. Edge k of P0 P1 P2 runs from P(k+1) to P(k+2).
"""
from __future__ import annotations

import re
from fractions import Fraction


def exact_points(points):
    return [(Fraction(x), Fraction(y)) for x, y in points]


def centre(pixel):
    return (Fraction(2 * pixel[0] + 1, 2), Fraction(2 * pixel[1] + 1, 2))


def edge_value(tri, k, point):
    """Twice the signed area of (P(k+1), P(k+2), point)."""
    (xi, yi), (xj, yj) = tri[(k + 1) % 3], tri[(k + 2) % 3]
    x, y = point
    return (xj - xi) * (y - yi) - (yj - yi) * (x - xi)


def twice_area(tri):
    return edge_value(tri, 0, tri[0])


def counter_clockwise(tri):
    return tri if twice_area(tri) > 0 else [tri[0], tri[2], tri[1]]


def keeps_tie(tri, k) -> bool:
    """DESIGN.md's top-left rule in a y-up frame: a point on an edge counts
    when the edge is a left edge (the triangle lies on its +x side) or a
    bottom horizontal edge (the triangle lies above it). ``tri`` is
    counter-clockwise, so the inside is to the left of P(k+1) -> P(k+2):
    its inward normal is (-(dy), dx)."""
    (xi, yi), (xj, yj) = tri[(k + 1) % 3], tri[(k + 2) % 3]
    inward_x, inward_y = -(yj - yi), xj - xi
    return inward_x > 0 or (inward_x == 0 and inward_y > 0)


def inside(tri, point) -> bool:
    """Top-left coverage of ``point`` by the counter-clockwise ``tri``."""
    for k in range(3):
        e = edge_value(tri, k, point)
        if e < 0 or (e == 0 and not keeps_tie(tri, k)):
            return False
    return True


def weights(tri, point):
    """Barycentric weights: ratios of signed areas."""
    whole = twice_area(tri)
    return [edge_value(tri, k, point) / whole for k in range(3)]


def perspective_value(tri, point, w, s):
    """s/w and 1/w interpolated linearly in screen space, then divided."""
    lam = weights(tri, point)
    num = sum(l * Fraction(sk) / Fraction(wk) for l, sk, wk in zip(lam, s, w))
    den = sum(l / Fraction(wk) for l, wk in zip(lam, w))
    return num / den


def triangles_of(points):
    pts = exact_points(points)
    return [counter_clockwise(pts[3 * n:3 * n + 3]) for n in range(len(pts) // 3)]


def depth_at(points, depths, n, point):
    """Depth of triangle n at ``point``: the barycentric mix of its vertex
    depths (vertex order as given; weights do not depend on winding)."""
    tri = exact_points(points[3 * n:3 * n + 3])
    zs = [Fraction(str(z)) for z in depths[3 * n:3 * n + 3]]
    return sum(l * z for l, z in zip(weights(tri, point), zs))


def zbuffer_owner(points, depths, pixel):
    """Index of the triangle a z-buffer (z < ZB, input order) keeps at
    ``pixel``, or None."""
    point = centre(pixel)
    best, owner = None, None
    for n, tri in enumerate(triangles_of(points)):
        if inside(tri, point):
            z = depth_at(points, depths, n, point)
            if best is None or z < best:
                best, owner = z, n
    return owner


def painter_fails(points, depths, grid) -> bool:
    """Sorting by mean vertex depth, farthest first (stable), and drawing
    without a depth test: does some pixel show another triangle than the
    z-buffer's?"""
    tris = triangles_of(points)
    means = [sum(Fraction(str(z)) for z in depths[3 * n:3 * n + 3]) / 3 for n in range(len(tris))]
    order = sorted(range(len(tris)), key=lambda n: -means[n])
    for j in range(grid[1]):
        for i in range(grid[0]):
            point = centre((i, j))
            painted = None
            for n in order:
                if inside(tris[n], point):
                    painted = n
            if painted != zbuffer_owner(points, depths, (i, j)):
                return True
    return False


def coverage(points, pixel, n) -> Fraction:
    """The fraction of the n x n regular samples of ``pixel`` inside."""
    tri = triangles_of(points)[0]
    hits = sum(inside(tri, (pixel[0] + Fraction(2 * a + 1, 2 * n),
                            pixel[1] + Fraction(2 * b + 1, 2 * n)))
               for a in range(n) for b in range(n))
    return Fraction(hits, n * n)


def affine_gradient(tri, values):
    """(d/dx, d/dy) of the plane through the vertices' values (Cramer's rule)."""
    (x0, y0), (x1, y1), (x2, y2) = tri
    q0, q1, q2 = (Fraction(v) for v in values)
    det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    dx = ((q1 - q0) * (y2 - y0) - (q2 - q0) * (y1 - y0)) / det
    dy = ((x1 - x0) * (q2 - q0) - (x2 - x0) * (q1 - q0)) / det
    return dx, dy


def mip_level(points, uv, size, top) -> int:
    """OpenGL's nearest mip level for an affine mapping: rho the longer
    derivative vector in texels, lambda = log2(rho), level 0 when
    lambda <= 1/2, else the L with L - 1/2 < lambda <= L + 1/2, at most
    ``top``. Decided on rho^2 exactly: lambda <= L + 1/2 is
    rho^2 <= 2^(2L + 1)."""
    tri = exact_points(points)
    ux, uy = affine_gradient(tri, uv[0::2])
    vx, vy = affine_gradient(tri, uv[1::2])
    w, h = size
    rho2 = max((ux * w) ** 2 + (vx * h) ** 2, (uy * w) ** 2 + (vy * h) ** 2)
    level = 0
    while rho2 > Fraction(2) ** (2 * level + 1):
        level += 1
    return min(level, top)


PIXEL = re.compile(r"p = \((-?\d+), (-?\d+)\)")


def asked_pixel(text: str) -> tuple[int, int]:
    found = PIXEL.findall(text)
    assert len(found) == 1, text
    return int(found[0][0]), int(found[0][1])


def numbers(answer_text: str) -> list[Fraction]:
    """The numbers of an "(a, b, c)" answer (decimals or fractions; commas
    and/or spaces between them)."""
    return [Fraction(part) for part in re.split(r"[,\s]+", answer_text.strip("()")) if part]
