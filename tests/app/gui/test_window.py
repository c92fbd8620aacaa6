"""The main window, driven the way a person drives it."""
import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication

from algorithms.core import registry
from algorithms.core.registry import format_value
from app.model import notation
from app.model.variable_rows import RowOrder
from app.gui.window import DEMO_POINTS, MainWindow
from tests.support import record
from tests.support.gui import WAIT_MS

LEFT = Qt.MouseButton.LeftButton
NONE = Qt.KeyboardModifier.NoModifier
DEMO = ("line-bresenham", DEMO_POINTS)  # the run a new window shows


pytestmark = pytest.mark.window(settled=True)


def click_grid(window, grid_pos):
    grid = window.grid
    QTest.mouseClick(grid.viewport(), LEFT, NONE, grid.widget_pos_of(grid_pos))


def press(window, key, modifier=NONE, widget=None):
    QTest.keyClick(widget or QApplication.focusWidget() or window, key, modifier)


def test_opens_on_the_demo_scene(window):
    trace = record(*DEMO)
    assert window.player.spec.name == "line-bresenham"
    assert window.player.points == list(DEMO_POINTS)
    assert window.player.index == len(trace) - 1
    assert window.transport.counter.text() == f"step {len(trace) - 1} / {len(trace) - 1}"
    assert window.picker.current_name() == "line-bresenham"
    assert "Bresenham" in window.windowTitle()


def test_placing_two_points_by_clicking(window):
    click_grid(window, (2.5, 20.5))
    assert window.player.points == [(2, 20)] and window.player.trace is None
    assert "Q" in window.message.text()
    click_grid(window, (30.4, 1.7))
    assert window.player.points == [(2, 20), (30, 1)]
    trace = record("line-bresenham", ((2, 20), (30, 1)))
    assert np.array_equal(window.player.trace.written_pixels(), trace.written_pixels())
    # The numbers in the points editor follow.
    assert [window.points.cell_text(1, axis) for axis in ("x", "y")] == ["30", "1"]


def test_dragging_a_handle(window):
    grid = window.grid
    a, b = grid.widget_pos_of((28.5, 15.5)), grid.widget_pos_of((26.5, 20.5))
    QTest.mousePress(grid.viewport(), LEFT, NONE, a)
    for k in range(1, 7):
        QTest.mouseMove(grid.viewport(), a + (b - a) * (k / 6))
    QTest.mouseRelease(grid.viewport(), LEFT, NONE, b)
    assert window.player.points == [DEMO_POINTS[0], (26, 20)]
    assert window.player.index == window.player.last  # was at the end, stays there


def test_choosing_an_algorithm_and_the_comparison(window, qtbot):
    assert not window.compare.isChecked()  # off until asked for
    window.compare.setChecked(True)
    item = window.picker.item_for("line-dda")
    rect = window.picker.visualItemRect(item)
    QTest.mouseClick(window.picker.viewport(), LEFT, NONE, rect.center())
    assert window.player.spec.name == "line-dda"
    assert "DDA" in window.windowTitle()
    a = {tuple(p) for p in record(*DEMO).written_pixels().tolist()}
    b = {tuple(p) for p in record("line-dda", DEMO_POINTS).written_pixels().tolist()}
    expected = a ^ b
    assert {tuple(c) for c in window.grid.outlines.layer("difference").tolist()} == expected
    text = window.difference_label.text()
    assert text.startswith(str(len(expected))) and "Bresenham" in text
    # The checkbox turns the comparison off.
    window.compare.setChecked(False)
    assert len(window.grid.outlines.layer("difference")) == 0
    assert window.difference_label.text() == ""


def shows_the_whole_run(window, name):
    player = window.player
    assert window.picker.current_name() == name
    assert player.trace is not None, name
    player.first()
    player.to_last()
    assert window.code.lines.rowCount() == len(player.trace.code)
    assert window.transport.counter.text() == f"step {player.last:,} / {player.last:,}"


# Picking each algorithm in the registry's order, starting from the demo:
# the algorithms refused, with the message that says why. Every one runs on
# the points on show or on a shape of its own, so none is.
REFUSED_IN_TURN = {}


