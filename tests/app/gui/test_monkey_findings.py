"""Bugs the monkey test found, kept as plain tests."""
import pytest

from algorithms import registry
from app.model import scene as scenes


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
