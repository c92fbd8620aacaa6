"""The session without Qt: scene edits, recording (in place and in the
background), the step on show, undo and redo, and what it tells listeners."""
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from algorithms.core import registry
from algorithms.core.registry import InputError
from app.model.scene import Scene
from app.model.session import CANCELLED_MESSAGE, Session

from tests.support import ROOT
from tests.support.bresenham import bresenham_pixels
P, Q = (1, 1), (12, 5)


class Heard:
    """What a session told its listeners, in order."""

    def __init__(self, session: Session):
        self.events = []
        for name in ("scene_changed", "trace_changed", "step_changed", "comparison_changed",
                     "recording_started", "recording_finished", "message"):
            getattr(session, name).connect(
                lambda *args, name=name: self.events.append((name, *args)))

    def of(self, name: str) -> list:
        return [event for event in self.events if event[0] == name]


@pytest.fixture
def session():
    s = Session()
    s.sync_wait = None  # every recording is waited for, unless a test says otherwise
    s.set_scene("line-bresenham", [P, Q], {}, (16, 8))
    return s


def test_app_model_loads_no_qt():
    """The model, the renderer, the analysis and the command line run without Qt."""
    code = ("import sys, app.model.session, app.model.compare, app.model.tools, "
            "app.model.drawing, app.cli; "
            "bad = sorted(m for m in sys.modules "
            "if m.split('.')[0] in ('PySide6', 'pyqtgraph', 'widgets')); print(bad)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, check=True, env={"PYTHONPATH": str(ROOT)})
    assert out.stdout.strip() == "[]", out.stdout


def test_a_scene_is_recorded_and_shown_at_its_last_step(session):
    assert session.scene == Scene(algorithm="line-bresenham", points=(P, Q), width=16,
                                  height=8, options=session.spec.resolve())
    assert session.points == [P, Q] and session.breaks == () and session.grid == (16, 8)
    assert session.trace is not None and session.index == session.last == len(session) - 1
    pixels = {tuple(p) for p in session.trace.written_pixels().tolist()}
    assert {P, Q} <= pixels
    assert session.state().index == session.index


def test_moving_the_step(session):
    heard = Heard(session)
    session.first()
    session.step(3)
    session.step(-1)
    session.seek(10 ** 6)
    assert [e[1] for e in heard.of("step_changed")] == [0, 3, 2, session.last]
    session.seek(session.last)  # already there: no news
    assert len(heard.of("step_changed")) == 4
    session.stepper = lambda index, delta: None  # a stepper with nowhere to go
    session.step(-1)
    assert session.index == session.last


def test_an_edit_keeps_the_step_where_it_was_as_a_fraction(session):
    session.seek(session.last // 2)
    fraction = session.index / session.last
    session.set_points([P, (14, 7)])
    assert abs(session.index / session.last - fraction) < 0.1
    session.to_last()
    session.set_points([P, (15, 7)])
    assert session.index == session.last  # at the end it stays at the end


def test_incomplete_points_leave_no_trace_and_bad_ones_change_nothing(session):
    heard = Heard(session)
    session.set_points([P])
    assert session.trace is None and session.points == [P] and not session.scene.complete
    assert heard.of("trace_changed") and heard.of("scene_changed")
    session.set_points([P, Q])
    with pytest.raises(InputError, match="takes 2 points"):
        session.set_points([P, Q, Q])
    with pytest.raises(InputError):
        session.set_option("symmetric", "maybe")
    with pytest.raises(InputError, match="maximum grid size"):
        session.max_grid = 64
        session.set_grid(65, 8)
    assert session.points == [P, Q] and session.grid == (16, 8)


def test_the_grid_clamps_points_and_the_origin_is_part_of_the_scene(session):
    session.set_grid(10, 4)
    assert session.points == [P, (9, 3)] and session.grid == (10, 4)
    trace = session.trace
    session.set_origin(True)
    assert session.y_down and session.scene.origin == "top-left" and session.trace is trace


def test_contours_keep_their_breaks():
    session = Session()
    session.sync_wait = None
    square = [(1, 1), (9, 1), (9, 9), (1, 9)]
    hole = [(3, 3), (6, 3), (5, 6)]
    session.set_scene("polygon-scanline", [square, hole], {}, (12, 12))
    assert session.breaks == (4,) and session.points == square + hole
    session.set_points(square + hole[:2])  # a contour of two: not run
    assert session.input_points() == [square]
    assert session.scene.points == (tuple(square), tuple(hole[:2]))


def test_undo_and_redo_take_back_whole_edits(session):
    first = session.scene
    with session.edit(("gesture", 1)):
        session.set_points([P, (13, 5)])
    with session.edit(("gesture", 1)):
        session.set_points([P, (14, 6)])  # the same gesture: one entry
    with session.edit():
        session.set_algorithm("line-dda")
    with session.edit():
        session.set_origin(True)
    assert len(session.history) == 3 and session.history.undo_text == "origin"
    assert session.undo().origin == "bottom-left" and not session.y_down
    assert session.undo().algorithm == "line-bresenham" and session.spec.name == "line-bresenham"
    assert session.undo() == first and session.scene == first
    assert session.undo() is None
    session.redo()
    assert session.points == [P, (14, 6)]


def test_a_refused_undo_says_why(session):
    heard = Heard(session)
    with session.edit():
        session.set_points([P, (13, 5)])
    original = session.record
    session.record = lambda *args, **kwargs: (_ for _ in ()).throw(InputError("refused"))
    session.undo()
    session.record = original
    assert heard.of("message") == [("message", "refused")]
    assert session.points == [P, (13, 5)]


def test_an_algorithm_switch_compares_with_the_algorithm_before(session):
    session.set_algorithm("line-dda")
    assert session.previous[0].name == "line-bresenham" and session.compared
    assert session.previous_title == registry.get("line-bresenham").title
    session.set_compare(False)
    assert not session.compared and len(session.differences) == 0


def test_a_refused_switch_shows_the_example_shape():
    session = Session()
    session.sync_wait = None
    notched = [(0, 0), (20, 0), (10, 10), (20, 20), (0, 20)]
    session.set_scene("polygon-scanline", [notched], {}, (24, 24))
    session.set_algorithm("polygon-convex")
    assert session.refusal and session.points != notched and session.trace is not None


def test_a_background_recording_is_delivered_when_asked():
    session = Session()
    session.sync_wait = None
    session.set_scene("flood-fill", [[(0, 0), (6, 0), (6, 6), (0, 6)]], {}, (300, 300))
    old = session.trace
    heard = Heard(session)
    gate, record = threading.Event(), session.outcome
    session.outcome = lambda *a, **k: gate.wait(10) and record(*a, **k)
    session.sync_wait = 0.0
    session.set_points([(0, 0), (200, 0), (200, 200), (0, 200)])
    assert session.recording and session.trace is old and session.shown_scene != session.scene
    assert heard.of("recording_started")
    gate.set()
    assert session.wait(30.0)
    assert session.trace is not old and heard.of("recording_finished") == [
        ("recording_finished", "")]


def test_a_cancelled_recording_puts_the_scene_back():
    session = Session()
    session.sync_wait = None
    session.set_scene("flood-fill", [[(0, 0), (6, 0), (6, 6), (0, 6)]], {}, (300, 300))
    old_scene, old_trace = session.scene, session.trace
    heard = Heard(session)
    gate, record = threading.Event(), session.outcome
    session.outcome = lambda *a, **k: gate.wait(10) and record(*a, **k)
    session.sync_wait = 0.0
    session.set_points([(0, 0), (200, 0), (200, 200), (0, 200)])
    job = session.job
    session.cancel_recording()
    gate.set()
    assert job.wait(10.0) and job.cancelled
    session.deliver()
    assert session.scene == old_scene and session.trace is old_trace
    assert heard.of("message") == [("message", CANCELLED_MESSAGE)]


def test_a_run_over_the_memory_budget_is_refused_and_changes_nothing(session):
    before = session.scene
    session.memory_limit = 1024  # bytes: less than any run needs
    with pytest.raises(InputError, match="over the limit of"):
        session.set_points([P, (15, 7)])
    assert session.scene == before and session.trace is not None
    session.memory_limit = 2 * 1024 ** 3
    session.set_points([P, (15, 7)])
    assert session.points == [P, (15, 7)]


@pytest.mark.parametrize("algorithm, points", [
    ("line-bresenham", [P, Q]),
    ("polygon-scanline", [(1, 1), (13, 2), (7, 7)]),
])
def test_stepping_on_replays_onto_the_raster_on_show_and_matches_a_fresh_replay(
        algorithm, points):
    """Steps forward reuse the raster on show; whatever the path (forward by
    one, a jump, back), every state equals the one replayed from a keyframe."""
    session = Session()
    session.sync_wait = None
    session.set_scene(algorithm, points, {}, (16, 8))
    trace, last = session.trace, session.last
    session.seek(0)
    raster = session.state().raster
    path = [1, 2, 3, last // 2, last // 2 - 1, last // 2 + 4, last]
    for index in path:
        session.seek(index)
        state, fresh = session.state(), trace.state_at(index, compact=True)
        assert state.index == index and state.step == fresh.step
        assert (state.raster.counts == fresh.raster.counts).all()
        if fresh.raster.colors is not None:
            assert (state.raster.colors == fresh.raster.colors).all()
        assert state.variables == fresh.variables
    assert session.state().raster is not raster or last < 4  # a step back starts afresh
    if algorithm == "line-bresenham":
        written = {(x, y) for y, x in zip(*state.raster.counts.nonzero())}
        assert written == set(bresenham_pixels(P, Q))


def test_a_step_forward_writes_into_the_raster_already_on_show(session):
    session.seek(2)
    raster = session.state().raster
    session.seek(3)
    assert session.state().raster is raster
    session.seek(1)
    assert session.state().raster is not raster


def test_events_are_declared_on_the_class_and_heard_per_session():
    from app.model.events import Event
    declared = {name for name, value in vars(Session).items() if isinstance(value, Event)}
    assert declared == {"scene_changed", "trace_changed", "step_changed", "comparison_changed",
                        "recording_started", "recording_progress", "recording_finished",
                        "message"}
    one, other = Session(), Session()
    heard = []
    one.step_changed.connect(heard.append)
    one.step_changed.connect(lambda i: heard.append(-i))
    other.step_changed.emit(3)
    one.step_changed.emit(5)
    assert heard == [5, -5]  # this session's callbacks only, in the order connected
    one.step_changed.disconnect(heard.append)
    one.step_changed.emit(7)
    assert heard == [5, -5, -7]
