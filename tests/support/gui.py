"""Shared by the window tests."""

# How long a test waits for the window to do something, in ms: long enough
# for the slowest, busiest machine. A wait ends as soon as its condition
# holds, so a long limit costs nothing; it only stops a test that would
# otherwise hang.
WAIT_MS = 60_000


def settle(qtbot, window):
    """Wait until the grid's view has taken its final place after showing:
    pyqtgraph fits the view to the widget's final size a moment later."""
    where = []

    def still():
        where.append(window.grid.widget_pos_of((0.0, 0.0)))
        return len(where) > 2 and where[-1] == where[-2] == where[-3]
    qtbot.waitUntil(still, timeout=WAIT_MS)


def shown_window(qtbot, *args, settled: bool = False, **kwargs):
    """A MainWindow(*args, **kwargs) on screen, closed after the test; with
    ``settled`` its grid view has taken its final place too."""
    from app.gui.window import MainWindow
    window = MainWindow(*args, **kwargs)
    qtbot.addWidget(window)
    window.show()
    qtbot.waitExposed(window)
    if settled:
        settle(qtbot, window)
    return window


def drag(qtbot, window, start, end, modifier=None, steps=4):
    """Press at grid point ``start``, move in ``steps``, release at ``end``."""
    from PySide6.QtCore import Qt
    from PySide6.QtTest import QTest
    modifier = Qt.KeyboardModifier.NoModifier if modifier is None else modifier
    left = Qt.MouseButton.LeftButton
    viewport = window.grid.viewport()
    a, b = window.grid.widget_pos_of(start), window.grid.widget_pos_of(end)
    QTest.mousePress(viewport, left, modifier, a)
    for k in range(1, steps + 1):
        QTest.mouseMove(viewport, a + (b - a) * (k / steps))
        qtbot.wait(15)  # pyqtgraph drops mouse moves that come too fast
    QTest.mouseRelease(viewport, left, modifier, b)


def on_screen(widget):
    """What the screen holds where ``widget`` is, as an (H, W, 4) array:
    the window's backing store, with whatever partial repaints left there."""
    top = widget.window()
    corner = widget.mapTo(top, widget.rect().topLeft())
    shot = widget.screen().grabWindow(top.winId(), corner.x(), corner.y(),
                                      widget.width(), widget.height())
    return image_array(shot.toImage())


def repainted(widget):
    """``widget`` painted whole afresh, as an (H, W, 4) array."""
    return image_array(widget.grab().toImage())


def image_array(image):
    """A QImage as an (H, W, 4) uint8 array (B, G, R, A)."""
    import numpy as np
    from PySide6.QtGui import QImage
    image = image.convertToFormat(QImage.Format.Format_ARGB32)
    rows = np.array(image.constBits(), np.uint8).reshape(image.height(), image.bytesPerLine())
    return rows[:, :image.width() * 4].reshape(image.height(), image.width(), 4).copy()


def off_cell_edges(grid):
    """A mask over ``grid``'s viewport: False within a screen pixel of a
    cell's edge, True elsewhere.

    Qt scales an image by stepping through it in fixed point from the left
    (and top) of the area it repaints, so a partial repaint can put a cell's
    edge one screen pixel away from where a whole repaint puts it when the
    edge falls within a hair of a pixel's centre. A stale cell, or a stale
    outline (drawn inset from the edges), still shows off the edges.
    """
    import numpy as np
    from PySide6.QtCore import QPointF
    viewport = grid.viewport()
    mask = np.ones((viewport.height(), viewport.width()), dtype=bool)
    to_screen = grid.viewportTransform()
    width, height = grid.grid_size
    for k in range(width + 1):
        x = round(to_screen.map(grid.image.mapToScene(QPointF(k, 0))).x())
        mask[:, max(0, x - 1):max(0, x + 2)] = False
    for k in range(height + 1):
        y = round(to_screen.map(grid.image.mapToScene(QPointF(0, k))).y())
        mask[max(0, y - 1):max(0, y + 2), :] = False
    return mask
