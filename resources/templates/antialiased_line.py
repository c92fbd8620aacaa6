"""An antialiased line of your own, for RasterLab to check.

    rasterlab check antialiased_line.py --against line-wu
    rasterlab check antialiased_line.py --against line-area

Write a generator ``draw(x0, y0, x1, y1)``: the end points are whole pixel
coordinates (y up) and may come in any octant. Yield each pixel with its
intensity (0 .. 1), as ``yield x, y, intensity``.

line-wu: in each column along the longer axis, the ideal line passes at a
fraction f of a pixel beyond the pixel row below it: that pixel gets
1 - f and the next one gets f (a pixel of intensity 0 may be left out).
line-area: each pixel gets the area it shares with the line's rectangle,
one pixel wide, from the centre of P to the centre of Q.

Intensities of a pixel yielded twice are added. A pixel passes when its
total is within 1/1024 of the expected one; the order does not matter.
The result is compared with the reference algorithm and the exact values
(fractions). Plain Python only: no imports from RasterLab, and only the
standard library. Each case runs in a separate process with a time and a
memory limit.
"""


def draw(x0, y0, x1, y1):
    # TODO: replace with your algorithm. This yields the two end pixels at full intensity.
    yield x0, y0, 1.0
    if (x1, y1) != (x0, y0):
        yield x1, y1, 1.0
