"""Long recordings run in the background: the window stays responsive, the
previous run stays on show, Cancel (or Esc) keeps it, the newest edit wins.

Every test here sets ``sync_wait = 0``, so any recording that is not done
the moment it starts goes on in the worker (tests/conftest.py makes every
other test wait for its recording).
"""
import gc
import threading

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from algorithms.core import registry
from app.gui.player import Player
from app.model.session import CANCELLED_MESSAGE
from app.gui.recording import GapMeter, seek_when_recorded
from app.gui.window import MainWindow
from tests.support.gui import WAIT_MS

# A square outline whose inside is a 1024 x 1024 region of free pixels.
BIG = 1025
SQUARE = [(0, 0), (BIG, 0), (BIG, BIG), (0, BIG)]
FILL_GRID = (1030, 1030)
SMALL_SQUARE = [(0, 0), (6, 0), (6, 6), (0, 6)]
TRIANGLE_GRID = (4096, 4096)
TRIANGLE = [(0.0, 0.0), (4096.0, 0.0), (0.0, 4096.0)]
TRIANGLE_CAP = 300_000
FILL_RGB, BOUNDARY_RGB = 0x2E86DE, 0xC0392B


def block(side_x: int, side_y: int, grid=FILL_GRID) -> np.ndarray:
    """Every pixel of [0, side_x] x [0, side_y] (a mask, rows are y): an
    axis-aligned rectangle's outline (its Bresenham segments are the rows
    and columns on its edge) plus the inside the fill reaches."""
    mask = np.zeros((grid[1], grid[0]), dtype=bool)
    mask[:side_y + 1, :side_x + 1] = True
    return mask


def written(trace, grid=FILL_GRID) -> np.ndarray:
    """The pixels the run writes, as a mask (each at least once)."""
    mask = np.zeros((grid[1], grid[0]), dtype=bool)
    pixels = trace.written_pixels()
    mask[pixels[:, 1], pixels[:, 0]] = True
    return mask


