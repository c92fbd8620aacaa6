"""Breakpoint conditions and step units against a plain scan of the frames.

Each oracle (tests/support/breakpoint_oracles.py) walks the trace one frame
at a time (``trace.step(i)``: its line's kind and branch, its pixel, its
values, its rich record) in plain Python and lists the frames where the
condition holds; the search under test must stop at the first of them after
(or before) any frame.
"""
import pytest

from algorithms.core.steps import Table, Vars
from app.model import breakpoints as bp
from tests.support import record
from tests.support.breakpoint_oracles import (BRESENHAM, POLYGON, TRIANGLES, ZBUFFER, aet_events,
                                              branch_events, depth_fail_events, first_after,
                                              frames, pixel_events, scanline_events,
                                              sign_events)


def check_every_start(trace, condition, events):
    for index in range(len(trace)):
        for direction in (+1, -1):
            assert bp.next_stop(trace, index, condition, direction) == \
                first_after(events, index, direction), (condition, index, direction)


# ----------------------------------------------------------- conditions
@pytest.mark.parametrize("segment", BRESENHAM)
@pytest.mark.parametrize("symmetric", [False, True])
def test_decision_sign_change_on_bresenham(segment, symmetric):
    trace = record("line-bresenham", list(segment), {"symmetric": symmetric})
    events = sign_events(trace)
    check_every_start(trace, "sign", events)


def test_decision_sign_includes_ties_and_has_stops():
    trace = record("line-bresenham", [(4, 5), (28, 15)])
    events = sign_events(trace)
    # The demo segment meets d = 0 twice: each tie is a stop of its own.
    ties = [s.index for s in frames(trace) if s.values.get("d") == 0]
    assert len(ties) == 2 and set(ties) <= set(events)


@pytest.mark.parametrize("segment", BRESENHAM)
def test_branch_change_on_bresenham(segment):
    trace = record("line-bresenham", list(segment))
    check_every_start(trace, "branch", branch_events(trace))


def test_branch_change_on_the_midpoint_ellipse():
    trace = record("ellipse-midpoint", [(16, 12)], {"rx": 11, "ry": 6})
    events = branch_events(trace)
    assert len(events) > 4
    check_every_start(trace, "branch", events)


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_aet_change_on_the_scanline_fill(rule):
    trace = record("polygon-scanline", POLYGON, {"fill_rule": rule})
    events = aet_events(trace)
    snapshots = [s.index for s in frames(trace)
                 if isinstance(s.record, Table) and s.record.name == "AET"]
    # A real condition: some snapshots change the table, most do not.
    assert 3 <= len(events) < len(snapshots)
    check_every_start(trace, "aet", events)


@pytest.mark.parametrize("name,points", [("polygon-scanline", POLYGON),
                                         ("polygon-convex", [POLYGON[0][:3]]),
                                         ("triangle-scan", TRIANGLES),
                                         ("line-bresenham", [(4, 5), (28, 15)])])
def test_new_scanline(name, points):
    trace = record(name, points)
    events = scanline_events(trace)
    assert len(events) >= 5
    check_every_start(trace, "scanline", events)


@pytest.mark.parametrize("name", ["triangle-bbox", "triangle-scan", "triangle-halfplane"])
def test_pixel_reached_on_a_triangle_run(name):
    trace = record(name, TRIANGLES)
    written = {tuple(p) for p in trace.written_pixels().tolist()}
    # Pixels written, pixels only visited (in a bounding box), pixels never reached.
    for pixel in [(10, 8), (19, 4), (12, 10), (28, 18), (0, 0), (31, 23), (3, 16)]:
        events = pixel_events(trace, pixel)
        assert bool(events) >= (pixel in written)
        check_every_start(trace, ("pixel", pixel), events)


def test_pixel_reached_on_spans():
    trace = record("polygon-scanline", POLYGON)
    for pixel in [(5, 5), (12, 8), (25, 6), (20, 14)]:
        check_every_start(trace, ("pixel", pixel), pixel_events(trace, pixel))


def test_depth_test_fails_on_an_occluded_triangle():
    trace = record("zbuffer", **ZBUFFER)
    events = depth_fail_events(trace)
    assert len(events) > 10
    check_every_start(trace, "depth", events)


def test_depth_test_fails_with_the_less_equal_test():
    options = {**ZBUFFER["options"], "z": (0.5,) * 6, "depth_test": "less-equal"}
    trace = record("zbuffer", ZBUFFER["points"], options)
    # Equal depths pass a "<=" test: nothing fails.
    assert bp.stops(trace, "depth").tolist() == []
    assert bp.unavailable(trace, "depth") == ""


