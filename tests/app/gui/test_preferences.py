"""Preferences kept between runs, the standard shortcuts, tooltips, About."""
import configparser
import platform
import re
from importlib import metadata
from pathlib import Path

import PySide6
import pytest
from PySide6.QtCore import QSettings, Qt, QTimer, qVersion
from PySide6.QtGui import QKeySequence, QPalette
from PySide6.QtTest import QTest
from PySide6.QtWidgets import (QAbstractButton, QAbstractSpinBox, QApplication, QComboBox,
                               QLineEdit, QSlider, QToolBar, QWidget)

from algorithms.core.raster import MAX_GRID
from algorithms.core.trace import DEFAULT_STEP_CAP
from app.gui import about, appdata, preferences
from app.gui.preferences import Preferences, apply_theme, default_values
from app.gui.window import GESTURES, MainWindow, ShortcutsDialog
from app.model import version
from tests.support import ROOT
from tests.support.gui import WAIT_MS

CTRL = Qt.KeyboardModifier.ControlModifier


@pytest.fixture
def settings_file(tmp_path, monkeypatch):
    """A settings file of this test's own; the light look afterwards."""
    path = tmp_path / "settings.ini"
    monkeypatch.setenv(appdata.SETTINGS_ENV, str(path))
    yield path
    apply_theme("light")


def open_window(qtbot) -> MainWindow:
    window = MainWindow()
    qtbot.addWidget(window)
    window.add_file_actions()
    window.add_report_entry()
    window.show()
    qtbot.waitExposed(window)
    return window


def focus_grid(qtbot, window) -> None:
    # Window shortcuts need the window active: giving its grid the focus does it.
    window.grid.setFocus()
    qtbot.waitUntil(window.grid.hasFocus, timeout=WAIT_MS)


def press(window, key, modifier=Qt.KeyboardModifier.NoModifier) -> None:
    QTest.keyClick(window.grid, key, modifier)


def rgb(color: str) -> list[int]:
    return [int(color[k:k + 2], 16) for k in (1, 3, 5)]


CHOSEN = {"theme": "dark", "grid_lines": False, "origin": "top-left", "speed": 37,
          "reopen_last": True, "step_cap": 123_456, "max_grid": 300, "memory_mb": 1536}
INK, CURRENT, CANDIDATE, GRID = "#12ab34", "#fe0102", "#0a0b0c", "#777778"


def test_preferences_persist_across_a_restart(qtbot, settings_file):
    first = open_window(qtbot)
    dialog = first.preferences.open_dialog()
    dialog.theme.setCurrentIndex(1)
    dialog.grid_lines.setChecked(False)
    dialog.origin.setCurrentIndex(1)
    dialog.speed.setValue(37)
    dialog.reopen_last.setChecked(True)
    dialog.step_cap.setValue(123_456)
    dialog.max_grid.setValue(300)
    dialog.memory_mb.setValue(1536)
    for name, color in (("ink", INK), ("current", CURRENT), ("candidate", CANDIDATE),
                        ("grid", GRID)):
        dialog.set_color(name, color)
    dialog.button_box.button(dialog.button_box.StandardButton.Ok).click()
    assert first.player.step_cap == 123_456  # applied at once in the open window
    assert first.player.memory_limit == 1536 * 1024 ** 2
    assert first.grid.y_down
    first.close()

    # What is on disk, read as a plain INI file.
    stored = configparser.ConfigParser()
    stored.read(settings_file)
    assert stored["limits"]["step_cap"] == "123456"
    assert stored["appearance"]["theme"] == "dark"

    apply_theme("light")  # a fresh start: the next window must set the look itself
    second = open_window(qtbot)
    values = Preferences().values()
    for name, value in CHOSEN.items():
        assert values[name] == value, name
    assert values["colors"]["dark"] == {"ink": INK, "current": CURRENT,
                                        "candidate": CANDIDATE, "grid": GRID}
    # ... and applied to the new window.
    window_color = QApplication.instance().palette().color(QPalette.ColorRole.Window)
    assert window_color.lightness() < 80
    assert not second.grid.grid_lines.isVisible()
    assert not second.preferences.grid_lines_action.isChecked()
    assert second.grid.y_down and second.grid_editor.origin.currentIndex() == 1
    assert second.transport.speed == 37 and second.player.speed == 37
    assert second.player.step_cap == 123_456
    assert second.player.max_grid == 300
    assert second.grid_editor.width_box.maximum() == 300
    # The demo line's first pixel (4, 5) is plotted in the chosen ink.
    assert list(second.grid.image.image[5, 4, :3]) == rgb(INK)
    assert second.grid.palette.current == CURRENT


