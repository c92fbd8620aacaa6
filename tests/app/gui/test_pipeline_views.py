"""The pipeline's side views at lecture-hall sizes: the scene from outside gets a usable share
of the window, no dock overlaps another, and the handles sit where the viewport puts the
vertices (computed here with the matrices written out in tests/support/pipeline.py)."""
from __future__ import annotations

import pytest

from algorithms.core import registry
from tests.support import pipeline as matrices
from tests.support.gui import WAIT_MS

CROSSING = [(21, 15), (24, 15), (27, 15), (8, 6), (24, 20), (40, 6)]
OPTIONS = {"z": (-5, 10, -5, -30, -30, -30), "eye": (24, 16, 3), "target": (24, 15, -5),
           "fov": 60, "near": 0.5, "far": 50}
GRID = (48, 32)


def _open_pipeline(window, qtbot, size):
    window.resize(*size)
    qtbot.waitUntil(lambda: window.width() == size[0], timeout=WAIT_MS)
    window.set_scene("pipeline", CROSSING, OPTIONS, grid=GRID)
    qtbot.waitUntil(lambda: window.outside_dock is not None and window.outside_dock.isVisible()
                    and window.player.trace is not None, timeout=WAIT_MS)
    qtbot.wait(50)  # the dock layout settles after the dock is shown


def _visible_docks(window):
    from PySide6.QtWidgets import QDockWidget
    return [d for d in window.findChildren(QDockWidget) if d.isVisible() and not d.isFloating()]


@pytest.mark.parametrize("size", [(1280, 720), (1920, 1080)])
@pytest.mark.window("triangle-bbox", [(3, 3), (28, 4), (15, 20)], {}, (32, 24))
def test_the_scene_from_outside_gets_a_usable_size(window, qtbot, size):
    _open_pipeline(window, qtbot, size)
    plot = window.outside_view.plot
    assert plot.height() >= window.height() / 4
    assert plot.width() >= 200
    docks = _visible_docks(window)
    outside = window.outside_dock.geometry()
    for dock in docks:
        if dock is not window.outside_dock:
            assert not dock.geometry().intersects(outside), dock.objectName()


@pytest.mark.window("triangle-bbox", [(3, 3), (28, 4), (15, 20)], {}, (32, 24))
def test_the_handles_sit_where_the_viewport_puts_the_vertices(window, qtbot):
    _open_pipeline(window, qtbot, (1280, 720))
    options = registry.get("pipeline").resolve(OPTIONS)
    expected = matrices.stages(CROSSING, OPTIONS["z"], options, GRID)
    in_front = expected["clip"][:, 3] > 0
    assert not in_front.all()  # P1 lies behind the eye: it has no place on the screen
    xs, ys = window.grid.handles.getData()
    assert list(xs) == pytest.approx(list(expected["window"][in_front, 0]))
    assert list(ys) == pytest.approx(list(expected["window"][in_front, 1]))
    assert "window space" in window.message.text()
    # They do not drag: a press on a handle grabs nothing.
    assert window.grid._handle_at(window.grid.scene_pos_of((xs[0], ys[0]))) is None
    window.set_scene("triangle-bbox", [(3, 3), (28, 4), (15, 20)], {}, grid=(32, 24))
    qtbot.waitUntil(lambda: not window.outside_dock.isVisible(), timeout=WAIT_MS)
    xs, ys = window.grid.handles.getData()
    assert (list(xs), list(ys)) == ([3, 28, 15], [3, 4, 20])  # at the points again
    assert "window space" not in window.message.text()


@pytest.mark.window("triangle-bbox", [(3, 3), (28, 4), (15, 20)], {}, (32, 24))
def test_the_side_picture_follows_the_stage_of_the_step(window, qtbot):
    _open_pipeline(window, qtbot, (1280, 720))
    for step, title in ((1, "Model"), (2, "View"), (3, "Projection"), (4, "Clip"),
                        (5, "Divide"), (6, "Viewport"), (8, "Rasterize")):
        window.player.seek(step)
        qtbot.waitUntil(lambda: window.outside_dock.windowTitle().startswith(title),
                        timeout=WAIT_MS)
