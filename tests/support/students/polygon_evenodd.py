"""A student's polygon fill (for the tests): even-odd crossings in exact fractions."""
from fractions import Fraction as F
import math

def draw(contours):
    edges = []
    for c in contours:
        pts = [(F(x), F(y)) for x, y in c]
        edges += list(zip(pts, pts[1:] + pts[:1]))
    ys = [p[1] for e in edges for p in e]; xs = [p[0] for e in edges for p in e]
    for y in range(math.floor(min(ys)) - 1, math.ceil(max(ys)) + 1):
        py = y + F(1, 2)
        for x in range(math.floor(min(xs)) - 1, math.ceil(max(xs)) + 1):
            px = x + F(1, 2)
            w = 0
            for (ax, ay), (bx, by) in edges:
                side = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
                if ay <= py < by and side > 0:
                    w += 1
                elif by <= py < ay and side < 0:
                    w -= 1
            if w % 2:
                yield x, y
