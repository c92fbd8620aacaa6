"""The session (app/model/session.py) as a Qt object: its news as Qt
signals, and timed play.

``Player`` forwards the scene, the trace and the step on show to its
``Session`` and adds play at a chosen speed. Play at high speed skips
frames: each timer tick advances by as many steps as the elapsed time and
the speed call for, so the display never falls behind. Play stops at the
end of the run and whenever a new trace is installed at its last step.

A run with animation frames (aa-temporal) plays at no more than
``flashes.playback_cap`` steps a second, SAFE_FPS animation frames a
second, whatever speed is chosen (WCAG 2.3.1): the chosen speed is kept and
shown, the effective one is ``effective_speed``, and ``speedCapped`` says
so when play starts, or the speed changes, above the cap.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QElapsedTimer, QObject, Qt, QTimer, Signal

from algorithms.core.registry import InputError
from algorithms.core.trace import DEFAULT_STEP_CAP

from app.gui.main_thread_gc import collect_in_main_thread
from app.model.session import Session
from app.render.flashes import cap_note, playback_cap

MIN_SPEED = 1.0
MAX_SPEED = 2000.0
DEFAULT_SPEED = 8.0
# The timer never fires faster than this: about 60 frames a second.
MIN_TICK_MS = 16


def _forward(name: str, settable: bool = False) -> property:
    """A property reading (and writing) the session's attribute ``name``."""
    def read(self):
        return getattr(self.session, name)

    def write(self, value):
        setattr(self.session, name, value)
    return property(read, write if settable else None, doc=f"The session's ``{name}``.")


