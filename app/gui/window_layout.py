"""The main window's centre (the grid above the transport bar), its docks
(Scene; pseudo-code, variables, tables and the depth buffer) and its status
bar: built once, by ``build_layout`` from ``MainWindow.__init__``, which sets
the widgets on the window under the names the rest of the program uses."""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (QCheckBox, QFrame, QLabel, QLineEdit, QPushButton, QScrollArea,
                               QSizePolicy, QVBoxLayout, QWidget)

from algorithms.core.raster import MAX_GRID
from widgets.depth_view import DepthView
from widgets.docks import panel_dock
from widgets.editors import AlgorithmPicker, GridEditor, OptionsEditor
from widgets.error_scale import ErrorScale
from widgets.grid_view import PixelGridView
from widgets.code_panel import CodePanel
from widgets.panels import VariablesPanel
from widgets.tables import TablesPanel
from widgets.transport import TransportBar
from widgets.vertex_table import VertexTable

from app.gui.look import coverage_rows, legend, legend_rows, section
from app.render.compose import OUTLINE_STYLE, PALETTE


def build_layout(window) -> None:
    """Make the main window's widgets and lay them out."""
    _build_centre(window)
    _build_scene_dock(window)
    _build_code_dock(window)
    _build_status(window)


def _build_centre(window) -> None:
    window.grid = PixelGridView(PALETTE, OUTLINE_STYLE, window)
    window.grid.setObjectName("pixelGrid")
    window.grid.setAccessibleName("Pixel grid")
    window.grid.setAccessibleDescription("The pixels the run has written up to the step on "
                                         "show, the points and the ideal primitive")
    window.transport = TransportBar(window)
    centre = QWidget(window)
    layout = QVBoxLayout(centre)
    layout.setContentsMargins(0, 0, 0, 0)
    layout.setSpacing(0)
    layout.addWidget(window.grid, 1)
    layout.addWidget(window.transport)
    window.setCentralWidget(centre)


def _build_scene_dock(window) -> None:
    panel = QWidget()
    layout = QVBoxLayout(panel)
    layout.setContentsMargins(10, 4, 10, 10)
    layout.setSpacing(6)
    _add_input_sections(window, panel, layout)
    _add_grid_section(window, panel, layout)
    _add_display_section(window, panel, layout)
    layout.addStretch(1)

    scroll = QScrollArea()
    scroll.setWidget(panel)
    scroll.setWidgetResizable(True)
    scroll.setFrameShape(QFrame.Shape.NoFrame)
    scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
    window.scene_dock = panel_dock("Scene", "sceneDock", scroll, window)
    window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, window.scene_dock)
    panel.setMinimumWidth(240)


def _add_input_sections(window, panel, layout) -> None:
    """Algorithm, Options and Points: what the run takes."""
    layout.addWidget(section("Algorithm"))
    window.picker_search = QLineEdit(panel)
    window.picker_search.setPlaceholderText("Search algorithms\u2026")
    window.picker_search.setClearButtonEnabled(True)
    window.picker_search.setToolTip("Type part of a name, family or idea (\"edge\", "
                                    "\"circle\"); Enter picks the first one listed")
    layout.addWidget(window.picker_search)
    window.picker = AlgorithmPicker(panel)
    window.picker.setMinimumHeight(300)
    window.picker.setMaximumHeight(420)  # about ten of the algorithms at once
    layout.addWidget(window.picker)
    window.picker_search.textChanged.connect(window.picker.set_filter)
    window.picker_search.returnPressed.connect(window.picker.choose_first_shown)

    layout.addWidget(section("Options"))
    window.options = OptionsEditor(panel)
    layout.addWidget(window.options)

    layout.addWidget(section("Points"))
    window.points = VertexTable(panel)  # one row per vertex: x, y, colour, z, w
    layout.addWidget(window.points)
    window.hint = QLabel(panel)
    window.hint.setObjectName("summary")
    window.hint.setWordWrap(True)
    layout.addWidget(window.hint)


