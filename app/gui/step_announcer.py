"""A step said to a screen reader (WCAG 4.1.3, status messages).

When a person moves to another step (the step keys, the transport's
buttons, the slider, Home and End), the step's description in words
(``app/model/step_words.py``) goes to assistive technology: as Qt's
accessibility announcement where this Qt has one (QAccessibleAnnouncementEvent,
Qt 6.8 and later), and always into the status bar, which a screen reader
reads on request (and, without the announcement, is told has changed).
Playback says nothing: a reader would fall behind and talk over the
lecture. *View > Describe step* (Ctrl+D) says the step on show at any time.
"""
from __future__ import annotations

from PySide6 import QtGui
from PySide6.QtCore import QObject, QTimer, Signal
from PySide6.QtGui import QAccessible, QAccessibleEvent, QAction, QKeySequence

from app.model.step_words import describe

# None on a Qt without accessibility announcements: the status bar alone speaks.
EVENT = getattr(QtGui, "QAccessibleAnnouncementEvent", None)
SETTLE_MS = 150  # a drag of the slider is said once, where it stops
SHOWN_MS = 15000  # how long the description stays in the status bar


class StepAnnouncer(QObject):
    """Says the step on show when a person changes it, and on demand."""

    #: (text, how): what was said and how, "announcement" or "status".
    announced = Signal(str, str)

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.action = QAction("&Describe step", window)
        self.action.setShortcut(QKeySequence("Ctrl+D"))
        self.action.setToolTip("Say what the step on show does, in words, to a screen reader "
                               "and in the status bar (Ctrl+D)")
        self.action.triggered.connect(self.describe_now)
        window.menus["view"].addAction(self.action)
        window.addAction(self.action)
        self._settle = QTimer(self, singleShot=True, interval=SETTLE_MS)
        self._settle.timeout.connect(self.describe_now)
        self._trace = window.player.trace
        window.player.frameChanged.connect(self._frame_changed)
        window.player.traceChanged.connect(self._trace_changed)
        # Play from the end first goes back to step 0: not a step to say.
        window.player.playingChanged.connect(self._playing_changed)

    def text(self) -> str:
        """The step on show in words ("" when there is no run)."""
        player = self.window.player
        if player.trace is None:
            return ""
        return describe(player.trace, player.index, self.window.numbers.numbers)

    def describe_now(self) -> str:
        """Say the step on show; the text said."""
        text = self.text()
        if text:
            self.say(text)
        return text

    def say(self, text: str) -> None:
        self.window.statusBar().showMessage(text, SHOWN_MS)
        status = self.window.statusBar()
        if EVENT is not None:
            QAccessible.updateAccessibility(EVENT(self.window, text))
            how = "announcement"
        else:
            # Without an announcement, a reader that follows the status bar
            # is told its text changed.
            QAccessible.updateAccessibility(QAccessibleEvent(status, QAccessible.Event.NameChanged))
            how = "status"
        self.announced.emit(text, how)

    def _frame_changed(self, _index: int) -> None:
        player = self.window.player
        # Playback is not a person's step, nor the step a new run is shown
        # at (the session says the step after the new trace).
        if player.trace is not self._trace:
            self._trace = player.trace
            return
        if player.playing:
            self._settle.stop()
        else:
            self._settle.start()

    def _trace_changed(self) -> None:
        self._settle.stop()

    def _playing_changed(self, playing: bool) -> None:
        if playing:
            self._settle.stop()
