"""Hard cases and independent oracles for the circle variants and curves
(algorithms/circles/variants.py, algorithms/circles/curves.py), shared by their own
tests and the stability suite."""
from __future__ import annotations

import math
from fractions import Fraction
from math import isqrt

from algorithms.exact import circles as exact_circles
from algorithms.exact import lines as exact_lines


# ------------------------------------------------------------ oracles
def printed_c(r):
    """The lecture's MidpointCircle, line for line, with the SE update's 5 lost."""
    drawn = [(0, r), (0, -r), (r, 0), (-r, 0)]
    x, y, d = 0, r, 5 // 4 - r
    while y > x:
        if d < 0:
            d = d + 2 * x + 3
            x = x + 1
        else:
            d = d + 2 * (x - y)
            x = x + 1
            y = y - 1
        drawn += [(x, y), (x, -y), (-x, y), (-x, -y), (y, x), (y, -x), (-y, x), (-y, -x)]
    return drawn


def cell_meets_circle(pixel, r) -> bool:
    """Does the circle of radius r cross the square of the pixel at this offset
    (corners at half-integers)? Exact: the square's nearest and farthest points."""
    near = sum(0 if c == 0 else min(abs(2 * c - 1), abs(2 * c + 1)) ** 2 for c in pixel)
    far = sum(max(abs(2 * c - 1), abs(2 * c + 1)) ** 2 for c in pixel)
    return near <= 4 * r * r <= far


def chebyshev_gaps(pixels) -> int:
    """Steps between consecutive pixels (and back to the first) that skip a pixel."""
    closed = list(pixels) + [pixels[0]]
    return sum(max(abs(a[0] - b[0]), abs(a[1] - b[1])) > 1 for a, b in zip(closed, closed[1:]))


def disk_oracle(centre, r) -> set:
    """Pixels whose centres lie within r of the centre, in Fractions."""
    cx, cy, rr = (Fraction(v) for v in (*centre, r))
    half = Fraction(1, 2)
    columns = range(math.floor(cx - rr) - 1, math.ceil(cx + rr) + 1)
    rows = range(math.floor(cy - rr) - 1, math.ceil(cy + rr) + 1)
    return {(i, j) for i in columns for j in rows
            if (i + half - cx) ** 2 + (j + half - cy) ** 2 <= rr * rr}


def outline_oracle(disk) -> set:
    return {(i, j) for i, j in disk
            if any(n not in disk for n in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)))}


def wu_pixels_oracle(r) -> set:
    """The offsets Wu's circle lights: per octant column floor(h), and floor(h) + 1
    unless h is whole; mirrored 8 ways."""
    octant, x = [], 0
    while x * x <= r * r - x * x:
        h2 = r * r - x * x
        y = isqrt(h2)
        octant.append((x, y))
        if y * y != h2:
            octant.append((x, y + 1))
        x += 1
    return exact_circles.eight_way(octant)


def de_casteljau(points, t):
    pts = [tuple(Fraction(c) for c in p) for p in points]
    while len(pts) > 1:
        pts = [tuple(a + (b - a) * t for a, b in zip(p, q)) for p, q in zip(pts, pts[1:])]
    return pts[0]


def polyline_oracle(points, n):
    """Corners round(B(k/N)) by de Casteljau, joined by the textbook Bresenham's pixels."""
    corners = []
    for k in range(n + 1):
        bx, by = de_casteljau(points, Fraction(k, n))
        corners.append(tuple(exact_lines.round_half_up_exact(v) for v in (bx, by)))
    pixels = [corners[0]]
    for p, q in zip(corners, corners[1:]):
        pixels += exact_lines.nearest_pixel_line(p, q, "toward-P")[1:]
    return corners, pixels


# --------------------------------------------- stability-suite checks
def _offsets(case, pixels):
    (xc, yc), = case.points
    return [(x - xc, y - yc) for x, y in pixels]


