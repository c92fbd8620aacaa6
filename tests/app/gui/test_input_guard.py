"""No edit by accident and every edit undoable: the wheel over an unfocused
spin box or combo box changes nothing, and Ctrl+Z takes back a scene edit
wherever the focus is."""
import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QWheelEvent
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication

from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window(shown=True)


def wheel(widget, notches=-3):
    """Scroll the wheel over the middle of ``widget`` (down: negative)."""
    middle = QPointF(widget.rect().center())
    event = QWheelEvent(middle, QPointF(widget.mapToGlobal(middle.toPoint())), QPoint(0, 0),
                        QPoint(0, 120 * notches), Qt.MouseButton.NoButton,
                        Qt.KeyboardModifier.NoModifier, Qt.ScrollPhase.NoScrollPhase, False)
    QApplication.sendEvent(widget, event)


def test_the_wheel_over_unfocused_controls_changes_nothing(window, qtbot):
    window.grid.setFocus()
    editor = window.grid_editor
    width, origin = editor.width_box.value(), editor.origin.currentIndex()
    points = list(window.player.points)
    for control in (editor.width_box, editor.width_box.lineEdit(), editor.origin):
        wheel(control, -3)
    assert editor.width_box.value() == width and editor.origin.currentIndex() == origin
    assert window.player.grid[0] == width and window.player.points == points
    assert not editor.width_box.hasFocus()
    # Focused, the wheel is the control's again.
    editor.width_box.setFocus()
    qtbot.waitUntil(editor.width_box.hasFocus, timeout=WAIT_MS)
    wheel(editor.width_box, -1)
    assert editor.width_box.value() == width - 1


def test_ctrl_z_undoes_a_spin_box_edit_with_the_focus_in_it(window, qtbot):
    box = window.grid_editor.width_box
    before = window.player.grid
    box.setFocus()
    qtbot.waitUntil(box.hasFocus, timeout=WAIT_MS)
    box.selectAll()
    QTest.keyClicks(box, "20")
    QTest.keyClick(box, Qt.Key.Key_Return)
    assert window.player.grid[0] == 20
    QTest.keyClick(box, Qt.Key.Key_Z, Qt.KeyboardModifier.ControlModifier)
    assert window.player.grid == before and box.value() == before[0]
    QTest.keyClick(box, Qt.Key.Key_Z, Qt.KeyboardModifier.ControlModifier
                   | Qt.KeyboardModifier.ShiftModifier)
    assert window.player.grid[0] == 20


@pytest.mark.parametrize("where", ["grid", "code", "picker", "origin", "option"])
def test_ctrl_z_reaches_the_history_wherever_the_focus_is(window, qtbot, where):
    window.picker.algorithmChosen.emit("line-dda")  # an edit to take back, as a click makes it
    assert window.player.spec.name == "line-dda"
    widget = {"grid": window.grid, "code": window.code, "picker": window.picker,
              "origin": window.grid_editor.origin,
              "option": window.options}[where]
    target = widget.focusProxy() or widget
    target.setFocus()
    QTest.keyClick(QApplication.focusWidget() or target, Qt.Key.Key_Z,
                   Qt.KeyboardModifier.ControlModifier)
    assert window.player.spec.name == "line-bresenham"


def test_the_wheel_over_an_options_editor_made_for_a_run_changes_nothing(window, qtbot):
    window.picker.algorithmChosen.emit("circle-midpoint")
    box = window.options.editor("radius")  # made when the algorithm was chosen
    qtbot.wait(10)  # it shows
    window.grid.setFocus()
    radius = window.player.options["radius"]
    wheel(box, -4)
    assert box.value() == radius and window.player.options["radius"] == radius
