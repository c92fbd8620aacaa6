"""A recording's monitor: progress every so many steps, cancellation."""
import numpy as np
import pytest

from algorithms.core.steps import CALC, CodeLine, Note, Start, Vars
from algorithms.core.trace import Cancelled, RecordMonitor, Trace
from tests.support import record

STEPS = 100_000
P, Q = (0, 0), (STEPS - 1, 3 * (STEPS - 1) // 10)
LINE = ("line-bresenham", [P, Q])
GRID = (4096, 4096)


def test_progress_comes_every_so_many_steps_and_changes_nothing():
    heard = []
    every = 10_000
    trace = record(*LINE, grid=GRID, monitor=RecordMonitor(heard.append, every))
    plain = record(*LINE, grid=GRID)
    assert len(trace) == len(plain)
    # An x-major segment writes one pixel per column, in order.
    assert np.array_equal(trace.written_pixels()[:, 0], np.arange(STEPS))
    assert np.array_equal(trace.x, plain.x) and np.array_equal(trace.y, plain.y)
    assert heard == sorted(heard) and heard[-1] <= len(trace)
    # At least one report per ``every`` steps recorded, none closer than that.
    assert len(heard) >= STEPS // every - 1
    assert all(b - a >= every for a, b in zip(heard, heard[1:]))


def test_cancel_stops_the_recording_at_the_next_report():
    heard = []
    monitor = RecordMonitor(None, every=5_000)

    def progress(steps):
        heard.append(steps)
        monitor.cancel()
    monitor.progress = progress
    with pytest.raises(Cancelled):
        record(*LINE, grid=GRID, monitor=monitor)
    assert len(heard) == 1 and monitor.cancelled


def test_a_monitor_cancelled_before_the_start_records_nothing_long():
    monitor = RecordMonitor(every=1_000)
    monitor.cancel()
    # heard while the run checks its points, or after the first (small) chunk
    with pytest.raises(Cancelled, match=r"cancelled (between two steps|after (\d{1,3}|1,\d{3}) "
                                        r"steps)"):
        record(*LINE, grid=GRID, monitor=monitor)


def test_a_cancel_is_heard_within_a_run_of_rich_records():
    # Rich records only (as the scan-line fill yields): the cancel, made
    # here by the run itself as another thread would, stops the recording
    # after the record during which it came, long before a report is due.
    monitor = RecordMonitor(every=1_000_000)
    yielded = []

    def frames():
        yield Start(line=0, values=())
        for k in range(100_000):
            if k == 50:
                monitor.cancel()
            yielded.append(k)
            yield Vars(line=1, values={"k": k}) if k % 2 else Note(line=1, text=str(k))

    code = (CodeLine("start"), CodeLine("set", CALC))
    with pytest.raises(Cancelled):
        Trace.record(frames(), code, 8, 8, monitor=monitor)
    assert len(yielded) <= 52
