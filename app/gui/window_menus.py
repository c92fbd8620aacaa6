"""The main window's menus, actions and drawing toolbar, built by
``build_menus`` from ``MainWindow.__init__``. Other modules add their entries
to ``window.menus`` by name and their actions through ``window.add_action``."""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import QToolBar

from widgets.grid_view import DRAW, MARKER

from app.gui import colour_vision
from app.gui.appdata import APP_NAME


def build_menus(window) -> None:
    """The menu bar, its actions (``window.actions_`` by key) and the drawing toolbar."""
    bar = window.menuBar()
    file_menu = bar.addMenu("&File")
    # Other modules add their entries to these menus by name.
    window.menus = {"file": file_menu}
    quit_action = file_menu.addAction("&Quit")
    quit_action.setShortcut(QKeySequence("Ctrl+Q"))  # what StandardKey.Quit is on Linux
    quit_action.triggered.connect(window.close)
    window.actions_: dict[str, QAction] = {}
    for key, title in (("edit", "&Edit"), ("view", "&View"), ("run", "&Run")):
        window.menus[key] = bar.addMenu(title)
    _build_edit_menu(window, window.menus["edit"])
    _build_playback_menu(window, window.menus["run"])
    _build_view_menu(window, window.menus["view"])
    _build_toolbar(window)

    help_menu = window.menus["help"] = bar.addMenu("&Help")
    keys = help_menu.addAction("&Keyboard shortcuts")
    keys.setShortcut(QKeySequence("F1"))
    keys.triggered.connect(window.show_shortcuts)
    about = help_menu.addAction(f"&About {APP_NAME}")
    about.triggered.connect(window.show_about)


def add_action(window, menu, key, text, shortcut, slot,
               context=Qt.ShortcutContext.WindowShortcut, owner=None) -> QAction:
    """An action in ``menu``, kept in ``window.actions_`` under ``key``;
    its shortcut works where ``context`` says, on ``owner`` (the window)."""
    act = QAction(text, window)
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
    (owner or window).addAction(act)
    window.actions_[key] = act
    return act


def _build_edit_menu(window, menu) -> None:
    add_action(window, menu, "undo", "&Undo", "Ctrl+Z", window.undo)
    redo = add_action(window, menu, "redo", "&Redo", "Ctrl+Shift+Z", window.redo)
    redo.setShortcuts([QKeySequence("Ctrl+Shift+Z"), QKeySequence("Ctrl+Y")])
    menu.addSeparator()
    # Enter and Backspace belong to the grid only: elsewhere they confirm
    # a typed number or delete a character.
    grid_only = Qt.ShortcutContext.WidgetWithChildrenShortcut
    add_action(window, menu, "close", "&Close the contour", "Return", window.grid.close_contour,
                    grid_only, window.grid)
    add_action(window, menu, "remove", "Remove the &last point", "Backspace",
                    window.grid.remove_last_point, grid_only, window.grid)
    add_action(window, menu, "clear", "C&lear points", None, window.clear_points).setToolTip(
        "Remove every point (Ctrl+Z brings them back)")
    menu.addSeparator()
    group = QActionGroup(window)
    draw = add_action(window, menu, "draw", "&Draw points", None,
                           lambda: window.set_tool(DRAW))
    seed = add_action(window, menu, "marker", "Place the &seed", "S",
                           lambda: window.set_tool(MARKER if window.grid.tool != MARKER else DRAW))
    for act in (draw, seed):
        act.setCheckable(True)
        group.addAction(act)
    draw.setChecked(True)
    draw.setToolTip("Clicks on the grid place points; drag a handle to move one")


def _build_playback_menu(window, play) -> None:
    add_action(window, play, "play", "Play / Pause", "Space", window.player.toggle)
    play.addSeparator()
    add_action(window, play, "forward", "Step forward", "Right", window.player.forward)
    add_action(window, play, "back", "Step back", "Left", window.player.back)
    add_action(window, play, "forward10", "Ten steps forward", "Shift+Right",
                    lambda: window.player.step(10))
    add_action(window, play, "back10", "Ten steps back", "Shift+Left",
                    lambda: window.player.step(-10))
    play.addSeparator()
    add_action(window, play, "first", "First step", "Home", window.player.first)
    add_action(window, play, "last", "Last step", "End", window.player.to_last)


def _build_view_menu(window, view) -> None:
    fit = view.addAction("Fit grid to view")
    fit.setShortcut(QKeySequence("F"))
    fit.triggered.connect(window.grid.fit)
    window.addAction(fit)
    window.y_down_action = view.addAction("Origin top-left, y down")
    window.y_down_action.setCheckable(True)
    window.y_down_action.setToolTip("Pixel (0, 0) at the top-left, y growing downwards "
                                    "(Ctrl+Z takes it back)")
    # Connected to set_y_down through the undo history (app/gui/edits.py).
    for box, text, key in ((window.show_primitive, "Ideal primitive", ""),
                           (window.compare, "Compare with previous algorithm", ""),
                           (window.coverage, "Coverage counts", "C")):
        act = view.addAction(text)
        act.setCheckable(True)
        act.setChecked(box.isChecked())
        if key:
            act.setShortcut(QKeySequence(key))
            window.addAction(act)
        act.toggled.connect(box.setChecked)
        box.toggled.connect(act.setChecked)
        window.actions_[f"view-{text}"] = act
    window.coverage_action = window.actions_["view-Coverage counts"]
    window.coverage_action.setToolTip(window.coverage.toolTip() + " (C)")
    window.depth_action = view.addAction("Depth buffer")
    window.depth_action.setCheckable(True)
    window.depth_action.setChecked(True)
    window.depth_action.setToolTip("Show the depth buffer (near dark, far light) of runs "
                                   "that keep one")
    # Connected by the depth display (app/gui/window_depth.py).
    window.actions_["view-Depth buffer"] = window.depth_action
    window.error_action = view.addAction("Coverage error")
    window.error_action.setCheckable(True)
    window.error_action.setToolTip("Colour each pixel by coverage - exact coverage (white: "
                                   "none; vermillion: too much, blue and hatched: too "
                                   "little, fullest at the run's largest)")
    window.error_action.toggled.connect(lambda _on: window.show_frame())
    window.actions_["view-Coverage error"] = window.error_action
    colour_vision.install(window, view)
    view.addSeparator()
    for dock in (window.scene_dock, window.code_dock, window.variables_dock, window.tables_dock):
        view.addAction(dock.toggleViewAction())


def _build_toolbar(window) -> None:
    bar = QToolBar("Drawing", window)
    bar.setObjectName("drawingTools")
    bar.setMovable(False)
    bar.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
    for key in ("draw", "marker"):
        bar.addAction(window.actions_[key])
    bar.addSeparator()
    for key in ("close", "remove", "clear", "undo", "redo"):
        bar.addAction(window.actions_[key])
    bar.addSeparator()
    bar.addAction(window.coverage_action)
    for act in bar.actions():
        button = bar.widgetForAction(act)
        if button is not None:
            # The buttons never take the focus: Space and the arrows stay
            # with playback, Enter and Backspace with the grid.
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
    window.toolbar = bar
    window.addToolBar(Qt.ToolBarArea.TopToolBarArea, bar)
