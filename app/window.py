"""The main window: the pixel grid in the middle, the scene on the left,
pseudo-code and variables on the right, the transport bar at the bottom.

``launch()`` opens it on the demo scene; ``MainWindow`` can also be built
on its own (tests, screenshots, benchmarks) and driven through
``window.player``.
"""
from __future__ import annotations

import sys

import numpy as np
from PySide6.QtCore import QRect, Qt
from PySide6.QtGui import QAction, QColor, QIcon, QKeySequence, QPainter, QPixmap
from PySide6.QtWidgets import (QApplication, QCheckBox, QDialog, QDialogButtonBox, QDockWidget,
                               QFrame, QHBoxLayout, QHeaderView, QLabel, QMainWindow, QMessageBox,
                               QPushButton, QScrollArea, QSizePolicy, QTableWidget,
                               QTableWidgetItem, QVBoxLayout, QWidget)

from algorithms import registry
from algorithms.raster import MAX_GRID, Raster
from algorithms.registry import InputError
from algorithms.steps import PLOT, VISIT, Span
from widgets.editors import AlgorithmPicker, GridEditor, OptionsEditor, PointsEditor
from widgets.grid_view import PixelGridView
from widgets.panels import CodePanel, VariablesPanel
from widgets.transport import TransportBar

from .player import Player, open_ended
from .render import OUTLINE_STYLE, PALETTE, compose

APP_NAME = "RasterLab"
PREFERRED_ALGORITHM = "line-bresenham"
# The demo segment: slope 5/12 has two exact ties (d = 0), where the
# textbook Bresenham and a rounding DDA may choose differently.
DEMO_POINTS = [(4, 5), (28, 15)]
DEMO_GRID = (32, 24)

