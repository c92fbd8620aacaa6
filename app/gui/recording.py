"""The status bar while a long run records in the background
(``app.model.recording`` runs it): "Recording… N steps", a busy progress
bar and the Cancel button (also Esc).
"""
from __future__ import annotations

import time

from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QKeySequence, QShortcut
from PySide6.QtWidgets import QLabel, QProgressBar, QPushButton

# The progress bar appears once a recording has run this long (ms), so that
# runs just longer than the player's wait do not make it flash.
SHOW_AFTER_MS = 150


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
        player = self.window.player
        shown = tuple(tuple(p) for p in self.window.grid.points)
        if player.spec is not None and (message or shown != tuple(player.sketch.points)):
            # The scene went back (cancelled, refused) or was replaced by an
            # example shape (points too few for it, too): the editors follow
            # the player again. (The session's message listener shows the message.)
            self.window.follow_scene()


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

