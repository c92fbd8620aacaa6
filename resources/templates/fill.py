"""A flood fill of your own, for RasterLab to check.

    rasterlab check fill.py --against flood-fill

Write a generator ``draw(contours, seed)``: ``contours`` is a list of closed
outlines, each a list of [x, y] vertices (whole pixel coordinates, y up);
``seed`` is the pixel [x, y] the fill starts from, inside the outlines.
Yield every pixel the fill colours, once, in any order, as ``yield x, y``.

The outline pixels are the boundary: each edge, from one vertex to the
next (the last back to the first), has one pixel per step along its longer
axis, the other coordinate rounded to the nearest whole number (halves
up). ``outline`` below draws them for you: the fill is your part. The
fill grows from the seed to the four edge neighbours (E, W, N, S) of each
pixel it colours and never colours an outline pixel.

The pixels are compared, as a collection, with flood-fill's and with the
exact region (every pixel the seed reaches). Plain Python only: no imports
from RasterLab, and only the standard library. Each case runs in a
separate process with a time and a memory limit.
"""


def outline(contours):
    """The set of the outline's pixels."""
    wall = set()
    for contour in contours:
        for k, (x0, y0) in enumerate(contour):
            x1, y1 = contour[(k + 1) % len(contour)]
            n = max(abs(x1 - x0), abs(y1 - y0))
            for i in range(n + 1):
                if n == 0:
                    wall.add((x0, y0))
                else:  # round(i * dx / n) with halves up, in whole numbers
                    wall.add((x0 + (2 * i * (x1 - x0) + n) // (2 * n),
                              y0 + (2 * i * (y1 - y0) + n) // (2 * n)))
    return wall


def draw(contours, seed):
    wall = outline(contours)
    # TODO: replace with your fill. This yields the seed pixel only.
    if tuple(seed) not in wall:
        yield seed[0], seed[1]