def test_the_last_scene_is_reopened_when_asked(qtbot, settings_file, tmp_path):
    scene = ROOT / "resources" / "scenes"
    example = sorted(scene.glob("*.json"))[0]
    target = tmp_path / "mine.json"
    target.write_text(example.read_text())
    first = open_window(qtbot)
    assert first.file_actions.open_path(target)
    Preferences().set("reopen_last", True)
    expected = first.player.spec.name
    first.close()
    second = open_window(qtbot)
    assert preferences.reopen_last_scene(second)
    assert second.file_actions.path == target and second.player.spec.name == expected
    target.unlink()
    third = open_window(qtbot)
    assert not preferences.reopen_last_scene(third)  # gone: the demo stays, no error box


def test_corrupt_or_out_of_range_values_fall_back_to_the_defaults(qtbot, settings_file):
    settings_file.write_text(
        "[appearance]\ntheme=purple\ngrid_lines=maybe\n"
        "[defaults]\norigin=middle\nspeed=-5\nreopen_last_scene=2\n"
        "[limits]\nstep_cap=12abc\nmax_grid=999999\n"
        "[colors]\ndark\\ink=notacolour\nlight\\current=#12345\n")
    prefs = Preferences()
    # The damaged values are really there, as text ...
    assert prefs.settings.value("limits/step_cap") == "12abc"
    assert prefs.settings.value("colors/dark/ink") == "notacolour"
    values = prefs.values()  # ... and read back as the defaults.
    expected = {"theme": "light", "grid_lines": True, "origin": "bottom-left", "speed": 8,
                "reopen_last": False, "step_cap": 5_000_000, "max_grid": 4096}
    assert {name: values[name] for name in expected} == expected
    assert values == default_values()
    window = open_window(qtbot)  # opens, with the defaults in force
    assert window.player.step_cap == DEFAULT_STEP_CAP == 5_000_000
    assert window.player.max_grid == MAX_GRID == 4096
    assert window.grid.grid_lines.isVisible()


@pytest.mark.parametrize("name, value", [("step_cap", 999), ("step_cap", 50_000_001),
                                         ("max_grid", MAX_GRID + 1), ("theme", "blue"),
                                         ("speed", 0), ("grid_lines", "perhaps")])
def test_a_bad_value_is_refused_when_set(settings_file, name, value):
    prefs = Preferences()
    with pytest.raises(ValueError):
        prefs.set(name, value)
    assert prefs.get(name) == default_values()[name]


def test_reaching_the_step_cap_names_the_setting(qtbot, settings_file):
    Preferences().set("step_cap", 1000)
    window = open_window(qtbot)
    window.set_grid(1200, 8)
    window.set_points([(0, 0), (1199, 3)])  # 1,200 plotted pixels, more than the cap
    trace = window.player.trace
    assert trace.truncated and len(trace) == 1000
    text = window.message.text()
    assert "1,000" in text and '"Step cap"' in text and "Preferences" in text


def test_a_run_over_the_memory_setting_is_refused_and_the_scene_kept(qtbot, settings_file):
    Preferences().set("memory_mb", 64)
    window = open_window(qtbot)
    assert window.player.memory_limit == 64 * 1024 ** 2
    before = window.player.scene
    window.set_grid(4096, 4096)  # a run here may need more than 64 MiB
    assert window.player.scene.width == before.width
    assert "over the limit of 64.0 MB" in window.message.text()


def test_reaching_the_grid_limit_names_the_setting(qtbot, settings_file):
    Preferences().set("max_grid", 64)
    window = open_window(qtbot)
    window.set_grid(100, 20)
    assert window.player.grid == (32, 24)  # refused, unchanged
    assert "Maximum grid size" in window.message.text() and "64x64" in window.message.text()
    window.grid_editor.width_box.setValue(500)  # the box stops at the limit, and says so
    assert window.player.grid == (64, 24)
    assert "Maximum grid size" in window.statusBar().currentMessage()


ISSUE_KEYS = ("Ctrl+O", "Ctrl+S", "Ctrl+E", "Ctrl+Z", "Space", "Right", "Left", "Home", "End",
              "F1")


def _bound_action(window, key):
    wanted = QKeySequence(key)
    for action in window.findChildren(type(window.preferences.action)):
        if wanted in action.shortcuts():
            return action
    return None


