"""Plain frames, recorded a list at a time, give the columns a frame-by-frame
reading gives, wherever the run turns to floats, huge integers, NumPy
numbers or rich records, and wherever the step cap falls."""
import math
from collections import namedtuple

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.core.steps import NO_PIXEL, PLOT, CodeLine, Start, Vars
from algorithms.core.trace import RecordMonitor, Trace, TraceError

CODE = (CodeLine("start"), CodeLine("plot(x, y)", PLOT), CodeLine("set"))

# How each kind of segment writes its k-th frame's value.
VALUES = {
    "int": lambda k: k - 500,
    "float": lambda k: k / 3,
    "huge": lambda k: 2 ** 60 + 2 * k + 1,  # not a double: it must round as float() does
    "bigger": lambda k: 2 ** 70 + k,  # beyond 64 bits
    "numpy": lambda k: np.int32(k),
    "bool": lambda k: k % 2 == 0,
    # either side of 32 bits
    "edge32": lambda k: (2 ** 31 - 1, -2 ** 31, 2 ** 31, -2 ** 31 - 1)[k % 4],
    "named": lambda k: k,  # the frame is a tuple subclass
}
Frame = namedtuple("Frame", "line x y value")


def build(segments):
    """The frames of the segments after a Start, and the columns a reading
    of one frame at a time in Python gives."""
    frames, expected = [Start(line=0, values=("v",))], [(0, NO_PIXEL, NO_PIXEL, math.nan)]
    for kind, length in segments:
        for k in range(length):
            if kind == "vars":
                frames.append(Vars(line=2, values={"k": k}))
                expected.append((2, NO_PIXEL, NO_PIXEL, math.nan))
            else:
                value, y = VALUES[kind](k), len(frames) % 89
                frame = (1, k % 97, y, value)
                frames.append(Frame(*frame) if kind == "named" else frame)
                expected.append((1, k % 97, y, float(value)))
    return frames, expected


def columns_of(trace):
    return list(zip(trace.line.tolist(), trace.x.tolist(), trace.y.tolist(),
                    trace.values[:, 0].tolist()))


def same(got, expected):
    assert len(got) == len(expected)
    for step, (a, b) in enumerate(zip(got, expected)):
        assert a[:3] == b[:3], step
        assert (math.isnan(a[3]) and math.isnan(b[3])) or a[3] == b[3], step


SEGMENT = st.tuples(st.sampled_from(sorted(VALUES) + ["vars"]), st.integers(1, 2600))


@settings(max_examples=40, deadline=None)
@given(st.lists(SEGMENT, min_size=1, max_size=4))
def test_columns_equal_a_frame_by_frame_reading(segments):
    frames, expected = build(segments)
    same(columns_of(Trace.record(iter(frames), CODE, 128, 128)), expected)


@settings(max_examples=15, deadline=None)
@given(st.lists(SEGMENT, min_size=1, max_size=3), st.integers(1, 6000))
def test_the_cap_falls_anywhere(segments, cap):
    frames, expected = build(segments)
    trace = Trace.record(iter(frames), CODE, 128, 128, step_cap=cap)
    same(columns_of(trace), expected[:cap])
    assert trace.truncated == (len(frames) > cap)


@pytest.mark.parametrize("every", [1, 7, 1000, 5000])
def test_a_monitor_changes_nothing(every):
    frames, expected = build([("int", 3000), ("float", 2500), ("vars", 3), ("int", 1800)])
    heard = []
    trace = Trace.record(iter(frames), CODE, 128, 128, monitor=RecordMonitor(heard.append, every))
    same(columns_of(trace), expected)
    assert all(b - a >= every for a, b in zip(heard, heard[1:]))


def test_rich_records_keep_their_steps_after_a_long_plain_run():
    frames, _ = build([("int", 2500), ("vars", 2), ("int", 10)])
    trace = Trace.record(iter(frames), CODE, 128, 128)
    assert trace.steps_of().tolist() == [0, 2501, 2502]
    assert trace.variables_at(2502)["k"] == 1


@pytest.mark.parametrize("bad", [(1, 0, 0), (1, 0, 0, 1, 2), (1, "x", 0, 1), (-1, 0, 0, 1),
                                 (1, 2 ** 40, 0, 1), (70_000, 0, 0, 1), (1, 0, 0, (1,)),
                                 (1 << 24, 0, 0, 1)])
def test_a_bad_frame_after_a_long_plain_run_is_reported(bad):
    frames, _ = build([("int", 3000)])
    with pytest.raises(TraceError, match=r"is not \(line, x, y, value\)"):
        Trace.record(iter(frames + [bad] + frames[1:5]), CODE, 128, 128)


def test_a_line_beyond_the_code_after_a_long_plain_run_is_named():
    frames, _ = build([("int", 3000)])
    with pytest.raises(TraceError, match="step 3001: pseudo-code line 9 does not exist"):
        Trace.record(iter(frames + [(9, 0, 0, 1)]), CODE, 128, 128)


def test_a_bad_frame_is_reported_before_a_bad_record_after_it():
    frames, _ = build([("int", 3000)])
    with pytest.raises(TraceError, match=r"is not \(line, x, y, value\)"):
        Trace.record(iter(frames + [(1, 0, 0, 1, (1, 2, 3)), 7] + frames[1:5]), CODE, 128, 128)