def test_every_algorithm_in_the_registry_shows(window):
    """Whatever the registry holds, picking it shows a run (on the current
    points or on a shape of its own) and never crashes; only the expected
    ones are refused, with their reason, and the run on show stays."""
    refused = {}
    for spec in registry.all_specs():
        before = window.player.spec.name
        window.picker.setCurrentItem(window.picker.item_for(spec.name))
        if window.player.spec.name == spec.name:
            shows_the_whole_run(window, spec.name)
        else:
            assert window.player.spec.name == before
            refused[spec.name] = window.message.text()
    assert refused == REFUSED_IN_TURN


def test_changing_an_option(window):
    box = window.options.editor("symmetric")
    box.click()
    assert window.player.options["symmetric"] is True
    trace = record(*DEMO, {"symmetric": True})
    assert np.array_equal(window.player.trace.written_pixels(), trace.written_pixels())


def test_an_invalid_option_does_not_crash(window):
    # One colour for a segment's two ends: the option's check accepts the
    # list, the run refuses it.
    window.options.valueEdited.emit("colors", ("#ff0000",))
    assert "two colours" in window.options.error_text("colors")
    assert window.player.options["colors"] == ()
    assert window.player.trace is not None
    window.options.valueEdited.emit("colors", ("#ff0000", "#0000ff"))
    assert window.options.error_text("colors") == ""
    assert window.player.state().raster.colors is not None


def test_an_invalid_float_text_does_not_crash(window):
    spec = next(s for s in registry.all_specs() if any(o.kind == "float" for o in s.options))
    option = next(o for o in spec.options if o.kind == "float")
    window.set_algorithm(spec.name)
    editor = window.options.editor(option.name)
    field = editor.lineEdit() if hasattr(editor, "lineEdit") else editor
    field.setText("not a number")
    field.editingFinished.emit()
    assert window.options.error_text(option.name)
    assert window.player.options[option.name] == option.default


def test_stepping_with_the_buttons(window):
    window.transport.first_button.click()
    assert window.player.index == 0
    window.transport.forward_button.click()
    window.transport.forward_button.click()
    assert window.player.index == 2
    window.transport.back_button.click()
    assert window.player.index == 1
    window.transport.last_button.click()
    assert window.player.index == window.player.last


def test_scrubbing_the_timeline(window):
    window.transport.timeline.setValue(9)
    assert window.player.index == 9
    assert window.transport.counter.text().startswith("step 9 /")
    trace = record(*DEMO)
    assert window.grid.outlines.layer("current").tolist() == [list(trace.step(9).pixel)]


def test_play_and_pause(window, qtbot):
    window.transport.speed_box.setValue(200)
    window.player.first()
    window.transport.play_button.click()
    assert window.player.playing
    qtbot.waitUntil(lambda: window.player.index > 3, timeout=WAIT_MS)
    window.transport.play_button.click()
    assert not window.player.playing
    stopped = window.player.index
    qtbot.wait(50)
    assert window.player.index == stopped
    window.transport.play_button.click()
    qtbot.waitUntil(lambda: not window.player.playing, timeout=WAIT_MS)
    assert window.player.index == window.player.last


def test_keyboard_shortcuts_wherever_the_focus_is(window, qtbot):
    player = window.player
    for widget in (window.grid, window.picker, window.options.editor("symmetric"),
                   window.grid_editor.origin):
        widget.setFocus()
        qtbot.waitUntil(lambda: widget.hasFocus(), timeout=WAIT_MS)
        press(window, Qt.Key.Key_Home, widget=widget)
        assert player.index == 0, widget
        press(window, Qt.Key.Key_Right, widget=widget)
        press(window, Qt.Key.Key_Right, widget=widget)
        assert player.index == 2, widget
        press(window, Qt.Key.Key_Left, widget=widget)
        assert player.index == 1, widget
        press(window, Qt.Key.Key_Right, Qt.KeyboardModifier.ShiftModifier, widget=widget)
        assert player.index == 11, widget
        press(window, Qt.Key.Key_End, widget=widget)
        assert player.index == player.last, widget
        press(window, Qt.Key.Key_Home, widget=widget)
        press(window, Qt.Key.Key_Space, widget=widget)
        assert player.playing, widget
        press(window, Qt.Key.Key_Space, widget=widget)
        assert not player.playing, widget
    # The spin boxes of the grid size keep their keys for typing.
    box = window.grid_editor.width_box
    box.setFocus()
    qtbot.waitUntil(box.hasFocus, timeout=WAIT_MS)
    player.seek(5)
    press(window, Qt.Key.Key_Home, widget=box)
    press(window, Qt.Key.Key_Right, widget=box)
    assert player.index == 5