# ------------------------------------------------------------ step units
def test_frame_unit_moves_one_frame_and_stops_at_the_ends():
    trace = record("line-bresenham", [(4, 5), (28, 15)])
    assert bp.step_target(trace, 3, "frame", 1) == 4
    assert bp.step_target(trace, 3, "frame", -1) == 2
    assert bp.step_target(trace, 3, "frame", 10) == 13
    assert bp.step_target(trace, len(trace) - 1, "frame", 1) is None
    assert bp.step_target(trace, 0, "frame", -1) is None


def check_unit(trace, unit, events):
    assert len(events) >= 2
    for index in range(len(trace)):
        for count in (1, -1, 3, -3):
            if count > 0:
                later = [e for e in events if e > index]
                expected = later[min(count, len(later)) - 1] if later else None
            else:
                earlier = [e for e in events if e < index]
                expected = earlier[max(len(earlier) + count, 0)] if earlier else None
            assert bp.step_target(trace, index, unit, count) == expected, (unit, index, count)


def test_decision_unit():
    for name, points, options in (("line-bresenham", [(4, 5), (28, 15)], {}),
                                  ("zbuffer", ZBUFFER["points"], ZBUFFER["options"])):
        trace = record(name, points, options)
        events = [s.index for s in frames(trace) if s.branch]
        check_unit(trace, "decision", events)


def test_scanline_unit():
    trace = record("polygon-scanline", POLYGON)
    check_unit(trace, "scanline", scanline_events(trace))


def test_primitive_unit_on_triangles_and_the_zbuffer():
    for name, points, options in (("triangle-scan", TRIANGLES, {}),
                                  ("zbuffer", ZBUFFER["points"], ZBUFFER["options"])):
        trace = record(name, points, options)
        events = [s.index for s in frames(trace)
                  if isinstance(s.record, Vars) and "triangle" in s.record.values]
        assert len(events) == len(points) // 3
        check_unit(trace, "primitive", events)


def test_primitive_unit_on_ear_clipping():
    trace = record("polygon-tessellate", [POLYGON[0]])
    events = [s.index for s in frames(trace) if isinstance(s.record, Table)
              and s.record.name.startswith("edge functions of triangle")]
    assert len(events) == len(POLYGON[0]) - 2  # a simple polygon of n vertices: n - 2 ears
    check_unit(trace, "primitive", events)


# ---------------------------------------------------------- unavailable
@pytest.mark.parametrize("name,points,kind", [
    ("polygon-scanline", POLYGON, "sign"),
    ("polygon-scanline", POLYGON, "branch"),
    ("line-bresenham", [(4, 5), (28, 15)], "aet"),
    ("painter", ZBUFFER["points"], "depth"),
    ("line-bresenham", [(4, 5), (28, 15)], "depth"),
    ("line-bresenham", [(4, 5), (28, 15)], "primitive"),
    ("polygon-scanline", POLYGON, "decision"),
])
def test_unavailable_conditions_are_reported_not_raised(name, points, kind):
    trace = record(name, points)
    assert bp.unavailable(trace, kind)
    if kind in bp.CONDITIONS:
        assert bp.next_stop(trace, 0, kind) is None
        assert bp.next_stop(trace, len(trace) - 1, kind, -1) is None
    else:
        assert bp.step_target(trace, 0, kind, 1) is None


def test_first_stop_picks_the_nearest_condition_within_the_bound():
    trace = record("line-bresenham", [(4, 5), (28, 15)])
    sign, branch = sign_events(trace), branch_events(trace)
    for index in range(len(trace)):
        nearest = first_after(sorted(set(sign) | set(branch)), index, +1)
        stop = bp.first_stop(trace, index, ["branch", "sign", "aet"], +1)
        assert (stop and stop.index) == nearest
        if stop is not None:
            assert stop.index in (sign if stop.condition.kind == "sign" else branch)
            assert bp.first_stop(trace, index, ["sign", "branch"], +1, bound=stop.index - 1) is None


def test_bad_conditions_are_refused_clearly():
    with pytest.raises(ValueError, match="unknown breakpoint condition"):
        bp.Condition("nowhere")
    with pytest.raises(ValueError, match="needs a pixel"):
        bp.Condition("pixel")


def test_the_logic_needs_no_qt():
    import subprocess
    import sys
    code = ("import sys, app.model.breakpoints; "
            "sys.exit(any(m.split('.')[0] in ('PySide6', 'pyqtgraph') for m in sys.modules))")
    root = __file__.rsplit("/tests/", 1)[0]
    assert subprocess.run([sys.executable, "-c", code], cwd=root).returncode == 0
