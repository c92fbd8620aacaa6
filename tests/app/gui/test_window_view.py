"""The window on a lecture hall's screen: presentation mode, the zoom of the
whole window, the layout kept and reset, a 1280 x 720 projector, Copy view."""
import sys
from functools import partial

import pytest
from PySide6.QtCore import QRect, QSettings, Qt
from PySide6.QtGui import QKeySequence
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication

from app.gui import window_view
from app.gui.about import shortcut_rows
from app.gui.window import MainWindow
from app.gui.window_view import MIN_SIZE
from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window(shown=True)


def inside(window, widget) -> bool:
    """Is all of ``widget`` on show inside the window's own area?"""
    top_left = widget.mapTo(window, widget.rect().topLeft())
    return widget.isVisible() and window.rect().contains(QRect(top_left, widget.size()))


def press_present(window) -> None:
    """The presentation key of this system (F11; Cmd+Ctrl+F on macOS)."""
    QTest.keySequence(window.grid, window.actions_["present"].shortcut())


def point_size(widget) -> float:
    return widget.font().pointSizeF()


def test_presentation_hides_the_docks_and_esc_restores_them(window, qtbot):
    window.inspector.action.trigger()
    docks = [d for d in (window.scene_dock, window.inspector.dock) if d.isVisible()]
    assert len(docks) == 2
    code_size = point_size(window.code.lines)
    press_present(window)
    qtbot.waitUntil(window.isFullScreen, timeout=WAIT_MS)
    assert window.view.presenting
    for hidden in (*docks, window.toolbar, window.menuBar(), window.statusBar()):
        assert not hidden.isVisible(), hidden
    assert window.code_dock.isVisible() and window.variables_dock.isVisible()
    assert inside(window, window.transport)
    assert point_size(window.code.lines) >= 1.5 * code_size  # large type beside the grid
    QTest.keyClick(window.grid, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not window.isFullScreen(), timeout=WAIT_MS)
    assert not window.view.presenting
    for shown in (*docks, window.toolbar, window.menuBar(), window.statusBar()):
        assert shown.isVisible(), shown
    assert point_size(window.code.lines) == code_size


def test_the_key_and_the_view_menu_toggle_presentation(window, qtbot):
    action = window.actions_["present"]
    assert action in window.menus["view"].actions()
    action.trigger()
    qtbot.waitUntil(window.isFullScreen, timeout=WAIT_MS)
    press_present(window)
    qtbot.waitUntil(lambda: not window.isFullScreen(), timeout=WAIT_MS)
    assert window.scene_dock.isVisible()


def test_on_macos_the_standard_key_presents_and_the_sheet_names_it(make_window, qtbot,
                                                                    monkeypatch):
    # macOS's Qt theme gives Ctrl+Meta+F (Cmd+Ctrl+F) as the full-screen key;
    # the window, its tooltip and the shortcuts sheet must take that, not F11.
    mac = QKeySequence("Ctrl+Meta+F")
    monkeypatch.setattr(window_view, "presentation_keys",
                        partial(window_view.presentation_keys, [mac], "darwin"))
    window = make_window()
    action = window.actions_["present"]
    assert action.shortcuts() == [mac]
    named = mac.toString(QKeySequence.SequenceFormat.NativeText)
    assert (named, "Presentation") in shortcut_rows(window)
    assert f"({named}; Esc leaves)" in action.toolTip()
    QTest.keyClick(window.grid, Qt.Key.Key_F11)  # the system's key on macOS, not ours
    qtbot.wait(50)
    assert not window.view.presenting
    QTest.keyClick(window.grid, Qt.Key.Key_F, Qt.KeyboardModifier.ControlModifier
                   | Qt.KeyboardModifier.MetaModifier)
    qtbot.waitUntil(lambda: window.view.presenting, timeout=WAIT_MS)
    QTest.keyClick(window.grid, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not window.view.presenting, timeout=WAIT_MS)


@pytest.mark.skipif(sys.platform == "darwin", reason="macOS takes F11 for itself")
def test_elsewhere_f11_comes_first_in_the_sheet(window):
    keys = window.actions_["present"].shortcuts()
    assert keys[0] == QKeySequence("F11")
    row = dict((text, named) for named, text in shortcut_rows(window))["Presentation"]
    assert row.startswith("F11")
    assert "(F11; Esc leaves)" in window.actions_["present"].toolTip()


