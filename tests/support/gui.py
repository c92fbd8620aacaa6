"""Shared by the window tests."""


def settle(qtbot, window):
    """Wait until the grid's view has taken its final place after showing:
    pyqtgraph fits the view to the widget's final size a moment later."""
    where = []

    def still():
        where.append(window.grid.widget_pos_of((0.0, 0.0)))
        return len(where) > 2 and where[-1] == where[-2] == where[-3]
    qtbot.waitUntil(still, timeout=2000)


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
