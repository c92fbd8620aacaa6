"""A student's triangle (for the tests): edge functions in exact fractions, top-left rule."""
from fractions import Fraction as F
import math

def draw(x0, y0, x1, y1, x2, y2):
    a, b, c = (F(x0), F(y0)), (F(x1), F(y1)), (F(x2), F(y2))
    area = (b[0]-a[0])*(c[1]-a[1]) - (b[1]-a[1])*(c[0]-a[0])
    if area == 0:
        return
    if area < 0:
        b, c = c, b
    edges = [(a, b), (b, c), (c, a)]
    xs = [p[0] for p in (a, b, c)]; ys = [p[1] for p in (a, b, c)]
    for y in range(math.floor(min(ys)) - 1, math.ceil(max(ys)) + 1):
        for x in range(math.floor(min(xs)) - 1, math.ceil(max(xs)) + 1):
            px, py = x + F(1, 2), y + F(1, 2)
            ok = True
            for (p, q) in edges:
                dx, dy = q[0] - p[0], q[1] - p[1]
                e = dx * (py - p[1]) - dy * (px - p[0])
                if e < 0 or (e == 0 and not (dy < 0 or (dy == 0 and dx > 0))):
                    ok = False
                    break
            if ok:
                yield x, y
