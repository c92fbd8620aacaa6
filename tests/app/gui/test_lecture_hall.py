"""The window in front of a lecture hall: presentation mode as one layout,
scaled as a whole and put back exactly; the Variables panel's order; the
zoom at 1280 x 720; keys that step wherever the focus is; the timeline's
groove; a primitive drawn starts at its first step."""
import pytest
from PySide6.QtCore import QPoint, QRect, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QDockWidget, QWidget

from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window(shown=True)


def present(window, qtbot):
    window.actions_["present"].trigger()  # its key: test_window_view.py
    qtbot.waitUntil(lambda: window.view.presenting, timeout=WAIT_MS)
    qtbot.wait(50)


def leave(window, qtbot):
    QTest.keyClick(window.grid, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not window.view.presenting, timeout=WAIT_MS)
    qtbot.wait(50)


def decision_step(window) -> int:
    trace = window.player.trace
    return next(i for i in range(len(trace)) if "update" in dict(
        window.player.spec.panel_rows(trace, i)))


def sizes_of(window) -> dict:
    """The font of every widget on show (the widgets held, so that their
    wrappers stay the same), and the size of every dock on show."""
    fonts = {w: w.font().toString() for w in (window, *window.findChildren(QWidget))
             if w.isVisible()}
    docks = {d.objectName(): d.size().toTuple() for d in window.findChildren(QDockWidget)
             if d.isVisible()}
    return {"fonts": fonts, "docks": docks}


def same_fonts(before, after) -> list:
    """The widgets on show before and after whose fonts differ."""
    return [w for w in before if w in after and before[w] != after[w]]


def test_presenting_scales_header_names_and_values_alike_and_esc_puts_all_back(window, qtbot):
    window.resize(1280, 720)
    window.player.seek(decision_step(window))
    qtbot.wait(50)
    table = window.variables.table
    before = sizes_of(window)
    usual = table.horizontalHeader().font().pointSizeF()
    present(window, qtbot)
    header = table.horizontalHeader().font().pointSizeF()
    assert header > usual
    assert table.font().pointSizeF() == header  # the names' type
    assert table.item(0, 1).font().pointSizeF() == header  # the values'
    assert window.code.lines.font().pointSizeF() == pytest.approx(
        header / usual * window.code.lines.property("typeScaleBase").pointSizeF())
    # The step's decision rows in sight, on top.
    assert window.variables.shown_names()[:3] == ["d", "choice", "decision"]
    leave(window, qtbot)
    after = sizes_of(window)
    assert same_fonts(before["fonts"], after["fonts"]) == []
    assert len(after["fonts"]) >= 0.9 * len(before["fonts"])
    assert after["docks"] == before["docks"]
    # Twice over: nothing grows from one presentation to the next.
    present(window, qtbot)
    assert table.horizontalHeader().font().pointSizeF() == header
    leave(window, qtbot)
    again = sizes_of(window)
    assert same_fonts(after["fonts"], again["fonts"]) == [] and again["docks"] == after["docks"]


def test_the_variables_list_the_step_first_and_fold_the_constants(window, qtbot):
    window.resize(1280, 720)
    window.player.seek(decision_step(window))
    qtbot.wait(50)
    panel = window.variables
    names = [name for name, _text in panel.rows()]
    assert names[:4] == ["d", "choice", "decision", "update"]
    assert set(names[4:]) == {"dx", "dy", "incrE", "incrNE", "octant", "steep"}
    assert panel.folded and panel.shown_names()[:4] == names[:4]
    assert "dx" not in panel.shown_names()
    group = panel.table.visualItemRect(panel.table.item(4, 0)).center()
    QTest.mouseClick(panel.table.viewport(), Qt.MouseButton.LeftButton, pos=group)
    assert not panel.folded
    assert not any(panel.table.isRowHidden(row) for row in range(panel.table.rowCount()))


def test_an_exercise_and_the_texture_stay_in_presentation_mode(make_window, qtbot):
    window = make_window()
    window.exercise_mode.action.trigger()
    assert window.exercise_mode.dock.isVisible() and not window.variables_dock.isVisible()
    present(window, qtbot)
    assert window.exercise_mode.dock.isVisible()
    assert not window.variables_dock.isVisible()  # it would give the answers away
    leave(window, qtbot)
    assert window.exercise_mode.dock.isVisible() and not window.variables_dock.isVisible()
    textured = make_window("triangle-texture")
    qtbot.waitUntil(lambda: textured.texture_dock is not None
                    and textured.texture_dock.isVisible(), timeout=WAIT_MS)
    present(textured, qtbot)
    assert textured.texture_dock.isVisible()
    leave(textured, qtbot)


