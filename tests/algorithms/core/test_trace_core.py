"""The trace core: random access equals a slow replay, the cap, the protocol."""
import random

import numpy as np
import pytest

from algorithms.core.registry import get
from algorithms.core.steps import CALC, NO_PIXEL, PLOT, CodeLine, Note, Start, Table, Vars
from algorithms.core.trace import Trace, TraceError
from tests.support.linecases import LINE_ALGORITHMS, trace_of
from tests.support.trace_oracle import slow_replay

CODE = (CodeLine("start"), CodeLine("plot(x, y)", PLOT), CodeLine("set variables"),
        CodeLine("remark"))


def same_raster(a, b):
    assert np.array_equal(a.counts, b.counts)
    if a.colors is None or b.colors is None:
        assert a.colors is None and b.colors is None
    else:
        assert np.array_equal(a.colors, b.colors)


# ------------------------------------------------------ state_at == replay
@pytest.mark.parametrize("name", LINE_ALGORITHMS)
@pytest.mark.parametrize("gap", [3, 1024])
def test_every_step_of_small_traces(name, gap, small_keyframes):
    small_keyframes(gap)
    options = {"colors": ["#ff0000", "#00ffff"]}
    if name == "line-parametric":
        options["dt"] = 0.02  # duplicates: pixels written more than once
    trace = trace_of(name, (2, 3), (17, 9), options, grid=(20, 12))
    for i in range(len(trace)):
        state = trace.state_at(i)
        same_raster(state.raster, slow_replay(trace, i))
        assert state.step == trace.step(i)
    if gap == 3:
        assert len(trace._keyframes) > 3


def test_random_steps_of_a_long_line_on_a_big_grid(small_keyframes):
    probe = get("line-bresenham").record(((0, 0), (1499, 997)), grid=(1500, 1000))
    small_keyframes(1, budget=12 * slow_replay(probe, 0).bytes())
    trace = get("line-bresenham").record(((0, 0), (1499, 997)), grid=(1500, 1000))
    n = len(trace)
    trace.raster_at(0)
    gap = trace._keyframes.gap
    assert len(trace._keyframes) >= 10 and gap < n // 5
    rng = random.Random(7)
    picks = {0, gap - 1, gap, gap + 1, 2 * gap - 1, n - 2, n - 1} | {rng.randrange(n) for _ in range(8)}
    for i in sorted(picks):
        same_raster(trace.raster_at(i), slow_replay(trace, i))
    assert int(trace.raster_at(n - 1).counts.sum()) == 1500


def test_random_steps_of_a_long_run_with_colours_and_repeats(small_keyframes):
    small_keyframes(37)
    trace = get("line-parametric").record(((0, 0), (300, 200)),
                                          {"dt": 1e-4, "colors": ["#000000", "#ffffff"]}, grid=(320, 240))
    n = len(trace)
    assert n > 10_000 and trace.nbytes() / n <= 64
    trace.raster_at(n - 1)
    assert len(trace._keyframes) > 50 and trace._keyframes.gap < n // 50
    rng = random.Random(11)
    for i in sorted({37, 38, 74, n - 1} | {rng.randrange(n) for _ in range(6)}):
        same_raster(trace.raster_at(i), slow_replay(trace, i))
    # The last write to a pixel decides its colour; counts keep the repeats.
    final = trace.raster_at(n - 1)
    assert final.counts.sum() == len(trace.written_pixels()) and final.counts.max() > 1


def test_candidates_are_e_and_ne_of_the_previous_pixel():
    trace = trace_of("line-bresenham", (0, 0), (7, 3))
    assert trace.state_at(2).candidates == [(1, 0), (1, 1)]
    assert trace.state_at(2).variables["choice"] == "E"


# ------------------------------------------------------------------ the cap
def frames(count):
    yield Start(line=0, values=("v",))
    for k in range(count - 1):
        yield (1, k, 0, float(k))


