"""Where a seed fill starts, shared by its generator (fill.py) and its
kernel (fill_kernel.py): the states of a grid pixel, the midpoint circle as
an outline, the search for a free pixel inside an outline, and the checks
of a given seed, with the messages both give."""
from __future__ import annotations

import math
from fractions import Fraction

from algorithms.circles.midpoint import midpoint_circle_pixels
from algorithms.core.registry import InputError
from algorithms.core.trace import checkpoint, work_allowance

FREE, BOUNDARY, FILLED, WALL = 0, 1, 2, 3


def circle_outline(centre, radius: int, four: bool = False) -> list[tuple[int, int]]:
    """The midpoint circle's pixels once each, in order around the centre.

    Sorted by angle, consecutive pixels are 8-neighbours, so ``four`` can add
    the corner pixel that closes each diagonal step, as for polygons.
    """
    xc, yc = centre
    ring = [tuple(map(int, p)) for p in midpoint_circle_pixels([centre], {"radius": radius})]
    ring.sort(key=lambda p: math.atan2(p[1] - yc, p[0] - xc))
    pixels = dict.fromkeys(ring)
    if four:
        for a, b in zip(ring, ring[1:] + ring[:1]):
            if abs(a[0] - b[0]) == 1 and abs(a[1] - b[1]) == 1:
                pixels[(b[0], a[1])] = None
    return list(pixels)


def inside_pixel(contours, free, grid) -> tuple[int, int] | None:
    """A free pixel whose centre is inside the outlines (even-odd), or None.

    Inside counts crossings of all contours, so a hole is outside. Rows are
    tried from the first contour's mean row outwards, and in a row the pixel
    nearest its mean column wins; ``free(x, y)`` says whether a pixel may be
    filled, and is never true off the ``grid`` (width, height), so only the
    grid's rows and columns are tried.
    """
    width, height = grid
    xs, ys = [p[0] for p in contours[0]], [p[1] for p in contours[0]]
    middle_x, middle_y = sum(xs) / len(xs), round(sum(ys) / len(ys))
    rows = range(max(min(ys), 0), min(max(ys) + 1, height))
    # A row looks at every edge: its work counts against the step cap, so a
    # search that finds nothing (an outline that covers every row) ends.
    edges, allowance = sum(len(c) for c in contours), work_allowance()
    for tried, y in enumerate(sorted(rows, key=lambda y: (abs(y - middle_y), y))):
        checkpoint()
        if (tried + 1) * edges > allowance:
            raise InputError(f"flood-fill: no free pixel found inside the outline in the "
                             f"{tried:,} of {len(rows):,} rows the step cap lets the search "
                             f"try ({allowance:,} edge tests); give a seed with seed=X,Y")
        crossings = sorted(c for contour in contours for c in _crossings(contour, y))
        # Pixel centres strictly between two crossings are inside.
        inside = [x for lo, hi in zip(crossings[::2], crossings[1::2])
                  for x in range(max(math.floor(lo) + 1, 0), min(math.ceil(hi), width))
                  if free(x, y)]
        if inside:
            return min(inside, key=lambda x: (abs(x - middle_x), x)), y
    return None


def _crossings(contour, y):
    """x where the horizontal line through y crosses the contour's edges.

    An edge counts when one end is above y and the other is not, so a vertex
    on the line is counted once.
    """
    for k, (ax, ay) in enumerate(contour):
        bx, by = contour[(k + 1) % len(contour)]
        if (ay > y) != (by > y):
            yield ax + Fraction((y - ay) * (bx - ax), by - ay)


def seed_pixel(name, options, auto, region, on_outline) -> tuple[int, int]:
    """The seed pixel; ``auto()`` finds one inside the outline or None;
    ``on_outline(x, y)`` says whether a grid pixel is an outline pixel."""
    seed = options["seed"]
    if seed == "auto":
        found = auto()
        if found is None:
            raise InputError(f"{name}: no free pixel lies inside the outline; "
                             "give a seed with seed=X,Y")
        return found
    x, y = seed
    if not region.inside(x, y):
        raise InputError(f"{name}: the seed ({x}, {y}) lies outside the "
                         f"{region.width}x{region.height} grid")
    if options["mode"] == "boundary" and on_outline(x, y):
        raise InputError(f"{name}: the seed ({x}, {y}) lies on the boundary; pick a pixel "
                         "inside the outline, or set mode=region to recolour the outline")
    return x, y


def circle_seed(centre, region, on_outline):
    """The centre pixel, when the circle leaves it free."""
    return tuple(centre) if region.inside(*centre) and not on_outline(*centre) else None
