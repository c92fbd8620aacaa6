"""The main window: the pixel grid in the middle, the scene on the left,
pseudo-code and variables on the right, the transport bar at the bottom.

``launch()`` opens it on the demo scene; ``MainWindow`` can also be built
on its own (tests, screenshots, benchmarks) and driven through
``window.player``.
"""
from __future__ import annotations

import bisect
import sys

import numpy as np
from PySide6.QtCore import QRect, Qt
from PySide6.QtGui import (QAction, QActionGroup, QColor, QIcon, QKeySequence, QPainter,
                           QPixmap)
from PySide6.QtWidgets import (QApplication, QCheckBox, QDialog, QDialogButtonBox,
                               QFrame, QHBoxLayout, QHeaderView, QLabel, QMainWindow, QMessageBox,
                               QPushButton, QScrollArea, QSizePolicy, QTableWidget,
                               QTableWidgetItem, QToolBar, QVBoxLayout, QWidget)

from algorithms import registry
from algorithms.raster import MAX_GRID, Raster
from algorithms.registry import InputError
from algorithms.steps import Note, Table
from widgets.docks import panel_dock
from widgets.depth_view import DepthView
from app.model.drawing import CONTOURS, point_labels
from widgets.editors import AlgorithmPicker, GridEditor, OptionsEditor
from widgets.vertex_table import VertexTable
from widgets.grid_view import DRAW, MARKER, PixelGridView
from widgets.panels import CodePanel, VariablesPanel
from widgets.tables import TablesPanel
from widgets.transport import TransportBar

from app.gui.appdata import APP_NAME
from app.model.insight import PixelTally, has_insight, inside_chips, row_tones
from app.model.inputs import split_contours
from app.gui.player import Player
from app.model.session import default_scene, open_ended
from app.render import frame as frame_view
from app.render.compose import (COVERAGE_LEVELS, OUTLINE_STYLE, PALETTE, compose, coverage_counts,
                                depth_image, depth_range, error_image, error_stats)
from app.model.tables import TableIndex
from app.model.tools import (circle_kind, circle_options, clamp_option, drawing_mode,
                             marker_option, placing_message, shape_paths, tool_hint)
# What a frame shows is worked out in app/render/frame.py, shared with export.
from app.render.frame import step_cells as _step_cells
from app.render.frame import html_caption as _caption
from app.render.frame import ideal_paths  # noqa: F401 (part of this module's interface)

PREFERRED_ALGORITHM = "line-bresenham"
# The demo segment: slope 5/12 has two exact ties (d = 0), where the
# textbook Bresenham and a rounding DDA may choose differently.
DEMO_POINTS = [(4, 5), (28, 15)]
DEMO_GRID = (32, 24)

# What the shortcuts sheet lists besides the window's actions (which it
# reads from the menus): pointer gestures and keys that belong to one widget.
GESTURES = (
    ("Mouse wheel", "Zoom the grid"),
    ("Drag (empty cell)", "Pan the grid (with any tool: drag with the middle button)"),
    ("Click", "Place a point (a full set of points starts a new one)"),
    ("Drag a handle", "Move a point"),
    ("Ctrl+click, Ctrl+drag", "Polygons and triangles: place to 1/256 px (otherwise 1/8 px)"),
    ("Double-click", "Close the polygon being drawn (so does a click on its first vertex)"),
    ("Shift+click", "Start a new contour: a hole or a second part of the polygon"),
    ("Click on a vertex", "Triangles: add a point exactly there, shared by two triangles"),
    ("Drag (circles)", "From an empty cell: the centre, then the radius"),
    ("Drag the square handle", "Change a circle's radius, or an ellipse's rx and ry"),
    ("Shift+drag (ellipses)", "Keep rx and ry equal"),
    ("Drag the star", "Flood fill: move the seed"),
    ("Right-click", "Menu: place the seed, close the contour, remove or clear points"),
    ("Alt+click", "Pin the pixel for the pixel inspector (Ctrl+I); Esc lets go"),
    ("Tab, Enter (vertex table)", "Next cell; typing replaces the value"),
    ("Insert, Delete (vertex table)", "Add a vertex after the selected one, remove it"),
    ("F2 (bookmarks)", "Rename the selected bookmark"),
    ("Esc (while recording)", "Cancel the recording; the previous run stays"),
)

STYLE = """
QLabel#section { color: #55606d; font-weight: bold; padding-top: 8px; }
QLabel#summary { color: #55606d; }
QLabel#stepCaption { color: #1d2733; padding: 2px 0 4px 0; }
QLabel#seriesTitle { color: #55606d; }
QLabel#codeNotes { color: #4b5563; background: #f3f5f8; border: 1px solid #dde2e8;
                   border-radius: 4px; padding: 6px; }
QLabel#stepCounter { font-weight: bold; }
QTableWidget#codeLines { background: #ffffff; border: 1px solid #dde2e8; }
QTreeWidget#algorithmPicker { border: 1px solid #dde2e8; }
QTableWidget#variables { border: 1px solid #dde2e8; }
QWidget#transport { background: #f3f5f8; border-top: 1px solid #d5dbe2; }
QLabel#legend { color: #3d4754; }
QStatusBar QLabel#differences { color: #b0245f; padding: 0 10px; }
QStatusBar QLabel#cursor { color: #3d4754; padding: 0 6px 0 10px; border-left: 1px solid #cfd5dc; }
QStatusBar QLabel#coverage { color: #c2255c; padding: 0 10px; }
QToolBar#drawingTools { spacing: 2px; padding: 1px 4px; }
"""
ERROR_STYLE = "color: #c92a2a;"


