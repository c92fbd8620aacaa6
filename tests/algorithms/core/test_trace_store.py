"""Lean storage of a trace: grown columns, pickled batches of rich records, the peak."""
import math
import pickle
import tracemalloc
from dataclasses import fields

import numpy as np
import pytest

from algorithms.core import trace_store
from algorithms.core.steps import CALC, NO_PIXEL, PLOT, CodeLine, Note, Span, Start, Table, Vars
from algorithms.core.trace import Trace
from algorithms.core.trace_store import Columns, Records

CODE = (CodeLine("start"), CodeLine("plot(x, y)", PLOT), CodeLine("set", CALC))


def test_columns_grown_chunk_by_chunk_equal_the_joined_chunks():
    dtype = np.dtype([("line", "u2"), ("x", "i4"), ("y", "i4"), ("v0", "f8"), ("v1", "f8")])
    rng = np.random.default_rng(1)
    chunks = []
    for size in (3, 0, 17, 100, 1, 250):
        chunk = np.zeros(size, dtype)
        for name in dtype.names:
            chunk[name] = rng.integers(0, 1000, size)
        chunks.append(chunk)
    columns = Columns(("v0", "v1"), 4)
    for chunk in chunks:
        columns.append(chunk)
    columns.finish()
    joined = np.concatenate(chunks)
    assert len(columns.line) == len(joined) == columns.count
    for name in ("line", "x", "y"):
        assert np.array_equal(getattr(columns, name), joined[name])
    assert np.array_equal(columns.values, np.stack([joined["v0"], joined["v1"]], axis=1))


def test_records_come_back_equal_across_batches(monkeypatch):
    monkeypatch.setattr(trace_store, "BATCH", 3)
    monkeypatch.setattr(trace_store, "CACHED_BATCHES", 1)
    records = Records()
    kept = [Vars(line=2, values={"k": k, "name": f"n{k}"}) for k in range(11)]
    kept[5] = Vars(line=2, values={"f": lambda: 1})  # does not pickle: kept as it is
    for record in kept:
        records.add(record)
    steps = np.arange(0, 110, 10)
    records.finish(steps)
    for step, record in zip(steps.tolist(), kept):
        got = records.get(step)
        assert got is record if step == 50 else got == record
        assert records.get(step + 1) is None
    picked = np.array([0, 1, 4, 9, 10])
    assert records.at_positions(picked)[:3] == [kept[0], kept[1], kept[4]]


def frames(steps: int, rich_every: int):
    yield Start(line=0, values=("v",))
    for k in range(1, steps):
        if rich_every and k % rich_every == 0:
            yield Note(line=2, text=f"note {k}") if k % 2 else Vars(line=2, values={"k": k})
        else:
            yield (1, k % 97, k // 97, float(k))


@pytest.mark.parametrize("rich_every", [0, 5, 300])
def test_mixed_streams_record_every_frame(rich_every):
    trace = Trace.record(frames(20_000, rich_every), CODE, 100, 300)
    expected = list(frames(20_000, rich_every))
    assert len(trace) == len(expected)
    for k in range(0, len(expected), 37):
        frame = expected[k]
        if isinstance(frame, tuple):
            assert (int(trace.line[k]), int(trace.x[k]), int(trace.y[k])) == frame[:3]
            assert trace.values[k, 0] == frame[3] and trace.record_at(k) is None
        else:
            assert trace.record_at(k) == frame and int(trace.line[k]) == frame.line
            assert k == 0 or math.isnan(trace.values[k, 0])


def test_recording_peak_stays_well_under_twice_what_is_kept():
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        trace = Trace.record(frames(300_000, 0), CODE, 100, 4000)
        kept, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    kept -= base
    assert kept >= trace.nbytes()
    # Growth by a quarter and one chunk on top; joining chunks at the end took 2.4x.
    assert (peak - base) < 1.6 * kept


RICH = [Start(line=0, values=("v", "w"), constants={"a": 1}, pixel_value="v", replaces=True),
        Vars(line=2, values={"k": 3, "q": 0.5}, pixel=(4, 5)),
        Table(line=2, name="AET", columns=("x", "dx"), rows=((1, 0.5), (2, -1.0)), pixel=(1, 2)),
        Note(line=2, text="a note", pixel=(7, 8), brief=True),
        Span(line=1, y=3, x_start=2, x_end=9, value=12.0)]


@pytest.mark.parametrize("record", RICH, ids=lambda r: type(r).__name__)
def test_rich_records_pickle_to_equal_records(record):
    # The state handed to pickle is the fields' values in declaration order,
    # which the dataclass's own __setstate__ reads back.
    assert record.__getstate__() == tuple(getattr(record, f.name) for f in fields(record))
    again = pickle.loads(pickle.dumps(record, pickle.HIGHEST_PROTOCOL))
    assert type(again) is type(record) and again == record


def test_runs_of_mixed_rich_records_come_back_in_step_order(monkeypatch):
    monkeypatch.setattr(trace_store, "BATCH", 4)  # many sealed (pickled) batches
    stream = [RICH[0]] + [RICH[1 + k % 4] if k % 3 else (1, k, 0, 1.0, 2.0) for k in range(1, 60)]
    trace = Trace.record(iter(stream), CODE, 64, 8)
    assert len(trace) == len(stream)
    for k, frame in enumerate(stream):
        if isinstance(frame, tuple):
            assert trace.record_at(k) is None and int(trace.x[k]) == k
        else:
            assert trace.record_at(k) == frame
            pixel = frame.pixel if k else None
            assert (int(trace.x[k]), int(trace.y[k])) == (pixel or (NO_PIXEL, NO_PIXEL))
    kinds = {type(r) for r in RICH[1:]}
    for kind in kinds:
        expected = [k for k, f in enumerate(stream) if type(f) is kind]
        assert trace.steps_of(kind).tolist() == expected