def test_the_shortcut_sheet_lists_the_keys_that_work(qtbot, settings_file):
    window = open_window(qtbot)
    seen = []

    def read_and_close():
        dialog = QApplication.activeModalWidget()
        if isinstance(dialog, ShortcutsDialog):
            seen.extend(dialog.rows)
            dialog.reject()
            timer.stop()
    timer = QTimer(window)
    timer.timeout.connect(read_and_close)
    timer.start(20)
    focus_grid(qtbot, window)
    press(window, Qt.Key.Key_F1)
    timer.stop()
    assert seen, "F1 did not open the shortcuts sheet"
    sheet = {}
    for keys, text in seen:
        for key in keys.split(", "):
            sheet[key] = text
    for key in ISSUE_KEYS:
        action = _bound_action(window, key)
        assert action is not None, f"no action has {key}"
        assert sheet[key] == action.text().replace("&", "").replace("\u2026", ""), key
    # The pointer gestures of the hand-written list are there too.
    assert sheet["Mouse wheel"] == dict(GESTURES)["Mouse wheel"]


def test_the_issue_shortcuts_work(qtbot, settings_file, monkeypatch):
    window = open_window(qtbot)
    player = window.player
    calls = []
    monkeypatch.setattr("app.gui.file_actions.QFileDialog.getOpenFileName",
                        lambda *a, **k: calls.append("open") or ("", ""))
    monkeypatch.setattr("app.gui.file_actions.QFileDialog.getSaveFileName",
                        lambda *a, **k: calls.append("save") or ("", ""))
    focus_grid(qtbot, window)
    press(window, Qt.Key.Key_O, CTRL)
    press(window, Qt.Key.Key_S, CTRL)
    assert calls == ["open", "save"]
    press(window, Qt.Key.Key_E, CTRL)
    controller = window.file_actions.export_controller
    assert controller is not None and controller.dialog.isVisible()
    controller.close()

    last = len(player.trace) - 1
    press(window, Qt.Key.Key_Home)
    assert player.index == 0
    press(window, Qt.Key.Key_Right)
    press(window, Qt.Key.Key_Right)
    press(window, Qt.Key.Key_Left)
    assert player.index == 1
    press(window, Qt.Key.Key_End)
    assert player.index == last
    press(window, Qt.Key.Key_Home)
    press(window, Qt.Key.Key_Space)
    assert player.playing
    press(window, Qt.Key.Key_Space)
    assert not player.playing

    before = list(player.points)
    window.clear_points()
    assert player.points == []
    press(window, Qt.Key.Key_Z, CTRL)
    assert player.points == before


def test_preferences_shortcut_opens_the_dialog(qtbot, settings_file):
    window = open_window(qtbot)
    focus_grid(qtbot, window)
    press(window, Qt.Key.Key_Comma, CTRL)
    assert window.preferences.dialog is not None and window.preferences.dialog.isVisible()
    window.preferences.dialog.reject()


def test_about_names_the_version_and_the_runtime(qtbot, settings_file, monkeypatch):
    window = open_window(qtbot)
    shown = []
    monkeypatch.setattr("app.gui.window.QMessageBox.about", lambda parent, title, text:
                        shown.append(text))
    window.show_about()
    text = shown[0]
    assert f"Version {metadata.version('rasterlab')}" in text
    for part in (qVersion(), PySide6.__version__, platform.python_version()):
        assert part in text


def test_the_version_falls_back_to_pyproject(monkeypatch):
    def missing(name):
        raise metadata.PackageNotFoundError(name)
    monkeypatch.setattr(version.metadata, "version", missing)
    declared = re.search(r'^version\s*=\s*"([^"]+)"', (ROOT / "pyproject.toml").read_text(),
                         re.MULTILINE).group(1)
    assert about.app_version() == version.app_version() == declared


CONTROLS = (QAbstractButton, QComboBox, QAbstractSpinBox, QLineEdit, QSlider)


def _tooltip(widget, top) -> str:
    """The tooltip Qt shows over ``widget``: its own, else the nearest
    ancestor's (a tooltip event goes up to the parent when unanswered)."""
    while widget is not None and widget is not top:
        if widget.toolTip().strip():
            return widget.toolTip()
        widget = widget.parentWidget()
    return ""