class Player(QObject):
    """The current scene, its recorded trace and the step on show."""

    #: A new trace was recorded (or the trace was dropped: ``trace`` is None).
    traceChanged = Signal()
    #: The step on show changed (its index).
    frameChanged = Signal(int)
    #: Play started (True) or stopped (False).
    playingChanged = Signal(bool)
    #: The comparison result changed.
    comparisonChanged = Signal()
    #: A recording went on in the background (the previous trace stays on show).
    recordingStarted = Signal()
    #: Steps recorded so far by the background recording.
    recordingProgress = Signal(int)
    #: The background recording ended: "" when its trace was installed as
    #: asked, else why the scene is not the one asked for (cancelled,
    #: refused, an example shape instead).
    recordingFinished = Signal(str)
    #: Play goes slower than the speed chosen, lest the animation flash:
    #: the line saying so.
    speedCapped = Signal(str)
    # News from the recording worker, run in this object's thread.
    _posted = Signal(object)

    def __init__(self, parent=None, step_cap: int = DEFAULT_STEP_CAP):
        super().__init__(parent)
        collect_in_main_thread(self)  # the recording thread must never destroy Qt objects
        self._posted.connect(self._take_news)
        self.session = session = Session(step_cap, post=self._posted.emit)
        session.trace_changed.connect(self._trace_changed)
        session.step_changed.connect(self.frameChanged.emit)
        session.comparison_changed.connect(self.comparisonChanged.emit)
        session.recording_started.connect(self.recordingStarted.emit)
        session.recording_progress.connect(self.recordingProgress.emit)
        session.recording_finished.connect(self.recordingFinished.emit)
        self._speed = DEFAULT_SPEED
        self._cap = None  # the run's playback_cap, steps a second
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.timeout.connect(self._tick)
        self._clock = QElapsedTimer()
        self._owed = 0.0  # fractional steps carried over between ticks
        # Optional hook (app/gui/breakpoint_actions.py): stop_finder(index,
        # target) gives a frame in index+1 .. target where play must stop, or None.
        self.stop_finder = None

    # The session's state, read where the window shows it.
    scene = _forward("scene")
    spec = _forward("spec")
    options = _forward("options")
    points = _forward("points")
    breaks = _forward("breaks")
    sketch = _forward("sketch")
    grid = _forward("grid")
    trace = _forward("trace")
    index = _forward("index")
    last = _forward("last")
    previous = _forward("previous")
    previous_title = _forward("previous_title")
    differences = _forward("differences")
    compared = _forward("compared")
    refusal = _forward("refusal")
    shown_scene = _forward("shown_scene")
    trace_spec = _forward("trace_spec")
    recording = _forward("recording")
    step_cap = _forward("step_cap", settable=True)
    memory_limit = _forward("memory_limit", settable=True)
    max_grid = _forward("max_grid", settable=True)
    sync_wait = _forward("sync_wait", settable=True)
    stepper = _forward("stepper", settable=True)

    def __len__(self) -> int:
        return len(self.session)

    # ------------------------------------------------------------- edits
    def set_scene(self, algorithm: str, points, options: dict | None = None,
                  grid=(32, 24)) -> None:
        self.session.set_scene(algorithm, points, options, grid)

    def set_algorithm(self, name: str) -> None:
        self.session.set_algorithm(name)

    def set_option(self, name: str, value) -> None:
        self.session.set_option(name, value)

    def set_options(self, values: dict) -> None:
        self.session.set_options(values)

    def set_points(self, points, breaks=None) -> None:
        self.session.set_points(points, breaks)

    def draw(self, gesture) -> None:
        self.session.draw(gesture)

    def restore(self, points, breaks, options: dict, algorithm: str | None = None,
                grid=None) -> None:
        self.session.restore(points, breaks, options, algorithm, grid)

    def set_grid(self, width: int, height: int) -> None:
        self.session.set_grid(width, height)

    def set_compare(self, enabled: bool) -> None:
        self.session.set_compare(enabled)

    def input_points(self):
        return self.session.input_points()

    def state(self):
        return self.session.state()

    def final_raster(self):
        return self.session.final_raster()

    def cancel_recording(self) -> None:
        self.session.cancel_recording()

    def stop_recording(self, timeout: float = 2.0) -> None:
        self.session.stop_recording(timeout)

    # --------------------------------------------------------- movement
    def seek(self, index: int) -> None:
        self.session.seek(index)

    def step(self, delta: int) -> None:
        self.pause()
        self.session.step(delta)

    def forward(self) -> None:
        self.step(1)

    def back(self) -> None:
        self.step(-1)

    def first(self) -> None:
        self.pause()
        self.session.first()

    def to_last(self) -> None:
        self.pause()
        self.session.to_last()

    def _take_news(self, news) -> None:
        """Run what the recording worker posted, here in this object's thread."""
        news()

    def _trace_changed(self) -> None:
        capped = self.capped
        self._cap = None if self.trace is None else playback_cap(self.trace_spec, self.trace)
        if self.trace is None or self.index >= self.last:
            self.pause()
        elif self.playing:
            self._speed_changed(capped)
        self.traceChanged.emit()

    # -------------------------------------------------------------- play
    @property
    def speed(self) -> float:
        """Steps per second while playing."""
        return self._speed

    def set_speed(self, steps_per_second: float) -> None:
        speed = float(steps_per_second)
        if not math.isfinite(speed):
            raise InputError("the speed must be a finite number of steps per second")
        capped = self.capped
        self._speed = min(max(speed, MIN_SPEED), MAX_SPEED)
        if self.playing:
            self._speed_changed(capped)

    @property
    def speed_cap(self) -> float | None:
        """The most steps a second the run on show plays at (None: no limit)."""
        return self._cap

    @property
    def capped(self) -> bool:
        """Is the chosen speed above the run's cap?"""
        return self._cap is not None and self._speed > self._cap

    @property
    def effective_speed(self) -> float:
        """Steps per second play goes at: the speed, held to the cap."""
        return min(self._speed, self._cap) if self.capped else self._speed

    @property
    def interval(self) -> int:
        """Milliseconds between two timer ticks of play."""
        return self._timer.interval()

    def _speed_changed(self, was_capped: bool) -> None:
        """While playing: retime the ticks, and say so when the cap newly applies."""
        self._timer.setInterval(self._interval())
        if self.capped and not was_capped:
            self.speedCapped.emit(cap_note(self._cap))

    @property
    def playing(self) -> bool:
        return self._timer.isActive()

    def play(self) -> None:
        if self.playing or self.trace is None or len(self.trace) < 2:
            return
        if self.index >= self.last:
            self.seek(0)  # play from the start when the run is already over
        self._owed = 0.0
        self._clock.start()
        self._timer.start(self._interval())
        self.playingChanged.emit(True)
        if self.capped:
            self.speedCapped.emit(cap_note(self._cap))

    def pause(self) -> None:
        if self.playing:
            self._timer.stop()
            self.playingChanged.emit(False)

    def toggle(self) -> None:
        if self.playing:
            self.pause()
        else:
            self.play()

    def _interval(self) -> int:
        return max(MIN_TICK_MS, int(1000.0 / self.effective_speed))

    def _tick(self) -> None:
        elapsed = self._clock.restart() / 1000.0
        self._owed += elapsed * self.effective_speed
        # At least one step a tick, so slow speeds move visibly on time.
        steps = max(1, int(self._owed))
        self._owed = max(0.0, self._owed - steps)
        target = min(self.index + steps, self.last)
        stop = None if self.stop_finder is None else self.stop_finder(self.index, target)
        if stop is not None:
            self.seek(stop)
            self.pause()
            return
        self.seek(target)
        if target >= self.last:
            self.pause()