def check_bresenham(case, options, trace, pixels):
    assert set(_offsets(case, pixels)) == exact_circles.midpoint_circle(options["radius"]), \
        f"{case}: unlike the exact circle"


def check_polar(case, options, trace, pixels):
    offsets = _offsets(case, pixels)
    r = options["radius"]
    assert all(cell_meets_circle(p, r) for p in offsets), f"{case}: a pixel off the circle"
    final = trace.final_variables()
    assert final["gaps"] == chebyshev_gaps(offsets), f"{case}: gaps miscounted"
    if options["dt"] == "auto":
        assert final["gaps"] == 0, f"{case}: gaps with dt = 1/R"


def check_printed(case, options, trace, pixels):
    assert _offsets(case, pixels) == printed_c(options["radius"]), f"{case}: not as printed"


def check_distance(case, options, trace, pixels):
    disk = disk_oracle(case.points[0], options["radius"])
    expected = disk if options["shape"] == "disk" else outline_oracle(disk)
    assert len(pixels) == len(set(pixels)) and set(pixels) == expected, f"{case}: unlike the disk"


def check_wu(case, options, trace, pixels):
    assert set(_offsets(case, pixels)) == wu_pixels_oracle(options["radius"]), \
        f"{case}: unlike Wu's two pixels per column"


def check_bezier(case, options, trace, pixels):
    assert pixels == polyline_oracle(case.points, options["segments"])[1], \
        f"{case}: unlike the polyline"


# The stability suite's checks, by the name an algorithm's oracle declares.
CHECKS = {"bresenham-circle": check_bresenham, "polar-circle": check_polar,
          "printed-midpoint-circle": check_printed, "disk": check_distance,
          "wu-circle": check_wu, "bezier-polyline": check_bezier}

# ------------------------------------------------------------- cases
CENTRES = {"centre": (12, 10), "centre at origin": (0, 0), "negative centre": (-30, -4),
           "far centre": (1_000_000, -1_000_000)}
REAL_CENTRES = {"on a pixel centre": (12.5, 10.5), "on a corner": (12.0, 10.0),
                "fractional": (12.3, 9.85), "negative": (-30.25, -4.75),
                "far": (1_000_000.5, -1_000_000.0), "tiny": (5e-324, 1e-300)}
CONTROLS = {"arch": ((1, 1), (4, 20), (25, 20), (30, 2)), "point": ((5, 5),) * 4,
            "collinear": ((0, 0), (10, 5), (20, 10), (30, 15)), "loop": ((2, 2), (38, 30),
                                                                       (2, 30), (38, 2)),
            "cusp": ((0, 0), (30, 20), (0, 20), (30, 0)),
            "wide": ((-2000, 0), (0, 2000), (2000, 0), (0, -2000)),
            "far": tuple((1_000_000_000 + x, -1_000_000_000 + y)
                         for x, y in ((1, 1), (4, 20), (25, 20), (30, 2)))}


def cases(spec, make) -> list:
    """The hard cases of one of these algorithms; ``make(name, points, options, valid)``."""
    found = []
    if spec.name == "curve-bezier":
        for name, points in CONTROLS.items():
            for n in (1, 3, 64):
                found.append(make(f"{name} N={n}", points, {"segments": n}, True))
        return found
    if spec.name == "circle-distance":
        for name, centre in REAL_CENTRES.items():
            for r in (0, 0.5, 1, 2.5, 7.3, 40):
                for shape in ("disk", "outline"):
                    found.append(make(f"{name} r={r} {shape}", (centre,),
                                      {"radius": r, "shape": shape}, True))
        return found
    extras = [{}, {"dt": 0.5}, {"dt": 0.001}] if spec.name == "circle-polar" else [{}]
    for name, centre in CENTRES.items():
        for r in (0, 1, 2, 3, 5, 7, 50, 4096):
            for extra in extras:
                found.append(make(f"{name} r={r} {extra}", (centre,), {"radius": r, **extra},
                                  True))
    return found
