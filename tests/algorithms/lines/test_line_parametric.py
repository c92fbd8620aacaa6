"""The parametric form: endpoints, t without drift, duplicates and gaps.

A duplicate is a plot of a pixel that was plotted before (at the previous
step or any earlier one); a gap is a jump between consecutive distinct
plotted pixels that are not 8-neighbours. Both counts are recomputed here
from the emitted pixels with the exact helpers, never read back from the
algorithm to check itself.
"""
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import lines as exact
from algorithms.core.registry import InputError, get
from tests.support.linecases import NAMED_CASES, segments, trace_of

NEAR = Fraction(1, 10 ** 9)  # far above the float error of t * (Q - P)
DTS = st.one_of(st.sampled_from(["auto", 1.0, 0.5, 0.3, 0.1, 0.05, 0.013, 0.001]),
                st.floats(0.002, 1.0))


def run(p, q, dt):
    trace = trace_of("line-parametric", p, q, {"dt": dt})
    writes = trace.writes()
    pixels = [tuple(map(int, pixel)) for pixel in trace.written_pixels()]
    return trace, writes, pixels


def check(p, q, dt):
    trace, writes, pixels = run(p, q, dt)
    assert pixels[0] == p and pixels[-1] == q
    t = trace.series("t")[writes]
    n = max(abs(q[0] - p[0]), abs(q[1] - p[1]))
    # t_k comes from a whole counter k, so it does not drift; the last is exactly 1.
    expected = [k / n if n else 0.0 for k in range(len(t) - 1)] if dt == "auto" \
        else [k * dt for k in range(len(t) - 1)]
    assert list(t[:-1]) == expected
    assert t[-1] == 1.0 and all(a < b for a, b in zip(t, t[1:]))
    if dt != "auto":
        assert len(t) - 1 == next(k for k in range(10 ** 7) if k * dt >= 1)
    # Each pixel is the rounded point P + t (Q - P) for its t. The float
    # product t * (Q - P) is rounded to a double, which can land exactly on
    # a half that the exact product misses by an ulp (0.3 * 5 is 1.5 in
    # floats, 1.4999999999999999444 exactly), so near a half either
    # neighbour is accepted.
    for (x, y), tk in zip(pixels, t):
        for got, start, delta in ((x, p[0], q[0] - p[0]), (y, p[1], q[1] - p[1])):
            value = start + Fraction(float(tk)) * delta
            nearest = exact.round_half_up_exact(value)
            allowed = {nearest}
            for side in (-1, 1):
                if abs(value - nearest - Fraction(side, 2)) < NEAR:
                    allowed.add(nearest + side)
            assert got in allowed
    # Running counts at every plot, and the totals at the end.
    duplicates = trace.series("duplicates")[writes]
    gaps = trace.series("gaps")[writes]
    for k in range(len(pixels)):
        assert duplicates[k] == exact.duplicate_count(pixels[:k + 1])
        assert gaps[k] == exact.gap_count(pixels[:k + 1])
    final = trace.final_variables()
    assert final["duplicates"] == exact.duplicate_count(pixels)
    assert final["gaps"] == exact.gap_count(pixels)
    assert final["plots"] == len(pixels) and final["pixels"] == len(set(pixels))
    return final, pixels


@pytest.mark.parametrize("p, q", NAMED_CASES)
@pytest.mark.parametrize("dt", ["auto", 0.3, 0.01])
def test_named_cases(p, q, dt):
    check(p, q, dt)


@settings(max_examples=120)
@given(segments(60), DTS)
def test_counts_and_endpoints(pq, dt):
    check(*pq, dt)


@settings(max_examples=120)
@given(segments(300))
def test_auto_step_leaves_no_gaps_and_no_duplicates(pq):
    p, q = pq
    final, pixels = check(p, q, "auto")
    assert final["gaps"] == 0
    # One plot per major-axis pixel; a point is plotted at t = 0 and t = 1.
    assert final["duplicates"] == (1 if p == q else 0)


def test_a_coarse_step_leaves_gaps_and_a_fine_one_repeats():
    final, pixels = check((0, 0), (20, 5), 0.1)
    assert final["gaps"] == 10 and final["duplicates"] == 0  # every step jumps two columns
    final, pixels = check((0, 0), (10, 3), 0.001)
    assert final["plots"] == 1001 and final["duplicates"] == 1001 - len(set(pixels))
    assert final["gaps"] == 0


def test_the_last_step_is_clamped_to_one():
    trace, writes, pixels = run((0, 0), (9, 4), 0.3)  # t = 0, 0.3, 0.6, 0.9, then 1
    assert list(trace.series("t")[writes]) == [0.0, 0.3, 0.6, 0.8999999999999999, 1.0]
    assert pixels[-1] == (9, 4)


def test_dt_option():
    option = get("line-parametric").option("dt")
    assert option.parse("auto") == "auto"
    assert option.parse("0.25") == 0.25
    for bad in ("0", "-0.1", "1.5", "nan", "fast"):
        with pytest.raises(InputError):
            option.parse(bad)
