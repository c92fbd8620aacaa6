"""An ellipse algorithm of your own, for RasterLab to check.

    rasterlab check ellipse.py --against ellipse-midpoint

Write a generator ``draw(xc, yc, rx, ry)``: the centre is a whole pixel, rx
and ry whole half-axes (0 or more; 0 gives a segment; y up). Yield every
pixel of the ellipse, one per step, as ``yield x, y`` or with named
variables ``yield x, y, {"d": d}``.

The four mirror images of a computed pixel may come in any order: an ellipse
is compared as a collection of pixels with the reference algorithm.

Plain Python only: no imports from RasterLab, and only the standard library.
Each case runs in a separate process with a time and a memory limit.
"""


def draw(xc, yc, rx, ry):
    # TODO: replace with your algorithm. This draws only the four axis points.
    for x, y in {(xc, yc + ry), (xc + rx, yc), (xc, yc - ry), (xc - rx, yc)}:
        yield x, y
