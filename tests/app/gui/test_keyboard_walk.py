"""The window walked with key events only: every key goes to the widget that
has the focus (or the active popup or window), as a person's keyboard does;
no mouse event is sent and no slot is called.

The walk draws a line (the algorithm chosen by search, two points placed with
the grid's cursor), steps it, opens the compare window and steps there,
exports a GIF through the export dialog with a typed path, and answers an
exercise question.
"""
import pytest
from PIL import Image
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QMenu

from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window(settled=True, files=True)

K = Qt.Key
NONE, SHIFT, CTRL, ALT = (Qt.KeyboardModifier.NoModifier, Qt.KeyboardModifier.ShiftModifier,
                          Qt.KeyboardModifier.ControlModifier, Qt.KeyboardModifier.AltModifier)


def focused():
    """Where a key goes: the open menu, else the focused widget, else the active window."""
    return (QApplication.activePopupWidget() or QApplication.focusWidget()
            or QApplication.activeWindow())


def press(key, modifier=NONE, times=1):
    for _ in range(times):
        QTest.keyClick(focused(), key, modifier)


def type_text(text):
    QTest.keyClicks(focused(), text)


def menu(qtbot, letter, item_letter):
    """Alt+letter opens a menu of the menu bar; the item's letter picks it."""
    press(getattr(K, f"Key_{letter.upper()}"), ALT)
    qtbot.waitUntil(lambda: isinstance(QApplication.activePopupWidget(), QMenu), timeout=WAIT_MS)
    press(getattr(K, f"Key_{item_letter.upper()}"))


def test_walk_the_window_by_keyboard(qtbot, window, tmp_path):
    window.activateWindow()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is window.grid, timeout=WAIT_MS)
    player = window.player

    # Choose the algorithm: Ctrl+F to the search, a few letters, Enter.
    press(K.Key_F, CTRL)
    assert focused() is window.picker_search
    type_text("line-dda")
    press(K.Key_Return)
    assert player.spec.name.startswith("line-dda")
    assert focused() is window.grid  # Enter gave the keys back to the grid

    # Place two points with the cursor: K turns it on, Enter places.
    press(K.Key_K)
    cursor = window.keyboard.cursor
    assert cursor.active
    press(K.Key_Home)  # not the cursor's: the run to its first step
    cursor_cell = cursor.cell
    press(K.Key_Return)
    press(K.Key_Right, SHIFT, times=3)
    press(K.Key_Up, SHIFT)
    press(K.Key_Up)
    press(K.Key_Return)
    x, y = cursor_cell
    assert player.points == [cursor_cell, (x + 15, y + 6)]
    assert window.keyboard.label.text().startswith(f"cursor ({x + 15}, {y + 6})")

    # Step it: K gives the arrows back to stepping.
    press(K.Key_K)
    assert not cursor.active
    press(K.Key_Home)
    press(K.Key_Right, times=3)
    assert player.index == 3

    # Compare (Ctrl+K): its own window steps with the same keys; Esc closes it.
    press(K.Key_K, CTRL)
    qtbot.waitUntil(lambda: window.compare_entry.window is not None
                    and QApplication.activeWindow() is window.compare_entry.window,
                    timeout=WAIT_MS)
    compare = window.compare_entry.window
    press(K.Key_Home)
    press(K.Key_Right, times=2)
    assert compare.position == 2
    press(K.Key_Escape)
    qtbot.waitUntil(lambda: not compare.isVisible(), timeout=WAIT_MS)
    window.activateWindow()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is window, timeout=WAIT_MS)

    # Export a GIF: Ctrl+E, Alt+G to the path, type it, Enter exports.
    target = tmp_path / "walk.gif"
    press(K.Key_E, CTRL)
    dialog = window.file_actions.export_controller.dialog
    qtbot.waitUntil(lambda: QApplication.activeWindow() is dialog, timeout=WAIT_MS)
    press(K.Key_G, ALT)
    assert focused() is dialog.path
    press(K.Key_A, CTRL)
    type_text(str(target))
    press(K.Key_Return)
    qtbot.waitUntil(target.exists, timeout=WAIT_MS)
    qtbot.waitUntil(lambda: not dialog.running, timeout=WAIT_MS)
    with Image.open(target) as gif:
        assert gif.format == "GIF" and gif.n_frames > 1
    press(K.Key_Escape)
    qtbot.waitUntil(lambda: not dialog.isVisible(), timeout=WAIT_MS)
    window.activateWindow()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is window, timeout=WAIT_MS)

    # An exercise: Run > Exercise (Alt+R, X); the name, Enter; the answer.
    menu(qtbot, "r", "x")
    exercise = window.exercise_mode
    assert exercise.active
    panel = exercise.panel
    if exercise.exercise is None:  # the student's name first
        assert focused() is panel.student
        type_text("Ada")
        press(K.Key_Return)
    assert exercise.exercise is not None and exercise.exercise.current is not None
    assert exercise.exercise.current.kind == "pixel"  # a DDA asks which pixel comes next
    assert focused() is panel.entry  # the keyboard is at the question
    type_text(f"{x + 1}, {y}")
    press(K.Key_Return)
    assert exercise.exercise.score[1] == 1  # one question answered and graded
    assert panel.feedback.text()


@pytest.mark.window("line-bresenham", [(1, 1), (12, 5)], grid=(16, 12), settled=True)
def test_a_branch_is_chosen_with_the_keyboard(qtbot, window):
    """Bresenham's questions are choices: Tab reaches them, Enter or Space presses one."""
    window.activateWindow()
    window.exercise_mode.panel.student.setText("Ada")  # asked once, kept in the settings
    menu(qtbot, "r", "x")
    exercise, panel = window.exercise_mode, window.exercise_mode.panel
    if exercise.exercise is None:
        panel.student.setFocus(Qt.FocusReason.TabFocusReason)
        type_text("Ada")
        press(K.Key_Return)
    question = exercise.exercise.current
    assert question.choices
    # From the grid, F6 goes round to the exercise dock, and Tab to the choices.
    while not panel.isAncestorOf(focused()):
        press(K.Key_F6)
    for _ in range(10):
        if focused() is panel.choice_button(question.choices[0]):
            break
        press(K.Key_Tab)
    assert focused() is panel.choice_button(question.choices[0])
    step = window.player.index
    press(K.Key_Space)
    assert exercise.exercise.score[1] == 1
    assert window.player.index >= step and not window.player.playing  # Space did not play
    if exercise.exercise.current is not None and exercise.exercise.current.choices:
        assert panel.isAncestorOf(focused())  # on to the next question's choices
        press(K.Key_Return)
        assert exercise.exercise.score[1] == 2
