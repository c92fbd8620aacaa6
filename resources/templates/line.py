"""A line algorithm of your own, for RasterLab to check.

    rasterlab check line.py --against line-bresenham
    rasterlab check line.py --against line-dda

Write a generator ``draw(x0, y0, x1, y1)``: the end points are whole pixel
coordinates (y up). Yield every pixel of the line, from (x0, y0) to
(x1, y1), one per step:

    yield x, y                 # the pixel only
    yield x, y, {"d": d}       # the pixel and named variables

RasterLab compares your pixels, in order, with the reference algorithm and
with the exact line (the pixel nearest the ideal line in every column). A
variable is compared when you give it the reference's name: Bresenham's
decision variable is "d", and a step shows the d that decided its pixel
(the value tested before it is updated; the first pixel shows the starting
d = 2*dy - dx). Ties (d = 0) choose the step along the major axis only
(E, not NE, in the first octant's terms).

line-dda adds x_inc = dx / steps and y_inc = dy / steps to floats x and y
(steps = max(|dx|, |dy|)) and rounds both halves up: round(v) means
floor(v + 1/2), in Python math.floor(v + 0.5). Python's own round() rounds
halves to even (round(0.5) == 0, round(2.5) == 2) and fails every case
where a coordinate lands on a half.

Plain Python only: no imports from RasterLab, and only the standard library
(math, fractions). Each case runs in a separate process with a time and a
memory limit, so an endless loop or an exception fails that case only.
"""


def draw(x0, y0, x1, y1):
    # TODO: replace with your algorithm. This draws only the two ends.
    yield x0, y0
    if (x1, y1) != (x0, y0):
        yield x1, y1