def _section(text: str, parent=None) -> QLabel:
    label = QLabel(text.upper(), parent)
    label.setObjectName("section")
    font = label.font()
    if font.pointSizeF() > 0:
        font.setPointSizeF(font.pointSizeF() * 0.85)
    font.setLetterSpacing(font.SpacingType.PercentageSpacing, 108)
    label.setFont(font)
    return label


def _legend_chip(color: str, fill: bool) -> QLabel:
    label = QLabel()
    label.setPixmap(_chip_pixmap(color, fill))
    return label


def _chip_pixmap(color: str, fill: bool) -> QPixmap:
    pixmap = QPixmap(14, 14)
    pixmap.fill(Qt.GlobalColor.transparent)
    painter = QPainter(pixmap)
    if fill:
        painter.fillRect(1, 1, 12, 12, QColor(color))
    else:
        pen = painter.pen()
        pen.setColor(QColor(color))
        pen.setWidth(3)
        painter.setPen(pen)
        painter.drawRect(2, 2, 10, 10)
    painter.end()
    return pixmap


def _legend(rows) -> QWidget:
    """Chips with their meaning: (colour, filled?, text) per row;
    ``widget.chips`` keeps (chip, filled?) to recolour them."""
    widget = QWidget()
    widget.chips = []
    box = QVBoxLayout(widget)
    box.setSpacing(2)
    box.setContentsMargins(0, 4, 0, 0)
    for color, fill, text in rows:
        row = QHBoxLayout()
        row.setSpacing(6)
        chip = _legend_chip(color, fill)
        widget.chips.append((chip, fill))
        row.addWidget(chip)
        label = QLabel(text)
        label.setObjectName("legend")
        row.addWidget(label, 1)
        box.addLayout(row)
    return widget


# The highlight legend: (Palette field, filled chip?, meaning).
LEGEND = (("current", False, "pixel or span of this step"),
          ("candidate", False, "candidates of the decision"),
          ("difference", False, "differs from previous algorithm"),
          ("overdraw", True, "written more than once"))


def _legend_rows(palette) -> list:
    return [(getattr(palette, field), fill, text) for field, fill, text in LEGEND]


def _coverage_rows(palette) -> list:
    return [(color, True, text) for color, text in zip(palette.coverage, COVERAGE_LEVELS)]


def _recolor(legend, rows) -> None:
    for (chip, fill), (color, _fill, _text) in zip(legend.chips, rows):
        chip.setPixmap(_chip_pixmap(color, fill))


def _is_pixel(value) -> bool:
    return isinstance(value, tuple) and len(value) == 2 and all(
        isinstance(v, int) and not isinstance(v, bool) for v in value)


def app_icon() -> QIcon:
    """A staircase of pixels under a thin ideal line."""
    icon = QIcon()
    for size in (16, 32, 64, 128):
        pixmap = QPixmap(size, size)
        pixmap.fill(QColor(PALETTE.background))
        painter = QPainter(pixmap)
        cell = size / 8
        ink = QColor(PALETTE.ink)
        for k in range(8):
            y = round(k * 5 / 8)
            painter.fillRect(QRect(round(k * cell), round(size - (y + 2) * cell - cell),
                                   max(1, round(cell)), max(1, round(cell))), ink)
        pen = painter.pen()
        pen.setColor(QColor(PALETTE.primitive))
        pen.setWidthF(max(1.0, size / 24))
        painter.setPen(pen)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.drawLine(round(cell / 2), round(size - 2.5 * cell),
                         round(size - cell / 2), round(size - 2.5 * cell - 7 * cell * 5 / 8))
        painter.end()
        icon.addPixmap(pixmap)
    return icon


