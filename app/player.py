"""Playback: the recorded run of the current scene and the step shown.

``Player`` owns the scene (algorithm, points, options, grid), records it
into a ``Trace`` whenever any of those change, and moves the current step:
first, back, forward, last, seek, and timed play at a chosen speed.

Where the step goes after a re-recording
----------------------------------------
* If the old run was shown at its last step (or there was no run), the new
  run is shown at its last step too: dragging an end point of a finished
  line shows the finished line for the new position.
* Otherwise the step keeps its relative position in the run (half-way stays
  half-way), so a run being stepped through mid-way stays mid-way. Play goes
  on if it was on.

Comparison with the previous algorithm
--------------------------------------
When the algorithm changes, the one before it is remembered. From then on
every recording also records the remembered algorithm on the same points
and grid, and ``differences`` lists the cells where the two final results
differ, until the algorithm changes again or the comparison is turned off.

Play at high speed skips frames: each timer tick advances by as many steps
as the elapsed time and the speed call for, so the display never falls
behind.
"""
from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import QElapsedTimer, QObject, Qt, QTimer, Signal

from algorithms import registry
from algorithms.registry import InputError
from algorithms.raster import Raster, check_grid
from algorithms.trace import DEFAULT_STEP_CAP, FrameState, Trace


from .render import differences

