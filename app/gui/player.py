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

Points, contours and shapes still being drawn
---------------------------------------------
``points`` is always one flat list; ``breaks`` holds the indices where a
new contour starts (polygons with holes, several fill outlines), so that
the grid, the points editor and the undo history all deal with one list.
While a person is still drawing, the run uses only what is complete: the
contours that have enough vertices, the whole triangles among 3k + 1 or
3k + 2 points. The rest stays on the grid as handles until it is finished.

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
import os
from dataclasses import dataclass, replace

import numpy as np
from PySide6.QtCore import QElapsedTimer, QObject, Qt, QTimer, Signal

from algorithms import registry
from algorithms.registry import InputError
from algorithms.raster import MAX_GRID, Raster, check_grid
from algorithms.trace import DEFAULT_STEP_CAP, Cancelled, FrameState, Trace


from app.model.inputs import clean_breaks, complete, contour_sizes, flatten, runnable_input
from app.gui.recording import Job
from app.render.compose import differences

# How long an edit waits for its recording before it goes on in the
# background (seconds); RASTERLAB_RECORD_WAIT overrides it ("inf": always
# wait, as the tests do).
SYNC_WAIT = 0.02
CANCELLED_MESSAGE = "Recording cancelled: the previous scene and run are kept."

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
    #: A recording went on in the background (the previous trace stays on show).
    recordingStarted = Signal()
    #: Steps recorded so far by the background recording.
    recordingProgress = Signal(int)
    #: The background recording ended: "" when its trace was installed as
    #: asked, else why the scene is not the one asked for (cancelled,
    #: refused, an example shape instead).
    recordingFinished = Signal(str)
    # From the worker thread (queued to this object's thread).
    _jobProgress = Signal(object, int)
    _jobDone = Signal(object)

    def __init__(self, parent=None, step_cap: int = DEFAULT_STEP_CAP):
        super().__init__(parent)
        self.sync_wait = _sync_wait()
        self._job: Job | None = None  # the background recording, if one runs
        self._job_at_end = None
        self._shown = None  # the scene the trace on show belongs to, while a job runs
        self._jobProgress.connect(self._job_progressed)
        self._jobDone.connect(self._job_done)
        self.step_cap = step_cap
        # The largest grid side accepted (a preference, at most MAX_GRID).
        self.max_grid = MAX_GRID
        self.spec = None
        self.options: dict = {}
        self.points: list[tuple] = []
        self.breaks: tuple[int, ...] = ()  # where contours 2, 3, ... start in points
        self.grid = (32, 24)
        self.trace: Trace | None = None
        self.index = 0
        self.error = ""  # why the scene could not be recorded, if it could not
        self.compare_enabled = True
        self.previous = None  # (spec, options) of the algorithm before this one
        self.differences = np.zeros((0, 2), dtype=np.int64)
        self.compared = False  # did the last recording run the comparison?
        self.refusal = ""  # why the last algorithm switch fell back to an example shape
        self._state: FrameState | None = None
        self._final: Raster | None = None
        self._speed = DEFAULT_SPEED
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.timeout.connect(self._tick)
        self._clock = QElapsedTimer()
        self._owed = 0.0  # fractional steps carried over between ticks
        # Optional hooks (app/gui/breakpoint_actions.py): stepper(index, delta)
        # gives where a step of delta units goes (None: nowhere);
        # stop_finder(index, target) gives a frame in index+1 .. target
        # where play must stop, or None.
        self.stepper = None
        self.stop_finder = None

    # ------------------------------------------------------------- scene
    def set_scene(self, algorithm: str, points, options: dict | None = None,
                  grid=(32, 24)) -> None:
        """Replace the whole scene at once; raises InputError if it is bad.

        Nothing changes when the scene is rejected.
        """
        spec = registry.get(algorithm)
        width, height = _checked_grid(grid, self.max_grid)
        resolved = spec.resolve(options)
        points, breaks = flatten(spec, points)
        self._change(_Scene(spec, resolved, points, breaks, (width, height), None),
                     at_end=True, always=True)

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
        points, breaks = self._fit_points(spec)
        self.refusal = ""  # set again when the run ends (here or in the background)
        previous = (self.spec, dict(self.options)) if self.spec is not None else None
        scene = _Scene(spec, options, points, breaks, self.grid, previous)

        def work(monitor):
            refusal = ""
            if complete(spec, points, breaks):
                try:
                    return self._outcome(scene, monitor, refusal="")
                except InputError as error:
                    # The algorithm refuses this shape (a concave polygon for
                    # the convex fill, say): show its own example and say why.
                    refusal = str(error)
            shape, shape_breaks, defaults = default_scene(spec, scene.grid)
            example = replace(scene, points=shape, breaks=shape_breaks,
                              options=spec.resolve({**carried, **defaults}))
            try:
                return self._outcome(example, monitor, refusal=refusal)
            except InputError as error:
                # A carried option this run refuses (one colour set while the
                # points were being placed, say) must not block the switch.
                example = replace(example, options=spec.resolve(defaults))
                return self._outcome(example, monitor, refusal=refusal or str(error))
        self._change(scene, work=work, always=True)

    def set_option(self, name: str, value) -> None:
        """Set one option; raises InputError (and keeps the last good value)
        when the value is bad or the run rejects it."""
        self.set_options({name: value})

    def set_options(self, values: dict) -> None:
        """Set several options with one recording (an ellipse's rx and ry
        dragged together); all or none of them change."""
        checked = {name: self.spec.option(name).check(value) for name, value in values.items()}
        if all(self.options.get(name) == value for name, value in checked.items()):
            return
        self._change(replace(self._scene(), options=dict(self.options, **checked)))

    def set_points(self, points, breaks=None) -> None:
        """Set the points (and, for contour inputs, where each contour
        starts; None keeps the breaks that still fit). Fewer points than the
        algorithm takes leave no trace (the person is still placing them).
        Raises InputError on bad points; nothing changes then."""
        points = [tuple(p) for p in points]
        if not open_ended(self.spec) and len(points) > self.spec.inputs.count:
            raise InputError(f"{self.spec.title} takes {self.spec.inputs.count} points, "
                             f"got {len(points)}")
        breaks = clean_breaks(self.spec, len(points), self.breaks if breaks is None else breaks)
        if points == self.points and breaks == self.breaks and self.trace is not None:
            return
        self._change(replace(self._scene(), points=points, breaks=breaks))

    def restore(self, points, breaks, options: dict, algorithm: str | None = None,
                grid=None) -> None:
        """Put back points, breaks and options together (undo), and the
        algorithm and grid when given; raises InputError and changes
        nothing when the run refuses them. The step keeps its place."""
        spec = self.spec if algorithm is None else registry.get(algorithm)
        grid = self.grid if grid is None else _checked_grid(grid, self.max_grid)
        points = [tuple(p) for p in points]
        options = spec.resolve(options)
        breaks = clean_breaks(spec, len(points), breaks)
        previous = self.previous if spec is self.spec else (self.spec, dict(self.options))
        self._change(_Scene(spec, options, points, breaks, grid, previous))

    def input_points(self):
        """The points as the algorithm takes them (a list of contours for
        polygon inputs), without anything still being drawn."""
        return runnable_input(self.spec, self.points, self.breaks)

    def set_grid(self, width: int, height: int) -> None:
        """Resize the grid; points outside it are moved to its edge."""
        width, height = _checked_grid((width, height), self.max_grid)
        if (width, height) == self.grid:
            return
        points = [_clamp(p, width, height, self.spec.inputs.integer) for p in self.points]
        self._change(replace(self._scene(), points=points, grid=(width, height)))

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
        if self.stepper is not None and self.trace is not None:
            target = self.stepper(self.index, delta)
            if target is not None:
                self.seek(target)
            return
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
        stop = None if self.stop_finder is None else self.stop_finder(self.index, target)
        if stop is not None:
            self.seek(stop)
            self.pause()
            return
        self.seek(target)
        if target >= self.last:
            self.pause()

    # --------------------------------------------------------- internals
    def _record(self, spec, points, options, grid, breaks=(), monitor=None) -> Trace:
        try:
            trace = spec.record(runnable_input(spec, points, breaks), options, grid,
                                step_cap=self.step_cap, monitor=monitor)
        except (InputError, Cancelled):
            raise
        except Exception as error:  # noqa: BLE001 - a failing run must not end the program
            # A run that fails on this input is reported like a bad input:
            # the scene keeps its last good state and the program goes on.
            raise InputError(f"{spec.title} cannot run on this input "
                             f"({type(error).__name__}: {error})") from None
        if trace.truncated:
            # In the window the cap is a preference: name where to raise it.
            trace.message = (f"Recording stopped at the step cap of {self.step_cap:,} steps; "
                             "the run goes on beyond it. Raise \"Step cap\" in "
                             "Edit > Preferences or use a smaller input.")
        return trace

    # The scene as one value, so that a recording can run on a copy of it
    # and the scene on show can be put back when the recording is cancelled.
    def _scene(self) -> "_Scene":
        return _Scene(self.spec, self.options, self.points, self.breaks, self.grid,
                      self.previous)

    def _put_scene(self, scene: "_Scene") -> None:
        self.spec, self.options, self.points = scene.spec, scene.options, scene.points
        self.breaks, self.grid, self.previous = scene.breaks, scene.grid, scene.previous

    def _change(self, scene: "_Scene", at_end=None, work=None, always=False) -> None:
        """Make ``scene`` the scene, recorded by ``work(monitor)`` (default:
        record it when complete). The recording runs in a worker: when it
        ends within ``sync_wait`` its outcome is installed before this
        returns (an InputError is raised then and nothing changes);
        otherwise the scene changes now, the trace on show stays until the
        recording ends, and an earlier background recording is cancelled.
        ``at_end`` None: the step goes to the end if it is there when the
        new trace comes."""
        if work is None and not always and not complete(scene.spec, scene.points, scene.breaks):
            self._drop_job()
            self._put_scene(scene)
            self._take(_Outcome(scene, None, None), at_end)
            return
        job = Job(work or (lambda monitor: self._outcome(scene, monitor)),
                  self._jobProgress.emit, self._jobDone.emit).start()
        # The first scene has no run on show to fall back on: it is waited for.
        if job.wait(None if self.spec is None else self.sync_wait):
            if job.error is not None:
                raise job.error  # nothing has changed
            self._drop_job()
            self._put_scene(job.result.scene)
            self._take(job.result, at_end)
            return
        if self._job is None:
            self._shown = self._scene()
        else:
            self._job.cancel()  # only the newest recording is ever installed
        self._job, self._job_at_end = job, at_end
        self._put_scene(scene)
        self.recordingStarted.emit()

    def _outcome(self, scene: "_Scene", monitor=None, refusal=None) -> "_Outcome":
        """Record ``scene`` and what goes with it (runs in the worker)."""
        trace = self._record(scene.spec, scene.points, scene.options, scene.grid,
                             scene.breaks, monitor)
        # Replay caches and the comparison are made here too, so that
        # installing the trace does not hold up the window.
        end = len(trace) - 1
        final = trace.raster_at(end)
        # The last step's state shares the final raster (nothing writes to
        # either): one framebuffer, not two, on a 4096 x 4096 grid.
        last = FrameState(end, trace.step(end), final, trace.variables_at(end),
                          trace.candidates_at(end))
        enabled = self.compare_enabled
        found = self._comparison(scene, final, monitor) if enabled else None
        return _Outcome(scene, trace, final, found, enabled, refusal, last)

    def _take(self, outcome: "_Outcome", at_end) -> None:
        if outcome.refusal is not None:
            self.refusal = outcome.refusal
        self._install(outcome.trace, self._at_end() if at_end is None else at_end, outcome)

    def _job_progressed(self, job, steps: int) -> None:
        if job is self._job:
            self.recordingProgress.emit(steps)

    def _job_done(self, job) -> None:
        if job is not self._job:
            return  # replaced or cancelled meanwhile
        self._job = None
        if job.error is not None or job.cancelled:
            self._put_back_shown(CANCELLED_MESSAGE if job.error is None else str(job.error))
            return
        self._shown = None
        outcome = job.result
        self._put_scene(outcome.scene)
        self._take(outcome, self._job_at_end)
        self.recordingFinished.emit(self._finish_note(outcome))

    def _finish_note(self, outcome) -> str:
        if not outcome.refusal:
            return ""
        return (f"{outcome.scene.spec.title} refused the points drawn before "
                f"({outcome.refusal}); showing an example shape instead.")

    @property
    def shown_scene(self) -> "_Scene":
        """The scene the trace on show was recorded from: while a recording
        runs in the background, the one before the edit."""
        return self._shown if self._shown is not None else self._scene()

    @property
    def trace_spec(self):
        """The algorithm of the trace on show."""
        return self.shown_scene.spec

    @property
    def recording(self) -> bool:
        """Is a recording running in the background?"""
        return self._job is not None

    def cancel_recording(self) -> None:
        """Stop the background recording: the scene and trace on show stay."""
        if self._job is None:
            return
        self._job.cancel()
        self._job = None
        self._put_back_shown(CANCELLED_MESSAGE)

    def _put_back_shown(self, message: str) -> None:
        """The recording ended without a trace: the scene on show is the scene again."""
        self._put_scene(self._shown)
        self._shown = None
        self.recordingFinished.emit(message)

    def stop_recording(self, timeout: float = 2.0) -> None:
        """Cancel the background recording and wait for its thread to end
        (the window is closing)."""
        job = self._job
        self.cancel_recording()
        if job is not None:
            job.wait(timeout)

    def _drop_job(self) -> None:
        """A newer scene was installed: a background recording is void."""
        if self._job is not None:
            self._job.cancel()
            self._job = None
            self._shown = None
            self.recordingFinished.emit("")

    def _install(self, trace: Trace | None, at_end: bool, outcome=None) -> None:
        old_len, old_index = len(self), self.index
        self.trace = trace
        self._state = None
        self._final = None if outcome is None else outcome.final
        if outcome is not None:
            self._state = outcome.last_state  # used when the step goes to the end
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
        if outcome is not None and outcome.compare_enabled == self.compare_enabled:
            found = outcome.comparison
            self.differences, self.compared = found if found else (_NO_CELLS, False)
        else:
            self._compare(emit=False)
        self.traceChanged.emit()
        self.comparisonChanged.emit()
        self.frameChanged.emit(self.index)

    def _at_end(self) -> bool:
        return self.trace is None or self.index >= self.last

    def _complete(self, points, breaks=()) -> bool:
        return complete(self.spec, points, breaks)

    def _fit_points(self, spec):
        """The current points and breaks as the new algorithm takes them:
        triangles become contours of three and back; a fixed count keeps
        the first points."""
        points = [_clamp(p, *self.grid, spec.inputs.integer) for p in self.points]
        old = self.spec.inputs if self.spec is not None else None
        inputs = spec.inputs
        if inputs.contours:
            if old is not None and old.multiple:
                return points, tuple(range(old.count, len(points), old.count))
            return points, clean_breaks(spec, len(points), self.breaks)
        if inputs.multiple:
            sizes = contour_sizes(len(points), self.breaks)
            if self.breaks and any(size != inputs.count for size in sizes):
                return [], ()  # contours that are not triangles: start afresh
            return points, ()
        return points[:inputs.count], ()

    def _same_option(self, option) -> bool:
        """Is ``option`` also an option of the current algorithm, of the same
        kind, and set to something other than its default there?"""
        for old in self.spec.options:
            if old.name == option.name:
                return old.kind == option.kind and self.options.get(old.name) != old.default
        return False

    def _compare(self, emit: bool = True) -> None:
        found = None
        if self.compare_enabled and self.trace is not None:
            found = self._comparison(self._scene(), self.final_raster())
        self.differences, self.compared = found if found else (_NO_CELLS, False)
        if emit:
            self.comparisonChanged.emit()

    def _comparison(self, scene: "_Scene", final: Raster, monitor=None):
        """(differing cells, True) against the remembered algorithm, or None
        when there is none or it does not take this input."""
        if scene.previous is None:
            return None
        spec, options = scene.previous
        if not complete(spec, scene.points, scene.breaks):
            return None
        try:
            other = self._record(spec, scene.points, options, scene.grid, scene.breaks, monitor)
        except InputError:
            return None  # the other algorithm does not take this input
        return differences(other.raster_at(len(other) - 1), final), True

    @property
    def previous_title(self) -> str:
        return "" if self.previous is None else self.previous[0].title