class MainWindow(QMainWindow):
    """RasterLab's main window."""

    def __init__(self, algorithm: str | None = None, points=None, options: dict | None = None,
                 grid=DEMO_GRID, parent=None):
        super().__init__(parent)
        self.setWindowTitle(APP_NAME)
        self.setWindowIcon(app_icon())
        self.setStyleSheet(STYLE)
        self.palette_ = PALETTE
        self.player = Player(self)
        self.history = self.player.session.history  # undo and redo of scene edits
        self._empty_image = None
        self._last_hover = None
        self._error = ""  # the last refusal, shown until the next good change
        self._tables = TableIndex(None)
        self._tally = None
        self._notes: list[int] = []
        self._tables_for = None  # the algorithm the tables dock was last shown for
        self._depth = None  # (clear, near, far) of a run that keeps a depth buffer
        self._accuracy = None  # AccuracyCache of the antialiasing run on show

        self._build_centre()
        self._build_scene_dock()
        self._build_code_dock()
        self._build_status()
        self._build_actions()
        self._connect()

        specs = registry.all_specs()
        self.picker.set_specs(specs)
        names = [spec.name for spec in specs]
        if algorithm is None:
            algorithm = PREFERRED_ALGORITHM if PREFERRED_ALGORITHM in names else names[0]
        breaks = ()
        if points is None and algorithm == PREFERRED_ALGORITHM:
            points = DEMO_POINTS
        elif points is None:
            points, breaks, _ = default_scene(registry.get(algorithm), grid)
        self.set_scene(algorithm, points, options, grid, breaks)
        self.resize(1280, 800)
        self.resizeDocks([self.scene_dock, self.code_dock], [255, 395], Qt.Orientation.Horizontal)
        self.resizeDocks([self.code_dock, self.variables_dock], [330, 430], Qt.Orientation.Vertical)
        if self._tables:
            self._make_room_for_tables()
        # Hook: stored preferences, Edit > Preferences (app/gui/preferences.py).
        from app.gui.preferences import install_preferences
        install_preferences(self)
        from app.gui.compare_window import install_compare  # View > Compare… (Ctrl+K)
        install_compare(self)
        from app.gui.gallery import install_gallery  # Help > Hard cases… (app/gui/gallery.py)
        install_gallery(self)
        from app.gui.breakpoint_actions import (install_breakpoints)  # step units, breakpoints, bookmarks
        install_breakpoints(self)
        from app.gui.inspector_dock import install_inspector  # View > Pixel inspector (Ctrl+I)
        install_inspector(self)
        from app.gui.recording import install_recording  # long runs: progress bar and Cancel (Esc)
        install_recording(self)

    # ----------------------------------------------------------- building
    def _build_centre(self) -> None:
        self.grid = PixelGridView(PALETTE, OUTLINE_STYLE, self)
        self.grid.setObjectName("pixelGrid")
        self.transport = TransportBar(self)
        centre = QWidget(self)
        layout = QVBoxLayout(centre)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addWidget(self.grid, 1)
        layout.addWidget(self.transport)
        self.setCentralWidget(centre)

    def _build_scene_dock(self) -> None:
        panel = QWidget()
        layout = QVBoxLayout(panel)
        layout.setContentsMargins(10, 4, 10, 10)
        layout.setSpacing(6)

        layout.addWidget(_section("Algorithm"))
        self.picker = AlgorithmPicker(panel)
        self.picker.setMinimumHeight(150)
        self.picker.setMaximumHeight(260)
        layout.addWidget(self.picker)

        layout.addWidget(_section("Options"))
        self.options = OptionsEditor(panel)
        layout.addWidget(self.options)

        layout.addWidget(_section("Points"))
        self.points = VertexTable(panel)  # one row per vertex: x, y, colour, z, w
        layout.addWidget(self.points)
        self.hint = QLabel(panel)
        self.hint.setObjectName("summary")
        self.hint.setWordWrap(True)
        layout.addWidget(self.hint)

        layout.addWidget(_section("Grid"))
        self.grid_editor = GridEditor(MAX_GRID, panel)
        layout.addWidget(self.grid_editor)
        fit = QPushButton("Fit grid to view", panel)
        fit.setToolTip("Zoom and pan so that the whole grid is in view (F)")
        fit.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        fit.clicked.connect(self.grid.fit)
        layout.addWidget(fit)

        layout.addWidget(_section("Display"))
        self.show_primitive = QCheckBox("Ideal primitive", panel)
        self.show_primitive.setChecked(True)
        self.show_primitive.setToolTip("Draw the exact primitive the pixels stand for")
        self.compare = QCheckBox("Compare with previous algorithm", panel)
        self.compare.setChecked(True)
        self.compare.setToolTip("After switching algorithm, outline the pixels where the "
                                "previous algorithm's final result differs")
        self.coverage = QCheckBox("Coverage counts", panel)
        self.coverage.setToolTip("Colour every pixel by how many times it has been written "
                                 "so far (0, 1, 2, 3+): overlaps in a mesh stand out")
        for box in (self.show_primitive, self.compare, self.coverage):
            layout.addWidget(box)
        self.legend = _legend(_legend_rows(PALETTE))
        self.coverage_legend = _legend(_coverage_rows(PALETTE))
        self.coverage_legend.hide()
        layout.addWidget(self.legend)
        layout.addWidget(self.coverage_legend)
        layout.addStretch(1)

        scroll = QScrollArea()
        scroll.setWidget(panel)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.scene_dock = panel_dock("Scene", "sceneDock", scroll, self)
        self.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, self.scene_dock)
        panel.setMinimumWidth(240)

    def _build_code_dock(self) -> None:
        self.code = CodePanel(self)
        self.code_dock = panel_dock("Pseudo-code", "codeDock", self.code, self)
        self.variables = VariablesPanel(self)
        self.variables_dock = panel_dock("Variables", "variablesDock", self.variables, self)
        self.tables = TablesPanel(self)
        self.tables_dock = panel_dock("Tables", "tablesDock", self.tables, self)
        for dock in (self.code_dock, self.variables_dock):
            self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, dock)
        self.splitDockWidget(self.code_dock, self.variables_dock, Qt.Orientation.Vertical)
        # Tables are wide and short: under the grid, side by side, between
        # the scene and the pseudo-code columns (which keep their height).
        self.setCorner(Qt.Corner.BottomLeftCorner, Qt.DockWidgetArea.LeftDockWidgetArea)
        self.setCorner(Qt.Corner.BottomRightCorner, Qt.DockWidgetArea.RightDockWidgetArea)
        self.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, self.tables_dock)
        across = (Qt.DockWidgetArea.BottomDockWidgetArea, Qt.DockWidgetArea.TopDockWidgetArea)
        self.tables_dock.dockLocationChanged.connect(
            lambda area: self.tables.set_side_by_side(area in across))
        self.tables.set_side_by_side(True)
        self.tables_dock.hide()
        # The depth buffer beside the colour buffer, for runs that keep one.
        self.depth_view = DepthView(PALETTE, self)
        self.depth_dock = panel_dock("Depth buffer", "depthDock", self.depth_view, self)
        self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.depth_dock)
        self.splitDockWidget(self.code_dock, self.depth_dock, Qt.Orientation.Vertical)
        self.depth_dock.hide()
        self.depth_dock.visibilityChanged.connect(self._depth_dock_shown)

    def _build_status(self) -> None:
        status = self.statusBar()
        self.message = QLabel(self)
        self.message.setObjectName("message")
        self.message.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.coverage_label = QLabel(self)
        self.coverage_label.setObjectName("coverage")
        self.difference_label = QLabel(self)
        self.difference_label.setObjectName("differences")
        self.cursor_label = QLabel(self)
        self.cursor_label.setObjectName("cursor")
        self.cursor_label.setMinimumWidth(210)
        status.addWidget(self.message, 1)
        status.addPermanentWidget(self.coverage_label)
        self.error_label = QLabel(self)
        self.error_label.setObjectName("coverageError")
        status.addPermanentWidget(self.error_label)
        status.addPermanentWidget(self.difference_label)
        status.addPermanentWidget(self.cursor_label)

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

    def _action(self, menu, key, text, shortcut, slot, context=Qt.ShortcutContext.WindowShortcut,
                owner=None) -> QAction:
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
        self._action(menu, "undo", "&Undo", "Ctrl+Z", self.undo)
        redo = self._action(menu, "redo", "&Redo", "Ctrl+Shift+Z", self.redo)
        redo.setShortcuts([QKeySequence("Ctrl+Shift+Z"), QKeySequence("Ctrl+Y")])
        menu.addSeparator()
        # Enter and Backspace belong to the grid only: elsewhere they confirm
        # a typed number or delete a character.
        grid_only = Qt.ShortcutContext.WidgetWithChildrenShortcut
        self._action(menu, "close", "&Close the contour", "Return", self.grid.close_contour,
                     grid_only, self.grid)
        self._action(menu, "remove", "Remove the &last point", "Backspace",
                     self.grid.remove_last_point, grid_only, self.grid)
        self._action(menu, "clear", "C&lear points", None, self.clear_points).setToolTip(
            "Remove every point (Ctrl+Z brings them back)")
        menu.addSeparator()
        group = QActionGroup(self)
        draw = self._action(menu, "draw", "&Draw points", None,
                            lambda: self.set_tool(DRAW))
        seed = self._action(menu, "marker", "Place the &seed", "S",
                            lambda: self.set_tool(MARKER if self.grid.tool != MARKER else DRAW))
        for act in (draw, seed):
            act.setCheckable(True)
            group.addAction(act)
        draw.setChecked(True)
        draw.setToolTip("Clicks on the grid place points; drag a handle to move one")

    def _build_playback_menu(self, play) -> None:
        self._action(play, "play", "Play / Pause", "Space", self.player.toggle)
        play.addSeparator()
        self._action(play, "forward", "Step forward", "Right", self.player.forward)
        self._action(play, "back", "Step back", "Left", self.player.back)
        self._action(play, "forward10", "Ten steps forward", "Shift+Right",
                     lambda: self.player.step(10))
        self._action(play, "back10", "Ten steps back", "Shift+Left", lambda: self.player.step(-10))
        play.addSeparator()
        self._action(play, "first", "First step", "Home", self.player.first)
        self._action(play, "last", "Last step", "End", self.player.to_last)

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
        self.error_action.setToolTip("Colour each pixel by |coverage - exact coverage| "
                                     "(white: none, red: the run's largest)")
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

    def _connect(self) -> None:
        p = self.player
        p.traceChanged.connect(self._trace_changed)
        p.frameChanged.connect(self._frame_changed)
        p.playingChanged.connect(self.transport.set_playing)
        p.comparisonChanged.connect(self._comparison_changed)
        p.session.message.connect(self._say_error)

        t = self.transport
        t.firstRequested.connect(p.first)
        t.backRequested.connect(p.back)
        t.playRequested.connect(p.toggle)
        t.forwardRequested.connect(p.forward)
        t.lastRequested.connect(p.to_last)
        t.seekRequested.connect(self._scrub)
        t.speedChanged.connect(p.set_speed)
        p.set_speed(t.speed)

        g = self.grid
        g.hoverChanged.connect(self._hover)
        # Scene edits (grid gestures, the vertex table, the algorithm, options,
        # grid size, origin) go through the undo history: app/gui/edits.py.
        from app.gui.edits import install_edits
        install_edits(self)
        self.show_primitive.toggled.connect(g.set_show_primitive)
        self.compare.toggled.connect(p.set_compare)
        self.coverage.toggled.connect(self._coverage_toggled)

    # ------------------------------------------------------- scene input
    def set_scene(self, algorithm: str, points, options=None, grid=DEMO_GRID, breaks=()) -> None:
        """Show a whole scene; raises InputError when it is bad. Contour
        inputs may come as a list of contours or flat with ``breaks``."""
        if breaks:
            points = split_contours(points, breaks)
        self.player.set_scene(algorithm, points, options, grid)
        self.history.clear()
        self.edits.refresh()
        self._scene_changed()

    def set_algorithm(self, name: str) -> None:
        try:
            self.player.set_algorithm(name)
        except InputError as error:
            self._say_error(str(error))
            self.picker.set_current(self.player.spec.name)
            return
        self._scene_changed()
        if self.player.refusal:
            self._say_error(f"{self.player.spec.title} refused the points drawn before "
                            f"({self.player.refusal}); showing an example shape instead.")

    def set_option(self, name: str, value) -> None:
        try:
            self.player.set_option(name, value)
        except InputError as error:
            self.options.show_error(name, str(error))
            self.options.set_values({name: self.player.options[name]})
            self._say_error(str(error))
            return
        self.options.accept(name, self.player.options[name])

    def _set_grid_options(self, values: dict) -> None:
        """Options set by a gesture on the grid: the editors follow."""
        try:
            self.player.set_options(values)
        except InputError as error:
            self._say_error(str(error))
            for name in values:
                self.options.show_error(name, str(error))
            return
        for name in values:
            self.options.set_values({name: self.player.options[name]})
            self.options.accept(name, self.player.options[name])

    def set_points(self, points, breaks=None) -> None:
        try:
            self.player.set_points(points, breaks)
        except InputError as error:
            self._say_error(str(error))
        self._sync_points(keep_open=True)

    def clear_points(self) -> None:
        self.edits.once(lambda: self.set_points([], ()))

    def _sync_points(self, keep_open: bool = False) -> None:
        player = self.player
        self.grid.set_points(player.points, player.breaks, keep_open)
        self.points.set_points(player.points, self._labels(), player.breaks)
        self.edits.sync_table()

    def _labels(self) -> list[str]:
        spec, player = self.player.spec, self.player
        return point_labels(drawing_mode(spec), spec.inputs.count, len(player.points),
                            player.breaks, spec.inputs.names)

    def _radius_dragged(self, rx: float, ry: float) -> None:
        spec = self.player.spec
        names = circle_options(spec)
        self._set_grid_options({name: clamp_option(spec.option(name), value)
                                for name, value in zip(names, (rx, ry))})

    def _marker_placed(self, pixel) -> None:
        option = marker_option(self.player.spec)
        if option is not None:
            self._set_grid_options({option.name: (int(pixel[0]), int(pixel[1]))})

    def set_tool(self, tool: str) -> None:
        """``"draw"``: clicks place points; ``"marker"``: a click places the seed."""
        if tool == MARKER and marker_option(self.player.spec) is None:
            tool = DRAW
        self.grid.set_tool(tool)
        self.actions_["marker" if tool == MARKER else "draw"].setChecked(True)

    def set_grid(self, width: int, height: int) -> None:
        try:
            self.player.set_grid(width, height)
        except InputError as error:
            self._say_error(str(error))
        self._sync_grid()

    def _sync_grid(self) -> None:
        """The grid's editors and view follow the player's grid and points."""
        self.grid_editor.set_grid(*self.player.grid)
        self.points.set_grid(*self.player.grid)
        self.grid.set_grid(*self.player.grid)
        self._sync_points()

    def set_palette(self, palette) -> None:
        """Draw the grid, the legends and new frames in ``palette``'s colours."""
        self.palette_ = palette
        self._empty_image = None  # composed with the old colours
        self.grid.set_palette(palette)
        _recolor(self.legend, _legend_rows(palette))
        _recolor(self.coverage_legend, _coverage_rows(palette))

    def set_y_down(self, y_down: bool) -> None:
        """Origin top-left with y down (True), or bottom-left with y up."""
        self.player.session.set_origin(y_down)
        self.grid.set_y_down(y_down)
        self.depth_view.set_y_down(y_down)
        self.grid_editor.set_y_down(y_down)
        self.y_down_action.blockSignals(True)
        self.y_down_action.setChecked(y_down)
        self.y_down_action.blockSignals(False)
        self._hover(self._last_hover)

    # -------------------------------------------------------------- undo
    # The whole scene is remembered before each edit: app/gui/edits.py.
    def undo(self) -> None:
        self.edits.undo()

    def redo(self) -> None:
        self.edits.redo()

    def _scene_changed(self) -> None:
        """Editors follow the player's scene (after an algorithm switch, say)."""
        spec, player = self.player.spec, self.player
        mode = drawing_mode(spec)
        self.picker.set_current(spec.name)
        self.setWindowTitle(f"{spec.title} \u2014 {APP_NAME}")
        self.options.set_options(spec.options, player.options, spec.inputs.count,
                                 spec.inputs.names)
        self.points.set_input(spec.inputs.count, spec.inputs.names, spec.inputs.integer,
                              open_ended(spec), spec.inputs.count if spec.inputs.multiple else 0)
        self.points.set_grid(*player.grid)
        self.grid_editor.set_grid(*player.grid)
        self.grid.set_grid(*player.grid)
        self.grid.set_input(spec.inputs.count, spec.inputs.integer, spec.inputs.names,
                            closed=mode == CONTOURS, open_ended=open_ended(spec), mode=mode)
        marker = marker_option(spec)
        self.grid.set_marker_name(marker.name if marker else "")
        self.actions_["marker"].setVisible(marker is not None)
        if marker is not None:
            self.actions_["marker"].setText(f"Place the {marker.name}")
        else:
            self.set_tool(DRAW)
        self.actions_["close"].setVisible(mode == CONTOURS)
        self.hint.setText(tool_hint(spec))
        self._sync_points()
        self._show_inputs()

    def _show_inputs(self) -> None:
        """The circle's rim handle and the seed marker follow the options."""
        spec, options = self.player.spec, self.player.options
        names = circle_options(spec)
        radii = [float(options[name]) for name in names]
        self.grid.set_circle(circle_kind(spec), *(radii * 2)[:2])
        marker = marker_option(spec)
        if marker is None:
            return
        value = options.get(marker.name)
        trace = self.player.trace
        if isinstance(value, tuple):
            self.grid.set_marker(value)
        elif trace is not None and _is_pixel(trace.start.constants.get(marker.name)):
            # Chosen by the algorithm ("auto"): shown faint.
            self.grid.set_marker(trace.start.constants[marker.name], automatic=True)
        else:
            self.grid.set_marker(None)

    # ------------------------------------------------------------ display
    def _scrub(self, index: int) -> None:
        self.player.pause()
        self.player.seek(index)

    def _trace_changed(self) -> None:
        player, trace, spec = self.player, self.player.trace, self.player.spec
        self._error = ""
        self.grid.set_shape(shape_paths(spec, player.points, player.options, player.breaks))
        self._show_inputs()
        self._tables = TableIndex(trace)
        self._tally = PixelTally(trace) if trace is not None and has_insight(
            trace.value_names) else None
        self._notes = [] if trace is None else sorted(
            i for i, r in trace.records.items() if isinstance(r, Note))
        self._show_tables_dock()
        self._prepare_depth_and_accuracy()
        if trace is None:
            self.transport.set_range(-1)
            self.variables.set_series(None)
            self.variables.set_rows([])
            self.variables.set_chips([])
            self.tables.set_tables([])
            self.code.set_current(None)
            self._update_message()
            return
        self.code.set_code([line.text for line in trace.code], spec.notes)
        self.transport.set_range(len(trace) - 1)
        name = _series_name(trace)
        decision = name is not None and name == trace.start.decision
        self.variables.set_series(None if name is None else trace.series(name), name or "",
                                  decision)

    def _show_tables_dock(self) -> None:
        """The tables dock appears for runs with tables and goes for runs
        without; a person who closes it keeps it closed for this algorithm."""
        name = self.player.spec.name
        if self.player.trace is None:
            return  # points being placed: the grid must not move under the pointer
        if not self._tables:
            if self.tables_dock.isVisibleTo(self):
                self.tables_dock.hide()
                self._tables_for = None  # hidden here, so shown again here
            return
        if self._tables_for != name:
            self.tables_dock.show()
            self._make_room_for_tables()
        self._tables_for = name

    def _make_room_for_tables(self) -> None:
        # Room for the tables' rows, up to eight; the grid gives up height.
        self.tables.set_tables(self._tables.at(self.player.index))
        self.resizeDocks([self.tables_dock], [self.tables.fitting_height()],
                         Qt.Orientation.Vertical)

    def _frame_changed(self, index: int) -> None:
        self.show_frame()

    def show_frame(self) -> None:
        """Bring the grid and the panels to the player's current step."""
        player = self.player
        state = player.state()
        if state is None:
            self.grid.set_image(self._blank())
            self.grid.set_highlights((), ())
            self.variables.set_caption("No run: place the points first.")
            self.coverage_label.setText("")
            self._update_message()
            return
        accuracy = self._accuracy if self.error_action.isChecked() else None
        if accuracy is not None and not self.coverage.isChecked():
            self.grid.set_image(error_image(accuracy.error, accuracy.max))
        else:
            self.grid.set_image(compose(state.raster, None, self.palette_,
                                        coverage=self.coverage.isChecked()))
        self._show_depth(state)
        self._show_samples(state)
        self._show_error_summary()
        cells, spans = _step_cells(state)
        self.grid.set_highlights(cells, state.candidates, spans)
        self._show_cracks(player.trace, state.index)
        trace, index = player.trace, state.index
        self.transport.set_position(index)
        self.code.set_current(state.step.line)
        self.variables.set_caption(_caption(state, len(trace) - 1))
        self._show_values(state)
        if self._tables:
            self.tables.set_tables(self._tables.at(index))
        self._show_coverage(state)
        self._update_message()
        self._hover(self._last_hover)

    def _show_values(self, state) -> None:
        trace, index = self.player.trace, state.index
        colour = frame_view.colour_name(trace.start)
        colors = (colour,) if colour else ()
        # The trace's own algorithm: a switch may still be recording.
        rows = self.player.trace_spec.panel_rows(trace, index)
        rows += self._accuracy_rows(state, rows)
        self.variables.set_rows(rows, colors, row_tones(rows) if self._tally else None)
        chips = []
        if self._tally is not None:
            chips = inside_chips(state.step.values, state.step.kind)
            tested, filled = self._tally.at(index)
            chips.append((f"{tested:,} tested \u00b7 {filled:,} filled", "info",
                          "pixels looked at, and pixels written, up to this step"))
        self.variables.set_chips(chips)
        self.variables.set_marker(index)

    def _show_coverage(self, state) -> None:
        if not self.coverage.isChecked():
            self.coverage_label.setText("")
            return
        _none, _once, twice, more = coverage_counts(state.raster)
        overlaps = twice + more
        cracks = len(crack_cells(self.player.trace, state.index))
        self.coverage_label.setText(
            ("No pixel covered twice" if not overlaps else
             f"{overlaps:,} pixel{'s' if overlaps != 1 else ''} covered twice or more"
             + (f" ({more:,} three times or more)" if more else ""))
            + (f" · {cracks:,} crack{'s' if cracks != 1 else ''} outlined" if cracks else ""))

    # ------------------------------------------- depth, samples, accuracy
    def _prepare_depth_and_accuracy(self) -> None:
        """Per run: the depth view's scale, and the exact coverage of an
        antialiasing run (worked out when first needed, then kept)."""
        player, trace = self.player, self.player.trace
        self._depth = None
        self._accuracy = None
        if trace is not None and trace.start.depth_value is not None:
            clear = float(trace.start.constants.get("clear_depth",
                                                    player.options.get("clear_depth", 1.0)))
            self._depth = (clear, *depth_range(trace.series(trace.start.depth_value), clear))
        if trace is not None and player.spec.family == "antialias" \
                and trace.start.pixel_value is not None:
            self._accuracy = AccuracyCache(player.spec, player.points, player.options,
                                           player.grid, trace)
            if not self._accuracy.available:
                self._accuracy = None
        self.error_action.setEnabled(self._accuracy is not None)
        self.depth_action.setEnabled(self._depth is not None)
        self._place_depth_dock()

    def _place_depth_dock(self) -> None:
        want = self._depth is not None and self.depth_action.isChecked()
        if want != self.depth_dock.isVisibleTo(self):
            self.depth_dock.setVisible(want)

    def _depth_toggled(self, on: bool) -> None:
        self._place_depth_dock()
        self.show_frame()

    def _depth_dock_shown(self, visible: bool) -> None:
        # Closing the dock by its own button turns the View toggle off.
        if not visible and self._depth is not None and not self.depth_dock.isVisibleTo(self):
            self.depth_action.blockSignals(True)
            self.depth_action.setChecked(False)
            self.depth_action.blockSignals(False)

    def _show_depth(self, state) -> None:
        if self._depth is None or not self.depth_dock.isVisibleTo(self):
            return
        clear, near, far = self._depth
        depth = state.raster.depth
        if depth is None:
            depth = np.full(state.raster.counts.shape, np.nan)
        self.depth_view.set_y_down(self.grid.y_down)
        self.depth_view.set_image(depth_image(depth, clear, near, far), near, far)

    def _show_samples(self, state) -> None:
        samples = frame_view.pixel_samples(self.player.trace, state.index)
        if samples is None:
            self.grid.set_samples()
        else:
            self.grid.set_samples(samples.xs, samples.ys, samples.hits, samples.current)

    def _show_error_summary(self) -> None:
        accuracy = self._accuracy if self.error_action.isChecked() else None
        if accuracy is None:
            self.error_label.setText("")
            return
        self.error_label.setText(f"Coverage error: RMS {accuracy.rms:.4f} \u00b7 "
                                 f"max {accuracy.max:.4f}")
        self.error_label.setToolTip("|coverage - exact coverage| per pixel; the RMS is taken "
                                    "over the pixels the run or the exact shape covers")

    def _accuracy_rows(self, state, rows) -> list:
        """Exact coverage and error of the step's pixel, unless the
        algorithm's own explanation already gives them."""
        accuracy, pixel = self._accuracy, state.pixel
        if accuracy is None or pixel is None or any(name == "exact coverage"
                                                    for name, _ in rows):
            return []
        x, y = pixel
        if not state.raster.inside(x, y):
            return []
        exact = float(accuracy.exact[y, x])
        final = float(accuracy.estimate[y, x])
        return [("exact coverage", f"{exact:.6f}"),
                ("error (final)", f"{final - exact:+.6f}")]

    def _show_cracks(self, trace, index: int) -> None:
        """With coverage counts on, outline the cracks a mesh run reports
        (its "cracks" table) instead of the compared run's differences."""
        if not self.coverage.isChecked():
            self.grid.set_differences(self.player.differences)
            return
        self.grid.set_differences(crack_cells(trace, index))

    def _coverage_toggled(self, on: bool) -> None:
        self.legend.setVisible(not on)
        self.coverage_legend.setVisible(on)
        self.show_frame()

    def _comparison_changed(self) -> None:
        player = self.player
        self.grid.set_differences(player.differences)
        if not player.compared:
            self.difference_label.setText("")
            return
        count = len(player.differences)
        other = player.previous_title
        if count == 0:
            self.difference_label.setText(f"Same pixels as {other}")
        else:
            self.difference_label.setText(
                f"{count} pixel{'s' if count != 1 else ''} differ{'s' if count == 1 else ''} "
                f"from {other}")

    def _blank(self) -> np.ndarray:
        width, height = self.player.grid
        if self._empty_image is None or self._empty_image.shape[:2] != (height, width):
            self._empty_image = compose(Raster(width, height), None, self.palette_)
        return self._empty_image

    def _hover(self, pixel) -> None:
        self._last_hover = pixel
        if pixel is None:
            self.cursor_label.setText("")
            return
        x, y = pixel
        text = f"pixel ({x}, {y})"
        state = self.player.state()
        if state is not None and state.raster.inside(x, y):
            count = int(state.raster.counts[y, x])
            if count:
                text += " \u00b7 written" + (f" {count}\u00d7" if count > 1 else "")
                if state.raster.colors is not None and state.raster.colors[y, x] >= 0:
                    text += f" \u00b7 #{int(state.raster.colors[y, x]):06x}"
        self.cursor_label.setText(text)

    # ----------------------------------------------------------- messages
    def _say_error(self, text: str) -> None:
        """A refusal: shown (in red) until the next change that works."""
        self._error = text
        self._update_message()

    def _update_message(self) -> None:
        """The status line: a refusal, else a cut-short run, else what to
        place next, else the algorithm's latest note at or before the step."""
        player = self.player
        trace = player.trace
        text, error = self._error, bool(self._error)
        if not text and trace is not None and trace.truncated:
            text = trace.message
        if not text:
            text = placing_message(player.spec, player.points, player.breaks)
        if not text and trace is not None and self._notes:
            k = bisect.bisect_right(self._notes, player.index) - 1
            if k >= 0:
                text = f"Step {self._notes[k]:,}: {trace.records[self._notes[k]].text}"
        self._say(text, error)

    def _say(self, text: str, error: bool = False) -> None:
        self.message.setText(text)
        self.message.setToolTip(text)
        self.message.setStyleSheet(ERROR_STYLE if error else "")

    # ------------------------------------------------------------ dialogs
    def show_shortcuts(self) -> None:
        from app.gui.about import shortcut_rows
        dialog = ShortcutsDialog(self, shortcut_rows(self, GESTURES))
        dialog.exec()

    def show_about(self) -> None:
        from app.gui.about import app_version, runtime_versions
        count = len(registry.all_specs())
        QMessageBox.about(
            self, f"About {APP_NAME}",
            f"<h3>{APP_NAME}</h3>"
            "<p>Step through the classic rasterization algorithms on a magnified pixel "
            "grid: every frame shows the pixel being decided, the candidates it was "
            "chosen from, the variables and the line of pseudo-code that ran.</p>"
            f"<p>{count} algorithm{'s' if count != 1 else ''} available. "
            "Pixel (i, j) is the square [i, i+1) \u00d7 [j, j+1) with its centre at "
            "(i + \u00bd, j + \u00bd).</p>"
            "<p>Built with Python, Qt (PySide6), pyqtgraph and numpy.</p>"
            f"<p>Version {app_version()} · {runtime_versions()}</p>")

    def closeEvent(self, event):  # noqa: N802
        self.player.pause()
        self.player.stop_recording()  # a background recording ends with the window
        super().closeEvent(event)


