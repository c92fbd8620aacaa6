"""Grid traversal against the exact set of cells a segment meets.

The oracle clips the segment against each cell (or each pixel's diamond)
in Fractions, Liang-Barsky style: a different method from the column
sweep and the crossing walk under test.
"""
from __future__ import annotations

import random
from fractions import Fraction

import pytest

from algorithms.core import registry
from algorithms.core.steps import Note

SEGMENTS = [((0.5, 0.5), (7.5, 3.5)), ((1, 1), (4, 4)), ((2.25, 7.75), (9.5, 1.125)),
            ((3, 2), (3, 9)), ((1.5, 4), (12.25, 4)), ((6.75, 6.75), (6.75, 6.75)),
            ((10.5, 2.5), (1.5, 8.5)), ((6, 12), (10, 4)), ((9, 3), (2, 10)), ((0.125, 0.0), (5.0, 11.0)), ((4, 4.5), (9, 4.5))]


def meets(p, q, box, open_box=False, half_open=False):
    """Does segment p-q meet the box (lo_x, hi_x, lo_y, hi_y)? Closed, open, or
    half-open (lower faces in, upper faces out, as [i, i+1) x [j, j+1))."""
    low_face_open, high_face_open = open_box, open_box or half_open
    lo, hi = Fraction(0), Fraction(1)
    low_open = high_open = False  # is the bound from an open face (strict)?
    for a0, a1, b_lo, b_hi in ((p[0], q[0], box[0], box[1]), (p[1], q[1], box[2], box[3])):
        a0, a1 = Fraction(a0), Fraction(a1)
        if a1 == a0:
            above = b_lo < a0 if low_face_open else b_lo <= a0
            below = a0 < b_hi if high_face_open else a0 <= b_hi
            if not (above and below):
                return False
            continue
        # t at the lower face and at the upper face, each with its openness
        faces = sorted((((b_lo - a0) / (a1 - a0), low_face_open),
                        ((b_hi - a0) / (a1 - a0), high_face_open)))
        (t0, open0), (t1, open1) = faces
        if t0 > lo or (t0 == lo and open0):
            lo, low_open = t0, open0
        if t1 < hi or (t1 == hi and open1):
            hi, high_open = t1, open1
    return lo < hi or (lo == hi and not low_open and not high_open)


def cells_near(p, q):
    xs, ys = [int(Fraction(v)) for v in (p[0], q[0])], [int(Fraction(v)) for v in (p[1], q[1])]
    return [(i, j) for i in range(min(xs) - 2, max(xs) + 3) for j in range(min(ys) - 2, max(ys) + 3)]


def touched(p, q, open_box=False, half_open=False):
    return {(i, j) for i, j in cells_near(p, q)
            if meets(p, q, (i, i + 1, j, j + 1), open_box, half_open)}


def run(name, p, q, options=None, grid=(16, 16)):
    trace = registry.get(name).record((p, q), options or {}, grid=grid)
    return [tuple(c) for c in trace.written_pixels().tolist()]


def on_grid(cells, grid=(16, 16)):
    return {(i, j) for i, j in cells if 0 <= i < grid[0] and 0 <= j < grid[1]}


def random_segments(count, seed):
    """Real segments on the grid, many on grid lines, corners or halves."""
    rng = random.Random(seed)

    def coordinate():
        return rng.choice((rng.randint(0, 15), rng.randint(0, 30) / 2, rng.randint(0, 60) / 4,
                           round(rng.uniform(0, 15.9), 3)))
    return [((coordinate(), coordinate()), (coordinate(), coordinate())) for _ in range(count)]


HARD = [((2, 5.5), (10, 5.5)), ((0, 0), (2, 2)), ((2, 5), (10, 5)), ((5, 2), (5, 9)),
        ((3, 3), (3, 3)), ((4, 4), (1, 1)), ((0, 3), (3, 0)), ((6, 1.5), (1, 1.5))]


@pytest.mark.parametrize("p, q", SEGMENTS + HARD + random_segments(150, 33))
def test_supercover_is_every_cell_the_segment_meets_half_open_by_default(p, q):
    cells = run("line-supercover", p, q)
    assert len(cells) == len(set(cells)), "a cell plotted twice"
    assert set(cells) == on_grid(touched(p, q, half_open=True))


@pytest.mark.parametrize("p, q", SEGMENTS + HARD + random_segments(150, 34))
def test_closed_supercover_is_every_closed_cell_the_segment_meets(p, q):
    cells = run("line-supercover", p, q, {"cells": "closed"})
    assert len(cells) == len(set(cells)), "a cell plotted twice"
    assert set(cells) == on_grid(touched(p, q))


def test_the_named_hard_cases_differ_as_the_conventions_say():
    # Horizontal on a cell border: half-open starts in P's own column and takes row 5 only.
    assert set(run("line-supercover", (2, 5.5), (10, 5.5))) == {(x, 5) for x in range(2, 11)}
    assert (1, 5) in run("line-supercover", (2, 5.5), (10, 5.5), {"cells": "closed"})
    assert set(run("line-supercover", (2, 5), (10, 5))) == {(x, 5) for x in range(2, 11)}
    assert {(x, 4) for x in range(1, 11)} <= set(
        run("line-supercover", (2, 5), (10, 5), {"cells": "closed"}))
    # The exact diagonal through corners: half-open takes the diagonal cells alone.
    assert run("line-supercover", (0, 0), (2, 2)) == [(0, 0), (1, 1), (2, 2)]
    closed = set(run("line-supercover", (0, 0), (2, 2), {"cells": "closed"}))
    assert closed == {(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (2, 1), (2, 2)}


def test_cells_outside_the_grid_are_named_in_a_note_not_plotted():
    trace = registry.get("line-supercover").record(((0, 0), (2, 2)), {"cells": "closed"},
                                                   grid=(16, 16))
    notes = [step.record.text for step in map(trace.step, range(len(trace)))
             if isinstance(step.record, Note)]
    assert len(notes) == 1 and notes[0].startswith("3 cells") and "(-1, -1)" in notes[0]
    assert all(x >= 0 and y >= 0 for x, y in trace.written_pixels().tolist())
    half_open = registry.get("line-supercover").record(((0, 0), (2, 2)), {}, grid=(16, 16))
    assert not any(isinstance(half_open.step(i).record, Note) for i in range(len(half_open)))


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


def test_a_corner_pass_takes_one_side_cell_where_the_closed_supercover_takes_both():
    p, q = (1, 1), (4, 4)
    woo = set(run("line-amanatides-woo", p, q))
    cover = set(run("line-supercover", p, q, {"cells": "closed"}))
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