SHORTCUTS = (
    ("Space", "Play or pause"),
    ("Right", "Step forward"),
    ("Left", "Step back"),
    ("Shift+Right", "Ten steps forward"),
    ("Shift+Left", "Ten steps back"),
    ("Home", "First step"),
    ("End", "Last step"),
    ("F", "Fit the grid to the view"),
    ("Mouse wheel", "Zoom the grid"),
    ("Drag (empty cell)", "Pan the grid"),
    ("Click", "Place a point (a full set of points starts a new one)"),
    ("Drag a handle", "Move a point"),
    ("F1", "This list"),
    ("Ctrl+Q", "Quit"),
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
"""


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
    label = QLabel()
    label.setPixmap(pixmap)
    return label


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
        self._empty_image = None
        self._last_hover = None

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
        self.set_scene(algorithm, DEMO_POINTS if points is None else points, options, grid)
        self.resize(1280, 800)
        self.resizeDocks([self.scene_dock, self.code_dock], [255, 395], Qt.Orientation.Horizontal)
        self.resizeDocks([self.code_dock, self.variables_dock], [330, 430], Qt.Orientation.Vertical)

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
        self.points = PointsEditor(panel)
        layout.addWidget(self.points)
        hint = QLabel("Click the grid to place points; drag a handle to move one.", panel)
        hint.setObjectName("summary")
        hint.setWordWrap(True)
        layout.addWidget(hint)

        layout.addWidget(_section("Grid"))
        self.grid_editor = GridEditor(MAX_GRID, panel)
        layout.addWidget(self.grid_editor)
        fit = QPushButton("Fit grid to view", panel)
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
        layout.addWidget(self.show_primitive)
        layout.addWidget(self.compare)
        layout.addLayout(self._legend())
        layout.addStretch(1)

        scroll = QScrollArea()
        scroll.setWidget(panel)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.scene_dock = QDockWidget("Scene", self)
        self.scene_dock.setObjectName("sceneDock")
        self.scene_dock.setWidget(scroll)
        self.scene_dock.setFeatures(QDockWidget.DockWidgetFeature.DockWidgetMovable
                                    | QDockWidget.DockWidgetFeature.DockWidgetClosable)
        self.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, self.scene_dock)
        panel.setMinimumWidth(240)

    def _legend(self) -> QVBoxLayout:
        rows = ((PALETTE.current, False, "pixel of this step"),
                (PALETTE.candidate, False, "candidates of the decision"),
                (PALETTE.difference, False, "differs from previous algorithm"),
                (PALETTE.overdraw, True, "written more than once"))
        box = QVBoxLayout()
        box.setSpacing(2)
        box.setContentsMargins(0, 4, 0, 0)
        for color, fill, text in rows:
            row = QHBoxLayout()
            row.setSpacing(6)
            row.addWidget(_legend_chip(color, fill))
            label = QLabel(text)
            label.setObjectName("legend")
            row.addWidget(label, 1)
            box.addLayout(row)
        return box

    def _build_code_dock(self) -> None:
        self.code = CodePanel(self)
        self.code_dock = QDockWidget("Pseudo-code", self)
        self.code_dock.setObjectName("codeDock")
        self.code_dock.setWidget(self.code)
        self.variables = VariablesPanel(self)
        self.variables_dock = QDockWidget("Variables", self)
        self.variables_dock.setObjectName("variablesDock")
        self.variables_dock.setWidget(self.variables)
        for dock in (self.code_dock, self.variables_dock):
            dock.setFeatures(QDockWidget.DockWidgetFeature.DockWidgetMovable
                             | QDockWidget.DockWidgetFeature.DockWidgetClosable)
            self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, dock)
        self.splitDockWidget(self.code_dock, self.variables_dock, Qt.Orientation.Vertical)

    def _build_status(self) -> None:
        status = self.statusBar()
        self.message = QLabel(self)
        self.message.setObjectName("message")
        self.message.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.difference_label = QLabel(self)
        self.difference_label.setObjectName("differences")
        self.cursor_label = QLabel(self)
        self.cursor_label.setObjectName("cursor")
        self.cursor_label.setMinimumWidth(210)
        status.addWidget(self.message, 1)
        status.addPermanentWidget(self.difference_label)
        status.addPermanentWidget(self.cursor_label)

    def _build_actions(self) -> None:
        bar = self.menuBar()
        file_menu = bar.addMenu("&File")
        quit_action = file_menu.addAction("&Quit")
        quit_action.setShortcut(QKeySequence.StandardKey.Quit)
        quit_action.triggered.connect(self.close)

        play = bar.addMenu("&Playback")
        self.actions_: dict[str, QAction] = {}

        def action(key, text, shortcut, slot):
            act = QAction(text, self)
            act.setShortcut(QKeySequence(shortcut))
            # Shortcuts work wherever the focus is in the window; editors
            # that need the key for typing (spin boxes, text fields) keep it.
            act.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
            act.triggered.connect(slot)
            play.addAction(act)
            self.addAction(act)
            self.actions_[key] = act
            return act

        action("play", "Play / Pause", "Space", self.player.toggle)
        play.addSeparator()
        action("forward", "Step forward", "Right", self.player.forward)
        action("back", "Step back", "Left", self.player.back)
        action("forward10", "Ten steps forward", "Shift+Right", lambda: self.player.step(10))
        action("back10", "Ten steps back", "Shift+Left", lambda: self.player.step(-10))
        play.addSeparator()
        action("first", "First step", "Home", self.player.first)
        action("last", "Last step", "End", self.player.to_last)

        view = bar.addMenu("&View")
        fit = view.addAction("Fit grid to view")
        fit.setShortcut(QKeySequence("F"))
        fit.triggered.connect(self.grid.fit)
        self.addAction(fit)
        self.y_down_action = view.addAction("Origin top-left, y down")
        self.y_down_action.setCheckable(True)
        self.y_down_action.toggled.connect(self.set_y_down)
        primitive = view.addAction("Ideal primitive")
        primitive.setCheckable(True)
        primitive.setChecked(True)
        primitive.toggled.connect(self.show_primitive.setChecked)
        self.show_primitive.toggled.connect(primitive.setChecked)
        compare = view.addAction("Compare with previous algorithm")
        compare.setCheckable(True)
        compare.setChecked(True)
        compare.toggled.connect(self.compare.setChecked)
        self.compare.toggled.connect(compare.setChecked)
        view.addSeparator()
        for dock in (self.scene_dock, self.code_dock, self.variables_dock):
            view.addAction(dock.toggleViewAction())

        help_menu = bar.addMenu("&Help")
        keys = help_menu.addAction("&Keyboard shortcuts")
        keys.setShortcut(QKeySequence("F1"))
        keys.triggered.connect(self.show_shortcuts)
        about = help_menu.addAction(f"&About {APP_NAME}")
        about.triggered.connect(self.show_about)

    def _connect(self) -> None:
        p = self.player
        p.traceChanged.connect(self._trace_changed)
        p.frameChanged.connect(self._frame_changed)
        p.playingChanged.connect(self.transport.set_playing)
        p.comparisonChanged.connect(self._comparison_changed)

        t = self.transport
        t.firstRequested.connect(p.first)
        t.backRequested.connect(p.back)
        t.playRequested.connect(p.toggle)
        t.forwardRequested.connect(p.forward)
        t.lastRequested.connect(p.to_last)
        t.seekRequested.connect(self._scrub)
        t.speedChanged.connect(p.set_speed)
        p.set_speed(t.speed)

        self.grid.pointsEdited.connect(self.set_points)
        self.grid.hoverChanged.connect(self._hover)
        self.grid.clearRequested.connect(lambda: self.set_points([]))
        self.points.pointsEdited.connect(self.set_points)
        self.picker.algorithmChosen.connect(self.set_algorithm)
        self.options.valueEdited.connect(self.set_option)
        self.grid_editor.gridChanged.connect(self.set_grid)
        self.grid_editor.originChanged.connect(self.set_y_down)
        self.show_primitive.toggled.connect(self.grid.set_show_primitive)
        self.compare.toggled.connect(p.set_compare)

    # ------------------------------------------------------- scene input
    def set_scene(self, algorithm: str, points, options=None, grid=DEMO_GRID) -> None:
        """Show a whole scene; raises InputError when it is bad."""
        self.player.set_scene(algorithm, points, options, grid)
        self._scene_changed()

    def set_algorithm(self, name: str) -> None:
        try:
            self.player.set_algorithm(name)
        except InputError as error:
            self._say(str(error))
            self.picker.set_current(self.player.spec.name)
            return
        self._scene_changed()

    def set_option(self, name: str, value) -> None:
        try:
            self.player.set_option(name, value)
        except InputError as error:
            self.options.show_error(name, str(error))
            self.options.set_values({name: self.player.options[name]})
            return
        self.options.accept(name, self.player.options[name])

    def set_points(self, points) -> None:
        try:
            self.player.set_points(points)
        except InputError as error:
            self._say(str(error))
        self.grid.set_points(self.player.points)
        self.points.set_points(self.player.points)

    def set_grid(self, width: int, height: int) -> None:
        try:
            self.player.set_grid(width, height)
        except InputError as error:
            self._say(str(error))
        self.grid_editor.set_grid(*self.player.grid)
        self.points.set_grid(*self.player.grid)
        self.grid.set_grid(*self.player.grid)
        self.grid.set_points(self.player.points)
        self.points.set_points(self.player.points)

    def set_y_down(self, y_down: bool) -> None:
        """Origin top-left with y down (True), or bottom-left with y up."""
        self.grid.set_y_down(y_down)
        self.grid_editor.set_y_down(y_down)
        self.y_down_action.blockSignals(True)
        self.y_down_action.setChecked(y_down)
        self.y_down_action.blockSignals(False)
        self._hover(self._last_hover)

    def _scene_changed(self) -> None:
        """Editors follow the player's scene (after an algorithm switch, say)."""
        spec = self.player.spec
        self.picker.set_current(spec.name)
        self.setWindowTitle(f"{spec.title} \u2014 {APP_NAME}")
        self.options.set_options(spec.options, self.player.options, spec.inputs.count,
                                 spec.inputs.names)
        self.points.set_input(spec.inputs.count, spec.inputs.names, spec.inputs.integer)
        self.points.set_grid(*self.player.grid)
        self.points.set_points(self.player.points)
        self.grid_editor.set_grid(*self.player.grid)
        self.grid.set_grid(*self.player.grid)
        self.grid.set_input(spec.inputs.count, spec.inputs.integer, spec.inputs.names,
                            closed=spec.inputs.count >= 3 and spec.family != "lines",
                            open_ended=open_ended(spec))
        self.grid.set_points(self.player.points)

    # ------------------------------------------------------------ display
    def _scrub(self, index: int) -> None:
        self.player.pause()
        self.player.seek(index)

    def _trace_changed(self) -> None:
        player, trace, spec = self.player, self.player.trace, self.player.spec
        self.grid.set_shape(ideal_paths(spec, player.points, player.options))
        if trace is None:
            self.transport.set_range(-1)
            self.variables.set_series(None)
            self.variables.set_rows([])
            self.code.set_current(None)
            missing = spec.inputs.count - len(player.points)
            names = spec.inputs.names
            following = names[len(player.points)] if len(player.points) < len(names) else "the next point"
            self._say(f"Click on the grid to place {following}"
                      + (f" ({missing} more point{'s' if missing > 1 else ''} to go)." if missing > 1 else "."))
            return
        self.code.set_code([line.text for line in trace.code], spec.notes)
        self.transport.set_range(len(trace) - 1)
        name = _series_name(trace)
        decision = name is not None and name == trace.start.decision
        self.variables.set_series(None if name is None else trace.series(name), name or "",
                                  decision)
        self._say(trace.message if trace.truncated else "")

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
            return
        self.grid.set_image(compose(state.raster, None, self.palette_))
        self.grid.set_highlights(_current_cells(state), state.candidates)
        trace, index = player.trace, state.index
        self.transport.set_position(index)
        self.code.set_current(state.step.line)
        self.variables.set_caption(_caption(state, len(trace) - 1))
        colors = (trace.start.pixel_value,) if trace.start.pixel_value else ()
        self.variables.set_rows(player.spec.panel_rows(trace, index), colors)
        self.variables.set_marker(index)
        self._hover(self._last_hover)

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

    def _say(self, text: str) -> None:
        self.message.setText(text)
        self.message.setToolTip(text)

    # ------------------------------------------------------------ dialogs
    def show_shortcuts(self) -> None:
        dialog = ShortcutsDialog(self)
        dialog.exec()

    def show_about(self) -> None:
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
            "<p>Built with Python, Qt (PySide6), pyqtgraph and numpy.</p>")

    def closeEvent(self, event):  # noqa: N802
        self.player.pause()
        super().closeEvent(event)


