"""Preferences kept between runs, and the dialog that edits them.

``PreferencesController(window, Preferences())`` (made by
``MainWindow.__init__``) reads the stored preferences, applies them to the
window, and adds Edit > Preferences… (Ctrl+,) and View > Grid lines.

Reduce motion (Appearance) defaults to the system's own setting
(app/model/system_motion.py), read once when first needed; on, it stops Qt's
animated menus, tooltips, combo boxes and docks. Nothing in the window plays
on its own either way: play starts only by Space or the play button.

Preferences live in QSettings: the INI file named by ``$RASTERLAB_SETTINGS``
when that is set (tests and portable set-ups), else the person's RasterLab
settings (organisation and application "RasterLab", as the recent-files list
of app/gui/file_actions.py). A stored value that cannot be read back or is out of
range counts as unset: its default is used, nothing raises.
"""
from __future__ import annotations

import dataclasses
import functools
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import pyqtgraph as pg
from PySide6.QtCore import QObject, QSettings, Qt
from PySide6.QtGui import QAction, QColor, QIcon, QKeySequence, QPalette, QPixmap
from PySide6.QtWidgets import (QApplication, QCheckBox, QColorDialog, QComboBox, QDialog,
                               QDialogButtonBox, QFormLayout, QGridLayout, QGroupBox,
                               QPushButton, QSpinBox, QVBoxLayout)

from algorithms.core.raster import MAX_GRID
from algorithms.core.registry import InputError
from algorithms.core.trace import DEFAULT_STEP_CAP, MAX_STEP_CAP
from app.model import colours
from app.model.budget import DEFAULT_MEMORY_LIMIT
from app.model.system_motion import reduce_motion
from app.model.notation import NUMBERS
from widgets.transport import SPEED_MAX, SPEED_MIN

from app.gui.appdata import open_settings
from app.gui.look import apply_look
from app.render.compose import DARK_PALETTE, PALETTE

THEMES = ("light", "dark")
STEP_CAP_RANGE = (1_000, MAX_STEP_CAP)
MB = 1024 ** 2
MEMORY_MB_RANGE = (64, 1024 * 1024)  # what a run may need, in MiB
MIN_GRID = 16

BASE_PALETTES = {"light": PALETTE, "dark": DARK_PALETTE}
# The grid colours a person can choose: Palette field -> what it colours.
COLOR_NAMES = {
    "ink": "Plotted pixel",
    "current": "Current pixel",
    "candidate": "Candidates",
    "grid": "Grid lines",
}

# ------------------------------------------------------------ parsing values
def _as_bool(value) -> bool:
    if isinstance(value, bool):
        return value
    text = str(value).strip().lower()
    if text in ("true", "1", "yes", "on"):
        return True
    if text in ("false", "0", "no", "off"):
        return False
    raise ValueError(f"not a yes/no value: {value!r}")


def _int_in(low: int, high: int) -> Callable[[Any], int]:
    def parse(value) -> int:
        if isinstance(value, bool) or isinstance(value, float) and not value.is_integer():
            raise ValueError(f"not a whole number: {value!r}")
        number = int(str(value).strip()) if isinstance(value, str) else int(value)
        if not low <= number <= high:
            raise ValueError(f"{number} is outside {low} .. {high}")
        return number
    return parse


def _one_of(*choices: str) -> Callable[[Any], str]:
    def parse(value) -> str:
        text = str(value).strip().lower()
        if text not in choices:
            raise ValueError(f"{value!r} is not one of {', '.join(choices)}")
        return text
    return parse


def _color(value) -> str:
    text = str(value).strip().lower()
    if not re.fullmatch(r"#[0-9a-f]{6}", text):
        raise ValueError(f"not a #rrggbb colour: {value!r}")
    return text


@dataclass(frozen=True)
class Setting:
    key: str
    default: Any  # a value, or a function that finds it (the system's setting)
    parse: Callable[[Any], Any]

    def fallback(self):
        return self.default() if callable(self.default) else self.default


@functools.lru_cache(maxsize=1)
def system_reduce_motion() -> bool:
    """The system's reduce-motion setting, asked once per run."""
    return reduce_motion()


