"""Long recordings run in a worker thread; the window stays responsive.

``Job`` runs one recording (``work(monitor) -> result``) in a Python
thread. The player waits for it a short while (``Player.sync_wait``) and
takes the result at once when it is ready, so small runs behave as if they
were recorded in place; longer ones go on in the background and the player
installs the trace when they end. The worker runs Python bytecode, so it
holds the interpreter lock most of the time; the main thread still gets it
back at every switch interval (see ``SWITCH_INTERVAL``).

``install_recording(window)`` adds "Recording… N steps", a busy progress
bar and the Cancel button (also Esc) to the status bar.
"""
from __future__ import annotations

import sys
import threading
import time

from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QKeySequence, QShortcut
from PySide6.QtWidgets import QLabel, QProgressBar, QPushButton

from algorithms.trace import CHUNK, Cancelled, RecordMonitor

# While a worker records, the interpreter hands the lock over at least this
# often (seconds; Python's default is 0.005). Painting the window calls into
# Python many times, each call waiting up to this long for the lock: at
# 2 ms the first repaint after an edit took 80-95 ms, at 0.5 ms 20-30 ms,
# with the recording no slower (flood fill of 1024 x 1024: 2.0-2.2 s).
SWITCH_INTERVAL = 0.0005
# Steps between progress reports and cancellation checks.
REPORT_EVERY = CHUNK
# The progress bar appears once a recording has run this long (ms), so that
# runs just longer than the player's wait do not make it flash.
SHOW_AFTER_MS = 150

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
    worker thread (the player turns them into queued Qt signals). After the
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
    """Call back into Qt from the worker; the receiver may be gone already
    (window closed while the run was finishing)."""
    try:
        callback(*args)
    except RuntimeError:
        pass


# ------------------------------------------------------------------ window
class RecordingStatus:
    """The status bar's progress bar and Cancel button, shown while a
    recording runs in the background."""

    def __init__(self, window):
        self.window = window
        player = window.player
        self.bar = QProgressBar(window)
        self.bar.setObjectName("recordingProgress")
        self.bar.setRange(0, 0)  # busy: the length of a run is not known in advance
        self.bar.setMaximumWidth(120)
        self.bar.setTextVisible(False)  # busy bars draw no text: the label says it
        tip = ("A long run is being recorded in the background; the previous run stays "
               "on show and can be stepped meanwhile.")
        self.bar.setToolTip(tip)
        self.label = QLabel(window)
        self.label.setObjectName("recordingSteps")
        self.label.setToolTip(tip)
        self.button = QPushButton("Cancel", window)
        self.button.setObjectName("cancelRecording")
        self.button.setToolTip("Stop the recording and keep the previous scene and run (Esc)")
        self.button.clicked.connect(player.cancel_recording)
        self.shortcut = QShortcut(QKeySequence("Esc"), window)
        self.shortcut.activated.connect(player.cancel_recording)
        # Should another Esc shortcut come on meanwhile, Qt calls the two ambiguous.
        self.shortcut.activatedAmbiguously.connect(player.cancel_recording)
        self._lent = []  # other Esc shortcuts, off while a recording runs
        self._delay = QTimer(window)
        self._delay.setSingleShot(True)
        self._delay.setInterval(SHOW_AFTER_MS)
        self._delay.timeout.connect(self._appear)
        status = window.statusBar()
        status.addPermanentWidget(self.label)
        status.addPermanentWidget(self.bar)
        status.addPermanentWidget(self.button)
        self._show(False)
        player.recordingStarted.connect(self._started)
        player.recordingProgress.connect(self._progressed)
        player.recordingFinished.connect(self._finished)

    def _show(self, on: bool) -> None:
        if on:
            self._delay.start()  # Esc works at once, the widgets come later
        else:
            self._delay.stop()
            self._appear(False)
        # Esc belongs to others otherwise (the grid, the pixel inspector).
        # Two enabled Esc shortcuts would be ambiguous and neither would
        # fire, so the others are off meanwhile. (An application event
        # filter would do it too, but calling Python for every event costs
        # the event loop a wait for the interpreter lock each time.)
        if on and not self.shortcut.isEnabled():
            self._lent = [other for other in self.window.findChildren(QShortcut)
                          if other is not self.shortcut and other.isEnabled()
                          and other.key() == self.shortcut.key()]
            for other in self._lent:
                other.setEnabled(False)
        elif not on:
            for other in self._lent:
                other.setEnabled(True)
            self._lent = []
        self.shortcut.setEnabled(on)

    def _appear(self, on: bool = True) -> None:
        self.bar.setVisible(on)
        self.label.setVisible(on)
        self.button.setVisible(on)

    def _started(self) -> None:
        self.label.setText("Recording\u2026")
        self._show(True)

    def _progressed(self, steps: int) -> None:
        self.label.setText(f"Recording\u2026 {steps:,} steps")

    def _finished(self, message: str) -> None:
        self._show(False)
        if message and self.window.player.spec is not None:
            # The scene went back (cancelled, refused) or was replaced by an
            # example shape: the editors follow the player again.
            self.window._scene_changed()
            self.window._say_error(message)


def install_recording(window) -> RecordingStatus:
    window.recording_status = RecordingStatus(window)
    return window.recording_status


def seek_when_recorded(player, index: int) -> None:
    """Go to step ``index`` now or, when the run is still recording in the
    background, as soon as its trace is installed (not if it is cancelled)."""
    if not player.recording:
        player.seek(index)
        return

    def go(message: str) -> None:
        player.recordingFinished.disconnect(go)
        if not message:
            player.seek(index)
    player.recordingFinished.connect(go)


class GapMeter:
    """How long the event loop goes between ticks of a fast timer: each
    tick adds (seconds since the last tick, when). What the responsiveness
    test asserts and the recording benchmark prints."""

    def __init__(self, interval_ms: int = 10):
        self.ticks: list[tuple[float, float]] = []
        self._last = time.perf_counter()
        self._timer = QTimer()
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.timeout.connect(self._tick)
        self._timer.start(interval_ms)

    def _tick(self) -> None:
        now = time.perf_counter()
        self.ticks.append((now - self._last, now))
        self._last = now

    def restart(self) -> float:
        """Forget the ticks so far; the next gap counts from now (returned)."""
        self.ticks.clear()
        self._last = time.perf_counter()
        return self._last

    def stop(self) -> None:
        self._timer.stop()

    def split(self, at: float) -> tuple[list[float], list[float]]:
        """The gaps that ended by ``at``, and those after it."""
        return ([gap for gap, when in self.ticks if when <= at],
                [gap for gap, when in self.ticks if when > at])