def test_y_down_origin(window):
    window.grid_editor.origin.setCurrentIndex(1)
    assert window.grid.y_down and window.grid.view_box.yInverted()
    window.player.set_points([])
    click_grid(window, (3.5, 2.5))
    click_grid(window, (10.5, 20.5))
    # The algorithm runs on the numbers as shown in the y-down frame.
    assert window.player.points == [(3, 2), (10, 20)]
    # Pixel (3, 2) is drawn near the top of the grid.
    grid = window.grid
    assert grid.widget_pos_of((3.5, 2.5)).y() < grid.height() / 3
    assert window.y_down_action.isChecked()


def test_panels_show_the_current_frame(window):
    trace = record(*DEMO)
    spec = registry.get("line-bresenham")
    for index in (0, 1, 5, len(trace) - 1):
        window.transport.timeline.setValue(index)
        rows = window.variables.rows()
        # The algorithm's rows as a person reads them (app/model/notation.py),
        # in the panel's order (app/model/variable_rows.py).
        order = RowOrder.of(window.player.trace)
        assert rows == order.arrange([(name, notation.shown(text))
                                      for name, text in spec.panel_rows(trace, index)])
        assert all("<=" not in text and "d_i" not in text for _, text in rows)
        values = trace.variables_at(index)
        shown = dict(rows)
        for name in ("dx", "dy", "incrE", "incrNE"):
            assert shown[name] == format_value(values[name])
        if "d" in trace.step(index).values:
            assert shown["d"] == format_value(trace.step(index).values["d"])
        line = int(trace.line[index])
        assert window.code.current == line
        assert window.code.lines.item(line, 1).text() == trace.code[line].text
        assert window.variables.marker.value() == index
    # The decision variable is plotted over the whole run.
    np.testing.assert_array_equal(window.variables.series, trace.series("d"))


def test_status_bar_shows_the_pixel_under_the_cursor(window, qtbot):
    QTest.mouseMove(window.grid.viewport(), window.grid.widget_pos_of((4.5, 5.5)))
    qtbot.waitUntil(lambda: window.cursor_label.text().startswith("pixel (4, 5)"), timeout=WAIT_MS)
    assert "written" in window.cursor_label.text()


@pytest.mark.parametrize("y_down", [False, True])
def test_status_bar_shows_the_real_coordinates_under_the_cursor(window, qtbot, y_down):
    window.set_y_down(y_down)
    qtbot.wait(50)
    QTest.mouseMove(window.grid.viewport(), window.grid.widget_pos_of((6.25, 3.75)))
    qtbot.waitUntil(lambda: "at (" in window.cursor_label.text(), timeout=WAIT_MS)
    text = window.cursor_label.text()
    x, y = (float(v) for v in text.split("at (")[1].rstrip(")").split(", "))
    # Within a screen pixel of where the pointer is, in the frame of the axes.
    cell = abs(window.grid.widget_pos_of((1, 0)).x() - window.grid.widget_pos_of((0, 0)).x())
    assert abs(x - 6.25) <= 1.5 / cell and abs(y - 3.75) <= 1.5 / cell
    assert text.startswith("pixel (6, 3)")


def test_step_cap_message(qtbot):
    w = MainWindow()
    qtbot.addWidget(w)
    w.player.step_cap = 10
    w.set_points([(0, 0), (31, 20)])
    assert w.player.trace.truncated
    assert w.message.text() == w.player.trace.message


def test_grid_size_changes(window):
    window.grid_editor.width_box.setValue(20)
    window.grid_editor.height_box.setValue(12)
    assert window.player.grid == (20, 12)
    assert window.player.points == [DEMO_POINTS[0], (19, 11)]
    assert window.grid.image.image.shape[:2] == (12, 20)


def test_dialogs_open(window, qtbot):
    from app.gui.window import ShortcutsDialog
    dialog = ShortcutsDialog(window)
    qtbot.addWidget(dialog)
    assert dialog.findChild(type(window.variables.table)).rowCount() > 5