MIN_SPEED = 1.0
MAX_SPEED = 2000.0
DEFAULT_SPEED = 8.0
# The timer never fires faster than this: about 60 frames a second.
MIN_TICK_MS = 16


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

    def __init__(self, parent=None, step_cap: int = DEFAULT_STEP_CAP):
        super().__init__(parent)
        self.step_cap = step_cap
        self.spec = None
        self.options: dict = {}
        self.points: list[tuple] = []
        self.grid = (32, 24)
        self.trace: Trace | None = None
        self.index = 0
        self.error = ""  # why the scene could not be recorded, if it could not
        self.compare_enabled = True
        self.previous = None  # (spec, options) of the algorithm before this one
        self.differences = np.zeros((0, 2), dtype=np.int64)
        self.compared = False  # did the last recording run the comparison?
        self._state: FrameState | None = None
        self._final: Raster | None = None
        self._speed = DEFAULT_SPEED
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.timeout.connect(self._tick)
        self._clock = QElapsedTimer()
        self._owed = 0.0  # fractional steps carried over between ticks

    # ------------------------------------------------------------- scene
    def set_scene(self, algorithm: str, points, options: dict | None = None,
                  grid=(32, 24)) -> None:
        """Replace the whole scene at once; raises InputError if it is bad.

        Nothing changes when the scene is rejected.
        """
        spec = registry.get(algorithm)
        width, height = _checked_grid(grid)
        resolved = spec.resolve(options)
        points = [tuple(p) for p in points]
        trace = self._record(spec, points, resolved, (width, height))
        self.spec, self.options, self.points, self.grid = spec, resolved, points, (width, height)
        self.previous = None
        self._install(trace, at_end=True)

    def set_algorithm(self, name: str) -> None:
        """Switch algorithm on the same points. Options the person changed
        from their defaults carry over to options of the same name and kind;
        the rest take the new algorithm's defaults.

        The algorithm switched away from becomes the one compared against.
        """
        spec = registry.get(name)
        if self.spec is not None and spec.name == self.spec.name:
            return
        carried = {}
        for option in spec.options:
            if option.name in self.options and self._same_option(option):
                try:
                    carried[option.name] = option.check(self.options[option.name])
                except InputError:
                    pass
        options = spec.resolve(carried)
        points = self._fit_points(self.points, spec)
        if not self._complete(points, spec):
            # Too few points for this algorithm: start it on a shape of its own.
            points = default_points(spec, self.grid)
        trace = self._record(spec, points, options, self.grid) if self._complete(points, spec) else None
        previous = (self.spec, dict(self.options)) if self.spec is not None else None
        self.spec, self.options, self.points = spec, options, points
        self.previous = previous
        self._install(trace, at_end=self._at_end())

    def set_option(self, name: str, value) -> None:
        """Set one option; raises InputError (and keeps the last good value)
        when the value is bad or the run rejects it."""
        option = self.spec.option(name)
        checked = option.check(value)
        if self.options.get(name) == checked:
            return
        options = dict(self.options, **{name: checked})
        trace = None
        if self._complete(self.points):
            trace = self._record(self.spec, self.points, options, self.grid)
        self.options = options
        self._install(trace, at_end=self._at_end())

    def set_points(self, points) -> None:
        """Set the points; fewer than the algorithm takes leaves no trace
        (the person is still placing them). Raises InputError on bad points."""
        points = [tuple(p) for p in points]
        if not open_ended(self.spec) and len(points) > self.spec.inputs.count:
            raise InputError(f"{self.spec.title} takes {self.spec.inputs.count} points, "
                             f"got {len(points)}")
        if points == self.points and self.trace is not None:
            return
        trace = None
        if self._complete(points):
            trace = self._record(self.spec, points, self.options, self.grid)
        at_end = self._at_end()
        self.points = points
        self._install(trace, at_end=at_end)

    def set_grid(self, width: int, height: int) -> None:
        """Resize the grid; points outside it are moved to its edge."""
        width, height = _checked_grid((width, height))
        if (width, height) == self.grid:
            return
        points = [_clamp(p, width, height, self.spec.inputs.integer) for p in self.points]
        trace = None
        if self._complete(points):
            trace = self._record(self.spec, points, self.options, (width, height))
        at_end = self._at_end()
        self.grid, self.points = (width, height), points
        self._install(trace, at_end=at_end)

    def set_compare(self, enabled: bool) -> None:
        self.compare_enabled = bool(enabled)
        self._compare()

    # --------------------------------------------------------- movement
    def __len__(self) -> int:
        return 0 if self.trace is None else len(self.trace)

    @property
    def last(self) -> int:
        return max(0, len(self) - 1)

    def seek(self, index: int) -> None:
        if self.trace is None:
            return
        index = min(max(int(index), 0), self.last)
        if index != self.index:
            self.index = index
            self._state = None
            self.frameChanged.emit(index)

    def step(self, delta: int) -> None:
        self.pause()
        self.seek(self.index + delta)

    def forward(self) -> None:
        self.step(1)

    def back(self) -> None:
        self.step(-1)

    def first(self) -> None:
        self.pause()
        self.seek(0)

    def to_last(self) -> None:
        self.pause()
        self.seek(self.last)

    def state(self) -> FrameState | None:
        """The replayed state at the current step (computed once per step)."""
        if self.trace is None:
            return None
        if self._state is None or self._state.index != self.index:
            self._state = self.trace.state_at(self.index)
        return self._state

    def final_raster(self) -> Raster | None:
        if self.trace is None:
            return None
        if self._final is None:
            self._final = self.trace.raster_at(len(self.trace) - 1)
        return self._final

    # -------------------------------------------------------------- play
    @property
    def speed(self) -> float:
        """Steps per second while playing."""
        return self._speed

    def set_speed(self, steps_per_second: float) -> None:
        speed = float(steps_per_second)
        if not math.isfinite(speed):
            raise InputError("the speed must be a finite number of steps per second")
        self._speed = min(max(speed, MIN_SPEED), MAX_SPEED)
        if self.playing:
            self._timer.setInterval(self._interval())

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
        return max(MIN_TICK_MS, int(1000.0 / self._speed))

    def _tick(self) -> None:
        elapsed = self._clock.restart() / 1000.0
        self._owed += elapsed * self._speed
        # At least one step a tick, so slow speeds move visibly on time.
        steps = max(1, int(self._owed))
        self._owed = max(0.0, self._owed - steps)
        target = min(self.index + steps, self.last)
        self.seek(target)
        if target >= self.last:
            self.pause()

    # --------------------------------------------------------- internals
    def _record(self, spec, points, options, grid) -> Trace:
        try:
            return spec.record(_as_input(spec, points), options, grid, step_cap=self.step_cap)
        except InputError:
            raise
        except Exception as error:  # noqa: BLE001 - a failing run must not end the program
            # A run that fails on this input is reported like a bad input:
            # the scene keeps its last good state and the program goes on.
            raise InputError(f"{spec.title} cannot run on this input "
                             f"({type(error).__name__}: {error})") from None

    def _install(self, trace: Trace | None, at_end: bool) -> None:
        old_len, old_index = len(self), self.index
        self.trace = trace
        self._state = None
        self._final = None
        if trace is None:
            self.pause()
            self.index = 0
        elif at_end or old_len < 2:
            self.index = len(trace) - 1
        else:
            fraction = old_index / (old_len - 1)
            self.index = min(len(trace) - 1, round(fraction * (len(trace) - 1)))
        if trace is not None and self.index >= len(trace) - 1:
            self.pause()
        self._compare(emit=False)
        self.traceChanged.emit()
        self.comparisonChanged.emit()
        self.frameChanged.emit(self.index)

    def _at_end(self) -> bool:
        return self.trace is None or self.index >= self.last

    def _complete(self, points, spec=None) -> bool:
        return complete(spec or self.spec, points)

    def _fit_points(self, points, spec):
        """The current points as the new algorithm takes them."""
        points = [_clamp(p, *self.grid, spec.inputs.integer) for p in points]
        if not open_ended(spec) and len(points) > spec.inputs.count:
            points = points[:spec.inputs.count]
        return points

    def _same_option(self, option) -> bool:
        """Is ``option`` also an option of the current algorithm, of the same
        kind, and set to something other than its default there?"""
        for old in self.spec.options:
            if old.name == option.name:
                return old.kind == option.kind and self.options.get(old.name) != old.default
        return False

    def _compare(self, emit: bool = True) -> None:
        result = np.zeros((0, 2), dtype=np.int64)
        self.compared = False
        if self.compare_enabled and self.previous is not None and self.trace is not None:
            spec, options = self.previous
            if complete(spec, self.points):
                try:
                    other = self._record(spec, self.points, options, self.grid)
                    result = differences(other.raster_at(len(other) - 1), self.final_raster())
                    self.compared = True
                except InputError:
                    pass  # the other algorithm does not take this input
        self.differences = result
        if emit:
            self.comparisonChanged.emit()

    @property
    def previous_title(self) -> str:
        return "" if self.previous is None else self.previous[0].title


