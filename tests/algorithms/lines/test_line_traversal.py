"""Grid traversal against the exact set of cells a segment meets.

The oracle clips the segment against each cell (or each pixel's diamond)
in Fractions, Liang-Barsky style: a different method from the column
sweep and the crossing walk under test.
"""
from __future__ import annotations

from fractions import Fraction

import pytest

from algorithms.core import registry

SEGMENTS = [((0.5, 0.5), (7.5, 3.5)), ((1, 1), (4, 4)), ((2.25, 7.75), (9.5, 1.125)),
            ((3, 2), (3, 9)), ((1.5, 4), (12.25, 4)), ((6.75, 6.75), (6.75, 6.75)),
            ((10.5, 2.5), (1.5, 8.5)), ((6, 12), (10, 4)), ((9, 3), (2, 10)), ((0.125, 0.0), (5.0, 11.0)), ((4, 4.5), (9, 4.5))]


def meets(p, q, box, open_box):
    """Does segment p-q meet the box (lo_x, hi_x, lo_y, hi_y), closed or open?"""
    lo, hi = Fraction(0), Fraction(1)
    low_open = high_open = False  # is the bound from an open face (strict)?
    for a0, a1, b_lo, b_hi in ((p[0], q[0], box[0], box[1]), (p[1], q[1], box[2], box[3])):
        a0, a1 = Fraction(a0), Fraction(a1)
        if a1 == a0:
            inside = b_lo < a0 < b_hi if open_box else b_lo <= a0 <= b_hi
            if not inside:
                return False
            continue
        t0, t1 = sorted(((b_lo - a0) / (a1 - a0), (b_hi - a0) / (a1 - a0)))
        if t0 >= lo:
            lo, low_open = t0, open_box
        if t1 <= hi:
            hi, high_open = t1, open_box
    return lo < hi or (lo == hi and not low_open and not high_open)


def cells_near(p, q):
    xs, ys = [int(Fraction(v)) for v in (p[0], q[0])], [int(Fraction(v)) for v in (p[1], q[1])]
    return [(i, j) for i in range(min(xs) - 2, max(xs) + 3) for j in range(min(ys) - 2, max(ys) + 3)]


def touched(p, q, open_box=False):
    return {(i, j) for i, j in cells_near(p, q) if meets(p, q, (i, i + 1, j, j + 1), open_box)}


def run(name, p, q):
    trace = registry.get(name).record((p, q), {}, grid=(16, 16))
    return [tuple(c) for c in trace.written_pixels().tolist()]


@pytest.mark.parametrize("p, q", SEGMENTS)
def test_supercover_is_every_closed_cell_the_segment_meets(p, q):
    cells = run("line-supercover", p, q)
    assert len(cells) == len(set(cells)), "a cell plotted twice"
    assert set(cells) == touched(p, q)


@pytest.mark.parametrize("p, q", SEGMENTS)
def test_amanatides_woo_walks_four_connected_through_the_cells_it_must(p, q):
    cells = run("line-amanatides-woo", p, q)
    first = (int(Fraction(p[0]) // 1), int(Fraction(p[1]) // 1))
    last = (int(Fraction(q[0]) // 1), int(Fraction(q[1]) // 1))
    assert cells[0] == first and cells[-1] == last
    for a, b in zip(cells, cells[1:]):
        assert abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1, "not a 4-connected step"
    assert len(cells) == 1 + abs(last[0] - first[0]) + abs(last[1] - first[1])
    interior = touched(p, q, open_box=True)
    assert interior <= set(cells) <= touched(p, q)


def test_a_corner_pass_takes_one_side_cell_where_the_supercover_takes_both():
    p, q = (1, 1), (4, 4)
    woo, cover = set(run("line-amanatides-woo", p, q)), set(run("line-supercover", p, q))
    # Corners (2, 2) and (3, 3) are crossed; the walk takes (1, 2) and (2, 3) (y first).
    assert {(2, 1), (3, 2), (1, 2), (2, 3)} <= cover
    assert {(1, 2), (2, 3)} <= woo and not {(2, 1), (3, 2)} & woo


def in_diamond(point, i, j):
    """In u = x + y, v = x - y: [cu - 1/2, cu + 1/2) x (cv - 1/2, cv + 1/2) and
    the two corners (cu - 1/2, cv +- 1/2), the diamond with its lower-left edge."""
    cu, cv = i + j + 1, i - j
    u, v = Fraction(point[0]) + Fraction(point[1]), Fraction(point[0]) - Fraction(point[1])
    half = Fraction(1, 2)
    return (cu - half <= u < cu + half and abs(v - cv) < half) or \
        (u == cu - half and abs(v - cv) == half)


def diamond_oracle(p, q):
    """Cells whose diamond the segment meets (in u = x + y, v = x - y the open
    diamond is an open square and its lower-left edge the square's closed
    left side) and which do not hold Q in their diamond."""
    def uv(point):
        x, y = Fraction(point[0]), Fraction(point[1])
        return (x + y, x - y)
    pu, qu = uv(p), uv(q)
    lit = set()
    for i, j in cells_near(p, q):
        cu, cv = uv((i + Fraction(1, 2), j + Fraction(1, 2)))
        box = (cu - Fraction(1, 2), cu + Fraction(1, 2), cv - Fraction(1, 2), cv + Fraction(1, 2))
        left = (box[0], box[0], box[2], box[3])
        touched_ = meets(pu, qu, box, open_box=True) or meets(pu, qu, left, open_box=False)
        if touched_ and not in_diamond(q, i, j):
            lit.add((i, j))
    return lit


@pytest.mark.parametrize("p, q", SEGMENTS)
def test_diamond_exit_is_the_exact_rule(p, q):
    cells = run("line-diamond-exit", p, q)
    assert len(cells) == len(set(cells))
    assert set(cells) == diamond_oracle(p, q)


def test_diamond_exit_leaves_no_gap_where_the_line_passes_a_corner():
    # Slope 1/2 from a pixel centre: at x = 2.5 the line passes y = 3 exactly,
    # the corner between the diamonds of (2, 2) and (2, 3).
    cells = run("line-diamond-exit", (1.5, 2.5), (9.5, 6.5))
    assert sorted(x for x, _ in cells) == list(range(1, 9))  # one per column, Q's left out
    assert (2, 3) in cells and (2, 2) not in cells


def test_diamond_exit_draws_a_shared_end_pixel_once():
    a, b, c = (0.5, 0.5), (6.5, 3.5), (9.5, 9.5)
    first, second = set(run("line-diamond-exit", a, b)), set(run("line-diamond-exit", b, c))
    assert (6, 3) in second and (6, 3) not in first
    assert not first & second


def test_woo_with_a_subnormal_step_shows_an_infinite_tmax():
    """1 / 5e-324 is beyond any float: the panel shows infinity, not an OverflowError."""
    import math

    from algorithms.core import registry
    trace = registry.get("line-amanatides-woo").record([(0.0, 0.0), (0.0, 5e-324)])
    assert trace.variables_at(len(trace) - 1)["tMaxY"] == math.inf  # NaN tMaxX is not shown
    assert trace.written(0, len(trace)).pixels.tolist() == [[0, 0]]