SETTINGS = {
    "theme": Setting("appearance/theme", "light", _one_of(*THEMES)),
    "grid_lines": Setting("appearance/grid_lines", True, _as_bool),
    "origin": Setting("defaults/origin", "bottom-left", _one_of("bottom-left", "top-left")),
    "speed": Setting("defaults/speed", 8, _int_in(SPEED_MIN, SPEED_MAX)),
    "reopen_last": Setting("defaults/reopen_last_scene", False, _as_bool),
    "step_cap": Setting("limits/step_cap", DEFAULT_STEP_CAP, _int_in(*STEP_CAP_RANGE)),
    "max_grid": Setting("limits/max_grid", MAX_GRID, _int_in(MIN_GRID, MAX_GRID)),
    "memory_mb": Setting("limits/memory_mb", DEFAULT_MEMORY_LIMIT // MB, _int_in(*MEMORY_MB_RANGE)),
    # View > Exact fractions (app/gui/numbers_setting.py)
    "numbers": Setting("appearance/numbers", NUMBERS[0], _one_of(*NUMBERS)),
    "reduce_motion": Setting("appearance/reduce_motion", system_reduce_motion, _as_bool),
}


class Preferences:
    """Typed access to the stored preferences, with defaults."""

    def __init__(self, settings: QSettings | None = None):
        self.settings = settings if settings is not None else open_settings()

    def get(self, name: str):
        setting = SETTINGS[name]
        return self._read(setting.key, setting.fallback, setting.parse)

    def set(self, name: str, value) -> None:
        """Store ``value``; raises ValueError when it is not acceptable."""
        setting = SETTINGS[name]
        self.settings.setValue(setting.key, setting.parse(value))

    def color(self, theme: str, name: str) -> str:
        default = getattr(BASE_PALETTES[theme], name)
        return self._read(f"colors/{theme}/{name}", default, _color)

    def set_color(self, theme: str, name: str, value) -> None:
        if theme not in THEMES or name not in COLOR_NAMES:
            raise ValueError(f"no colour {name!r} in the {theme!r} theme")
        self.settings.setValue(f"colors/{theme}/{name}", _color(value))

    def values(self) -> dict:
        """Everything the dialog edits, as one dict."""
        values = {name: self.get(name) for name in SETTINGS}
        values["colors"] = {theme: {name: self.color(theme, name) for name in COLOR_NAMES}
                            for theme in THEMES}
        return values

    def update(self, values: dict) -> None:
        for name in SETTINGS:
            if name in values:
                self.set(name, values[name])
        for theme, colors in values.get("colors", {}).items():
            for name, value in colors.items():
                self.set_color(theme, name, value)
        self.settings.sync()

    def _read(self, key: str, default, parse):
        raw = self.settings.value(key)
        if raw is None:
            return default() if callable(default) else default
        try:
            return parse(raw)
        except (TypeError, ValueError, OverflowError):
            # a hand-edited or damaged file: fall back quietly
            return default() if callable(default) else default


def default_values() -> dict:
    values = {name: setting.fallback() for name, setting in SETTINGS.items()}
    values["colors"] = {theme: {name: getattr(BASE_PALETTES[theme], name)
                                for name in COLOR_NAMES} for theme in THEMES}
    return values


# ------------------------------------------------------------------- theme
_original_look: tuple[str, QPalette] | None = None


def dark_qpalette() -> QPalette:
    """A dark palette for Qt's own widgets (used with the Fusion style)."""
    roles = QPalette.ColorRole
    palette = QPalette()
    for role, color in ((roles.Window, "#232a33"), (roles.WindowText, "#e6edf3"),
                        (roles.Base, "#1b2027"), (roles.AlternateBase, "#222831"),
                        (roles.ToolTipBase, "#2d3540"), (roles.ToolTipText, "#e6edf3"),
                        (roles.PlaceholderText, "#8b949e"), (roles.Text, "#e6edf3"),
                        (roles.Button, "#2d3540"), (roles.ButtonText, "#e6edf3"),
                        (roles.BrightText, "#ff6b6b"), (roles.Link, "#5fa8f5"),
                        (roles.Highlight, "#2f6fb5"), (roles.HighlightedText, "#ffffff"),
                        (roles.Light, "#3a4350"), (roles.Midlight, "#303844"),
                        (roles.Mid, "#252c35"), (roles.Dark, "#161b21"),
                        (roles.Shadow, "#0b0e12")):
        palette.setColor(role, QColor(color))
    disabled = QPalette.ColorGroup.Disabled
    for role in (roles.WindowText, roles.Text, roles.ButtonText):
        palette.setColor(disabled, role, QColor("#6e7681"))
    return palette


def apply_theme(theme: str) -> None:
    """Set the whole application's look; "light" restores the look it had."""
    global _original_look
    app = QApplication.instance()
    if app is None:
        return
    if _original_look is None:
        _original_look = (app.style().name(), QPalette(app.palette()))
    if theme == "dark":
        app.setStyle("Fusion")
        app.setPalette(dark_qpalette())
    else:
        style, palette = _original_look
        if app.style().name() != style:
            app.setStyle(style)
        app.setPalette(palette)


# ----------------------------------------------------------- the window side
class PreferencesController(QObject):
    """Preferences of one window: the menu entries, the dialog, applying."""

    def __init__(self, window, preferences: Preferences):
        super().__init__(window)
        self.window = window
        self.prefs = preferences
        self.dialog: PreferencesDialog | None = None
        self._build_actions()
        self.apply(preferences.values(), first=True)
        window.grid_editor.gridChanged.connect(self._grid_typed)

    def _build_actions(self) -> None:
        window = self.window
        self.action = QAction("&Preferences\u2026", window)
        self.action.setShortcut(QKeySequence("Ctrl+,"))
        self.action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
        self.action.setMenuRole(QAction.MenuRole.PreferencesRole)
        self.action.setToolTip("Theme, colours, defaults and limits (Ctrl+,)")
        self.action.triggered.connect(self.open_dialog)
        edit = window.menus["edit"]
        edit.addSeparator()
        edit.addAction(self.action)
        window.addAction(self.action)
        self.grid_lines_action = QAction("Grid lines", window)
        self.grid_lines_action.setCheckable(True)
        self.grid_lines_action.setToolTip("Show the lines between the cells of the grid")
        self.grid_lines_action.toggled.connect(self._grid_lines_toggled)
        view = window.menus["view"]
        first = view.actions()[1] if len(view.actions()) > 1 else None
        view.insertAction(first, self.grid_lines_action)

    # ------------------------------------------------------------ applying
    def apply(self, values: dict, first: bool = False) -> None:
        """Make ``values`` take effect in the window. The origin and speed
        are defaults for a new window: the open one takes them when they
        change (or at start), not on every apply."""
        window = self.window
        old = self.prefs.values() if not first else {}
        theme = values["theme"]
        apply_theme(theme)
        dark = theme == "dark"
        if dark != window.dark and not first:  # restyling takes long: only on a change
            apply_look(window, dark)
        window.dark = dark
        palette = dataclasses.replace(BASE_PALETTES[theme], **values["colors"][theme])
        window.set_palette(palette)
        _theme_panels(window, dark)
        self.grid_lines_action.blockSignals(True)
        self.grid_lines_action.setChecked(values["grid_lines"])
        self.grid_lines_action.blockSignals(False)
        window.grid.set_grid_lines_visible(values["grid_lines"])
        if first or values["origin"] != old.get("origin"):
            window.set_y_down(values["origin"] == "top-left")
        if first or values["speed"] != old.get("speed"):
            window.transport.set_speed(values["speed"])
        self._apply_limits(values["step_cap"], values["max_grid"])
        window.player.memory_limit = values["memory_mb"] * MB
        apply_motion(window, values["reduce_motion"])
        window.show_frame()

    def _apply_limits(self, step_cap: int, max_grid: int) -> None:
        window, player = self.window, self.window.player
        player.max_grid = max_grid
        window.grid_editor.set_maximum(max_grid)
        width, height = player.grid
        if width > max_grid or height > max_grid:
            window.set_grid(min(width, max_grid), min(height, max_grid))
        if step_cap != player.step_cap:
            player.step_cap = step_cap
            if player.spec is not None:
                # Record the scene on show again under the new cap.
                try:
                    player.restore(player.points, player.breaks, player.options)
                except InputError as error:
                    window.say_error(str(error))

    def open_dialog(self) -> "PreferencesDialog":
        if self.dialog is None:
            self.dialog = PreferencesDialog(self.window)
            self.dialog.accepted.connect(lambda: self.save_and_apply(self.dialog.values()))
            self.dialog.apply_button.clicked.connect(
                lambda: self.save_and_apply(self.dialog.values()))
        self.dialog.set_values(self.prefs.values())
        self.dialog.open()
        return self.dialog

    def save_and_apply(self, values: dict) -> None:
        self.apply(values)
        self.prefs.update(values)

    # ------------------------------------------------------ live changes
    def _grid_lines_toggled(self, on: bool) -> None:
        self.window.grid.set_grid_lines_visible(on)
        self.prefs.set("grid_lines", on)

    def _grid_typed(self, width: int, height: int) -> None:
        limit = self.window.player.max_grid
        if max(width, height) >= limit:
            self.window.statusBar().showMessage(
                f"The grid is at its maximum size of {limit} pixels a side; raise "
                f"\"Maximum grid size\" in Edit > Preferences (up to {MAX_GRID}).", 8000)


ANIMATED_EFFECTS = (Qt.UIEffect.UI_AnimateMenu, Qt.UIEffect.UI_FadeMenu,
                    Qt.UIEffect.UI_AnimateCombo, Qt.UIEffect.UI_AnimateTooltip,
                    Qt.UIEffect.UI_FadeTooltip, Qt.UIEffect.UI_AnimateToolBox)
_system_effects: dict | None = None  # Qt's effects as the platform set them


def apply_motion(window, reduce: bool) -> None:
    """Reduce motion: no animated menus, tooltips, combo boxes or docks
    (the system's effects back when it is off)."""
    global _system_effects
    if _system_effects is None:
        _system_effects = {e: QApplication.isEffectEnabled(e) for e in ANIMATED_EFFECTS}
    for effect, enabled in _system_effects.items():
        QApplication.setEffectEnabled(effect, enabled and not reduce)
    window.setAnimated(not reduce)
    window.reduce_motion = bool(reduce)


def _theme_panels(window, dark: bool) -> None:
    """The few colours the panels set themselves for the light look."""
    for k in range(window.picker.topLevelItemCount()):
        window.picker.topLevelItem(k).setForeground(0, QColor("#9aa7b5" if dark else "#3d4754"))
    window.variables.set_meanings(colours.DARK if dark else colours.LIGHT)
    plot = getattr(window.variables, "plot", None)
    if plot is None:
        return
    plot.setBackground("#1b2027" if dark else "#ffffff")
    for axis in window.variables.plot_axes.values():
        axis.setTextPen(pg.mkPen("#c9d1d9" if dark else "#3d4754"))


def reopen_last_scene(window) -> bool:
    """At start: open the scene opened or saved last, when the preference
    asks for it and the file is still there."""
    controller, actions = window.preferences, window.file_actions
    if actions is None or not controller.prefs.get("reopen_last"):
        return False
    recent = actions.recent()
    if not recent:
        return False
    path = Path(recent[0])
    if not path.is_file():
        window.statusBar().showMessage(f"The last scene, {path}, is no longer there.", 8000)
        return False
    return actions.open_path(path)


# ------------------------------------------------------------------- dialog
def _swatch(color: str) -> QIcon:
    pixmap = QPixmap(28, 16)
    pixmap.fill(QColor(color))
    return QIcon(pixmap)


class PreferencesDialog(QDialog):
    """Edits a values dict (see ``Preferences.values``); OK and Apply hand
    it over, the dialog itself stores nothing."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setWindowTitle("Preferences")
        self._colors = default_values()["colors"]
        layout = QVBoxLayout(self)
        layout.addWidget(self._appearance_group())
        layout.addWidget(self._defaults_group())
        layout.addWidget(self._limits_group())
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel
                                   | QDialogButtonBox.StandardButton.Apply
                                   | QDialogButtonBox.StandardButton.RestoreDefaults, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        self.button_box = buttons
        self.apply_button = buttons.button(QDialogButtonBox.StandardButton.Apply)
        self.apply_button.setToolTip("Use these settings now and keep them")
        buttons.button(QDialogButtonBox.StandardButton.Ok).setToolTip(
            "Use these settings now, keep them and close")
        buttons.button(QDialogButtonBox.StandardButton.Cancel).setToolTip(
            "Close without changing anything")
        defaults = buttons.button(QDialogButtonBox.StandardButton.RestoreDefaults)
        defaults.setToolTip("Put every setting back to its default (press OK or Apply to use "
                            "them)")
        defaults.clicked.connect(lambda: self.set_values(default_values()))
        layout.addWidget(buttons)

    def _appearance_group(self) -> QGroupBox:
        group = QGroupBox("Appearance", self)
        form = QFormLayout(group)
        self.theme = QComboBox(group)
        self.theme.addItems(["Light", "Dark"])
        self.theme.setToolTip("Light or dark look for the whole window and the grid")
        self.theme.currentIndexChanged.connect(lambda _i: self._show_colors())
        form.addRow("&Theme", self.theme)
        colors = QGridLayout()
        self.color_buttons = {}
        for k, (name, text) in enumerate(COLOR_NAMES.items()):
            button = QPushButton(text, group)
            button.setToolTip(f"Colour of the {text.lower()} in this theme (click to choose)")
            button.clicked.connect(lambda _checked=False, n=name: self._choose(n))
            colors.addWidget(button, k // 2, k % 2)
            self.color_buttons[name] = button
        form.addRow("Grid colours", colors)
        self.grid_lines = QCheckBox("Show grid &lines", group)
        self.grid_lines.setToolTip("Draw the lines between the cells of the grid")
        form.addRow("", self.grid_lines)
        self.reduce_motion = QCheckBox("Reduce &motion", group)
        self.reduce_motion.setToolTip("No animated menus, tooltips or docks (the default is the "
                                      "system's own setting where it can be read)")
        form.addRow("", self.reduce_motion)
        return group

    def _defaults_group(self) -> QGroupBox:
        group = QGroupBox("New windows", self)
        form = QFormLayout(group)
        self.origin = QComboBox(group)
        self.origin.addItems(["Bottom-left, y up", "Top-left, y down"])
        self.origin.setToolTip("Where pixel (0, 0) is in a new window (a scene file's own "
                               "origin wins when it is opened)")
        form.addRow("Or&igin", self.origin)
        self.speed = QSpinBox(group)
        self.speed.setRange(SPEED_MIN, SPEED_MAX)
        self.speed.setSuffix(" steps/s")
        self.speed.setToolTip("Playback speed, in steps per second")
        form.addRow("Playback &speed", self.speed)
        self.reopen_last = QCheckBox("R&eopen the last scene at start", group)
        self.reopen_last.setToolTip("At start, open the scene file opened or saved last "
                                    "instead of the demo scene")
        form.addRow("", self.reopen_last)
        return group

    def _limits_group(self) -> QGroupBox:
        group = QGroupBox("Limits", self)
        form = QFormLayout(group)
        self.step_cap = QSpinBox(group)
        self.step_cap.setRange(*STEP_CAP_RANGE)
        self.step_cap.setSingleStep(1_000_000)
        self.step_cap.setGroupSeparatorShown(True)
        self.step_cap.setSuffix(" steps")
        self.step_cap.setToolTip("A run stops recording after this many steps (a longer run "
                                 f"takes more memory); {STEP_CAP_RANGE[0]:,} to "
                                 f"{STEP_CAP_RANGE[1]:,}")
        form.addRow("Step ca&p", self.step_cap)
        self.max_grid = QSpinBox(group)
        self.max_grid.setRange(MIN_GRID, MAX_GRID)
        self.max_grid.setSuffix(" px a side")
        self.max_grid.setToolTip(f"The largest grid width and height accepted ({MIN_GRID} to "
                                 f"{MAX_GRID})")
        form.addRow("Maximum &grid size", self.max_grid)
        self.memory_mb = QSpinBox(group)
        self.memory_mb.setRange(*MEMORY_MB_RANGE)
        self.memory_mb.setSingleStep(512)
        self.memory_mb.setGroupSeparatorShown(True)
        self.memory_mb.setSuffix(" MiB")
        self.memory_mb.setToolTip("A run whose estimated memory is larger is refused before it "
                                  "starts, and the scene stays as it was")
        form.addRow("Memory for a &run", self.memory_mb)
        return group

    # ---------------------------------------------------------- values
    def set_values(self, values: dict) -> None:
        self._colors = {theme: dict(colors) for theme, colors in values["colors"].items()}
        self.theme.setCurrentIndex(THEMES.index(values["theme"]))
        self.grid_lines.setChecked(values["grid_lines"])
        self.origin.setCurrentIndex(1 if values["origin"] == "top-left" else 0)
        self.speed.setValue(values["speed"])
        self.reopen_last.setChecked(values["reopen_last"])
        self.reduce_motion.setChecked(values["reduce_motion"])
        self.step_cap.setValue(values["step_cap"])
        self.max_grid.setValue(values["max_grid"])
        self.memory_mb.setValue(values["memory_mb"])
        self._show_colors()

    def values(self) -> dict:
        return {"theme": THEMES[self.theme.currentIndex()],
                "grid_lines": self.grid_lines.isChecked(),
                "origin": "top-left" if self.origin.currentIndex() == 1 else "bottom-left",
                "speed": self.speed.value(), "reopen_last": self.reopen_last.isChecked(),
                "step_cap": self.step_cap.value(), "max_grid": self.max_grid.value(),
                "memory_mb": self.memory_mb.value(),
                "reduce_motion": self.reduce_motion.isChecked(),
                "colors": {theme: dict(colors) for theme, colors in self._colors.items()}}

    def set_color(self, name: str, color: str) -> None:
        """Set a colour of the theme chosen in the dialog."""
        self._colors[THEMES[self.theme.currentIndex()]][name] = _color(color)
        self._show_colors()

    def _choose(self, name: str) -> None:
        theme = THEMES[self.theme.currentIndex()]
        chosen = QColorDialog.getColor(QColor(self._colors[theme][name]), self,
                                       COLOR_NAMES[name])
        if chosen.isValid():
            self.set_color(name, chosen.name())

    def _show_colors(self) -> None:
        theme = THEMES[self.theme.currentIndex()]
        for name, button in self.color_buttons.items():
            button.setIcon(_swatch(self._colors[theme][name]))
