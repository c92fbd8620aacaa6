"""A triangle algorithm of your own, for RasterLab to check.

    rasterlab check triangle.py --against triangle-bbox

Write a generator ``draw(x0, y0, x1, y1, x2, y2)``: the three vertices are
real numbers (pixel units, y up; the cases use multiples of 1/8, so no
snapping is needed). Yield every pixel the triangle covers, once, in any
order, as ``yield x, y`` (or with named variables, ``yield x, y, {"e0": e}``).

A pixel (x, y) is covered when its centre (x + 1/2, y + 1/2) lies strictly
inside, or exactly on a left edge or on a bottom horizontal edge (the
top-left rule seen with y up). A triangle of no area covers nothing, and
the vertices may come in either winding. With the vertices in
counter-clockwise order, the edge from a to b has the value
e(p) = (bx - ax)(py - ay) - (by - ay)(px - ax) at a point p: positive
inside. Where e = 0 at a centre, the edge decides: going down (a left edge)
or going right along a horizontal (a bottom edge), the pixel is covered;
going up (a right edge) or left along a horizontal (a top edge), it is not.
At a corner both edges must keep it.

The pixels are compared, as a collection, with the reference algorithm
and with the exact coverage. Plain Python only: no imports from RasterLab,
and only the standard library (fractions.Fraction is exact). Each case runs
in a separate process with a time and a memory limit.
"""


def draw(x0, y0, x1, y1, x2, y2):
    # TODO: replace with your algorithm. This yields the pixel of each vertex only.
    for x, y in {(int(x0), int(y0)), (int(x1), int(y1)), (int(x2), int(y2))}:
        yield x, y
