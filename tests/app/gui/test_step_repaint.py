"""A step repaints the widgets that show it (the grid, the plot, the
pseudo-code's lines, the values, the caption, the counter and the slider),
not the docks, panels and window behind them: those widgets fill their
own background, so Qt need not paint what is under them first."""
import pytest
from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QApplication, QDockWidget, QMainWindow

from tests.support.gui import WAIT_MS
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


def painted_while(qtbot, action):
    """The widgets painted while ``action`` runs and 30 ms after."""
    app = QApplication.instance()
    paints = Paints()
    app.installEventFilter(paints)
    try:
        action()
        qtbot.wait(30)
    finally:
        app.removeEventFilter(paints)
    return paints.painted


def painted_by_step(window, qtbot, index):
    return painted_while(qtbot, lambda: window.player.seek(index))


def wait_until_still(qtbot):
    """Wait until the window paints nothing of its own accord: the first
    show's layout and paints (or the docks' relayout after a new look) are
    over, however long a busy machine takes for them."""
    qtbot.waitUntil(lambda: not painted_while(qtbot, lambda: None), timeout=WAIT_MS)


def test_a_step_repaints_what_it_changes_and_nothing_behind(window, qtbot):
    window.player.pause()
    window.player.seek(3)
    wait_until_still(qtbot)
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
    wait_until_still(qtbot)
    painted = painted_by_step(window, qtbot, 4)
    assert not [w for w in painted if isinstance(w, (QMainWindow, QDockWidget))]
