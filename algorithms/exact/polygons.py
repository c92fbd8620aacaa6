"""Exact oracles for polygon fill: integers and fractions.Fraction, never floats.

Written from the definitions, not from polygons.py, so tests (and the
speed/error report) can hold the polygon algorithms to them.

Coordinates are snapped to 1/256 px; from there on everything is an integer.
The fill rule of DESIGN.md is a half-open rule: a pixel centre c is covered
exactly when the point c + (e, d), for infinitesimals 0 < d << e (a hair to
the right and a far smaller hair up), is inside. Such a point lies on no
edge, so it is inside or outside without doubt; that gives the left edges
and the bottom horizontal edges to the pixel, and the right and top ones
away. Here the winding number of that point is found with orientation tests
only (no intersection is computed):

* an edge a -> b counts when the horizontal line through c + (e, d) crosses
  it, which is ``min(a.y, b.y) <= c.y < max(a.y, b.y)``;
* it crosses to the right of c + (e, d) exactly when c lies strictly to the
  left of the upward-pointing edge (orientation test > 0); a centre on the
  edge itself is then left of the crossing point's right-hand neighbour, so
  it does not count.

Upward edges crossing on the right add 1, downward ones take 1 away: the
winding number. Even-odd takes its parity.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

UNIT = 256  # snapped units per pixel
RULES = ("evenodd", "nonzero")


def snap(value) -> int:
    """round(value * 256), halves to even, computed on the exact value."""
    return round(Fraction(value) * UNIT)


def snap_polygon(contours) -> list[list[tuple[int, int]]]:
    return [[(snap(x), snap(y)) for x, y in contour] for contour in contours]


def centre(i: int, j: int) -> tuple[int, int]:
    """The centre of pixel (i, j) in snapped units."""
    return UNIT * i + UNIT // 2, UNIT * j + UNIT // 2


def _edges(snapped):
    for contour in snapped:
        for k in range(len(contour)):
            yield contour[k], contour[(k + 1) % len(contour)]


def winding_number(snapped, px: int, py: int) -> int:
    """The winding number of (px, py) + (e, d), for a point in snapped units."""
    winding = 0
    for (ax, ay), (bx, by) in _edges(snapped):
        side = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
        if ay <= py < by and side > 0:
            winding += 1
        elif by <= py < ay and side < 0:
            winding -= 1
    return winding


def is_covered(winding: int, rule: str) -> bool:
    if rule not in RULES:
        raise ValueError(f"unknown fill rule {rule!r}")
    return winding % 2 == 1 if rule == "evenodd" else winding != 0


def box(snapped, margin: int = 1) -> tuple[int, int, int, int]:
    """(i0, j0, i1, j1): pixels i0 <= i < i1, j0 <= j < j1 around the polygon."""
    xs = [x for contour in snapped for x, _ in contour]
    ys = [y for contour in snapped for _, y in contour]
    return (min(xs) // UNIT - margin, min(ys) // UNIT - margin,
            max(xs) // UNIT + 1 + margin, max(ys) // UNIT + 1 + margin)


def winding_grid(snapped, area=None):
    """Winding numbers at every centre of a block: (array[j - j0, i - i0], i0, j0).

    Vectorised over the centres, one edge at a time, in int64: exact while
    coordinates stay below 2^28 snapped units (2^20 px), as checked.
    """
    i0, j0, i1, j1 = box(snapped) if area is None else area
    limit = 1 << 28
    for contour in snapped:
        for x, y in contour:
            if abs(x) >= limit or abs(y) >= limit:
                raise ValueError("coordinates too large for the int64 oracle")
    px = (UNIT * np.arange(i0, i1, dtype=np.int64) + UNIT // 2)[None, :]
    py = (UNIT * np.arange(j0, j1, dtype=np.int64) + UNIT // 2)[:, None]
    winding = np.zeros((j1 - j0, i1 - i0), dtype=np.int64)
    for (ax, ay), (bx, by) in _edges(snapped):
        if ay == by:
            continue
        side = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
        if ay < by:
            winding += ((ay <= py) & (py < by)) & (side > 0)
        else:
            winding -= ((by <= py) & (py < ay)) & (side < 0)
    return winding, i0, j0


def outline_grid(snapped, area=None):
    """Which centres of a block lie exactly on an edge: (array[j - j0, i - i0], i0, j0)."""
    i0, j0, i1, j1 = box(snapped) if area is None else area
    px = (UNIT * np.arange(i0, i1, dtype=np.int64) + UNIT // 2)[None, :]
    py = (UNIT * np.arange(j0, j1, dtype=np.int64) + UNIT // 2)[:, None]
    on = np.zeros((j1 - j0, i1 - i0), dtype=bool)
    for (ax, ay), (bx, by) in _edges(snapped):
        collinear = (bx - ax) * (py - ay) - (by - ay) * (px - ax) == 0
        between = ((min(ax, bx) <= px) & (px <= max(ax, bx))
                   & (min(ay, by) <= py) & (py <= max(ay, by)))
        on |= collinear & between
    return on, i0, j0


def covered_pixels(contours, rule: str = "evenodd") -> set[tuple[int, int]]:
    """Every covered pixel (i, j) of a polygon given in real coordinates."""
    snapped = snap_polygon(contours)
    winding, i0, j0 = winding_grid(snapped)
    mask = winding % 2 == 1 if rule == "evenodd" else winding != 0
    if rule not in RULES:
        raise ValueError(f"unknown fill rule {rule!r}")
    js, is_ = np.nonzero(mask)
    return {(int(i) + i0, int(j) + j0) for i, j in zip(is_, js)}


def covered_pixels_slowly(contours, rule: str = "evenodd") -> set[tuple[int, int]]:
    """The same set, one Python-integer winding number per centre (no numpy)."""
    snapped = snap_polygon(contours)
    i0, j0, i1, j1 = box(snapped)
    return {(i, j) for j in range(j0, j1) for i in range(i0, i1)
            if is_covered(winding_number(snapped, *centre(i, j)), rule)}


def distance_squared_to_boundary(snapped, px: int, py: int) -> Fraction:
    """Squared distance (px^2) from a snapped point to the nearest edge, exactly."""
    best = None
    for (ax, ay), (bx, by) in _edges(snapped):
        dx, dy = bx - ax, by - ay
        wx, wy = px - ax, py - ay
        length = dx * dx + dy * dy
        along = wx * dx + wy * dy
        if length == 0 or along <= 0:
            d = Fraction(wx * wx + wy * wy)
        elif along >= length:
            d = Fraction((px - bx) ** 2 + (py - by) ** 2)
        else:
            d = Fraction((dx * wy - dy * wx) ** 2, length)
        best = d if best is None else min(best, d)
    return best / UNIT ** 2


def on_boundary(snapped, px: int, py: int) -> bool:
    return distance_squared_to_boundary(snapped, px, py) == 0