_NO_CELLS = np.zeros((0, 2), dtype=np.int64)


@dataclass(frozen=True)
class _Scene:
    """What a recording is made of: algorithm, options, points, grid and the
    algorithm compared against."""

    spec: object
    options: dict
    points: list
    breaks: tuple
    grid: tuple
    previous: tuple | None


@dataclass
class _Outcome:
    """A finished recording: the scene it was made of (an example shape
    when the algorithm refused the points), its trace and replay cache."""

    scene: _Scene
    trace: Trace | None
    final: Raster | None
    comparison: tuple | None = None
    compare_enabled: bool = False
    refusal: str | None = None  # None: not an algorithm switch
    last_state: FrameState | None = None


def _sync_wait() -> float | None:
    """Seconds an edit waits for its recording (None: until it ends)."""
    text = os.environ.get("RASTERLAB_RECORD_WAIT", "")
    try:
        value = float(text) if text else SYNC_WAIT
    except ValueError:
        value = SYNC_WAIT
    return None if not math.isfinite(value) else max(0.0, value)


# A concave hexagon with a notch on its right (fractions of the grid): the
# example shape of polygon fills and flood fill.
_CONCAVE = ((0.12, 0.14), (0.86, 0.1), (0.6, 0.46), (0.88, 0.86), (0.42, 0.7), (0.14, 0.88))


