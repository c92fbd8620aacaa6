"""The texture panel at lecture-hall sizes: its pictures keep a quarter of the window's height
and grow with it, and its texts are whole (wrapped, and in their tooltips)."""
from __future__ import annotations

import pytest

from tests.support.gui import WAIT_MS

FLOOR = [(0, 0), (24, 0), (13.2, 15), (0, 0), (13.2, 15), (10.8, 15)]
OPTIONS = {"uv": (0, 0, 2, 0, 2, 9, 0, 0, 2, 9, 0, 9), "w": (1, 1, 10, 1, 10, 10),
           "texture": "checker:4", "filter": "trilinear"}


def _show_texture(window, qtbot, size):
    window.resize(*size)
    qtbot.waitUntil(lambda: window.width() == size[0], timeout=WAIT_MS)
    window.set_scene("triangle-texture", FLOOR, OPTIONS, grid=(24, 16))
    qtbot.waitUntil(lambda: window.texture_dock is not None and window.texture_dock.isVisible()
                    and window.player.trace is not None, timeout=WAIT_MS)
    window.player.seek(len(window.player.trace) // 2)
    qtbot.waitUntil(lambda: window.texture_view.caption.text() != "", timeout=WAIT_MS)
    qtbot.wait(50)  # the dock layout settles after the dock is shown


def _whole(label):
    return label.height() >= label.heightForWidth(label.width()) and \
        label.toolTip() == label.text()


@pytest.mark.parametrize("size", [(1280, 720), (1920, 1080)])
@pytest.mark.window("pipeline", [(3, 3), (28, 4), (15, 20)], {}, (32, 24))
def test_the_footprint_view_keeps_a_quarter_of_the_window(window, qtbot, size):
    # After the pipeline, whose docks took the room before.
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    _show_texture(window, qtbot, size)
    view = window.texture_view
    for plot in (view.texture_plot, view.level_plot):
        assert plot.height() >= window.height() // 4
    assert _whole(view.caption) and _whole(view.legend)
    assert "texels fetched" in view.caption.toolTip()
    # It grows with the window.
    before = view.texture_plot.height()
    window.resize(size[0], size[1] + 200)
    qtbot.waitUntil(lambda: view.texture_plot.height() >= window.height() // 4, timeout=WAIT_MS)
    assert view.texture_plot.height() > before
