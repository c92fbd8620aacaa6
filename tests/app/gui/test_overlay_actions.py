"""View > Overlays: the window draws the strokes of app/render/overlays.py for
the step on show, and follows the step."""
import math

import pytest

from app.render import overlays

TRIANGLE = ((4.25, 3.5), (27.5, 8.75), (11.125, 21.25))
pytestmark = pytest.mark.window("triangle-bbox", TRIANGLE)


def drawn(window):
    """(colour, x, y) of every point the overlay layer's items hold."""
    points = set()
    for colour, item in window.overlays.layer._items.items():
        xs, ys = item.getData()
        if xs is None:
            continue
        points |= {(colour, round(x, 9), round(y, 9)) for x, y in zip(xs, ys)
                   if not math.isnan(x)}
    return points


def expected(window, names):
    trace, index = window.player.trace, window.player.state().index
    return {(s.colour, round(x, 9), round(y, 9))
            for s in overlays.overlay_strokes(trace, index, names) for x, y in s.points}


def test_each_overlay_draws_its_strokes_and_follows_the_step(window, qtbot):
    window.player.seek(200)
    assert drawn(window) == set()
    for name in overlays.OVERLAYS:
        window.actions_[f"overlay-{name}"].setChecked(True)
        assert drawn(window) == expected(window, [name]) != set()
        window.actions_[f"overlay-{name}"].setChecked(False)
    window.actions_["overlay-distances"].setChecked(True)
    before = drawn(window)
    window.player.seek(240)
    assert drawn(window) == expected(window, ["distances"]) != before


def test_overlays_leave_other_families_alone(window):
    window.actions_["overlay-basis"].setChecked(True)
    window.set_algorithm("line-bresenham")
    assert drawn(window) == set()
