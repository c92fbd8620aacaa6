"""Play holds an animation to SAFE_FPS animation frames a second whatever
speed is chosen (app/gui/player.py, app/render/flash_guard.py), says so in
the status bar, and leaves runs without animation frames alone."""
import pytest

from algorithms.core.steps import Vars
from app.gui.player import MAX_SPEED, MIN_TICK_MS
from app.model import shipped
from app.model.scene import load
from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window()


def show(qtbot, window, name):
    scene = load(shipped.scene_path(name))
    window.set_scene(scene.algorithm, list(scene.points), dict(scene.options),
                     (scene.width, scene.height))
    qtbot.waitUntil(lambda: window.player.trace is not None
                    and window.player.trace_spec.name == scene.algorithm, timeout=WAIT_MS)
    window.player.first()


def fewest_steps_between_frames(trace) -> int:
    """Worked out from the records: frame k begins at the Vars record naming
    it and shows complete one step before frame k + 1 begins (the last one
    at the step before the closing record); the empty grid at step 0 is the
    picture before frame 0."""
    starts = [index for index, record in trace.records_of(Vars) if "frame" in record.values]
    complete = [0] + [start - 1 for start in starts[1:]] + [len(trace) - 2]
    return min(b - a for a, b in zip(complete, complete[1:]))


def test_a_fast_animation_plays_at_most_7_frames_a_second(qtbot, window):
    show(qtbot, window, "aa-motion-blur-jittered")
    player = window.player
    cap = 7 * fewest_steps_between_frames(player.trace)
    window.transport.set_speed(MAX_SPEED)
    player.play()
    try:
        assert player.speed == MAX_SPEED > cap          # the chosen speed is kept
        assert player.speed_cap == cap and player.effective_speed == cap
        assert player.interval == max(MIN_TICK_MS, int(1000 / cap))
        line = window.statusBar().currentMessage()
        assert line.startswith(f"Playing at most {cap} steps/s") and "3 times a second" in line
    finally:
        player.pause()


def test_it_is_said_once_and_a_slow_speed_is_not_capped(qtbot, window):
    show(qtbot, window, "aa-temporal-accumulation")
    player = window.player
    said = []
    player.speedCapped.connect(said.append)
    window.transport.set_speed(20)
    player.play()
    try:
        assert not player.capped and player.effective_speed == 20 and said == []
        window.transport.set_speed(MAX_SPEED)
        window.transport.set_speed(MAX_SPEED - 100)
        assert player.capped and len(said) == 1
        assert player.effective_speed == player.speed_cap < MAX_SPEED - 100
    finally:
        player.pause()


def test_a_run_without_animation_frames_plays_at_the_speed_chosen(qtbot, window):
    show(qtbot, window, "demo-bresenham")
    player = window.player
    said = []
    player.speedCapped.connect(said.append)
    window.transport.set_speed(MAX_SPEED)
    player.play()
    player.pause()
    assert player.speed_cap is None and player.effective_speed == MAX_SPEED
    assert said == []
