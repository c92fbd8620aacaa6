"""A circle algorithm of your own, for RasterLab to check.

    rasterlab check circle.py --against circle-midpoint

Write a generator ``draw(xc, yc, r)``: the centre is a whole pixel, r a whole
radius (0 or more; y up). Yield every pixel of the circle, one per step:

    yield x, y                 # the pixel only
    yield x, y, {"d": d}       # the pixel and named variables

The eight mirror images of a computed pixel may come in any order: a
circle is compared as a collection of pixels (each as often as the
reference plots it; on the axes and the diagonals the reference plots a
pixel once). It is compared with the reference algorithm and, for the
midpoint and square-root circles, with the exact result.

circle-midpoint starts at (0, r) with d = 1 - r and walks the second
octant while y > x: if d < 0 it goes E (d += 2x + 3; x += 1), else SE
(d += 2(x - y) + 5; x += 1; y -= 1), so a tie (d = 0) goes SE.

Plain Python only: no imports from RasterLab, and only the standard library.
Each case runs in a separate process with a time and a memory limit.
"""


def draw(xc, yc, r):
    # TODO: replace with your algorithm. This draws only the four axis points.
    for x, y in {(xc, yc + r), (xc + r, yc), (xc, yc - r), (xc - r, yc)}:
        yield x, y
