"""line-two-triangles: the pixels whose centres lie in the segment's
rectangle, by the top-left rule, against an exact test written here; and
how they differ from Bresenham's."""
from __future__ import annotations

import math
import random
from collections import Counter
from fractions import Fraction

from hypothesis import given, settings, strategies as st

from algorithms.core import registry
from tests.support.bresenham import bresenham_pixels

SPEC = registry.get("line-two-triangles")


def rectangle(p, q, width, caps):
    """The corners, counter-clockwise, in 1/256 px as Fractions: the segment
    between the end centres widened by width/2 on each side (and lengthened
    by width/2 at each end with square caps), each corner rounded to the
    nearest 1/256 px, halves to even, as triangle vertices are."""
    a = (p[0] + 0.5, p[1] + 0.5)
    b = (q[0] + 0.5, q[1] + 0.5)
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    u = ((b[0] - a[0]) / length, (b[1] - a[1]) / length) if length else (1.0, 0.0)
    h = width / 2
    e = h if caps == "square" else 0.0
    a = (a[0] - u[0] * e, a[1] - u[1] * e)
    b = (b[0] + u[0] * e, b[1] + u[1] * e)
    n = (-u[1] * h, u[0] * h)
    corners = [(a[0] - n[0], a[1] - n[1]), (b[0] - n[0], b[1] - n[1]),
               (b[0] + n[0], b[1] + n[1]), (a[0] + n[0], a[1] + n[1])]
    return [(Fraction(round(x * 256), 256), Fraction(round(y * 256), 256)) for x, y in corners]


def keeps(i, j, c) -> bool:
    """Centre c against the directed edge i -> j of a counter-clockwise
    polygon: inside, or on it where the edge is a left edge (going down) or
    a bottom edge (going right), the top-left rule with y up."""
    e = (j[0] - i[0]) * (c[1] - i[1]) - (j[1] - i[1]) * (c[0] - i[0])
    return e > 0 or (e == 0 and (j[1] < i[1] or (j[1] == i[1] and j[0] > i[0])))


def oracle(p, q, width, caps) -> set[tuple[int, int]]:
    corners = rectangle(p, q, width, caps)
    area2 = sum(corners[k][0] * corners[(k + 1) % 4][1] - corners[(k + 1) % 4][0] * corners[k][1]
                for k in range(4))
    if area2 <= 0:
        return set()
    xs = [c[0] for c in corners]
    ys = [c[1] for c in corners]
    pixels = set()
    for y in range(math.floor(min(ys)) - 1, math.ceil(max(ys)) + 1):
        for x in range(math.floor(min(xs)) - 1, math.ceil(max(xs)) + 1):
            c = (x + Fraction(1, 2), y + Fraction(1, 2))
            if all(keeps(corners[k], corners[(k + 1) % 4], c) for k in range(4)):
                pixels.add((x, y))
    return pixels


def bresenham(p, q) -> set[tuple[int, int]]:
    """The textbook loop's pixels in any octant: the segment mapped into the
    first octant by swapping and mirroring, and its pixels mapped back."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    sx, sy = (1 if dx >= 0 else -1), (1 if dy >= 0 else -1)
    steep = abs(dy) > abs(dx)
    a, b = (abs(dy), abs(dx)) if steep else (abs(dx), abs(dy))
    pixels = set()
    for u, v in bresenham_pixels((0, 0), (a, b)):
        ox, oy = (v, u) if steep else (u, v)
        pixels.add((p[0] + sx * ox, p[1] + sy * oy))
    return pixels


def written(p, q, **options) -> Counter:
    trace = SPEC.record((p, q), options)
    return Counter(trace.step(i).pixel for i in range(len(trace)) if trace.step(i).writes)


point = st.tuples(st.integers(-5, 40), st.integers(-5, 30))


@settings(max_examples=150)
@given(point, point, st.sampled_from([0.25, 0.5, 1.0, 1.5, 2.5, 4.0]),
       st.sampled_from(["square", "butt"]))
def test_the_pixels_are_the_rectangles_centres_by_the_top_left_rule(p, q, width, caps):
    counts = written(p, q, width=width, caps=caps)
    assert set(counts) == oracle(p, q, width, caps)
    assert all(n == 1 for n in counts.values()), "the shared diagonal gave a pixel twice"


def test_the_kernel_gives_the_generators_pixels_in_order():
    trace = SPEC.record(((2, 3), (28, 13)), {})
    steps = [trace.step(i).pixel for i in range(len(trace)) if trace.step(i).writes]
    assert [tuple(p) for p in SPEC.kernel(((2, 3), (28, 13)), SPEC.resolve({})).tolist()] == steps


def test_axis_and_diagonal_lines_one_pixel_wide_are_bresenhams():
    # every centre of the line lies on its axis, every other at 1 px (axis)
    # or 1/sqrt(2) px (diagonal) from it, beyond the half width
    for p, q in [((3, 4), (25, 4)), ((25, 4), (3, 4)), ((7, 2), (7, 20)), ((7, 20), (7, 2)),
                 ((2, 2), (20, 20)), ((20, 2), (2, 20)), ((5, 5), (5, 5))]:
        assert set(written(p, q, width=1.0, caps="square")) == bresenham(p, q)


def test_butt_caps_leave_out_the_end_on_a_right_or_top_edge():
    # the end centres lie on the rectangle's end edges: the left end is kept,
    # the right one (going right) is not
    assert set(written((3, 4), (12, 4), caps="butt")) == {(x, 4) for x in range(3, 12)}
    assert set(written((12, 4), (3, 4), caps="butt")) == {(x, 4) for x in range(3, 12)}
    assert set(written((5, 2), (5, 9), caps="butt")) == {(5, y) for y in range(2, 9)}


def test_how_the_pixels_differ_from_bresenhams_on_random_segments():
    rng = random.Random(1)
    extra = missing = segments = 0
    for _ in range(200):
        p = (rng.randint(0, 60), rng.randint(0, 40))
        q = (rng.randint(0, 60), rng.randint(0, 40))
        dx, dy = abs(q[0] - p[0]), abs(q[1] - p[1])
        if not dx or not dy:
            continue
        segments += 1
        mine, theirs = set(written(p, q)), bresenham(p, q)
        extra += len(mine - theirs)
        missing += len(theirs - mine)
        if 4 * dy >= dx and 4 * dx >= dy:
            # Bresenham's pixel is within 1/2 px of the line along the minor
            # axis, so within 1/(2 sqrt(1 + m^2)) across it: inside the
            # rectangle, by more than the corners' snapping, unless the
            # slope is shallow (or steep)
            assert theirs <= mine, (p, q)
        if dx >= dy:
            # the rectangle is sqrt(1 + m^2) < 2 px tall in a column
            per_column = Counter(x for x, _ in mine)
            assert max(per_column.values()) <= 2, (p, q)
    print(f"{segments} sloped segments, w = 1, square caps: {extra} pixels only in the "
          f"two triangles, {missing} only in Bresenham's")
    assert extra > 0
