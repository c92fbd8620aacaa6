"""Oracles of the antialiased lines (not a test module), from their definitions
in exact fractions: Xiaolin Wu's two pixels per column, and the subpixels a
zero-width segment passes through."""
from __future__ import annotations

import math
from collections import Counter
from fractions import Fraction


def wu_oracle(p, q, endpoints="full"):
    """In order, from the definition: along the major axis from P, column c
    holds the minor coordinate m = m0 + d_minor (c - c0) / d_major exactly;
    the pixel the line is nearer to, on P's side of m, takes 1 - f, the next
    one away from P's side takes f, f = |m - near| (a tie between axes goes to x)."""
    axis = 0 if abs(q[0] - p[0]) >= abs(q[1] - p[1]) else 1
    c0, c1, m0, m1 = p[axis], q[axis], p[1 - axis], q[1 - axis]
    if c0 == c1:
        return [(tuple(p), 1.0)]
    step = 1 if c1 > c0 else -1
    towards = 1 if m1 >= m0 else -1
    out = []
    for c in range(c0, c1 + step, step):
        m = m0 + Fraction((m1 - m0) * (c - c0), c1 - c0)
        near = math.floor(m) if towards > 0 else math.ceil(m)
        f = abs(m - near)
        half = Fraction(1, 2) if endpoints == "gap" and c in (c0, c1) else 1
        for minor, share in ((near, 1 - f), (near + towards, f)):
            if share:
                pixel = (c, minor) if axis == 0 else (minor, c)
                out.append((pixel, float(share * half)))
    return out


def meets_half_open(p, q, a, b):
    """Is there t in [0, 1] with a <= x(t) < a + 1 and b <= y(t) < b + 1?
    Intervals of t as (low, low included, high, high included)."""
    low, low_in, high, high_in = Fraction(0), True, Fraction(1), True
    for axis, start in ((0, a), (1, b)):
        d = q[axis] - p[axis]
        if d == 0:
            if not start <= p[axis] < start + 1:
                return False
            continue
        enter, leave = (start - p[axis]) / d, (start + 1 - p[axis]) / d
        # Going up, the cell's low side is included and its high side not; going down, the reverse.
        (lo, lo_in), (hi, hi_in) = ((enter, True), (leave, False)) if d > 0 else \
            ((leave, False), (enter, True))
        if lo > low or (lo == low and not lo_in):
            low, low_in = lo, lo_in
        if hi < high or (hi == high and not hi_in):
            high, high_in = hi, hi_in
    return low < high or (low == high and low_in and high_in)


def subpixel_counts(points, n, grid) -> Counter:
    """Per pixel, how many of its n x n subpixels the segment between the centres
    of its end pixels meets: every subpixel of the grid tried (those of the
    segment's bounding box: no other can meet it)."""
    p, q = (tuple(Fraction(2 * c + 1) * n / 2 for c in point) for point in points)
    counts = Counter()
    a_cells, b_cells = (range(max(0, math.floor(min(p[k], q[k]))),
                              min(grid[k] * n, math.floor(max(p[k], q[k])) + 1)) for k in (0, 1))
    for a in a_cells:
        for b in b_cells:
            if meets_half_open(p, q, a, b):
                counts[(a // n, b // n)] += 1
    return counts