def inside(window, widget) -> bool:
    corner = widget.mapTo(window, QPoint(0, 0))
    return window.rect().contains(QRect(corner, widget.size()))


@pytest.mark.parametrize("presses", [2, 4])
def test_zoom_at_1280_by_720_keeps_the_layout_whole(window, qtbot, presses):
    window.resize(1280, 720)
    window.player.seek(decision_step(window))
    qtbot.wait(50)
    widths = {d.objectName(): d.width() for d in window.findChildren(QDockWidget)
              if d.isVisible()}
    for _ in range(presses):
        QTest.keyClick(window.grid, Qt.Key.Key_Equal, Qt.KeyboardModifier.ControlModifier)
    qtbot.wait(100)
    t = window.transport
    speed = [w for w in (t.speed_slider, t.speed_box) if w.isVisible()]
    assert t.counter.geometry().right() < min(w.geometry().left() for w in speed)
    assert t.counter.width() >= t.counter.fontMetrics().horizontalAdvance(t.counter.text())
    for widget in (window.transport, t.counter, t.speed_box, window.code_dock,
                   window.variables_dock, window.scene_dock):
        assert inside(window, widget), widget
    assert window.width() <= 1280
    assert window.variables.shown_names()[:2] == ["d", "choice"]
    QTest.keyClick(window.grid, Qt.Key.Key_0, Qt.KeyboardModifier.ControlModifier)
    qtbot.wait(100)
    assert {d.objectName(): d.width() for d in window.findChildren(QDockWidget)
            if d.isVisible()} == widths


def test_transport_keys_step_after_the_search_and_with_a_clicker(window, qtbot):
    window.picker_search.setFocus()
    QTest.keyClicks(window.picker_search, "dda")
    QTest.keyClick(window.picker_search, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: window.player.spec.name == "line-dda", timeout=WAIT_MS)
    window.player.seek(3)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Right)
    assert window.player.index == 4
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_PageDown)
    assert window.player.index == 5
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_PageUp)
    assert window.player.index == 4
    # Typing in the search keeps its keys.
    window.picker_search.setFocus()
    QTest.keyClick(window.picker_search, Qt.Key.Key_Left)
    assert window.player.index == 4


def test_b_blanks_the_screen_and_b_brings_it_back(window, qtbot):
    QTest.keyClick(window.grid, Qt.Key.Key_B)
    blank = window.findChild(QWidget, "blankScreen")
    assert blank is not None and blank.isVisible() and blank.geometry() == window.rect()
    picture = blank.grab().toImage()
    assert picture.pixelColor(picture.width() // 2, picture.height() // 2).name() == "#000000"
    QTest.keyClick(window.grid, Qt.Key.Key_B)
    assert not blank.isVisible()


def test_a_scene_opened_from_the_gallery_gives_the_keys_back(window, qtbot):
    window.picker_search.setFocus()
    gallery = window.gallery_entry.open()
    qtbot.waitUntil(lambda: len(gallery.cases) > 0, timeout=WAIT_MS)
    gallery.list.setFocus()
    assert gallery.open_row(0)
    qtbot.waitUntil(lambda: QApplication.focusWidget() is window.grid, timeout=WAIT_MS)
    gallery.close()


def test_a_click_on_the_groove_goes_to_that_step(window, qtbot):
    window.player.seek(0)
    timeline = window.transport.timeline
    last = timeline.maximum()
    x = timeline.width() * 3 // 4
    QTest.mouseClick(timeline, Qt.MouseButton.LeftButton, pos=QPoint(x, timeline.height() // 2))
    # Where the pointer is, give or take the handle's half-width at the ends.
    assert abs(window.player.index - 0.75 * last) <= max(2, last // 10)


def test_a_primitive_drawn_starts_at_its_first_step(window, qtbot):
    window.clear_points()
    for point in ((3, 4), (20, 11)):
        QTest.mouseClick(window.grid.viewport(), Qt.MouseButton.LeftButton,
                         pos=window.grid.widget_pos_of(point))
        qtbot.wait(30)
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    assert len(window.player.points) == 2
    assert window.player.index == 0
    # Dragging an end of the line shown finished keeps it finished.
    window.player.to_last()
    window.set_points([(3, 4), (22, 11)])
    assert window.player.index == window.player.last
