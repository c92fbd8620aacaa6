"""A polygon fill of your own, for RasterLab to check.

    rasterlab check polygon.py --against polygon-scanline

Write a generator ``draw(contours)``: ``contours`` is a list of closed
contours, each a list of [x, y] vertices (real numbers, pixel units, y up;
a second contour may be a hole). Yield every pixel the polygon fills,
once, in any order, as ``yield x, y``.

A pixel is filled when its centre (x + 1/2, y + 1/2) is inside by the
even-odd rule (an odd number of edge crossings to its left); a centre
exactly on an edge counts when it lies on a left edge or on a bottom
horizontal edge, so that two polygons sharing an edge never both fill it.

The pixels are compared, as a collection, with the reference algorithm
and, for polygon-scanline, with the exact fill. Plain Python only: no
imports from RasterLab, and only the standard library. Each case runs in a
separate process with a time and a memory limit.
"""


def draw(contours):
    # TODO: replace with your algorithm. This yields the pixel of each vertex only.
    for contour in contours:
        for x, y in contour:
            yield int(x), int(y)