class ShortcutsDialog(QDialog):
    def __init__(self, parent=None):
        super().__init__(parent)
        self.setWindowTitle("Keyboard shortcuts")
        table = QTableWidget(len(SHORTCUTS), 2, self)
        table.setHorizontalHeaderLabels(["Key", "Action"])
        table.verticalHeader().setVisible(False)
        table.setEditTriggers(QTableWidget.EditTrigger.NoEditTriggers)
        table.setSelectionMode(QTableWidget.SelectionMode.NoSelection)
        table.setShowGrid(False)
        table.setAlternatingRowColors(True)
        for row, (key, text) in enumerate(SHORTCUTS):
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
        self.resize(460, 440)


def ideal_paths(spec, points, options) -> list:
    """The ideal primitive as [(points, closed), ...] in grid units.

    A whole-pixel point (i, j) stands for its pixel's centre (i + 1/2,
    j + 1/2). Lines: the segment between the end pixels' centres. Circles
    and ellipses: the exact curve of the radius options around the centre.
    Triangles given in threes: each triangle. Polygons and outlines: the
    closed polygon through the points.
    """
    inputs = spec.inputs
    if inputs.integer:
        centres = [(x + 0.5, y + 0.5) for x, y in points]
    else:
        centres = [(float(x), float(y)) for x, y in points]
    if not centres:
        return []
    if spec.family == "circles":
        rx = options.get("rx", options.get("radius"))
        ry = options.get("ry", options.get("radius"))
        if len(centres) != 1 or not all(isinstance(r, (int, float)) and not isinstance(r, bool)
                                        for r in (rx, ry)):
            return []
        (cx, cy), angles = centres[0], np.linspace(0, 2 * np.pi, 241)
        return [(list(zip(cx + rx * np.cos(angles), cy + ry * np.sin(angles))), False)]
    if getattr(inputs, "multiple", False):
        count = inputs.count
        return [(centres[k:k + count], True) for k in range(0, len(centres) - count + 1, count)]
    closed = getattr(inputs, "contours", False) or inputs.count >= 3
    return [(centres, closed and len(centres) >= 3)]


