"""The implicit form against the exact distance-to-segment rule."""
import math
from fractions import Fraction

import pytest
from hypothesis import given, settings

from algorithms.exact import lines as exact
from algorithms.core.steps import PLOT, VISIT
from tests.support.linecases import NAMED_CASES, segments, trace_of


def box(p, q, margin=0):
    return {(x, y)
            for x in range(min(p[0], q[0]) - margin, max(p[0], q[0]) + margin + 1)
            for y in range(min(p[1], q[1]) - margin, max(p[1], q[1]) + margin + 1)}


def check(p, q):
    trace = trace_of("line-implicit", p, q)
    tested = [trace.step(i) for i in range(len(trace)) if trace.step(i).pixel is not None]
    # Every pixel of the box is tested once, as a plot or a visit, x in the
    # outer loop and y in the inner one, from P's corner towards Q's.
    sx, sy = (1 if q[0] >= p[0] else -1), (1 if q[1] >= p[1] else -1)
    assert [step.pixel for step in tested] == [(x, y) for x in range(p[0], q[0] + sx, sx)
                                               for y in range(p[1], q[1] + sy, sy)]
    assert len(tested) == len(box(p, q))
    for step in tested:
        inside = exact.within_half(p, q, step.pixel)
        assert step.kind == (PLOT if inside else VISIT)
        shown = step.values["dist"]
        assert math.isclose(shown, math.sqrt(exact.segment_distance_sq(p, q, step.pixel)), abs_tol=1e-12)
    written = [tuple(map(int, pixel)) for pixel in trace.written_pixels()]
    # No pixel outside the box is within 1/2 of the segment either.
    assert set(written) == {pixel for pixel in box(p, q, margin=2) if exact.within_half(p, q, pixel)}
    assert len(written) == len(set(written))
    assert written[0] == p and written[-1] == q
    return written


@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_named_cases(p, q):
    check(p, q)


@settings(max_examples=150)
@given(segments(25))
def test_every_box_pixel_follows_the_exact_rule(pq):
    check(*pq)


def test_by_hand():
    # (1,0) and (1,1) are both sqrt(1/5) < 1/2 from (0,0)-(2,1): a thick spot.
    assert set(check((0, 0), (2, 1))) == {(0, 0), (1, 0), (1, 1), (2, 1)}
    # On a diagonal the side pixels are sqrt(1/2) away: only the diagonal.
    assert set(check((0, 0), (3, 3))) == {(0, 0), (1, 1), (2, 2), (3, 3)}
    assert check((2, 5), (2, 5)) == [(2, 5)]
    assert check((4, 1), (0, 1)) == [(4, 1), (3, 1), (2, 1), (1, 1), (0, 1)]


def test_no_pixel_centre_is_exactly_half_a_pixel_from_a_segment():
    # Why the strict "< 1/2" never has to break a tie with integer endpoints:
    # |PQ|^2 = 4 cross^2 needs |PQ| to be the whole number 2|cross|, an even
    # multiple of g = gcd(dx, dy) since cross is a multiple of g; but |PQ| / g
    # is then 1 or the hypotenuse of a primitive Pythagorean triple, both odd.
    # Near an end, 4 |XP|^2 = 1 has no integer solution.
    for dx in range(-9, 10):
        for dy in range(-9, 10):
            for pixel in box((0, 0), (dx, dy), margin=2):
                assert exact.segment_distance_sq((0, 0), (dx, dy), pixel) != Fraction(1, 4)


def test_explain_gives_the_exact_comparison():
    trace = trace_of("line-implicit", (0, 0), (2, 1))
    from algorithms.core.registry import get
    spec = get("line-implicit")
    rows = {}
    for i in range(len(trace)):
        if trace.step(i).pixel == (1, 0):
            rows = dict(spec.explain(trace, i))
    # cross((2,1), (1,0)) = 2*0 - 1*1 = -1, so 4*cross^2 = 4 < |PQ|^2 = 5.
    assert rows["test"] == "4*cross^2 = 4 < |PQ|^2 = 5, so dist < 1/2: plot"