def default_points(spec, grid) -> list[tuple]:
    """A pleasant first input for an algorithm on a grid: the centre for one
    point, a shallow segment for two, a slightly irregular polygon for more."""
    width, height = grid
    count = max(1, spec.inputs.count)
    integer = spec.inputs.integer
    if count == 1:
        raw = [(width / 2, height / 2)]
    elif count == 2:
        raw = [(width * 0.125, height * 0.21), (width * 0.875, height * 0.625)]
    else:
        raw = []
        for k in range(count):
            angle = math.radians(100 + 360 * k / count + (12 if k % 2 else 0))
            raw.append((width / 2 + 0.4 * width * math.cos(angle),
                        height / 2 + 0.4 * height * math.sin(angle)))
    if integer:
        return [_clamp((math.floor(x), math.floor(y)), width, height, True) for x, y in raw]
    # Real inputs: quarter pixels, clear of the pixel centres.
    return [_clamp((round(x * 4) / 4, round(y * 4) / 4), width, height, False) for x, y in raw]


def open_ended(spec) -> bool:
    """Does the algorithm take any number of points (a polygon's contour,
    k triangles) rather than exactly ``inputs.count``?"""
    inputs = spec.inputs
    return bool(getattr(inputs, "contours", False) or getattr(inputs, "multiple", False))


def complete(spec, points) -> bool:
    """Are there enough points, in a number the algorithm takes, to run it?"""
    inputs = spec.inputs
    if getattr(inputs, "contours", False):
        return len(points) >= inputs.count
    if getattr(inputs, "multiple", False):
        return len(points) > 0 and len(points) % inputs.count == 0
    return len(points) == inputs.count


def _as_input(spec, points):
    """The flat list of points in the shape the algorithm takes (one contour)."""
    return [list(points)] if getattr(spec.inputs, "contours", False) else list(points)


def _checked_grid(grid) -> tuple[int, int]:
    try:
        width, height = (int(v) for v in grid)
        check_grid(width, height)
    except (TypeError, ValueError) as error:
        raise InputError(str(error)) from None
    return width, height


def _clamp(point, width: int, height: int, integer: bool):
    x, y = point
    if integer:
        return (min(max(int(x), 0), width - 1), min(max(int(y), 0), height - 1))
    return (min(max(float(x), 0.0), float(width)), min(max(float(y), 0.0), float(height)))
