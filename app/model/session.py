"""The session: one scene, its recorded trace, the step on show, and the
undo history of the scene's edits.

Nothing here imports Qt. The window's ``Player`` (app/gui/player.py) adds
Qt signals and timed play on top; a script or a test drives a ``Session``
directly. What happens is told through the events ``Session`` declares
(``app/model/events.py``), connected and emitted as Qt's signals are.

Where the step goes after a re-recording
----------------------------------------
* If the old run was shown at its last step (or a scene is opened), the new
  run is shown at its last step too: dragging an end point of a finished
  line shows the finished line. A primitive just drawn starts at step 0.
* Otherwise the step keeps its relative position in the run (half-way stays
  half-way), so a run being stepped through mid-way stays mid-way.

Points, contours and shapes still being drawn
---------------------------------------------
The scene keeps the points as the algorithm takes them; ``points`` gives
them as one flat list and ``breaks`` the indices where a new contour starts
(polygons with holes, several fill outlines), so that the grid, the points
editor and the undo history all deal with one list. While a person is
still drawing, the run uses only what is complete (``Scene.runnable``): the
contours that have enough vertices, the whole triangles among 3k + 1 or
3k + 2 points. The rest stays on the grid as handles until it is finished.

Comparison with the previous algorithm
--------------------------------------
When the algorithm changes, the one before it is remembered. From then on
every recording also records the remembered algorithm on the same points
and grid, and ``differences`` lists the cells where the two final results
differ, until the algorithm changes again or the comparison is turned off.

Recording in the background
---------------------------
Every recording runs in a worker (app/model/recording.py). An edit waits
``sync_wait`` seconds for it; a longer run goes on in the background while
the previous trace stays on show. The worker hands its news to the
session's thread through ``post(function)`` (the Qt player queues it
through a signal); without a ``post``, news waits until ``deliver()`` or
``wait()`` is called.
"""
from __future__ import annotations

import math
import os
import queue
from contextlib import contextmanager

import numpy as np

from algorithms.core import registry
from algorithms.core.raster import MAX_GRID, Raster, check_grid
from algorithms.core.registry import InputError
from algorithms.core.trace import DEFAULT_STEP_CAP, Cancelled, FrameState, Trace

from app.model import drawing
from app.model.budget import DEFAULT_MEMORY_LIMIT, check_budget
from app.model.events import Event
from app.model.history import EditHistory
from app.model.examples import default_scene
from app.model.inputs import (clamp, clean_breaks, complete, contour_sizes, flatten,
                              open_ended, runnable_input)
from app.model.outcome import (CANCELLED_MESSAGE, Outcome, example_note, failure,  # noqa: F401
                               kept_note)
from app.model.recording import Job
from app.model.scene import Scene, SceneError
from app.model.geometry import differences
from app.model.tools import drawing_tool

# How long an edit waits for its recording before it goes on in the
# background (seconds); RASTERLAB_RECORD_WAIT overrides it ("inf": always
# wait, as the tests do).
SYNC_WAIT = 0.02
# Stepping on by at most this many steps replays them onto the raster on show;
# a longer jump (or a step back) replays from the nearest keyframe instead.
ONWARD_STEPS = 1024
_NO_CELLS = np.zeros((0, 2), dtype=np.int64)