def test_step_cap_stops_the_recording_with_a_message():
    trace = Trace.record(frames(10), CODE, 16, 4, step_cap=5)
    assert trace.truncated and len(trace) == 5
    assert "step cap" in trace.message and "5" in trace.message
    assert trace.written_pixels().tolist() == [[0, 0], [1, 0], [2, 0], [3, 0]]


def test_a_run_that_fits_the_cap_exactly_is_not_truncated():
    trace = Trace.record(frames(5), CODE, 16, 4, step_cap=5)
    assert not trace.truncated and len(trace) == 5 and trace.message == ""


def test_the_cap_through_the_registry():
    trace = get("line-implicit").record(((0, 0), (30, 20)), step_cap=50)
    assert trace.truncated and len(trace) == 50


# ------------------------------------------------------------ the protocol
def run_bad(*bad):
    def generator():
        yield Start(line=0, values=("v",))
        yield (1, 0, 0, 1.0)
        yield from bad
    return Trace.record(generator(), CODE, 8, 8)


@pytest.mark.parametrize("bad, words", [
    ((1, 0, 0), "is not (line, x, y, value)"),
    ((1, 0, 0, 1.0, 2.0), "is not (line, x, y, value)"),
    ((1, "x", 0, 1.0), "is not (line, x, y, value)"),
    ((1, 2 ** 40, 0, 1.0), "is not (line, x, y, value)"),
    ((-1, 0, 0, 1.0), "is not (line, x, y, value)"),
    ((1, 0.5, 0, 1.0), "is not (line, x, y, value)"),
    ((1, 0, 0, None), "is not (line, x, y, value)"),
    ((9, 0, 0, 1.0), "pseudo-code line 9 does not exist"),
    ({"line": 1}, "is not a frame steps.py allows here"),
    (Start(line=0, values=("v",)), "is not a frame steps.py allows here"),
])
def test_malformed_frames_raise_trace_error(bad, words):
    with pytest.raises(TraceError, match="step") as error:
        run_bad(bad)
    assert words in str(error.value)


def test_the_first_frame_must_be_start():
    with pytest.raises(TraceError, match="first frame"):
        Trace.record(iter([(1, 0, 0, 1.0)]), CODE, 8, 8)
    with pytest.raises(TraceError, match="first frame"):
        Trace.record(iter([]), CODE, 8, 8)


def test_rich_records_mid_stream():
    table = Table(line=3, name="AET", columns=("x", "dx"), rows=((1, 0.5),))

    def generator():
        yield Start(line=0, values=("v",), constants={"k": 7})
        yield (1, 0, 0, 1.0)                       # 1
        yield Vars(line=2, values={"a": 1, "b": "two"})        # 2
        yield (1, 1, 0, 2.0)                       # 3
        yield Note(line=3, text="a remark", pixel=(5, 5))    # 4
        yield table                                # 5
        yield Vars(line=2, values={"a": 3})                    # 6
        yield (1, 2, 0, 3.0)                       # 7
    trace = Trace.record(generator(), CODE, 8, 8)
    assert len(trace) == 8 and trace.steps_of().tolist() == [0, 2, 4, 5, 6]
    assert trace.variables_at(1) == {"k": 7, "v": 1.0}
    assert trace.variables_at(3) == {"k": 7, "a": 1, "b": "two", "v": 2.0}
    assert trace.variables_at(7) == {"k": 7, "a": 3, "b": "two", "v": 3.0}
    note = trace.step(4)
    assert note.record.text == "a remark" and note.pixel == (5, 5) and note.kind == CALC
    assert not note.writes and note.values == {}
    assert trace.step(5).record == table and trace.step(5).pixel is None
    assert trace.step(2).record.values == {"a": 1, "b": "two"}
    assert trace.written_pixels().tolist() == [[0, 0], [1, 0], [2, 0]]
    assert trace.final_variables() == {"k": 7, "a": 3, "b": "two", "v": 3}
    assert trace.state_at(4).raster.counts.sum() == 2  # the note's pixel is not written
    assert trace.x[4] == 5 and trace.x[5] == NO_PIXEL
