"""Breakpoints, step units and bookmarks in the window, driven by keys and clicks."""
import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QInputDialog, QMessageBox

from app.model import scene as scenes

from tests.support.gui import WAIT_MS, settle
from tests.support.breakpoint_oracles import (POLYGON, ZBUFFER, depth_fail_events, first_after,
                                              scanline_events, sign_events)

SHIFT = Qt.KeyboardModifier.ShiftModifier


def press(window, key, modifier=Qt.KeyboardModifier.NoModifier):
    QTest.keyClick(QApplication.focusWidget() or window, key, modifier)


def tick(window, *kinds):
    for kind, box in window.breakpoints.panel.boxes.items():
        box.setChecked(kind in kinds)


def message(window):
    return window.statusBar().currentMessage()


def test_f5_stops_where_the_decision_changes_sign(window):
    trace = window.player.trace
    events = sign_events(trace)
    tick(window, "sign")
    window.player.first()
    seen = []
    while True:
        before = window.player.index
        press(window, Qt.Key.Key_F5)
        if window.player.index == before:
            break
        seen.append(window.player.index)
        assert "decision variable changes sign" in message(window)
    assert seen == events
    assert message(window).startswith("No further stop")
    # Shift+F5 goes back through the same frames.
    press(window, Qt.Key.Key_F5, SHIFT)
    assert window.player.index == first_after(events, events[-1], -1)


def test_run_to_breakpoint_with_nothing_ticked_or_unavailable(window):
    tick(window)
    window.player.first()
    window.breakpoints.run_to(+1)
    assert window.player.index == 0 and "No breakpoint is set" in message(window)
    tick(window, "aet")
    window.breakpoints.run_to(+1)
    assert window.player.index == 0
    assert "No further stop" in message(window) and "AET changes" in message(window)
    assert not window.breakpoints.panel.boxes["aet"].isEnabled()


def test_step_unit_moves_the_arrow_keys_and_the_buttons(window):
    window.set_scene("polygon-scanline", POLYGON, {}, (32, 24))
    trace = window.player.trace
    rows = scanline_events(trace)
    window.breakpoints.set_unit("scanline")
    assert window.transport.forward_button.toolTip() == "Step forward one scanline (Right)"
    window.player.first()
    press(window, Qt.Key.Key_Right)
    assert window.player.index == rows[0]
    window.transport.forward_button.click()
    assert window.player.index == rows[1]
    press(window, Qt.Key.Key_Right, SHIFT)  # ten scanlines
    assert window.player.index == rows[11]
    press(window, Qt.Key.Key_Left)
    assert window.player.index == rows[10]
    window.player.to_last()
    press(window, Qt.Key.Key_Right)
    assert window.player.index == window.player.last
    assert "No further scanline" in message(window)
    # Back to frames: one frame a step.
    window.breakpoints.set_unit("frame")
    window.player.seek(5)
    press(window, Qt.Key.Key_Right)
    assert window.player.index == 6


def test_a_new_grid_keeps_the_pixel_condition_off(window):
    panel = window.breakpoints.panel
    panel.set_pixel(30, 20)
    panel.boxes["pixel"].setChecked(False)
    window.set_grid(16, 12)
    assert panel.pixel() == (15, 11) and not panel.boxes["pixel"].isChecked()


def test_a_unit_the_run_lacks_steps_by_frame(window):
    window.breakpoints.set_unit("primitive")  # a line is one primitive
    assert window.breakpoints.unit() == "frame"
    assert "stepping by frame" in window.breakpoints.panel.note.text()
    window.player.seek(3)
    press(window, Qt.Key.Key_Right)
    assert window.player.index == 4


def test_play_stops_at_a_failing_depth_test(window, qtbot):
    window.set_scene("zbuffer", ZBUFFER["points"], ZBUFFER["options"], (32, 24))
    fails = depth_fail_events(window.player.trace)
    tick(window, "depth")
    window.transport.speed_box.setValue(2000)
    window.player.first()
    window.player.play()
    qtbot.waitUntil(lambda: not window.player.playing, timeout=WAIT_MS)
    assert window.player.index == fails[0]
    assert "Play stopped at step" in message(window) and "depth test fails" in message(window)
    window.player.play()
    qtbot.waitUntil(lambda: not window.player.playing, timeout=WAIT_MS)
    assert window.player.index == fails[1]