def _add_grid_section(window, panel, layout) -> None:
    layout.addWidget(section("Grid"))
    window.grid_editor = GridEditor(MAX_GRID, panel)
    layout.addWidget(window.grid_editor)
    fit = QPushButton("Fit grid to view", panel)
    fit.setToolTip("Zoom and pan so that the whole grid is in view (F)")
    fit.setFocusPolicy(Qt.FocusPolicy.NoFocus)
    fit.clicked.connect(window.grid.fit)
    layout.addWidget(fit)


def _add_display_section(window, panel, layout) -> None:
    layout.addWidget(section("Display"))
    window.show_primitive = QCheckBox("Ideal primitive", panel)
    window.show_primitive.setChecked(True)
    window.show_primitive.setToolTip("Draw the exact primitive the pixels stand for")
    window.compare = QCheckBox("Compare with previous algorithm", panel)
    window.compare.setChecked(False)  # on when asked: its outlines are noise otherwise
    window.compare.setToolTip("After switching algorithm, outline the pixels where the "
                              "previous algorithm's final result differs")
    window.coverage = QCheckBox("Coverage counts", panel)
    window.coverage.setToolTip("Colour every pixel by how many times it has been written "
                               "so far (0, 1, 2, 3+): overlaps in a mesh stand out")
    for box in (window.show_primitive, window.compare, window.coverage):
        layout.addWidget(box)
    window.legend = legend(legend_rows(PALETTE))
    window.coverage_legend = legend(coverage_rows(PALETTE))
    window.coverage_legend.hide()
    layout.addWidget(window.legend)
    layout.addWidget(window.coverage_legend)


def _build_code_dock(window) -> None:
    window.code = CodePanel(window)
    window.code_dock = panel_dock("Pseudo-code", "codeDock", window.code, window)
    window.variables = VariablesPanel(window)
    window.variables_dock = panel_dock("Variables", "variablesDock", window.variables, window)
    window.tables = TablesPanel(window)
    window.tables_dock = panel_dock("Tables", "tablesDock", window.tables, window)
    for dock in (window.code_dock, window.variables_dock):
        window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, dock)
    window.splitDockWidget(window.code_dock, window.variables_dock, Qt.Orientation.Vertical)
    # Tables are wide and short: under the grid, side by side, between
    # the scene and the pseudo-code columns (which keep their height).
    window.setCorner(Qt.Corner.BottomLeftCorner, Qt.DockWidgetArea.LeftDockWidgetArea)
    window.setCorner(Qt.Corner.BottomRightCorner, Qt.DockWidgetArea.RightDockWidgetArea)
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, window.tables_dock)
    across = (Qt.DockWidgetArea.BottomDockWidgetArea, Qt.DockWidgetArea.TopDockWidgetArea)
    window.tables_dock.dockLocationChanged.connect(
        lambda area: window.tables.set_side_by_side(area in across))
    window.tables.set_side_by_side(True)
    window.tables_dock.hide()
    # The depth buffer beside the colour buffer, for runs that keep one.
    window.depth_view = DepthView(PALETTE, window)
    window.depth_dock = panel_dock("Depth buffer", "depthDock", window.depth_view, window)
    window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, window.depth_dock)
    window.splitDockWidget(window.code_dock, window.depth_dock, Qt.Orientation.Vertical)
    window.depth_dock.hide()


def _build_status(window) -> None:
    status = window.statusBar()
    window.message = QLabel(window)
    window.message.setObjectName("message")
    window.message.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
    window.coverage_label = QLabel(window)
    window.coverage_label.setObjectName("coverage")
    window.difference_label = QLabel(window)
    window.difference_label.setObjectName("differences")
    window.cursor_label = QLabel(window)
    window.cursor_label.setObjectName("cursor")
    window.cursor_label.setMinimumWidth(210)
    status.addWidget(window.message, 1)
    status.addPermanentWidget(window.coverage_label)
    window.error_label = QLabel(window)
    window.error_label.setObjectName("coverageError")
    status.addPermanentWidget(window.error_label)
    window.error_scale = ErrorScale(window)  # the coverage-error map's colours and sign
    window.error_scale.hide()
    status.addPermanentWidget(window.error_scale)
    status.addPermanentWidget(window.difference_label)
    status.addPermanentWidget(window.cursor_label)