class ShortcutsDialog(QDialog):
    def __init__(self, parent=None, rows=GESTURES):
        super().__init__(parent)
        self.setWindowTitle("Keyboard shortcuts")
        self.rows = list(rows)
        table = QTableWidget(len(self.rows), 2, self)
        table.setHorizontalHeaderLabels(["Key", "Action"])
        table.verticalHeader().setVisible(False)
        table.setEditTriggers(QTableWidget.EditTrigger.NoEditTriggers)
        table.setSelectionMode(QTableWidget.SelectionMode.NoSelection)
        table.setShowGrid(False)
        table.setAlternatingRowColors(True)
        for row, (key, text) in enumerate(self.rows):
            item = QTableWidgetItem(key)
            font = item.font()
            font.setBold(True)
            item.setFont(font)
            table.setItem(row, 0, item)
            table.setItem(row, 1, QTableWidgetItem(text))
        table.horizontalHeader().setSectionResizeMode(0, QHeaderView.ResizeMode.ResizeToContents)
        table.horizontalHeader().setSectionResizeMode(1, QHeaderView.ResizeMode.Stretch)
        note = QLabel("Playback keys work wherever the focus is, except while you are typing "
                      "in a number or text field.", self)
        note.setWordWrap(True)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close, self)
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(table)
        layout.addWidget(note)
        layout.addWidget(buttons)
        self.resize(640, 680)


