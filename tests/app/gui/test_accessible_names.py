"""Every control a person can reach has a name a screen reader speaks
(WCAG 4.1.2): asked of Qt's accessibility interface, as a screen reader
asks it, in the main window and in every dialog a test can open."""
from __future__ import annotations

import pytest
from PySide6.QtGui import QAccessible
from PySide6.QtWidgets import (QAbstractButton, QAbstractItemView, QAbstractSlider,
                               QAbstractSpinBox, QComboBox, QDockWidget, QGraphicsView,
                               QHeaderView, QLineEdit, QTabBar, QWidget)

from app.gui.shortcuts import ShortcutsDialog
from app.gui.worksheet_blanks import BlankColumns

# What a person operates: buttons of every kind, fields, lists and tables,
# tab bars, the grid and the plots (graphics views).
CONTROLS = (QAbstractButton, QComboBox, QAbstractSpinBox, QLineEdit, QAbstractSlider,
            QAbstractItemView, QTabBar, QGraphicsView)


@pytest.fixture(autouse=True)
def own_files(tmp_path, monkeypatch):
    monkeypatch.setenv("RASTERLAB_SETTINGS", str(tmp_path / "settings.ini"))
    monkeypatch.setenv("RASTERLAB_DATA_DIR", str(tmp_path / "data"))


def _is_qts_own(widget: QWidget) -> bool:
    """Parts Qt makes and names itself (a dock's float and close buttons, a
    spin box's line edit, a scroll area's bars): Qt names them for the reader."""
    while widget is not None:
        if widget.objectName().startswith("qt_"):
            return True
        if isinstance(widget.parentWidget(), (QAbstractSpinBox, QComboBox)):
            return True
        widget = widget.parentWidget()
    return False


def unnamed(top: QWidget) -> list[str]:
    """Each visible control under ``top`` whose accessible name is empty, as
    its class, object name or tooltip, and parent."""
    found = []
    for widget in top.findChildren(QWidget):
        if not isinstance(widget, CONTROLS) or not widget.isVisibleTo(top) or _is_qts_own(widget):
            continue
        if isinstance(widget, QHeaderView):
            continue  # a reader hears the headers through its table's interface
        interface = QAccessible.queryAccessibleInterface(widget)
        if interface is not None and interface.text(QAccessible.Text.Name).strip():
            continue
        parent = widget.parentWidget()
        found.append(f"{type(widget).__name__} {widget.objectName()!r} "
                     f"tooltip={widget.toolTip()[:60]!r} in {type(parent).__name__} "
                     f"{parent.objectName()!r}")
    return found


def assert_named(top: QWidget) -> None:
    missing = unnamed(top)
    assert not missing, "controls without an accessible name:\n" + "\n".join(missing)


def show_every_dock(window) -> None:
    for dock in window.findChildren(QDockWidget):
        dock.show()


def test_the_main_window(window):
    window.add_report_entry()
    show_every_dock(window)
    assert_named(window)


@pytest.mark.parametrize("algorithm, points", [
    ("polygon-scanline", [[(1, 1), (8, 2), (5, 7)]]),
    ("zbuffer", [(1, 1), (8, 2), (4, 7)]),
    ("triangle-texture", [(1, 1), (8, 2), (4, 7)]),
])
def test_the_main_window_of_other_families(make_window, algorithm, points):
    window = make_window(algorithm, points, grid=(12, 10))
    show_every_dock(window)
    assert_named(window)


def test_the_export_dialog(window, tmp_path):
    window.add_file_actions()
    controller = window.file_actions.export_animation()
    assert controller is not None
    assert_named(controller.dialog)
    controller.dialog.reject()


def test_preferences(window):
    window.add_file_actions()
    dialog = window.preferences.open_dialog()
    assert_named(dialog)
    dialog.reject()


def test_compare(window):
    window.compare_entry.action.trigger()
    assert_named(window.compare_entry.window)


def test_gallery(window):
    assert_named(window.gallery_entry.open())


def test_report(window):
    assert_named(window.add_report_entry().open())


def test_exercise_panel(window):
    mode = window.exercise_mode
    mode.action.trigger()
    mode.panel.student.setText("Ada Lovelace")
    mode.panel.student.editingFinished.emit()
    assert_named(mode.dock)


def test_worksheet_columns_and_shortcuts(window, qtbot):
    columns = BlankColumns(["d", "choice"], ["d"], window)
    qtbot.addWidget(columns)
    columns.show()
    assert_named(columns)
    sheet = ShortcutsDialog(window)
    qtbot.addWidget(sheet)
    sheet.show()
    assert_named(sheet)


def test_the_play_button_says_pause_while_playing(window):
    button = window.transport.play_button
    name = lambda: QAccessible.queryAccessibleInterface(button).text(QAccessible.Text.Name)
    assert name() == "Play"
    window.transport.set_playing(True)
    assert name() == "Pause"
    window.transport.set_playing(False)
    assert name() == "Play"
