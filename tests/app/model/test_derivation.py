"""s and n of the Bresenham derivation as segments on the grid, against
the exact ideal line."""
from fractions import Fraction

import pytest

from algorithms.core import registry
from algorithms.exact import lines as exact
from app.model.derivation import distance_segments


@pytest.mark.parametrize("p, q", [((1, 2), (13, 7)), ((20, 3), (4, 18)), ((3, 9), (15, 1))])
def test_s_reaches_the_ideal_line_and_n_the_upper_candidate(p, q):
    trace = registry.get("line-bresenham-textbook").record((p, q), {}, grid=(24, 24))
    decided = 0
    for i in range(len(trace)):
        marks = distance_segments((p, q), trace, i)
        if not marks:
            continue
        decided += 1
        (_, s, lower, line), (_, n, start, upper) = marks
        assert line == start and s + n == pytest.approx(1)
        # The lower candidate's centre is a pixel centre next to the step before.
        before = trace.step(i - 1).pixel
        assert max(abs(lower[0] - 0.5 - before[0]), abs(lower[1] - 0.5 - before[1])) == 1
        # The end of s lies on the ideal line through the pixel centres, exactly
        # as far as floats tell: its major coordinate's line value is its minor one.
        if exact.x_is_major(p, q):
            ideal = exact.line_value(p, q, round(line[0] - 0.5)) + Fraction(1, 2)
            assert line[1] == pytest.approx(float(ideal), abs=1e-9)
        else:
            ideal = exact.line_value(p, q, round(line[1] - 0.5)) + Fraction(1, 2)
            assert line[0] == pytest.approx(float(ideal), abs=1e-9)
        assert abs(upper[0] - lower[0]) + abs(upper[1] - lower[1]) == 1
    assert decided == max(abs(q[0] - p[0]), abs(q[1] - p[1]))


def test_nothing_to_draw_for_a_run_without_s_and_n():
    trace = registry.get("line-bresenham").record(((0, 0), (8, 3)), {}, grid=(10, 5))
    assert all(distance_segments(((0, 0), (8, 3)), trace, i) == [] for i in range(len(trace)))