class AccuracyCache:
    """How far an antialiasing run's coverages are from the exact ones:
    worked out once per run, on first use."""

    def __init__(self, spec, points, options, grid, trace):
        self._args = (spec, points, options, grid)
        self.trace = trace
        self._done = False
        self.available = spec.name != "aa-temporal" and len(points) > 0

    def _compute(self) -> None:
        if self._done:
            return
        self._done = True
        exact = frame_view.exact_reference(*self._args)
        estimate = frame_view.run_coverage(self.trace)
        if exact is None or estimate is None or exact.shape != estimate.shape:
            exact = np.zeros((self.trace.height, self.trace.width))
            estimate = exact
        self._exact, self._estimate = exact, estimate
        self._rms, self._max, self._error = error_stats(estimate, exact)

    def __getattr__(self, name):
        if name in ("exact", "estimate", "rms", "max", "error"):
            self._compute()
            return object.__getattribute__(self, "_" + name)
        raise AttributeError(name)


def _series_name(trace) -> str | None:
    """The value to plot over the run: the decision variable, else the first
    named value that has finite values."""
    start = trace.start
    if start.decision is not None and start.decision in trace.value_names:
        return start.decision
    colour = frame_view.colour_name(start)
    for name in trace.value_names:
        if name == colour:
            continue  # packed colours are not worth a plot
        if np.isfinite(trace.series(name)).any():
            return name
    return None


