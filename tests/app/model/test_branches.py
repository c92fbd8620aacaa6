"""The branch each step took, for the decision variable's plot: read from
the code line, which differs from the value's sign where ties go the
other way or the test is D > 0."""
import numpy as np
import pytest

from app.model.branches import NO_BRANCH, decision_branches
from tests.support import record


def exact_branches(trace, *names):
    """Per step: k for a step on a line whose branch is ``names[k]``, -1
    otherwise (from each step's own record)."""
    out = []
    for i in range(len(trace)):
        branch = trace.step(i).branch
        out.append(names.index(branch) if branch in names else NO_BRANCH)
    return np.array(out)


@pytest.mark.parametrize("name, points, options, names, differs", [
    # d <= 0 goes to E: here the sign happens to agree with the branch.
    ("line-bresenham", [(1, 1), (21, 11)], None, ("E", "NE"), False),
    # Ties (d = 0, the first step here) go to NE.
    ("line-bresenham-textbook", [(1, 1), (21, 11)], {"variant": "ties-ne"}, ("E", "NE"), True),
    # D > 0 goes to E.
    ("line-bresenham-textbook", [(1, 1), (21, 12)], {"variant": "sign-reversed"},
     ("E", "NE"), True),
    ("circle-midpoint", [(12, 12)], {"radius": 9}, ("E", "SE"), True),
])
def test_branches_follow_the_code_line_not_the_sign(name, points, options, names, differs):
    trace = record(name, points, options, grid=(25, 25))
    codes, shown = decision_branches(trace)
    assert shown == names
    assert np.array_equal(codes, exact_branches(trace, *names))
    d = trace.series(trace.start.decision)
    decided = codes != NO_BRANCH
    # Colouring by sign (<= 0 first, > 0 second) gets some of these wrong.
    by_sign = (d > 0).astype(int)
    assert (by_sign[decided] != codes[decided]).any() == differs


def test_the_ellipse_names_both_regions_pairs():
    trace = record("ellipse-midpoint", [(12, 12)], None, grid=(25, 25))
    codes, shown = decision_branches(trace)
    assert shown == ("E/S", "SE/SW")
    steps = [trace.step(i).branch for i in range(len(trace))]
    assert {b for b, c in zip(steps, codes) if c == 0} == {"E", "S"}
    assert {b for b, c in zip(steps, codes) if c == 1} == {"SE", "SW"}


@pytest.mark.parametrize("name, points, options, names", [
    # A comb whose first vertex is reflex: its ears are found after a miss or two.
    ("polygon-tessellate", [[(7.5, 8.5), (2.5, 20.5), (2.5, 2.5), (22.5, 2.5), (22.5, 20.5),
                             (17.5, 8.5), (12.5, 20.5)]], None, ("reflex", "blocked", "ear")),
    ("aa-adaptive", [(2.25, 2.5), (20.5, 6.25), (8.75, 19.5)], None, ("hit", "miss", "split")),
])
def test_a_decision_of_three_branches_gives_each_its_own_code(name, points, options, names):
    trace = record(name, points, options, grid=(25, 25))
    codes, shown = decision_branches(trace)
    assert shown == names
    assert np.array_equal(codes, exact_branches(trace, *names))
    assert set(codes.tolist()) >= {0, 1, 2}  # every branch taken somewhere in these scenes