def test_every_control_of_the_main_window_has_a_tooltip(qtbot, settings_file):
    window = open_window(qtbot)
    missing = []
    for widget in window.findChildren(QWidget):
        if not isinstance(widget, CONTROLS) or not widget.isVisibleTo(window):
            continue
        # Qt's own dock title buttons (close, float) are not ours to explain.
        if widget.objectName().startswith("qt_dockwidget_"):
            continue
        if not _tooltip(widget, window):
            text = widget.text() if hasattr(widget, "text") else ""
            missing.append(f"{type(widget).__name__} {widget.objectName()!r} {text!r}")
    for bar in window.findChildren(QToolBar):
        for action in bar.actions():
            if action.isSeparator() or not action.isVisible():
                continue
            # A tooltip that only repeats the button's text explains nothing.
            if action.toolTip().replace("&", "") == action.text().replace("&", ""):
                missing.append(f"toolbar action {action.text()!r}")
    assert not missing, "controls without a tooltip:\n" + "\n".join(missing)


def test_the_dialog_has_a_tooltip_on_every_control(qtbot, settings_file):
    window = open_window(qtbot)
    dialog = window.preferences.open_dialog()
    bare = [widget for widget in dialog.findChildren(QWidget)
            if isinstance(widget, CONTROLS) and widget.isVisibleTo(dialog)
            and not _tooltip(widget, dialog)]
    assert not bare
    dialog.reject()


def test_settings_of_the_tests_are_not_the_users(settings_file):
    # conftest points QSettings at a temporary folder for the whole session.
    default = QSettings("RasterLab", "RasterLab").fileName()
    assert "rasterlab-test-settings-" in default
    assert Path(Preferences().settings.fileName()) == settings_file


def test_apply_takes_effect_at_once_in_the_open_window(qtbot, settings_file):
    window = open_window(qtbot)
    window.set_grid(1200, 8)
    window.set_points([(0, 0), (1199, 3)])
    assert len(window.player.trace) > 1000 and not window.player.trace.truncated
    dialog = window.preferences.open_dialog()
    dialog.step_cap.setValue(1000)
    dialog.max_grid.setValue(1100)
    dialog.theme.setCurrentIndex(1)
    dialog.apply_button.click()
    assert window.player.grid == (1100, 8)  # shrunk to the new maximum
    assert window.grid_editor.width_box.maximum() == 1100
    assert window.player.trace.truncated and len(window.player.trace) == 1000
    assert '"Step cap"' in window.message.text()
    assert window.grid.palette.outside == preferences.DARK_PALETTE.outside
    # Both legends follow the theme: the "not written" coverage chip too.
    chip = window.coverage_legend.chips[0][0].pixmap().toImage().pixelColor(7, 7).name()
    assert chip == preferences.DARK_PALETTE.coverage[0]
    current = window.legend.chips[0][0].pixmap().toImage().pixelColor(2, 7).name()
    assert current == preferences.DARK_PALETTE.current
    # The run plot's numbers are light on its dark ground.
    assert [axis.textPen().color().name() for axis in window.variables.plot_axes.values()] \
        == ["#c9d1d9"] * 2
    dialog.reject()
    # The View menu's toggle is the same preference.
    window.preferences.grid_lines_action.setChecked(False)
    assert not window.grid.grid_lines.isVisible()
    assert Preferences().get("grid_lines") is False


def _signed_value_colours(window) -> set:
    """The text colours of the Variables panel's values written with a '+'."""
    table = window.variables.table
    items = [table.item(row, 1) for row in range(table.rowCount())]
    return {item.foreground().color().name() for item in items
            if item is not None and item.text().startswith("+")}


def test_the_dark_theme_draws_signs_and_branches_in_its_own_colours(qtbot, settings_file):
    window = open_window(qtbot)
    window.picker.setCurrentItem(window.picker.item_for("triangle-bbox"))
    window.set_points([(2, 2), (14, 3), (6, 12)])
    window.player.first()
    window.player.step(5)  # a pixel inside: e0, e1 and e2 all positive
    # Okabe-Ito blue on the light ground, sky blue on the dark one (app/model/colours.py).
    assert _signed_value_colours(window) == {"#0072b2"}
    dialog = window.preferences.open_dialog()
    dialog.theme.setCurrentIndex(1)
    dialog.apply_button.click()
    dialog.reject()
    assert _signed_value_colours(window) == {"#56b4e9"}
    # The decision dots of the d plot: orange for NE, not the light theme's vermillion.
    window.picker.setCurrentItem(window.picker.item_for("line-bresenham"))
    window.set_points([(0, 0), (12, 5)])
    brushes = {brush.color().name() for brush in window.variables.dots.data["brush"]}
    assert "#e69f00" in brushes and "#d55e00" not in brushes
    assert "color:#56b4e9" in window.variables.plot_title.text()