def _series_name(trace) -> str | None:
    """The value to plot over the run: the decision variable, else the first
    named value that has finite values."""
    start = trace.start
    if start.decision is not None and start.decision in trace.value_names:
        return start.decision
    for name in trace.value_names:
        if name == start.pixel_value:
            continue  # packed colours are not worth a plot
        if np.isfinite(trace.series(name)).any():
            return name
    return None


def _current_cells(state) -> list:
    """The cells the step works on: its pixel, or every pixel of a span."""
    record = state.step.record
    if isinstance(record, Span):
        return [(x, record.y) for x in range(record.x_start, record.x_end)]
    return [] if state.pixel is None else [state.pixel]


def _caption(state, last: int) -> str:
    step = state.step
    parts = [f"<b>Step {state.index:,}</b> of {last:,}"]
    if isinstance(step.record, Span) and step.pixel is not None:
        verb = "fills" if step.kind == PLOT else "scans"
        parts.append(f"{verb} row {step.record.y}, x {step.record.x_start}\u2013{step.record.x_end - 1}")
    elif step.pixel is not None and step.kind == PLOT:
        parts.append(f"plots ({step.pixel[0]}, {step.pixel[1]})")
    elif step.pixel is not None and step.kind == VISIT:
        parts.append(f"visits ({step.pixel[0]}, {step.pixel[1]})")
    elif state.index == 0:
        parts.append("set-up")
    else:
        parts.append("updates variables")
    if step.branch:
        parts.append(f"branch <b>{step.branch}</b>")
    return " \u00b7 ".join(parts)


def launch(argv=None) -> int:
    """Open the window on the demo scene and run until it is closed."""
    app = QApplication.instance()
    if app is None:
        app = QApplication(list(argv) if argv is not None else sys.argv[:1])
        app.setApplicationName(APP_NAME)
        app.setStyle("Fusion")
    app.setWindowIcon(app_icon())
    window = MainWindow()
    window.show()
    return app.exec()
