"""Specs, pseudo-code and the extra panel rows of the line algorithms."""
import json

import pytest

from algorithms.lines.forms import explicit_listing
from algorithms.core.registry import get
from algorithms.core.steps import PLOT, VISIT
from tests.support.linecases import LINE_ALGORITHMS, NAMED_CASES, trace_of


@pytest.mark.parametrize("name", LINE_ALGORITHMS)
@pytest.mark.parametrize("p, q", NAMED_CASES[:10])
def test_panel_rows_for_every_step(name, p, q):
    spec = get(name)
    trace = trace_of(name, p, q, {"colors": ["#000000", "#ffffff"]})
    for i in range(len(trace)):
        rows = spec.panel_rows(trace, i)
        assert all(isinstance(a, str) and isinstance(b, str) for a, b in rows)
    json.dumps(spec.describe())
    json.dumps(trace.final_variables())


@pytest.mark.parametrize("name", LINE_ALGORITHMS)
def test_the_code_has_plot_lines_and_the_run_ends_on_a_known_line(name):
    trace = trace_of(name, (0, 0), (5, 2))
    kinds = {line.kind for line in trace.code}
    assert PLOT in kinds
    assert (VISIT in kinds) == (name == "line-implicit")
    assert trace.step(0).record is trace.start


def test_incremental_explains_its_rounding():
    spec = get("line-incremental")
    trace = trace_of("line-incremental", (0, 0), (5, 4), {"rounding": "floor"})
    i = next(i for i in range(len(trace)) if trace.step(i).pixel == (2, 1))
    assert ("rounding", "floor(1.6) = 1") in spec.panel_rows(trace, i)
    trace = trace_of("line-incremental", (0, 0), (4, 5), {"rounding": "round"})
    i = next(i for i in range(len(trace)) if trace.step(i).pixel == (2, 2))
    assert ("rounding", "round(1.6) = floor(2.1) = 2") in spec.panel_rows(trace, i)
    # The float error that floor turns into a wrong pixel stays visible.
    trace = trace_of("line-incremental", (0, 0), (98, 2), {"rounding": "floor"})
    i = next(i for i in range(len(trace)) if trace.step(i).pixel == (49, 0))
    assert ("rounding", "floor(0.9999999999999999) = 0") in spec.panel_rows(trace, i)


def test_parametric_explains_duplicates_and_gaps():
    spec = get("line-parametric")
    trace = trace_of("line-parametric", (0, 0), (4, 0), {"dt": 0.1})
    rows = dict(spec.panel_rows(trace, 2))  # t = 0.1: p = (0.4, 0) rounds to P again
    assert rows["duplicate"] == "(0, 0) was plotted before"
    assert rows["p"] == "(0.4, 0) rounds to (0, 0)"
    trace = trace_of("line-parametric", (0, 0), (8, 0), {"dt": 0.5})
    rows = dict(spec.panel_rows(trace, 2))  # t = 0.5: (0,0) -> (4,0)
    assert rows["gap"] == "(0, 0) to (4, 0) skips at least one pixel"


def test_explicit_shows_the_case_it_takes():
    trace = trace_of("line-explicit", (7, 3), (0, 0))
    assert trace.variables_at(1)["choice"] == "x major"
    assert trace.variables_at(3)["choice"] == "descending"
    assert trace.step(3).line == explicit_listing(((7, 3), (0, 0)), {}).at["x_down"]
