"""Exact oracles of the visibility family (not a test module): which triangle a
pixel shows, from exact coverage and exact barycentric depths.

Written from the definitions in algorithms/visibility/, not from its code:
a triangle's fragments are the pixel centres it covers under the top-left
rule with vertices snapped to 1/256 px (algorithms/exact/triangles.py's
rule, tested in whole numbers by tests/support/raster_reference.py), and
a fragment's depth is alpha z0 + beta z1 + gamma z2 at the centre.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from algorithms.exact import triangles as exact_triangles
from algorithms.visibility.zbuffer_painter import PALETTE
from tests.support.raster_reference import triangle_pixels

PACKED = [int(c[1:], 16) for c in PALETTE]


def snapped(point):
    return tuple(exact_triangles.snap(v, 8) for v in point)


def depth_at(tri, zs, centre):
    """Barycentric depth at the centre, in fractions: alpha z0 + beta z1 + gamma z2."""
    (x0, y0), (x1, y1), (x2, y2) = tri
    px, py = centre
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    alpha = ((x1 - px) * (y2 - py) - (x2 - px) * (y1 - py)) / area
    beta = ((x2 - px) * (y0 - py) - (x0 - px) * (y2 - py)) / area
    gamma = 1 - alpha - beta
    return alpha * zs[0] + beta * zs[1] + gamma * zs[2]


def fragments(points, z, grid, rule="top-left"):
    """Per triangle k in input order: {(i, j): exact depth} of the centres it covers."""
    result = []
    for k in range(len(points) // 3):
        tri = [snapped(p) for p in points[3 * k:3 * k + 3]]
        zs = [Fraction(v) for v in z[3 * k:3 * k + 3]]
        covered = triangle_pixels(tri, grid, rule)
        result.append({pixel: depth_at(tri, zs, exact_triangles.centre(*pixel))
                       for pixel in covered})
    return result


def nearest_oracle(points, z, grid, test="less", clear=Fraction(1)):
    """Per pixel: the triangle the z-buffer must keep, and its exact depth.

    A fragment passes when its depth, rounded once to float64 as documented,
    is below the stored one (``less``) or not above it (``less-equal``).
    """
    width, height = grid
    owner = np.full((height, width), -1)
    depth = np.full((height, width), None, dtype=object)
    depth[...] = clear
    for k, covered in enumerate(fragments(points, z, grid)):
        for (i, j), d in covered.items():
            stored = float(depth[j, i])
            if float(d) < stored or (test == "less-equal" and float(d) == stored):
                owner[j, i], depth[j, i] = k, d
    return owner, depth


def palette_colors(owner) -> np.ndarray:
    """The packed palette colour of each pixel's triangle, -1 where there is none."""
    return np.where(owner >= 0, np.array(PACKED)[owner % len(PACKED)], -1)


# ------------------------------------------------ the painter with splitting
# The pieces' corners snap to 1/256 px, so an edge a cut ends on moves by
# up to 1/512 px at that end: a centre closer than this to an edge of its
# triangle may fall on either side.
SNAP = Fraction(1, 256)


def nearest(points, z, pixel, gap=Fraction(1, 50)):
    """The triangle whose plane is nearest at the pixel's centre, among those
    containing it; None when it holds the centre only on an edge or within
    SNAP of one (the fill rule and the snapped cuts decide there), or when
    another triangle holding it is within ``gap`` in depth (near the line
    where two triangles meet, or in one plane)."""
    px, py = pixel[0] + Fraction(1, 2), pixel[1] + Fraction(1, 2)
    found = []
    for t in range(len(points) // 3):
        (ax, ay), (bx, by), (cx, cy) = [tuple(Fraction(v) for v in p)
                                        for p in points[3 * t:3 * t + 3]]
        two_a = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
        if two_a == 0:
            continue
        if not (min(ax, bx, cx) <= px <= max(ax, bx, cx)
                and min(ay, by, cy) <= py <= max(ay, by, cy)):
            continue
        alpha = ((bx - px) * (cy - py) - (cx - px) * (by - py)) / two_a
        beta = ((cx - px) * (ay - py) - (ax - px) * (cy - py)) / two_a
        gamma = 1 - alpha - beta
        if min(alpha, beta, gamma) >= 0:
            za, zb, zc = (Fraction(v) for v in z[3 * t:3 * t + 3])
            clear = min(alpha, beta, gamma) > 0 and not near_an_edge(
                ((ax, ay), (bx, by), (cx, cy)), (px, py))
            found.append((alpha * za + beta * zb + gamma * zc, t, clear))
    found.sort()
    if not found or (len(found) > 1 and found[1][0] - found[0][0] < gap) or not found[0][2]:
        return None
    return found[0][1]


def near_an_edge(corners, point) -> bool:
    """Whether ``point`` is within SNAP of the line through an edge (exact)."""
    for k in range(3):
        (ax, ay), (bx, by) = corners[k], corners[(k + 1) % 3]
        cross = (bx - ax) * (point[1] - ay) - (by - ay) * (point[0] - ax)
        if cross * cross < SNAP * SNAP * ((bx - ax) ** 2 + (by - ay) ** 2):
            return True
    return False


def check_split(points, z, grid, trace) -> int:
    """Hold a painter-split trace to ``nearest`` at every pixel where it is clear;
    returns how many pixels were checked."""
    colours = dict(zip(map(tuple, trace.written_pixels().tolist()), trace.pixel_values()))
    checked = 0
    for i in range(grid[0]):
        for j in range(grid[1]):
            owner = nearest(points, z, (i, j))
            if owner is None:
                continue
            checked += 1
            assert colours.get((i, j)) == PACKED[owner % len(PACKED)], (i, j)
    return checked
