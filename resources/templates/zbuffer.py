"""A z-buffer of your own, for RasterLab to check.

    rasterlab check zbuffer.py --against zbuffer
    rasterlab check zbuffer.py --against painter    (yield every covered pixel)

Write a generator ``draw(triangles)``: ``triangles`` is a list of triangles,
each a list of three vertices [x, y, z] (x and y real, pixel units, y up;
the cases use multiples of 1/8; z is the depth, smaller is nearer). Draw
them in the given order. Each time a pixel's colour is written (the
fragment passes the depth test), yield ``x, y`` or ``x, y, {"z": z}``.

A pixel is covered when its centre (x + 1/2, y + 1/2) lies strictly inside
the triangle, or exactly on a left edge or on a bottom horizontal edge;
a triangle of no area covers nothing. z at the centre is interpolated
linearly (by the barycentric weights). The depth buffer starts at 1 and a
fragment passes when its z is smaller than the stored one.

Within one triangle the pixels may come in any order; the triangles come
in the given order. The pixels are compared, as a collection, with the
reference and the exact result; where you yield z, the k-th write at a
pixel must have the k-th expected depth (within 1e-9). Plain Python only:
no imports from RasterLab, and only the standard library
(fractions.Fraction is exact). Each case runs in a separate process with
a time and a memory limit.
"""


def draw(triangles):
    # TODO: replace with your algorithm. This yields the pixel of each first vertex only.
    for (x, y, z), _, _ in triangles:
        yield int(x), int(y), {"z": z}
