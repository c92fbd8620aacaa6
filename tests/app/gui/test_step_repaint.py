"""A step repaints the widgets that show it (the grid, the plot, the
pseudo-code's lines, the values, the caption, the counter and the slider),
not the docks, panels and window behind them: those widgets fill their
own background, so Qt need not paint what is under them first."""
import pytest
from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QApplication, QDockWidget, QMainWindow

from widgets.panels import CodePanel, VariablesPanel

pytestmark = pytest.mark.window(shown=True)


class Paints(QObject):
    def __init__(self):
        super().__init__()
        self.painted = []

    def eventFilter(self, watched, event):  # noqa: N802
        if event.type() == QEvent.Type.Paint:
            self.painted.append(watched)
        return False


def painted_by_step(window, qtbot, index):
    app = QApplication.instance()
    paints = Paints()
    app.installEventFilter(paints)
    try:
        window.player.seek(index)
        qtbot.wait(30)
    finally:
        app.removeEventFilter(paints)
    return paints.painted


def test_a_step_repaints_what_it_changes_and_nothing_behind(window, qtbot):
    window.player.pause()
    window.player.seek(3)
    qtbot.wait(30)
    painted = painted_by_step(window, qtbot, 4)
    names = {widget.objectName() for widget in painted}
    # What the step changed was repainted ...
    assert {"stepCaption", "stepCounter"} <= names
    assert window.code.lines.viewport() in painted
    assert window.variables.table.viewport() in painted
    # ... on its own.
    behind = [widget for widget in painted if isinstance(
        widget, (QMainWindow, QDockWidget, CodePanel, VariablesPanel))]
    assert behind == []


@pytest.mark.parametrize("name", ["dark", "light"])
def test_nothing_behind_after_a_change_of_theme(window, qtbot, theme, name):
    theme(name)
    window.player.pause()
    window.player.seek(3)
    qtbot.wait(500)  # the docks' animated relayout after the new look ends
    painted = painted_by_step(window, qtbot, 4)
    assert not [w for w in painted if isinstance(w, (QMainWindow, QDockWidget))]
