"""Bugs the monkey test found, kept as plain tests."""
import pytest

from algorithms.core import registry
from app.model import scene as scenes
from tests.support.gui import WAIT_MS


pytestmark = pytest.mark.window(shown=False)


def test_an_option_set_while_placing_points_does_not_block_a_switch(window):
    # While the points are incomplete there is no run to check the colours
    # against, so a single colour is taken; the next algorithm's run refuses
    # it. The switch used to be refused, leaving the person stuck.
    window.set_algorithm("flood-fill")
    window.set_points([(1, 1)])
    assert window.player.trace is None
    window.set_option("colors", ("#ff0000",))
    assert window.player.options["colors"] == ("#ff0000",)
    window.set_algorithm("flood-fill-circle")
    assert window.player.spec.name == "flood-fill-circle"
    assert window.player.trace is not None
    assert len(window.player.options["colors"]) == 2  # its own default pair
    assert "colours" in window.message.text()  # and it says why


@pytest.mark.parametrize("name", [spec.name for spec in registry.all_specs()
                                  if not spec.inputs.contours])
def test_a_scene_without_points_still_converts(name):
    # All points removed (Backspace): the autosave's to_json divided the
    # points into groups of zero and raised.
    assert scenes.Scene(algorithm=name, points=[]).to_json()["primitives"] == [{"points": []}]


def test_a_switch_to_a_fill_on_a_grid_too_thin_for_any_outline_keeps_the_points(window, qtbot):
    # On a grid one row high no outline has a free pixel inside, so the fill
    # refused the points and then its own example shape, and the switch was
    # refused: the window stayed on the polygon algorithm.
    window.set_algorithm("polygon-tessellate")
    window.set_points([(5.5, 0.5)])
    window.set_grid(12, 1)
    qtbot.waitUntil(lambda: not window.player.recording, timeout=WAIT_MS)
    window.set_algorithm("flood-fill")
    qtbot.waitUntil(lambda: not window.player.recording, timeout=WAIT_MS)
    assert window.player.spec.name == "flood-fill"
    assert window.picker.current_name() == "flood-fill"
    assert window.player.points == [(5, 0)]  # the point, as the fill takes it
    assert window.player.trace is None  # still being placed: nothing runs
    assert "enlarge the grid" in window.message.text()


def test_complete_points_no_fill_can_run_on_are_kept_until_a_seed_is_given(window, qtbot):
    window.set_algorithm("polygon-tessellate")
    window.set_points([(0.5, 0.5), (10.5, 0.5), (5.5, 1.5)])
    window.set_grid(12, 2)
    qtbot.waitUntil(lambda: not window.player.recording, timeout=WAIT_MS)
    assert window.player.grid == (12, 2) and window.player.trace is not None
    qtbot.waitUntil(lambda: not window.player.recording, timeout=WAIT_MS)
    window.set_algorithm("flood-fill")
    qtbot.waitUntil(lambda: not window.player.recording, timeout=WAIT_MS)
    assert window.player.spec.name == "flood-fill"
    assert window.player.points == [(0, 0), (10, 0), (5, 1)]
    assert "no free pixel" in window.message.text()
    # what the message says to do works: a seed outside the outline fills the rest
    window.set_option("seed", (11, 1))
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    assert window.player.options["seed"] == (11, 1)
