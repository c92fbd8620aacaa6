"""The playback controller: recording, moving, playing, re-recording."""
import numpy as np
import pytest

from algorithms.core import registry
from algorithms.core.registry import InputError
from app.gui.player import Player
from tests.support.gui import WAIT_MS

P, Q = (4, 5), (28, 15)
pytestmark = pytest.mark.player("line-bresenham", [P, Q], grid=(32, 24))


def expected_trace(name="line-bresenham", points=(P, Q), options=None, grid=(32, 24)):
    return registry.get(name).record(list(points), options or {}, grid)


def test_a_new_scene_is_shown_at_its_last_step(player):
    trace = expected_trace()
    assert len(player) == len(trace)
    assert player.index == len(trace) - 1
    assert np.array_equal(player.trace.written_pixels(), trace.written_pixels())


def test_moving_through_the_steps(player):
    player.first()
    assert player.index == 0
    player.forward()
    player.forward()
    assert player.index == 2
    player.back()
    assert player.index == 1
    player.seek(10_000)
    assert player.index == player.last
    player.seek(-5)
    assert player.index == 0
    player.to_last()
    assert player.index == len(player) - 1


def test_state_is_the_replayed_frame(player):
    player.seek(7)
    trace = expected_trace()
    state = player.state()
    assert state.index == 7
    assert state.step.pixel == trace.step(7).pixel
    assert np.array_equal(state.raster.counts, trace.raster_at(7).counts)


def test_re_recording_at_the_end_stays_at_the_end(player):
    player.set_points([P, (30, 20)])
    assert player.index == player.last == len(expected_trace(points=(P, (30, 20)))) - 1


def test_re_recording_mid_run_keeps_the_relative_position(player):
    player.seek(player.last // 2)
    fraction = player.index / player.last
    player.set_points([(0, 0), (31, 2)])  # a longer run
    assert abs(player.index / player.last - fraction) < 0.05
    assert player.index < player.last


def test_fewer_points_than_needed_leave_no_trace(player):
    player.set_points([P])
    assert player.trace is None and len(player) == 0 and player.state() is None
    player.set_points([P, Q])
    assert player.trace is not None
    with pytest.raises(InputError):
        player.set_points([P, Q, Q])


def test_a_bad_option_keeps_the_last_good_value(player):
    with pytest.raises(InputError):
        player.set_option("symmetric", "maybe")
    assert player.options["symmetric"] is False
    with pytest.raises(InputError):
        player.set_option("nonexistent", 1)
    # A value the option accepts but the run refuses (one colour for two ends).
    with pytest.raises(InputError):
        player.set_option("colors", ("#ff0000",))
    assert player.options["colors"] == ()
    assert player.trace is not None
    player.set_option("symmetric", True)
    assert player.options["symmetric"] is True


def test_switching_algorithm_compares_with_the_previous_one(player):
    player.set_algorithm("line-dda")
    assert player.spec.name == "line-dda" and player.points == [P, Q]
    assert player.previous_title == "Bresenham"
    a = {tuple(p) for p in expected_trace().written_pixels().tolist()}
    b = {tuple(p) for p in expected_trace("line-dda").written_pixels().tolist()}
    assert {tuple(c) for c in player.differences.tolist()} == a ^ b
    # The comparison follows the points.
    player.set_points([(0, 0), (26, 13)])
    a = {tuple(p) for p in expected_trace(points=((0, 0), (26, 13))).written_pixels().tolist()}
    b = {tuple(p) for p in expected_trace("line-dda", points=((0, 0), (26, 13))).written_pixels().tolist()}
    assert len(a ^ b) > 0
    assert {tuple(c) for c in player.differences.tolist()} == a ^ b
    assert player.compared
    player.set_compare(False)
    assert len(player.differences) == 0 and not player.compared


def test_grid_changes_clamp_the_points(player):
    player.set_grid(20, 10)
    assert player.points == [P, (19, 9)]
    assert player.trace.width == 20 and player.trace.height == 10
    with pytest.raises(InputError):
        player.set_grid(0, 10)
    with pytest.raises(InputError):
        player.set_grid(5000, 10)
    assert player.grid == (20, 10)


def test_play_runs_to_the_end_and_stops(qtbot, player):
    player.first()
    player.set_speed(400)
    with qtbot.waitSignal(player.playingChanged, timeout=WAIT_MS):
        player.play()
    assert player.playing
    qtbot.waitUntil(lambda: not player.playing, timeout=WAIT_MS)
    assert player.index == player.last


def test_play_skips_frames_at_high_speed(qtbot):
    player = Player()
    player.set_scene("line-bresenham", [(0, 0), (2000, 700)], grid=(2048, 1024))
    player.first()
    player.set_speed(2000)
    shown = []
    player.frameChanged.connect(shown.append)
    player.play()
    qtbot.waitUntil(lambda: not player.playing, timeout=WAIT_MS)
    assert player.index == player.last
    # About 60 frames a second: far fewer frames than steps.
    assert len(shown) < player.last / 3


def test_pause_and_toggle(qtbot, player):
    player.first()
    player.set_speed(5)
    player.toggle()
    assert player.playing
    player.toggle()
    assert not player.playing
    # Playing from the last step starts again from the first.
    player.to_last()
    player.play()
    assert player.index == 0 and player.playing
    player.pause()


def test_speed_is_clamped(player):
    player.set_speed(0)
    assert player.speed == 1
    player.set_speed(1e9)
    assert player.speed == 2000
    with pytest.raises(InputError):
        player.set_speed(float("nan"))
