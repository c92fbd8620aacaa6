"""Progress and cancellation of a recording, and the work a run may do.

A recording reports to its ``RecordMonitor``; the run's own code, while it
is made and recorded, can ask ``checkpoint()`` whether it was cancelled and
``work_allowance()`` how much plain work its step cap allows.
"""
from __future__ import annotations

import threading
from contextlib import contextmanager

DEFAULT_STEP_CAP = 5_000_000
CHUNK = 1 << 16  # steps between progress reports


class Cancelled(Exception):
    """A recording was stopped through its monitor before the run ended."""


class RecordMonitor:
    """Progress and cancellation of one recording, safe to share between threads.

    ``Trace.record`` calls ``report(steps)`` about every ``every`` steps (at
    the end of a bulk chunk, so the check costs nothing per frame);
    ``report`` raises ``Cancelled`` once ``cancel()`` has been called, from
    any thread, and otherwise passes the count to ``progress``.
    """

    def __init__(self, progress=None, every: int = CHUNK):
        self.progress = progress
        self.every = max(1, int(every))
        self._cancelled = threading.Event()

    def cancel(self) -> None:
        self._cancelled.set()

    @property
    def cancelled(self) -> bool:
        return self._cancelled.is_set()

    def report(self, steps: int) -> None:
        if self._cancelled.is_set():
            raise Cancelled(f"recording cancelled after {steps:,} steps")
        if self.progress is not None:
            self.progress(steps)


_watched = threading.local()


@contextmanager
def watching(monitor: RecordMonitor | None, step_cap: int | None = None):
    """While a run's own code works for ``monitor`` (made, then recorded),
    ``checkpoint()`` answers to it, and ``work_allowance()`` is ``step_cap``
    (when given)."""
    before = getattr(_watched, "monitor", None), getattr(_watched, "cap", None)
    _watched.monitor = monitor
    if step_cap is not None:
        _watched.cap = step_cap
    try:
        yield
    finally:
        _watched.monitor, _watched.cap = before


# Units of plain work (an edge tested in a row, a pixel passed over) a step
# is worth: a recorded flood-fill step (about 0.7 us) costs about as much as
# two of them.
WORK_PER_STEP = 2


def work_allowance() -> int:
    """The units of work the step cap of the run being made or recorded
    allows (the default cap outside one). Long work a run does between two
    frames (a search, pixels passed over as already drawn) counts against
    it, so the cap bounds all of a run's work, not only the steps it keeps."""
    cap = getattr(_watched, "cap", None)
    return WORK_PER_STEP * (DEFAULT_STEP_CAP if cap is None else cap)


def checkpoint() -> None:
    """Long work of a run between two frames (before its first, say) calls
    this now and then: it raises Cancelled once the recording it serves is
    cancelled, so a cancel need not wait for the next frame."""
    monitor = getattr(_watched, "monitor", None)
    if monitor is not None and monitor.cancelled:
        raise Cancelled("recording cancelled between two steps")