def test_a_1280_by_720_window_shows_the_transport_and_its_parts_apart(window, qtbot):
    window.resize(1280, 720)
    qtbot.waitUntil(lambda: window.height() <= 720, timeout=WAIT_MS)
    t = window.transport
    assert inside(window, t) and inside(window, t.play_button) and inside(window, t.speed_box)
    counter = t.counter.geometry()
    speed = min(w.geometry().left() for w in (t.speed_slider, t.speed_box))
    assert counter.right() < speed  # the step counter never runs into Speed
    assert inside(window, window.grid)


def test_the_window_opens_within_the_screen_and_has_a_minimum_size(window, tmp_path):
    window.view.remember(QSettings(str(tmp_path / "none.ini"), QSettings.Format.IniFormat))
    room = window.screen().availableGeometry()
    # (The test screen is 800 px square: smaller than any window can be.)
    assert window.width() <= max(room.width(), MIN_SIZE[0])
    assert window.height() <= max(room.height(), MIN_SIZE[1])
    window.resize(300, 200)
    assert window.width() >= MIN_SIZE[0] and window.height() >= MIN_SIZE[1]


def test_the_pseudo_code_column_gets_its_width_back(window, qtbot):
    window.resize(1280, 720)
    qtbot.wait(20)
    wide = window.code_dock.width()
    window.resize(MIN_SIZE[0], 720)
    qtbot.wait(20)
    window.resize(1280, 720)
    qtbot.waitUntil(lambda: window.code_dock.width() >= min(wide, 1280 // 3) - 10, timeout=WAIT_MS)


def test_zoom_keys_scale_the_whole_window_and_are_remembered(window, qtbot, tmp_path):
    settings = QSettings(str(tmp_path / "view.ini"), QSettings.Format.IniFormat)
    window.view.remember(settings)
    label = window.hint
    usual = point_size(label)
    QTest.keyClick(window.grid, Qt.Key.Key_Equal, Qt.KeyboardModifier.ControlModifier)
    QTest.keyClick(window.grid, Qt.Key.Key_Equal, Qt.KeyboardModifier.ControlModifier)
    assert point_size(label) == pytest.approx(usual * window.view.zoom) and window.view.zoom > 1
    zoom = window.view.zoom
    window.close()
    again = MainWindow()
    qtbot.addWidget(again)
    again.show()
    qtbot.waitExposed(again)
    again.view.remember(QSettings(str(tmp_path / "view.ini"), QSettings.Format.IniFormat))
    assert again.view.zoom == pytest.approx(zoom)
    assert point_size(again.hint) == pytest.approx(usual * zoom)
    assert again.actions_["zoom-reset"].shortcut().toString() == "Ctrl+0"
    again.actions_["zoom-reset"].trigger()
    assert again.view.zoom == 1.0 and point_size(again.hint) == pytest.approx(usual)
    assert again.actions_["zoom-out"].shortcut().toString() == "Ctrl+-"
    again.actions_["zoom-out"].trigger()
    assert point_size(again.hint) < usual


def test_the_layout_is_kept_between_runs_and_reset(window, qtbot, tmp_path):
    path = str(tmp_path / "layout.ini")
    window.view.remember(QSettings(path, QSettings.Format.IniFormat))
    window.scene_dock.hide()
    window.inspector.action.trigger()
    window.close()
    again = MainWindow()
    qtbot.addWidget(again)
    again.show()
    qtbot.waitExposed(again)
    again.view.remember(QSettings(path, QSettings.Format.IniFormat))
    assert not again.scene_dock.isVisible()
    assert again.inspector.dock.isVisible()
    again.actions_["reset-layout"].trigger()
    assert again.scene_dock.isVisible() and not again.inspector.dock.isVisible()
    assert again.code_dock.isVisible() and again.variables_dock.isVisible()


def test_copy_view_puts_the_grid_on_the_clipboard(window):
    QApplication.clipboard().clear()
    window.actions_["copy-view"].trigger()
    image = QApplication.clipboard().image()
    assert not image.isNull()
    ratio = window.grid.devicePixelRatioF()
    assert (image.width(), image.height()) == (round(window.grid.width() * ratio),
                                              round(window.grid.height() * ratio))
    # The grid's pixels, not a blank: the line's cells are there in the ink colour.
    colours = {image.pixelColor(x, y).name() for x in range(0, image.width(), 7)
               for y in range(0, image.height(), 7)}
    assert window.palette_.ink.lower() in colours or len(colours) > 3


def test_compare_is_off_by_default_and_its_colour_is_not_the_pins(window):
    from app.gui.inspector_dock import PIN_COLOUR
    from app.gui.preferences import BASE_PALETTES
    assert not window.compare.isChecked() and not window.player.session.compare_enabled
    assert not window.actions_["view-Compare with previous algorithm"].isChecked()

    def rgb(text):
        return [int(text[k:k + 2], 16) for k in (1, 3, 5)]
    for palette in BASE_PALETTES.values():
        for name in ("difference", "current", "candidate", "primitive"):
            other = getattr(palette, name)
            distance = sum((a - b) ** 2 for a, b in zip(rgb(PIN_COLOUR), rgb(other))) ** 0.5
            assert distance > 100, (name, other)


def test_zoomed_in_on_a_large_grid_the_view_follows_the_step(make_window, qtbot):
    window = make_window("line-bresenham", [(2, 3), (120, 80)], grid=(128, 96))
    from PySide6.QtCore import QRectF
    box = window.grid.view_box
    box.setRange(QRectF(0, 0, 16, 12), padding=0)  # zoomed in on the start
    qtbot.wait(20)
    trace = window.player.trace
    width = box.viewRange()[0][1] - box.viewRange()[0][0]
    for index in range(0, len(trace), 7):
        window.player.seek(index)
        cells = window.grid.outlines.layer("current")
        if not len(cells):
            continue
        x, y = (int(v) for v in cells[0])
        (x0, x1), (y0, y1) = box.viewRange()
        assert x0 <= x + 0.5 <= x1 and y0 <= y + 0.5 <= y1, (index, (x, y), box.viewRange())
        assert x1 - x0 == pytest.approx(width)  # panned, not zoomed out
    assert box.viewRange()[0][0] > 60  # it went along the line to its far end


def test_at_720_pixels_the_code_keeps_most_of_its_panel(window, qtbot):
    window.resize(1280, 720)
    qtbot.wait(50)
    code = window.code
    assert code.notes_area.height() <= code.height() // 3 + 1
    lines = code.lines
    shown = sum(1 for row in range(lines.rowCount())
                if 0 <= lines.rowViewportPosition(row) < lines.viewport().height())
    assert shown >= min(5, lines.rowCount())


def test_the_marked_code_line_takes_the_presentation_type_too(window, qtbot):
    """The marked line carries its own (bold) font: it grows with the rest
    of the code when presenting and shrinks back after."""
    window.player.seek(3)
    qtbot.wait(10)
    row = window.code.current
    assert row is not None

    def marked_size():
        return window.code.lines.item(row, 1).font().pointSizeF()
    before = marked_size()
    press_present(window)
    qtbot.waitUntil(lambda: window.view.presenting, timeout=WAIT_MS)
    assert marked_size() == point_size(window.code.lines) >= 1.5 * before
    # A line marked before is plain again: no font of its own, so it is
    # drawn in the table's (presentation) font like the rest.
    window.player.seek(len(window.player.trace) - 1)
    qtbot.wait(10)
    assert window.code.lines.item(row, 1).data(Qt.ItemDataRole.FontRole) is None
    QTest.keyClick(window.grid, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not window.view.presenting, timeout=WAIT_MS)
    lines = window.code.lines
    marked = window.code.current
    assert lines.item(marked, 1).font().pointSizeF() == point_size(lines) == before
    assert all(lines.item(k, 1).data(Qt.ItemDataRole.FontRole) is None
               for k in range(lines.rowCount()) if k != marked)


def test_the_words_on_the_grid_grow_when_presenting(window, qtbot):
    """M's label is read from the back row too: larger while presenting."""
    trace = window.player.trace
    step = next(i for i in range(len(trace)) if len(trace.candidates_at(i)) == 2)
    window.player.seek(step)
    qtbot.wait(10)
    (before,) = window.guides.item.label_sizes()
    press_present(window)
    qtbot.waitUntil(lambda: window.view.presenting, timeout=WAIT_MS)
    (presenting,) = window.guides.item.label_sizes()
    assert presenting >= 1.3 * before
    QTest.keyClick(window.grid, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not window.view.presenting, timeout=WAIT_MS)
    assert window.guides.item.label_sizes() == [before]
