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
The crossings are those of the scan line y + 1/2 with each edge whose
lower end is at or below it and whose upper end is above it (half-open:
a vertex on the scan line counts once, a horizontal edge never), at or
left of the centre. polygon-scanline snaps each vertex to the nearest
1/256 first (halves to even); with fill_rule nonzero, a centre is filled
when the crossings' directions (up +1, down -1) do not sum to 0.

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
