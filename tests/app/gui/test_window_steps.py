"""Stepping repaints only what the step changed, and the screen still shows
the whole picture: the grid's image is patched in place, never handed over
again, and what is on screen equals the grid painted afresh, forward and
backward."""
import numpy as np
import pytest
from PySide6.QtCore import QEvent, QObject

from app.render.compose import compose
from tests.support.gui import off_cell_edges, on_screen, repainted

pytestmark = pytest.mark.window("line-bresenham", [(1, 2), (44, 29)], grid=(48, 32))


class PaintedAreas(QObject):
    """The bounding rectangles of the paint events a widget receives."""

    def __init__(self, widget):
        super().__init__()
        self.rects = []
        widget.installEventFilter(self)

    def eventFilter(self, obj, event):  # noqa: N802
        if event.type() == QEvent.Type.Paint:
            self.rects.append(event.region().boundingRect())
        return False


def _step_to(qtbot, player, index):
    player.seek(index)
    qtbot.wait(5)  # the event loop paints what the step asked for


def test_steps_patch_the_grid_and_the_screen_shows_the_whole_picture(make_window, qtbot):
    window = make_window(settled=True)
    player, grid = window.player, window.grid
    player.pause()
    _step_to(qtbot, player, 4)
    handed = []
    original = grid.image.setImage
    grid.image.setImage = lambda *args, **kwargs: (handed.append(1), original(*args, **kwargs))
    painted = PaintedAreas(grid.viewport())
    inside = off_cell_edges(grid)
    assert inside.mean() > 0.5
    for index in [5, 6, 7, 12, 11, 10, 3, 2, 20, 21]:
        painted.rects.clear()
        _step_to(qtbot, player, index)
        # A step of one cell repaints a small part of the grid, not all of it.
        area = sum(rect.width() * rect.height() for rect in painted.rects)
        assert 0 < area < grid.viewport().width() * grid.viewport().height() / 4, index
        expected = compose(player.trace.state_at(index).raster, None, window.palette_)
        assert np.array_equal(grid.image.image, expected), index
        # What is on screen is the grid painted whole (see off_cell_edges).
        shown, whole = on_screen(grid), repainted(grid)
        assert np.array_equal(shown[inside], whole[inside]), index
    assert not handed  # the picture was patched in place every time