def same(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and bool(np.array_equal(a, b))


pytestmark = [pytest.mark.window("flood-fill", [SMALL_SQUARE], grid=FILL_GRID, sync_wait=0.0),
              pytest.mark.player("flood-fill", [SMALL_SQUARE], grid=FILL_GRID, sync_wait=0.0)]


class Signals:
    """What the player said, in order."""

    def __init__(self, player):
        self.events = []
        player.recordingStarted.connect(lambda: self.events.append(("started",)))
        player.recordingProgress.connect(lambda n: self.events.append(("progress", n)))
        player.recordingFinished.connect(lambda m: self.events.append(("finished", m)))
        player.traceChanged.connect(lambda: self.events.append(("trace",)))

    def of(self, kind):
        return [event for event in self.events if event[0] == kind]


def test_flood_fill_of_a_1024_region_records_in_the_background(qtbot, player):
    old = player.trace
    heard = Signals(player)
    player.set_points(SQUARE)
    # The edit returned at once: the scene is the new one, the run on show the old.
    assert player.recording and player.trace is old and player.points == SQUARE
    player.back()  # the old run can still be stepped
    assert player.index == len(old) - 2
    player.to_last()
    with qtbot.waitSignal(player.recordingFinished, timeout=60_000) as finished:
        pass
    assert finished.args == [""] and not player.recording
    kinds = [event[0] for event in heard.events]
    assert kinds[0] == "started" and kinds[-2:] == ["trace", "finished"]
    counts = [n for _, n in heard.of("progress")]
    assert counts and counts == sorted(counts) and len(set(counts)) == len(counts)
    trace = player.trace
    assert counts[-1] <= len(trace)
    # Independent oracle: the outline's pixels and the 1024 x 1024 inside.
    assert same(written(trace), block(BIG, BIG))
    colors = player.final_raster().colors
    assert np.all(colors[1:BIG, 1:BIG] == FILL_RGB)
    assert np.all(colors[0, :BIG + 1] == BOUNDARY_RGB)
    # And exactly the frames an in-place recording makes.
    direct = registry.get("flood-fill").record([SQUARE], {}, FILL_GRID)
    assert len(trace) == len(direct) and player.index == len(direct) - 1
    assert np.array_equal(trace.x, direct.x) and np.array_equal(trace.line, direct.line)


def test_triangle_on_a_4096_grid_records_in_the_background(qtbot):
    player = Player(step_cap=TRIANGLE_CAP)
    player.sync_wait = None
    player.set_scene("triangle-bbox", [(1.0, 1.0), (9.0, 1.0), (1.0, 9.0)], {}, TRIANGLE_GRID)
    player.sync_wait = 0.0
    player.set_points(TRIANGLE)
    assert player.recording
    with qtbot.waitSignal(player.recordingFinished, timeout=60_000):
        pass
    trace = player.trace
    assert len(trace) == TRIANGLE_CAP and trace.truncated
    direct = registry.get("triangle-bbox").record(TRIANGLE, {}, TRIANGLE_GRID,
                                                  step_cap=TRIANGLE_CAP)
    assert np.array_equal(trace.x, direct.x) and np.array_equal(trace.y, direct.y)
    # Each pixel written has its centre inside the triangle x + y <= 4096.
    pixels = trace.written_pixels()
    assert len(pixels) > 0
    assert np.all(2 * (pixels[:, 0] + pixels[:, 1]) + 2 <= 2 * 4096)
    assert np.all(pixels >= 0)


def test_cancel_keeps_the_previous_scene_and_run(qtbot, window):
    player = window.player
    old_trace, old_points = player.trace, list(player.points)
    window.set_points(SQUARE)
    assert player.recording
    status = window.recording_status
    qtbot.waitUntil(status.button.isVisible, timeout=WAIT_MS)
    assert status.bar.isVisible() and player.recording
    assert status.button.toolTip() and status.bar.toolTip()
    assert status.label.isVisible() and status.label.text().startswith("Recording\u2026")
    job = player.session.job
    QTest.keyClick(window, Qt.Key.Key_Escape)
    assert not player.recording
    assert player.points == old_points and player.trace is old_trace
    assert window.grid.points == old_points
    assert window.message.text() == CANCELLED_MESSAGE
    assert not status.bar.isVisible() and not status.button.isVisible()
    assert job.wait(5.0) and job.cancelled  # the worker stopped
    qtbot.wait(50)  # whatever the worker sent on its way out changes nothing
    assert player.trace is old_trace


def test_esc_cancels_the_recording_before_it_lets_go_of_a_pinned_pixel(qtbot, window):
    player = window.player
    old_trace = player.trace
    window.inspector.pin((3, 3))
    window.set_points(SQUARE)
    QTest.keyClick(window.grid.viewport(), Qt.Key.Key_Escape)
    assert not player.recording and player.trace is old_trace
    assert window.inspector.pinned == (3, 3)  # the first Esc went to the recording
    QTest.keyClick(window.grid.viewport(), Qt.Key.Key_Escape)
    assert window.inspector.pinned is None  # and the next one to the inspector


def test_cancel_button_stops_the_recording(qtbot, window):
    player = window.player
    old_trace = player.trace
    window.set_points(SQUARE)
    QTest.mouseClick(window.recording_status.button, Qt.MouseButton.LeftButton)
    assert not player.recording and player.trace is old_trace


def test_a_second_edit_while_recording_wins(qtbot, player):
    heard = Signals(player)
    player.set_points(SQUARE)
    first = player.session.job
    narrow = [(0, 0), (BIG, 0), (BIG, 300), (0, 300)]
    player.set_points(narrow)
    assert first.monitor.cancelled and player.recording
    with qtbot.waitSignal(player.recordingFinished, timeout=60_000):
        pass
    assert first.wait(5.0) and first.cancelled and first.result is None
    assert heard.of("trace") == [("trace",)]  # installed once: the newest
    assert player.points == narrow and same(written(player.trace), block(BIG, 300))


def test_a_run_refused_in_the_background_keeps_the_scene(qtbot, window, monkeypatch):
    player = window.player
    old_trace, old_options = player.trace, dict(player.options)
    # Hold the worker until the edit has returned, so that the refusal
    # surely comes from the background.
    gate, record = threading.Event(), player.session.outcome
    monkeypatch.setattr(player.session, "outcome",
                        lambda *a, **k: gate.wait(10) and record(*a, **k))
    window.set_points(SQUARE)
    window.set_option("seed", (0, 5))  # on the outline: the fill refuses it
    assert player.recording and player.options["seed"] == (0, 5)
    with qtbot.waitSignal(player.recordingFinished, timeout=60_000) as finished:
        gate.set()
    assert "lies on the boundary" in finished.args[0]
    assert player.options == old_options and player.points == SMALL_SQUARE
    assert player.trace is old_trace and window.grid.points == SMALL_SQUARE
    assert "lies on the boundary" in window.message.text()


def test_the_event_loop_stays_responsive_while_recording(qtbot, window):
    """A 10 ms timer ticks again and again while the recording runs: the
    event loop goes on in the meantime. Its gaps are printed, not bounded:
    how long they are depends on the machine and its load
    (benchmarks/bench_recording.py measures them)."""
    # Windows earlier tests left as garbage are destroyed now, not by a
    # collection while the gaps are measured (one took 0.4 s in a full run).
    gc.collect()
    meter = GapMeter(10)
    qtbot.wait(30)
    started = meter.restart()
    window.set_points(SQUARE)
    job = window.player.session.job
    qtbot.waitUntil(lambda: not window.player.recording, timeout=60_000)
    qtbot.wait(30)  # the installed trace is shown within these ticks
    meter.stop()
    assert same(written(window.player.trace), block(BIG, BIG))
    recording, after = meter.split(job.finished_at)
    worst, p99 = max(recording), float(np.percentile(recording, 99))
    print(f"\nevent-loop gaps while recording {len(window.player.trace):,} steps "
          f"({job.finished_at - started:.2f} s, {len(recording)} ticks): max "
          f"{worst * 1000:.1f} ms, p99 {p99 * 1000:.1f} ms; installing and showing the "
          f"trace: {max(after) * 1000:.1f} ms")
    # A recording that held the window's thread would leave it no tick until
    # its end; a flood fill of a million pixels records for seconds.
    assert len(recording) > 20


def test_closing_the_window_stops_the_recording(qtbot):
    w = MainWindow("flood-fill", [SMALL_SQUARE], grid=FILL_GRID)
    qtbot.addWidget(w)
    w.show()
    w.player.sync_wait = 0.0
    w.set_points(SQUARE)
    job = w.player.session.job
    assert job is not None
    w.close()
    assert job.done and job.cancelled and not w.player.recording
    assert not job._thread.is_alive() or job._thread.join(1.0) is None


def test_a_short_run_is_installed_before_the_edit_returns(qtbot, player):
    """Runs that end within the wait behave as before: no background, no signals."""
    heard = Signals(player)
    player.sync_wait = 5.0
    player.set_points([(0, 0), (9, 0), (9, 9), (0, 9)])
    assert not player.recording and heard.of("started") == [] and heard.of("trace")
    assert same(written(player.trace), block(9, 9))


def test_a_saved_step_is_reached_once_the_run_is_recorded(qtbot, player):
    player.set_points([(0, 0), (BIG, 0), (BIG, 300), (0, 300)])
    seek_when_recorded(player, 1234)
    assert player.index != 1234
    with qtbot.waitSignal(player.recordingFinished, timeout=60_000):
        pass
    assert player.index == 1234 and len(player.trace) > 1234


def test_the_first_scene_is_waited_for(qtbot):
    """With no run on show there is nothing to fall back on or to cancel to."""
    player = Player()
    player.sync_wait = 0.0
    player.set_scene("flood-fill", [[(0, 0), (300, 0), (300, 300), (0, 300)]], {}, (310, 310))
    assert not player.recording
    assert same(written(player.trace, (310, 310)), block(300, 300, (310, 310)))


def test_an_algorithm_switch_refused_in_the_background_shows_an_example(
        qtbot, window, monkeypatch):
    player = window.player
    notched = [(0, 0), (600, 0), (300, 300), (600, 600), (0, 600)]
    player.sync_wait = None
    window.set_points(notched)
    player.sync_wait = 0.0
    old_trace = player.trace
    gate, record = threading.Event(), player.session.outcome
    monkeypatch.setattr(player.session, "outcome",
                        lambda *a, **k: gate.wait(10) and record(*a, **k))
    window.set_algorithm("polygon-convex")
    # The editors follow the switch at once; the fill's run stays on show.
    assert player.recording and player.spec.name == "polygon-convex"
    assert window.picker.current_name() == "polygon-convex" and player.trace is old_trace
    assert player.trace_spec.name == "flood-fill"
    player.back()  # stepping the fill's run uses the fill's own panel rows
    with qtbot.waitSignal(player.recordingFinished, timeout=60_000) as finished:
        gate.set()
    assert "refused the points drawn before" in finished.args[0]
    assert player.trace_spec.name == "polygon-convex" and player.points != notched
    assert window.grid.points == player.points  # the editors show the example shape
    assert "refused the points drawn before" in window.message.text()


def test_an_example_shape_recorded_in_the_background_is_shown_on_the_grid(make_window, qtbot):
    """Two points are too few for a triangle: the switch records the
    algorithm's example in the background, and the grid then shows it."""
    w = make_window("line-bresenham", grid=(32, 24), sync_wait=0.0)
    assert len(w.player.points) == 2
    w.set_algorithm("aa-supersample")
    qtbot.waitUntil(lambda: not w.player.recording, timeout=30_000)
    qtbot.wait(10)
    assert len(w.player.points) == 3
    assert [tuple(p) for p in w.grid.points] == [tuple(p) for p in w.player.points]
    assert w.grid.labels() == ["T1.P1", "T1.P2", "T1.P3"]