def default_scene(spec, grid) -> tuple[list[tuple], tuple[int, ...], dict]:
    """A pleasant first scene for an algorithm: (points, breaks, options).

    Polygon and fill algorithms get a concave shape; one that only takes a
    convex polygon gets a convex one instead (tried, not looked up by name).
    """
    width, height = grid
    if spec.inputs.contours:
        points = [_grid_point(spec, fx * width, fy * height, grid) for fx, fy in _CONCAVE]
        try:
            spec.record(runnable_input(spec, points, ()), spec.resolve(), grid, step_cap=100_000)
        except Exception:  # noqa: BLE001 - any refusal: fall back to the convex shape
            points = default_points(spec, grid, vertices=6)
        return points, (), {}
    points = default_points(spec, grid)
    if spec.inputs.multiple and len(points) == 1:
        # Inputs of any number of points (a shape of 3k points, say): one
        # point may not be a shape; a triangle is (tried, not looked up).
        try:
            spec.record(runnable_input(spec, points, ()), spec.resolve(), grid, step_cap=100_000)
        except Exception:  # noqa: BLE001 - any refusal: a triangle instead
            points = default_points(spec, grid, vertices=3)
    return points, (), {}


def _grid_point(spec, x: float, y: float, grid):
    if spec.inputs.integer:
        return _clamp((math.floor(x), math.floor(y)), *grid, True)
    return _clamp((round(x * 4) / 4, round(y * 4) / 4), *grid, False)


def default_points(spec, grid, vertices: int | None = None) -> list[tuple]:
    """A pleasant first input for an algorithm on a grid: the centre for one
    point, a shallow segment for two, a slightly irregular polygon for more."""
    width, height = grid
    count = max(1, vertices or spec.inputs.count)
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


def _checked_grid(grid, limit: int = MAX_GRID) -> tuple[int, int]:
    try:
        width, height = (int(v) for v in grid)
        check_grid(width, height)
    except (TypeError, ValueError) as error:
        raise InputError(str(error)) from None
    if width > limit or height > limit:
        raise InputError(f"grid {width}x{height} is larger than the maximum grid size of "
                         f"{limit}x{limit}; raise \"Maximum grid size\" in "
                         f"Edit > Preferences (up to {MAX_GRID})")
    return width, height


def _clamp(point, width: int, height: int, integer: bool):
    x, y = point
    if integer:
        return (min(max(int(x), 0), width - 1), min(max(int(y), 0), height - 1))
    return (min(max(float(x), 0.0), float(width)), min(max(float(y), 0.0), float(height)))
