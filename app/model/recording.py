"""Long recordings run in a worker thread, so that whoever waits for them
(the window, a script) stays responsive.

``Job`` runs one recording (``work(monitor) -> result``) in a Python
thread. The session waits for it a short while (``Session.sync_wait``) and
takes the result at once when it is ready, so small runs behave as if they
were recorded in place; longer ones go on in the background and the session
installs the trace when they end. The worker runs Python bytecode, so it
holds the interpreter lock most of the time; the main thread still gets it
back at every switch interval (see ``SWITCH_INTERVAL``).
"""
from __future__ import annotations

import sys
import threading
import time

from algorithms.core.trace import Cancelled, RecordMonitor

# While a worker records, the interpreter hands the lock over at least this
# often (seconds; Python's default is 0.005). Painting the window calls into
# Python many times, each call waiting up to this long for the lock: at
# 2 ms the first repaint after an edit took 80-95 ms, at 0.5 ms 20-30 ms,
# with the recording no slower (flood fill of 1024 x 1024: 2.0-2.2 s).
SWITCH_INTERVAL = 0.0005
# Steps between progress reports and cancellation checks: small enough that
# Cancel stops the slowest steps (a z-buffer's, about 11 us) within 100 ms
# (65,536 steps took up to 640 ms there), large enough to cost nothing
# measurable per step.
REPORT_EVERY = 4096

_switch_lock = threading.Lock()
_running = 0
_saved_interval = None


def _enter_switching() -> None:
    global _running, _saved_interval
    with _switch_lock:
        if _running == 0:
            _saved_interval = sys.getswitchinterval()
            sys.setswitchinterval(min(_saved_interval, SWITCH_INTERVAL))
        _running += 1


def _leave_switching() -> None:
    global _running
    with _switch_lock:
        _running -= 1
        if _running == 0 and _saved_interval is not None:
            sys.setswitchinterval(_saved_interval)


class Job:
    """One recording in a daemon thread.

    ``on_progress(job, steps)`` and ``on_done(job)`` are called from the
    worker thread (the session hands them to its own thread). After the
    job is done, ``cancelled`` is True if it was cancelled (even just after
    its work ended); otherwise ``error`` or ``result`` holds the outcome.
    """

    def __init__(self, work, on_progress=None, on_done=None, every: int = REPORT_EVERY):
        self.work = work
        self.result = None
        self.error: BaseException | None = None
        self.cancelled = False
        self.finished_at = None  # time.perf_counter() when the work ended
        self._on_progress = on_progress
        self._on_done = on_done
        self.monitor = RecordMonitor(self._progress, every)
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._run, name="recording", daemon=True)

    def start(self) -> "Job":
        _enter_switching()
        self._thread.start()
        return self

    def wait(self, timeout: float | None) -> bool:
        """Wait up to ``timeout`` seconds (None: until done); is the job done?"""
        return self._done.wait(timeout)

    @property
    def done(self) -> bool:
        return self._done.is_set()

    def cancel(self) -> None:
        self.monitor.cancel()

    def _progress(self, steps: int) -> None:
        if self._on_progress is not None:
            _quietly(self._on_progress, self, steps)

    def _run(self) -> None:
        try:
            self.result = self.work(self.monitor)
        except Cancelled:
            self.cancelled = True
        except BaseException as error:  # noqa: BLE001 - handed to the main thread
            self.error = error
        finally:
            if self.monitor.cancelled:
                self.cancelled = True
            _leave_switching()
            self.finished_at = time.perf_counter()
            self._done.set()
            if self._on_done is not None:
                _quietly(self._on_done, self)


def _quietly(callback, *args) -> None:
    """Call back from the worker; a Qt receiver may be gone already
    (window closed while the run was finishing)."""
    try:
        callback(*args)
    except RuntimeError:
        pass
