"""The main window's menus, actions and drawing toolbar (a part of
``MainWindow``). Other modules add their entries to ``window.menus`` by
name and their actions through ``add_action``."""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import QToolBar

from widgets.grid_view import DRAW, MARKER

from app.gui.appdata import APP_NAME


class WindowMenus:
    """Menus and actions of the main window (a part of ``MainWindow``)."""

    def _build_actions(self) -> None:
        bar = self.menuBar()
        file_menu = bar.addMenu("&File")
        # Other modules add their entries to these menus by name.
        self.menus = {"file": file_menu}
        quit_action = file_menu.addAction("&Quit")
        quit_action.setShortcut(QKeySequence("Ctrl+Q"))  # what StandardKey.Quit is on Linux
        quit_action.triggered.connect(self.close)
        self.actions_: dict[str, QAction] = {}
        for key, title in (("edit", "&Edit"), ("view", "&View"), ("run", "&Run")):
            self.menus[key] = bar.addMenu(title)
        self._build_edit_menu(self.menus["edit"])
        self._build_playback_menu(self.menus["run"])
        self._build_view_menu(self.menus["view"])
        self._build_toolbar()

        help_menu = self.menus["help"] = bar.addMenu("&Help")
        keys = help_menu.addAction("&Keyboard shortcuts")
        keys.setShortcut(QKeySequence("F1"))
        keys.triggered.connect(self.show_shortcuts)
        about = help_menu.addAction(f"&About {APP_NAME}")
        about.triggered.connect(self.show_about)

    def add_action(self, menu, key, text, shortcut, slot,
                   context=Qt.ShortcutContext.WindowShortcut, owner=None) -> QAction:
        act = QAction(text, self)
        if shortcut:
            act.setShortcut(QKeySequence(shortcut))
            keys = act.shortcut().toString(QKeySequence.SequenceFormat.NativeText)
            plain = text.replace("&", "").rstrip("\u2026")
            act.setToolTip(f"{plain} ({keys})")
        # Shortcuts work wherever the focus is in the window; editors that
        # need the key for typing (spin boxes, text fields) keep it.
        act.setShortcutContext(context)
        act.triggered.connect(slot)
        menu.addAction(act)
        (owner or self).addAction(act)
        self.actions_[key] = act
        return act

    def _build_edit_menu(self, menu) -> None:
        self.add_action(menu, "undo", "&Undo", "Ctrl+Z", self.undo)
        redo = self.add_action(menu, "redo", "&Redo", "Ctrl+Shift+Z", self.redo)
        redo.setShortcuts([QKeySequence("Ctrl+Shift+Z"), QKeySequence("Ctrl+Y")])
        menu.addSeparator()
        # Enter and Backspace belong to the grid only: elsewhere they confirm
        # a typed number or delete a character.
        grid_only = Qt.ShortcutContext.WidgetWithChildrenShortcut
        self.add_action(menu, "close", "&Close the contour", "Return", self.grid.close_contour,
                        grid_only, self.grid)
        self.add_action(menu, "remove", "Remove the &last point", "Backspace",
                        self.grid.remove_last_point, grid_only, self.grid)
        self.add_action(menu, "clear", "C&lear points", None, self.clear_points).setToolTip(
            "Remove every point (Ctrl+Z brings them back)")
        menu.addSeparator()
        group = QActionGroup(self)
        draw = self.add_action(menu, "draw", "&Draw points", None,
                               lambda: self.set_tool(DRAW))
        seed = self.add_action(menu, "marker", "Place the &seed", "S",
                               lambda: self.set_tool(MARKER if self.grid.tool != MARKER else DRAW))
        for act in (draw, seed):
            act.setCheckable(True)
            group.addAction(act)
        draw.setChecked(True)
        draw.setToolTip("Clicks on the grid place points; drag a handle to move one")

    def _build_playback_menu(self, play) -> None:
        self.add_action(play, "play", "Play / Pause", "Space", self.player.toggle)
        play.addSeparator()
        self.add_action(play, "forward", "Step forward", "Right", self.player.forward)
        self.add_action(play, "back", "Step back", "Left", self.player.back)
        self.add_action(play, "forward10", "Ten steps forward", "Shift+Right",
                        lambda: self.player.step(10))
        self.add_action(play, "back10", "Ten steps back", "Shift+Left",
                        lambda: self.player.step(-10))
        play.addSeparator()
        self.add_action(play, "first", "First step", "Home", self.player.first)
        self.add_action(play, "last", "Last step", "End", self.player.to_last)

    def _build_view_menu(self, view) -> None:
        fit = view.addAction("Fit grid to view")
        fit.setShortcut(QKeySequence("F"))
        fit.triggered.connect(self.grid.fit)
        self.addAction(fit)
        self.y_down_action = view.addAction("Origin top-left, y down")
        self.y_down_action.setCheckable(True)
        self.y_down_action.setToolTip("Pixel (0, 0) at the top-left, y growing downwards "
                                      "(Ctrl+Z takes it back)")
        # Connected to set_y_down through the undo history (app/gui/edits.py).
        for box, text, key in ((self.show_primitive, "Ideal primitive", ""),
                               (self.compare, "Compare with previous algorithm", ""),
                               (self.coverage, "Coverage counts", "C")):
            act = view.addAction(text)
            act.setCheckable(True)
            act.setChecked(box.isChecked())
            if key:
                act.setShortcut(QKeySequence(key))
                self.addAction(act)
            act.toggled.connect(box.setChecked)
            box.toggled.connect(act.setChecked)
            self.actions_[f"view-{text}"] = act
        self.coverage_action = self.actions_["view-Coverage counts"]
        self.coverage_action.setToolTip(self.coverage.toolTip() + " (C)")
        self.depth_action = view.addAction("Depth buffer")
        self.depth_action.setCheckable(True)
        self.depth_action.setChecked(True)
        self.depth_action.setToolTip("Show the depth buffer (near dark, far light) of runs "
                                     "that keep one")
        self.depth_action.toggled.connect(self._depth_toggled)
        self.actions_["view-Depth buffer"] = self.depth_action
        self.error_action = view.addAction("Coverage error")
        self.error_action.setCheckable(True)
        self.error_action.setToolTip("Colour each pixel by coverage - exact coverage (white: "
                                     "none; red: too much, blue: too little, fullest at the "
                                     "run's largest)")
        self.error_action.toggled.connect(lambda _on: self.show_frame())
        self.actions_["view-Coverage error"] = self.error_action
        view.addSeparator()
        for dock in (self.scene_dock, self.code_dock, self.variables_dock, self.tables_dock):
            view.addAction(dock.toggleViewAction())

    def _build_toolbar(self) -> None:
        bar = QToolBar("Drawing", self)
        bar.setObjectName("drawingTools")
        bar.setMovable(False)
        bar.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
        for key in ("draw", "marker"):
            bar.addAction(self.actions_[key])
        bar.addSeparator()
        for key in ("close", "remove", "clear", "undo", "redo"):
            bar.addAction(self.actions_[key])
        bar.addSeparator()
        bar.addAction(self.coverage_action)
        for act in bar.actions():
            button = bar.widgetForAction(act)
            if button is not None:
                # The buttons never take the focus: Space and the arrows stay
                # with playback, Enter and Backspace with the grid.
                button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.toolbar = bar
        self.addToolBar(Qt.ToolBarArea.TopToolBarArea, bar)