def crack_cells(trace, index: int) -> list:
    """The pixels of the run's "cracks" table recorded at or before ``index``."""
    for at, record in trace.records.items():
        if at <= index and isinstance(record, Table) and record.name == "cracks":
            return [tuple(row) for row in record.rows]
    return []


def launch(argv=None) -> int:
    """Open the window on the demo scene and run until it is closed."""
    app = QApplication.instance()
    if app is None:
        app = QApplication(list(argv) if argv is not None else sys.argv[:1])
        app.setApplicationName(APP_NAME)
        app.setStyle("Fusion")
    app.setWindowIcon(app_icon())
    window = MainWindow()
    # Hook: scene files and export (File menu) come from app/gui/file_actions.py.
    from app.gui.file_actions import install_file_actions
    from app.gui.report_window import install_report_action
    install_file_actions(window)
    install_report_action(window)
    from app.gui.preferences import reopen_last_scene
    reopen_last_scene(window)
    # Hook: uncaught errors are logged and shown (app/gui/crash.py); unsaved
    # work is kept and offered back after a crash (app/gui/recovery.py).
    from app.gui.crash import install_crash_handler
    from app.gui.recovery import install_recovery
    install_crash_handler(window)
    recovery = install_recovery(window)
    window.show()
    recovery.offer()
    return app.exec()