class Session:
    """The current scene, its recorded trace and the step on show."""

    #: The scene was replaced: an edit, undo or redo, a file opened.
    scene_changed = Event()
    #: A new trace was installed (or the trace was dropped: ``trace`` is None).
    trace_changed = Event()
    #: The step on show changed (its index).
    step_changed = Event(int)
    #: The cells where the run and the previous algorithm's differ changed.
    comparison_changed = Event()
    #: A recording started in the background (the previous trace stays on show).
    recording_started = Event()
    #: Steps recorded so far by the background recording.
    recording_progress = Event(int)
    #: The background recording ended: "" when its trace was installed as
    #: asked, else why the scene is not the one asked for.
    recording_finished = Event(str)
    #: A message for the person (a refusal, an error of a run).
    message = Event(str)

    def __init__(self, step_cap: int = DEFAULT_STEP_CAP, post=None):
        self.sync_wait = sync_wait()
        self.step_cap = step_cap
        self.memory_limit = DEFAULT_MEMORY_LIMIT  # what a run may need (app/model/budget.py)
        # The largest grid side accepted (a preference, at most MAX_GRID).
        self.max_grid = MAX_GRID
        self.scene: Scene | None = None  # None until the first set_scene
        self.previous = None  # (spec, options) of the algorithm before this one
        self.trace: Trace | None = None
        self.index = 0
        self.compare_enabled = True
        self.differences = _NO_CELLS
        self.compared = False  # did the last recording run the comparison?
        self.refusal = ""  # what the last algorithm switch did instead of running the points
        self.history = EditHistory()
        # Optional hook (app/gui/breakpoint_actions.py): stepper(index, delta)
        # gives where a step of delta units goes (None: nowhere).
        self.stepper = None
        self._inbox = queue.SimpleQueue()
        self._post = post or self._inbox.put
        self._job: Job | None = None  # the background recording, if one runs
        self._job_at_end = None
        self._shown = None  # (scene, previous) the trace on show belongs to, while a job runs
        self._state: FrameState | None = None
        # The run and state the last step on show was replayed for (see _state_onward).
        self._replayed: tuple = (None, None)
        self._final: Raster | None = None
        self._edit_depth = 0  # nested edits count as the outer one
        # (tool, points, breaks) a gesture left with a contour open (``sketch``).
        self._open_sketch = None

    # ------------------------------------------------------- the scene
    @property
    def spec(self):
        return None if self.scene is None else self.scene.spec

    @property
    def options(self) -> dict:
        return {} if self.scene is None else self.scene.options

    @property
    def points(self) -> list[tuple]:
        """Every point, flat, including a contour or triangle still being drawn."""
        return [] if self.scene is None else list(self.scene.flat)

    @property
    def breaks(self) -> tuple[int, ...]:
        """Where contours 2, 3, ... start in ``points``."""
        return () if self.scene is None else self.scene.breaks

    @property
    def grid(self) -> tuple[int, int]:
        return (32, 24) if self.scene is None else self.scene.grid

    @property
    def y_down(self) -> bool:
        return self.scene is not None and self.scene.y_down

    def input_points(self):
        """The points as the algorithm takes them (a list of contours for
        polygon inputs), without anything still being drawn."""
        return self.scene.runnable()

    def set_scene(self, algorithm: str, points, options: dict | None = None,
                  grid=(32, 24)) -> None:
        """Replace the algorithm, points, options and grid at once (points
        flat or as contours); raises InputError and changes nothing when the
        scene is bad."""
        spec = registry.get(algorithm)
        width, height = _checked_grid(grid, self.max_grid)
        points, breaks = flatten(spec, points)
        scene = self._flat_scene(spec.name, points, breaks, spec.resolve(options), (width, height))
        self._change(scene, None, at_end=True, always=True)

    def set_algorithm(self, name: str) -> None:
        """Switch algorithm on the same points. Options the person changed
        from their defaults carry over to options of the same name and kind;
        the rest take the new algorithm's defaults. The algorithm switched
        away from becomes the one compared against."""
        spec = registry.get(name)
        if self.spec is not None and spec.name == self.spec.name:
            return
        carried = self._carried_options(spec)
        points, breaks = self._fit_points(spec)
        self.refusal = ""  # set again when the run ends (here or in the background)
        previous = (self.spec, dict(self.options)) if self.spec is not None else None
        width, height = self.grid
        scene = self._flat_scene(spec.name, points, breaks, spec.resolve(carried),
                                 (width, height))
        self._change(scene, previous, work=lambda monitor: self._switch(
            scene, previous, carried, monitor), always=True)

    def _switch(self, scene: Scene, previous, carried: dict, monitor) -> Outcome:
        """Record an algorithm switch (in the worker); an algorithm that
        refuses the points shows its own example shape and says why. When
        not even that fits the grid (a fill's on a grid one row high), the
        points are kept without a run."""
        spec, reason = scene.spec, ""
        if scene.complete:
            try:
                return self.outcome(scene, previous, monitor, refusal="")
            except InputError as error:
                reason = str(error)  # a concave polygon for the convex fill, say
        shape, shape_breaks, defaults = default_scene(spec, scene.grid)
        example = self._flat_scene(spec.name, shape, shape_breaks,
                                   spec.resolve({**carried, **defaults}), scene.grid)
        # A carried option this run refuses (one colour set while the points
        # were being placed, say) must not block the switch: then the defaults.
        for options in (example.options, spec.resolve(defaults)):
            try:
                return self.outcome(example.replace(options=options), previous, monitor,
                                    refusal=reason and example_note(spec, reason))
            except InputError as error:
                reason = reason or str(error)
        return Outcome(scene, previous, None, None, refusal=kept_note(spec, scene.grid, reason))

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
        self._change(self.scene.replace(options=dict(self.options, **checked)), self.previous)

    def set_points(self, points, breaks=None) -> None:
        """Set the points (and, for contour inputs, where each contour
        starts; None keeps the breaks that still fit). Fewer points than the
        algorithm takes leave no trace (the person is still placing them).
        Raises InputError on bad points; nothing changes then."""
        spec = self.spec
        points = [tuple(p) for p in points]
        if not open_ended(spec) and len(points) > spec.inputs.count:
            raise InputError(f"{spec.title} takes {spec.inputs.count} points, got {len(points)}")
        breaks = clean_breaks(spec, len(points), self.breaks if breaks is None else breaks)
        if points == self.points and breaks == self.breaks and self.trace is not None:
            return
        scene = self._flat_scene(spec.name, points, breaks, self.options, self.grid)
        self._change(scene, self.previous)

    @property
    def sketch(self) -> drawing.Sketch:
        """The points as the grid draws them: a contour is still being drawn
        while the points are those the gesture that opened it left."""
        key = (drawing_tool(self.spec, self.options), tuple(self.points), self.breaks)
        return drawing.Sketch(key[1], key[2], key == self._open_sketch)

    def draw(self, gesture) -> None:
        """Apply a gesture on the grid (app/model/drawing.py) to the points;
        InputError when the run refuses them: nothing changes then."""
        before = self.sketch
        after = drawing.apply(drawing_tool(self.spec, self.options), before, gesture)
        try:
            if (after.points, after.breaks) != (before.points, before.breaks):
                self.set_points(after.points, after.breaks)
        finally:
            key = (drawing_tool(self.spec, self.options), tuple(self.points), self.breaks)
            self._open_sketch = key if after.open and self.points else None

    def restore(self, points, breaks, options: dict, algorithm: str | None = None,
                grid=None) -> None:
        """Put back points, breaks and options together (undo, the points
        table), and the algorithm and grid when given; raises InputError and
        changes nothing when the run refuses them. The step keeps its place."""
        spec = self.spec if algorithm is None else registry.get(algorithm)
        grid = self.grid if grid is None else _checked_grid(grid, self.max_grid)
        points = [tuple(p) for p in points]
        breaks = clean_breaks(spec, len(points), breaks)
        previous = self.previous if spec is self.spec else (self.spec, dict(self.options))
        self._change(self._flat_scene(spec.name, points, breaks, spec.resolve(options), grid),
                     previous)

    def set_grid(self, width: int, height: int) -> None:
        """Resize the grid; points outside it are moved to its edge."""
        width, height = _checked_grid((width, height), self.max_grid)
        if (width, height) == self.grid:
            return
        points = [clamp(p, width, height, self.spec.inputs.integer) for p in self.points]
        scene = self._flat_scene(self.spec.name, points, self.breaks, self.options,
                                 (width, height))
        self._change(scene, self.previous)

    def set_origin(self, y_down: bool) -> None:
        """Origin top-left with y down (True) or bottom-left with y up: how
        the scene is shown and read; the run does not change."""
        origin = "top-left" if y_down else "bottom-left"
        if self.scene is None or origin == self.scene.origin:
            return
        self.scene = self.scene.replace(origin=origin)
        if self._shown is not None:
            self._shown = (self._shown[0].replace(origin=origin), self._shown[1])
        self.scene_changed.emit()

    def set_compare(self, enabled: bool) -> None:
        self.compare_enabled = bool(enabled)
        self._compare()

    def _origin(self) -> str:
        return "bottom-left" if self.scene is None else self.scene.origin

    def _flat_scene(self, algorithm: str, points, breaks, options, grid) -> Scene:
        width, height = grid
        return _made(Scene.of_flat, algorithm, points, breaks, options=options, width=width,
                     height=height, origin=self._origin())

    def _carried_options(self, spec) -> dict:
        carried = {}
        for option in spec.options:
            if option.name in self.options and self._same_option(option):
                try:
                    carried[option.name] = option.check(self.options[option.name])
                except InputError:
                    pass
        return carried

    def _same_option(self, option) -> bool:
        """Is ``option`` also an option of the current algorithm, of the same
        kind, and set to something other than its default there?"""
        for old in self.spec.options:
            if old.name == option.name:
                return old.kind == option.kind and self.options.get(old.name) != old.default
        return False

    def _fit_points(self, spec):
        """The current points and breaks as the new algorithm takes them:
        triangles become contours of three and back; a fixed count keeps
        the first points."""
        points = [clamp(p, *self.grid, spec.inputs.integer) for p in self.points]
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

    @property
    def previous_title(self) -> str:
        return "" if self.previous is None else self.previous[0].title

    # ------------------------------------------------------------ undo
    @contextmanager
    def edit(self, key=None, seconds: float | None = None):
        """Run an edit; if it changed the scene, remember the scene before
        it in ``history``. Edits with the same ``key`` merge while the entry
        is open (for ``seconds`` after the last one; None: until another
        edit)."""
        if self._edit_depth:
            yield
            return
        before = self.scene
        self._edit_depth += 1
        try:
            yield
        finally:
            self._edit_depth -= 1
            self.history.push(before, self.scene, key, seconds)

    def undo(self) -> Scene | None:
        """Put back the scene before the last edit and return it (None:
        nothing to undo). When the run refuses it, ``message`` says why and
        the scene stays; the origin comes back either way."""
        return self._go_to(self.history.undo(self.scene))

    def redo(self) -> Scene | None:
        return self._go_to(self.history.redo(self.scene))

    def _go_to(self, scene: Scene | None) -> Scene | None:
        if scene is None:
            return None
        if (tuple(scene.flat), scene.breaks) != (tuple(self.points), self.breaks):
            self._open_sketch = None  # the history's points count as finished
        try:
            self.restore(scene.flat, scene.breaks, dict(scene.options), scene.algorithm,
                         scene.grid)
        except InputError as error:
            self.message.emit(str(error))
        self.set_origin(scene.y_down)
        return scene

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
            self.step_changed.emit(index)

    def step(self, delta: int) -> None:
        """Go ``delta`` steps on (back when negative), in the stepper's units when one is set."""
        if self.stepper is not None and self.trace is not None:
            target = self.stepper(self.index, delta)
            if target is not None:
                self.seek(target)
            return
        self.seek(self.index + delta)

    def first(self) -> None:
        self.seek(0)

    def to_last(self) -> None:
        self.seek(self.last)

    def state(self) -> FrameState | None:
        """The replayed state at the current step (computed once per step)."""
        if self.trace is None:
            return None
        if self._state is None or self._state.index != self.index:
            self._state = self._state_onward() or self.trace.state_at(self.index, compact=True)
            self._replayed = (self.trace, self._state)
        return self._state

    def _state_onward(self) -> FrameState | None:
        """The state a few steps on from the last one replayed, made by
        replaying just the steps in between onto its raster (a step forward
        on a 4096 x 4096 grid then costs no fresh 16-million-cell raster).
        That raster is the session's own, so the earlier state is spent."""
        trace, state = self._replayed
        i = self.index
        if trace is not self.trace or state is None or not 0 < i - state.index <= ONWARD_STEPS:
            return None
        trace.replay(state.index + 1, i + 1, state.raster)
        return trace.state_on(i, state.raster)

    def final_raster(self) -> Raster | None:
        if self.trace is None:
            return None
        if self._final is None:
            self._final = self.trace.raster_at(len(self.trace) - 1)
        return self._final

    # -------------------------------------------------------- recording
    def record(self, spec, points, options, grid, monitor=None) -> Trace:
        """Record ``spec`` on runnable ``points``; any failure of the run
        becomes an InputError."""
        try:
            check_budget(spec, points, options, grid, self.step_cap, self.memory_limit,
                         time_limit=math.inf)  # the window shows progress and Cancel instead
            trace = spec.record(points, options, grid, step_cap=self.step_cap, monitor=monitor)
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

    def outcome(self, scene: Scene, previous, monitor=None, refusal=None) -> Outcome:
        """Record ``scene`` and what goes with it (runs in the worker)."""
        trace = self.record(scene.spec, scene.runnable(), scene.options, scene.grid, monitor)
        # Replay caches and the comparison are made here too, so that
        # installing the trace does not hold up the window.
        end = len(trace) - 1
        final = trace.raster_at(end)
        # The last step's state shares the final raster (nothing writes to
        # either): one framebuffer, not two, on a 4096 x 4096 grid.
        last = trace.state_on(end, final)
        enabled = self.compare_enabled
        found = self._comparison(scene, previous, final, monitor) if enabled else None
        return Outcome(scene, previous, trace, final, found, enabled, refusal, last)

    def _change(self, scene: Scene, previous, at_end=None, work=None, always=False) -> None:
        """Make ``scene`` the scene, recorded by ``work(monitor)`` (default:
        record it when complete). When the recording ends within
        ``sync_wait`` its outcome is installed before this returns (an
        InputError is raised then and nothing changes); otherwise the scene
        changes now, the trace on show stays until the recording ends, and
        an earlier background recording is cancelled. ``at_end`` None: the
        step goes to the end if it is there when the new trace comes."""
        self.deliver()  # news of recordings replaced since: let it go
        if work is None and not always and not scene.complete:
            self._drop_job()
            self._put_scene(scene, previous)
            self._take(Outcome(scene, previous, None, None), at_end)
            return
        job = Job(work or (lambda monitor: self.outcome(scene, previous, monitor)),
                  lambda job, steps: self._post(lambda: self._job_progressed(job, steps)),
                  lambda job: self._post(lambda: self._job_done(job))).start()
        # The first scene has no run on show to fall back on: it is waited for.
        if job.wait(None if self.scene is None else self.sync_wait):
            if job.error is not None:
                raise job.error  # nothing has changed
            self._drop_job()
            self._put_scene(job.result.scene, job.result.previous)
            self._take(job.result, at_end)
            return
        if self._job is None:
            self._shown = (self.scene, self.previous)
        else:
            self._job.cancel()  # only the newest recording is ever installed
        self._job, self._job_at_end = job, at_end
        self._put_scene(scene, previous)
        self.recording_started.emit()

    def _put_scene(self, scene: Scene, previous) -> None:
        changed = scene != self.scene
        self.scene, self.previous = scene, previous
        if changed:
            self.scene_changed.emit()

    def _take(self, outcome: Outcome, at_end) -> None:
        if outcome.refusal is not None:
            self.refusal = outcome.refusal
        self._install(outcome.trace, self._at_end() if at_end is None else at_end, outcome)

    def deliver(self) -> None:
        """Take in the news background recordings sent (without a ``post``)."""
        while True:
            try:
                news = self._inbox.get_nowait()
            except queue.Empty:
                return
            news()

    def wait(self, timeout: float | None = None) -> bool:
        """Wait for the background recording (without a ``post``) and take
        it in; is it over?"""
        if self._job is not None:
            self._job.wait(timeout)
        self.deliver()
        return not self.recording

    def _job_progressed(self, job, steps: int) -> None:
        if job is self._job:
            self.recording_progress.emit(steps)

    def _job_done(self, job) -> None:
        if job is not self._job:
            return  # replaced or cancelled meanwhile
        self._job = None
        if job.error is not None or job.cancelled:
            self._put_back_shown(CANCELLED_MESSAGE if job.error is None else failure(job.error))
            return
        self._shown = None
        outcome = job.result
        # The origin may have been set meanwhile (an open sets it after the
        # scene): it only changes how the run is shown, so it is kept.
        self._put_scene(outcome.scene.replace(origin=self.scene.origin), outcome.previous)
        self._take(outcome, self._job_at_end)
        self._finished(outcome.refusal or "")

    def _finished(self, note: str) -> None:
        self.recording_finished.emit(note)
        if note:
            self.message.emit(note)

    @property
    def shown_scene(self) -> Scene:
        """The scene the trace on show was recorded from: while a recording
        runs in the background, the one before the edit."""
        return self._shown[0] if self._shown is not None else self.scene

    @property
    def trace_spec(self):
        """The algorithm of the trace on show."""
        return self.shown_scene.spec

    @property
    def recording(self) -> bool:
        """Is a recording running in the background?"""
        return self._job is not None

    @property
    def job(self) -> Job | None:
        """The background recording, if one runs."""
        return self._job

    def cancel_recording(self) -> None:
        """Stop the background recording: the scene and trace on show stay."""
        if self._job is None:
            return
        self._job.cancel()
        self._job = None
        self._put_back_shown(CANCELLED_MESSAGE)

    def _put_back_shown(self, message: str) -> None:
        """The recording ended without a trace: the scene on show is the scene again."""
        self._put_scene(*self._shown)
        self._shown = None
        self._finished(message)

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
            self.recording_finished.emit("")

    def _install(self, trace: Trace | None, at_end: bool, outcome: Outcome) -> None:
        old_len, old_index = len(self), self.index
        self.trace = trace
        self._final = outcome.final
        self._state = outcome.last_state  # used when the step goes to the end
        if trace is None:
            self.index = 0
        elif at_end or old_len < 2:  # no run before: a primitive just drawn, from its start
            self.index = len(trace) - 1 if at_end else 0
        else:
            fraction = old_index / (old_len - 1)
            self.index = min(len(trace) - 1, round(fraction * (len(trace) - 1)))
        if outcome.compare_enabled == self.compare_enabled:
            found = outcome.comparison
            self.differences, self.compared = found if found else (_NO_CELLS, False)
        else:
            self._compare(emit=False)
        self.trace_changed.emit()
        self.comparison_changed.emit()
        self.step_changed.emit(self.index)

    def _at_end(self) -> bool:
        return self.trace is not None and self.index >= self.last

    def _compare(self, emit: bool = True) -> None:
        found = None
        if self.compare_enabled and self.trace is not None:
            found = self._comparison(self.scene, self.previous, self.final_raster())
        self.differences, self.compared = found if found else (_NO_CELLS, False)
        if emit:
            self.comparison_changed.emit()

    def _comparison(self, scene: Scene, previous, final: Raster, monitor=None):
        """(differing cells, True) against the remembered algorithm, or None
        when there is none or it does not take this input."""
        if previous is None:
            return None
        spec, options = previous
        flat, breaks = scene.flat, scene.breaks
        if not complete(spec, flat, breaks, options):
            return None
        try:
            other = self.record(spec, runnable_input(spec, flat, breaks, options), options, scene.grid,
                                monitor)
        except InputError:
            return None  # the other algorithm does not take this input
        return differences(other.raster_at(len(other) - 1), final), True


def _made(make, *args, **fields) -> Scene:
    """A scene made by ``make``; a scene that is not one is a bad input."""
    try:
        return make(*args, **fields)
    except SceneError as error:
        raise InputError(str(error)) from None


def sync_wait() -> float | None:
    """Seconds an edit waits for its recording (None: until it ends)."""
    text = os.environ.get("RASTERLAB_RECORD_WAIT", "")
    try:
        value = float(text) if text else SYNC_WAIT
    except ValueError:
        value = SYNC_WAIT
    return None if not math.isfinite(value) else max(0.0, value)


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
