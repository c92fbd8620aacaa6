"""View > Overlays: the window draws the strokes of app/render/overlays.py for
the step on show, and follows the step."""
import math

import pytest

from app.render import overlays

TRIANGLE = ((4.25, 3.5), (27.5, 8.75), (11.125, 21.25))
pytestmark = pytest.mark.window("triangle-bbox", TRIANGLE)
TRIANGLE_OVERLAYS = ("half-planes", "sub-triangles", "distances", "basis")


def drawn(window):
    """(colour, x, y) of every point the overlay layer's items hold."""
    points = set()
    for (colour, _width), item in window.overlays.layer._items.items():
        xs, ys = item.getData()
        if xs is None:
            continue
        points |= {(colour, round(x, 9), round(y, 9)) for x, y in zip(xs, ys)
                   if not math.isnan(x)}
    return points


def expected(window, names, line=None):
    trace, index = window.player.trace, window.player.state().index
    return {(s.colour, round(x, 9), round(y, 9))
            for s in overlays.overlay_strokes(trace, index, names, line) for x, y in s.points}


def test_each_overlay_draws_its_strokes_and_follows_the_step(window, qtbot):
    window.player.seek(200)
    assert drawn(window) == set()
    for name in TRIANGLE_OVERLAYS:
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


def test_the_octant_diagram_follows_the_line_and_says_the_mirrors(window, qtbot):
    window.actions_["overlay-octants"].setChecked(True)
    assert drawn(window) == set()  # a triangle run has no octant
    window.set_scene("line-bresenham", [(14, 14), (8, 1)], {}, (32, 24))
    qtbot.waitUntil(lambda: window.player.trace is not None
                    and window.player.spec.name == "line-bresenham", timeout=10_000)
    line = ((14.5, 14.5), (8.5, 1.5))
    assert drawn(window) == expected(window, ["octants"], line) != set()
    assert window.overlays.octant_text() == ("octant 6 -> 1: mirror x (x -> -x), then "
                                             "mirror y (y -> -y), then swap x and y")
    assert window.statusBar().currentMessage() == window.overlays.octant_text()
    window.actions_["overlay-octants"].setChecked(False)
    assert drawn(window) == set() and window.overlays.octant_text() == ""


def test_a_scene_switches_its_overlays_on(window, qtbot):
    from app.model import shipped
    from app.model.scene import load
    if window.file_actions is None:
        window.add_file_actions()
    window.file_actions.apply_scene(load(shipped.scene_path("line-octants")))
    assert window.actions_["overlay-octants"].isChecked()


def test_the_window_fills_and_labels_the_sub_triangles_as_export_does(window):
    window.player.seek(200)
    window.actions_["overlay-sub-triangles"].setChecked(True)
    trace, index = window.player.trace, window.player.state().index
    shapes = overlays.overlay_shapes(trace, index, ["sub-triangles"])
    layer = window.overlays.layer
    assert layer.fills() == [(tuple(f.points), tuple(f.colour) + (round(f.alpha * 255),))
                             for f in shapes.fills]
    assert layer.labels() == [(tuple(label.at), label.text) for label in shapes.labels]
    assert [text for _, text in layer.labels()] == ["\u03b1", "\u03b2", "\u03b3"]
    window.actions_["overlay-sub-triangles"].setChecked(False)
    assert layer.fills() == [] and layer.labels() == []
