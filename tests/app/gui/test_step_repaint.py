"""A step repaints the widgets that show it (the grid, the plot, the
pseudo-code's lines, the values, the caption, the counter and the slider),
not the docks, panels and window behind them: those widgets fill their own
background, so Qt need not paint what is under them first, and the caption
and the counter sit in rows whose height a new text cannot change, so no
step lays the window out again. Every step of the demo run is taken, at
the usual type size and at the largest zoom, where the tables scroll: it
holds whatever the machine's fonts make of the rows."""
import pytest
from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QApplication, QDockWidget, QMainWindow

from app.gui.window_view import ZOOMS
from tests.support.gui import WAIT_MS
from widgets.code_panel import CodePanel
from widgets.panels import VariablesPanel

pytestmark = pytest.mark.window(shown=True)

BEHIND = (QMainWindow, QDockWidget, CodePanel, VariablesPanel)


class Paints(QObject):
    def __init__(self):
        super().__init__()
        self.painted = []

    def eventFilter(self, watched, event):  # noqa: N802
        if event.type() == QEvent.Type.Paint:
            self.painted.append(watched)
        return False


def settle_docks(qtbot, window):
    """Wait until the docks and their panels keep their places: a new type
    or look lays them out again, animated, over several passes."""
    seen = []

    def still():
        seen.append([(dock.geometry(), dock.widget().geometry())
                     for dock in window.findChildren(QDockWidget)])
        return len(seen) > 3 and seen[-1] == seen[-2] == seen[-3] == seen[-4]
    qtbot.waitUntil(still, timeout=WAIT_MS)


def painted_by_step(window, qtbot, index):
    app = QApplication.instance()
    paints = Paints()
    app.installEventFilter(paints)
    try:
        window.player.seek(index)
        # Until the step's own caption is painted, however slow the machine;
        # then a little longer, for anything painted after it.
        qtbot.waitUntil(lambda: any(w.objectName() == "stepCaption" for w in paints.painted),
                        timeout=WAIT_MS)
        qtbot.wait(30)
    finally:
        app.removeEventFilter(paints)
    return paints.painted


def changed_rows_in_view(table, before, after) -> bool:
    """Whether a value that changed is in the table's view."""
    old = dict(before)
    for row, (name, text) in enumerate(after):
        if old.get(name) != text:
            rect = table.visualItemRect(table.item(row, 1))
            if rect.intersects(table.viewport().rect()):
                return True
    return False


def walk(window, qtbot):
    """Every step of the run from the first, with what each repainted."""
    window.player.pause()
    window.player.seek(0)
    qtbot.wait(30)
    for index in range(1, len(window.player.trace)):
        line, rows = window.code.current, window.variables.rows()
        painted = painted_by_step(window, qtbot, index)
        yield index, painted, line != window.code.current, \
            changed_rows_in_view(window.variables.table, rows, window.variables.rows())


@pytest.mark.parametrize("zoom", [1.0, ZOOMS[-1]])
def test_each_step_repaints_what_it_changes_and_nothing_behind(window, qtbot, zoom):
    window.view.set_zoom(zoom)
    settle_docks(qtbot, window)
    for index, painted, new_line, new_values in walk(window, qtbot):
        names = {widget.objectName() for widget in painted}
        # What the step changed was repainted ...
        assert {"stepCaption", "stepCounter"} <= names, index
        if new_line:
            assert window.code.lines.viewport() in painted, index
        if new_values:
            assert window.variables.table.viewport() in painted, index
        # ... on its own.
        assert [widget for widget in painted if isinstance(widget, BEHIND)] == [], index


@pytest.mark.parametrize("name", ["dark", "light"])
def test_nothing_behind_after_a_change_of_theme(window, qtbot, theme, name):
    theme(name)
    settle_docks(qtbot, window)
    for index, painted, _line, _values in walk(window, qtbot):
        assert [widget for widget in painted if isinstance(widget, BEHIND)] == [], index