def test_picking_the_pixel_on_the_grid(window, qtbot):
    settle(qtbot, window)
    panel = window.breakpoints.panel
    points = list(window.player.points)
    panel.pick.setChecked(True)
    grid = window.grid
    QTest.mouseClick(grid.viewport(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                     grid.widget_pos_of((12.5, 8.5)))
    assert panel.pixel() == (12, 8)
    assert panel.boxes["pixel"].isChecked() and not panel.pick.isChecked()
    assert window.player.points == points  # the click picked; it placed no point
    window.player.first()
    press(window, Qt.Key.Key_F5)
    assert window.player.trace.step(window.player.index).pixel == (12, 8)
    assert "pixel (12, 8) reached" in message(window)


# ------------------------------------------------------------- bookmarks
def rows(window):
    table = window.breakpoints.marks.table
    return [(table.item(r, 0).text(), int(table.item(r, 1).text().replace(",", "")))
            for r in range(table.rowCount())]


def test_bookmarks_add_rename_delete_and_jump(window, qtbot, monkeypatch):
    marks = window.breakpoints
    asked = []

    def answer(parent, title, label, mode, default):
        asked.append(default)
        return ("", True)  # an empty name takes the default

    monkeypatch.setattr(QInputDialog, "getText", answer)
    window.player.seek(12)
    press(window, Qt.Key.Key_B, Qt.KeyboardModifier.ControlModifier)
    assert asked == ["Step 12"] and rows(window) == [("Step 12", 12)]
    window.player.seek(3)
    marks.add_bookmark("start of the run")
    assert rows(window) == [("start of the run", 3), ("Step 12", 12)]  # in step order
    # Renaming in place.
    table = marks.marks.table
    table.item(1, 0).setText("the second tie")
    assert rows(window) == [("start of the run", 3), ("the second tie", 12)]
    # A name already taken is refused and the old one stays.
    table.item(1, 0).setText("start of the run")
    assert rows(window)[1] == ("the second tie", 12) and "already exists" in message(window)
    # Double-click jumps.
    window.player.to_last()
    rect = table.visualItemRect(table.item(1, 0))
    # As a person double-clicks: a press and release, then the double click.
    QTest.mouseClick(table.viewport(), Qt.MouseButton.LeftButton,
                     Qt.KeyboardModifier.NoModifier, rect.center())
    QTest.mouseDClick(table.viewport(), Qt.MouseButton.LeftButton,
                      Qt.KeyboardModifier.NoModifier, rect.center())
    assert window.player.index == 12
    # Renaming with the Rename button: type into the cell and press Enter.
    marks.marks.select(0)
    marks.marks.rename_button.click()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is not None
                    and QApplication.focusWidget().parent() is table.viewport(), timeout=WAIT_MS)
    editor = QApplication.focusWidget()
    editor.selectAll()
    QTest.keyClicks(editor, "  first  frame ")
    QTest.keyClick(editor, Qt.Key.Key_Return)  # the delegate commits on the next event
    qtbot.waitUntil(lambda: rows(window) == [("first frame", 3), ("the second tie", 12)],
                    timeout=WAIT_MS)
    marks.delete_bookmark(0)
    assert rows(window) == [("the second tie", 12)]
    assert window.bookmarks == [{"name": "the second tie", "step": 12}]


def test_bookmarks_are_saved_and_loaded_with_the_scene(window, qtbot, tmp_path, monkeypatch):
    marks = window.breakpoints
    window.player.seek(7)
    marks.add_bookmark("first tie")
    # The file actions come later (as when the program starts) and take them over.
    files = window.add_file_actions(QSettings(str(tmp_path / "s.ini"),
                                              QSettings.Format.IniFormat))
    assert files.bookmarks == [{"name": "first tie", "step": 7}]
    window.player.seek(19)
    marks.add_bookmark("second tie")
    path = tmp_path / "ties.json"
    assert files.save_to(path)
    assert scenes.load(path).bookmarks == ({"name": "first tie", "step": 7},
                                           {"name": "second tie", "step": 19})
    # A bookmark is part of the unsaved work.
    recovery = window.add_recovery(tmp_path / "recovery", delay_ms=10_000)
    assert not recovery.dirty
    marks.delete_bookmark(0)
    assert recovery.dirty
    marks.delete_bookmark(0)
    assert rows(window) == []
    discard = QMessageBox.StandardButton.Discard  # the unsaved deletions go
    monkeypatch.setattr(QMessageBox, "question", lambda *a, **k: discard)
    assert files.open_path(path)
    assert not recovery.dirty
    assert rows(window) == [("first tie", 7), ("second tie", 19)]
    marks.jump_to_bookmark(1)
    assert window.player.index == 19
    # The export dialog offers them as the ends of its range.
    controller = files.export_animation()
    dialog = controller.dialog
    assert dialog.marks_row.isVisibleTo(dialog)
    dialog.mark_first.setCurrentIndex(1)
    dialog.mark_first.activated.emit(1)
    dialog.mark_last.setCurrentIndex(2)
    dialog.mark_last.activated.emit(2)
    values = dialog.values()
    assert (values["range"], values["first"], values["last"]) == ("custom", 7, 19)
    controller.close()
