"""Plain frames recorded the fast way (lists packed by marshal or struct) give the columns
a frame-by-frame reading gives, wherever the run turns to floats, huge
integers, NumPy numbers or rich records, and wherever the step cap falls."""
import math
import time
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
    # either side of the 32-bit ints marshal writes in fixed cells
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


@settings(max_examples=40)
@given(st.lists(SEGMENT, min_size=1, max_size=4))
def test_columns_equal_a_frame_by_frame_reading(segments):
    frames, expected = build(segments)
    same(columns_of(Trace.record(iter(frames), CODE, 128, 128)), expected)


@settings(max_examples=15)
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


def test_rich_records_keep_their_steps_after_a_packed_run():
    frames, _ = build([("int", 2500), ("vars", 2), ("int", 10)])
    trace = Trace.record(iter(frames), CODE, 128, 128)
    assert trace.steps_of().tolist() == [0, 2501, 2502]
    assert trace.variables_at(2502)["k"] == 1


@pytest.mark.parametrize("bad", [(1, 0, 0), (1, 0, 0, 1, 2), (1, "x", 0, 1), (-1, 0, 0, 1),
                                 (1, 2 ** 40, 0, 1), (70_000, 0, 0, 1), (1, 0, 0, (1,)),
                                 (1 << 24, 0, 0, 1)])
def test_a_bad_frame_after_a_packed_run_is_reported(bad):
    frames, _ = build([("int", 3000)])
    with pytest.raises(TraceError, match=r"is not \(line, x, y, value\)"):
        Trace.record(iter(frames + [bad] + frames[1:5]), CODE, 128, 128)


def test_a_line_beyond_the_code_after_a_packed_run_is_named():
    frames, _ = build([("int", 3000)])
    with pytest.raises(TraceError, match="step 3001: pseudo-code line 9 does not exist"):
        Trace.record(iter(frames + [(9, 0, 0, 1)]), CODE, 128, 128)


def test_a_nested_tuple_that_fills_the_cells_of_two_frames_is_refused():
    # marshal writes this pair in the cells of two plain frames: the tags
    # match, only the tuples' lengths tell them apart
    frames, _ = build([("int", 3000)])
    with pytest.raises(TraceError, match=r"is not \(line, x, y, value\)"):
        Trace.record(iter(frames + [(1, 0, 0, 1, (1, 2, 3)), 7] + frames[1:5]), CODE, 128, 128)


def test_recordings_in_threads_do_not_share_a_packing_buffer(monkeypatch):
    # Finished recordings hand their buffer on; two at once must each get their own.
    from concurrent.futures import ThreadPoolExecutor

    from algorithms.core import trace_store
    monkeypatch.setattr(trace_store, "_spare_buffers", [])  # buffers the size of these runs
    def shifted(n):
        """Frames of run n, each run's pixels apart from the others'."""
        frames, expected = build([("int", 1500 + 300 * n), ("edge32", 40)])
        moved = [(line, x, y + 100 * n, *rest) for line, x, y, *rest in expected[1:]]
        return frames[:1] + [(line, x, y, int(v)) for line, x, y, v in moved], expected[:1] + moved

    runs = [shifted(n) for n in range(4)]

    def yielding(frames):
        for k, frame in enumerate(frames):
            if k % 50 == 0:
                time.sleep(0)  # let another thread pack into its buffer meanwhile
            yield frame

    def record(n):
        frames, expected = runs[n % 4]
        return columns_of(Trace.record(yielding(frames), CODE, 128, 128)), expected

    with ThreadPoolExecutor(4) as pool:
        for got, expected in pool.map(record, range(64)):
            same(got, expected)


# Items of frames that marshal writes in cells of other sizes, or in 5-byte
# cells that are not ints, or ints a frame's columns cannot take as they are.
ITEMS = st.one_of(st.integers(-2 ** 31, 2 ** 31 - 1), st.integers(-2 ** 40, 2 ** 40),
                  st.sampled_from([True, False, None, 0.5, (), (1,), (1, 2, 3), "i"]),
                  st.integers(0, 3).map(lambda n: tuple(range(n))))
SMALL = st.integers(-9, 9)
LINES = st.one_of(st.integers(0, 70_000), st.integers(-2 ** 31, 2 ** 31 - 1),
                  st.sampled_from([-1, 65_535, 65_536, 1 << 24, (1 << 24) + 5]))
PLAIN = st.tuples(st.integers(0, 9), SMALL, SMALL, st.integers(-2 ** 31, 2 ** 31 - 1))
# Runs of frames: a plain one, a near one, or a frame with a tuple nested
# after its values and a bare int, which marshal writes in two frames' cells.
RUNS = st.one_of(
    PLAIN.map(lambda frame: [frame]),
    st.tuples(LINES, ITEMS, ITEMS, ITEMS).map(lambda frame: [frame]),
    st.tuples(LINES, SMALL, SMALL, SMALL).map(lambda frame: [frame]),
    st.lists(ITEMS, min_size=0, max_size=6).map(lambda items: [tuple(items)]),
    ITEMS.map(lambda item: [item]),
    st.tuples(SMALL, SMALL, SMALL, SMALL, st.tuples(SMALL, SMALL, SMALL), SMALL).map(
        lambda t: [t[:5], t[5]]))


def plain(frame, k):
    """Whether the frame is k + 3 ints of 32 bits with a line the column holds."""
    return (type(frame) is tuple and len(frame) == k + 3
            and all(type(v) is int and -2 ** 31 <= v < 2 ** 31 for v in frame)
            and 0 <= frame[0] <= 65535)


@settings(max_examples=300)
@given(st.lists(RUNS, max_size=8))
def test_the_marshal_layout_packs_exactly_the_plain_frames(runs):
    frames = [frame for run in runs for frame in run]
    from algorithms.core.trace_store import _pack_formats
    pack, dtype = _pack_formats(1)[0]
    packed = pack(frames)
    if not all(plain(frame, 1) for frame in frames):
        assert packed is None
        return
    rows = np.frombuffer(packed, dtype)
    got = list(zip(rows["line"].tolist(), rows["x"].tolist(), rows["y"].tolist(),
                   rows["v0"].tolist()))
    assert got == frames
