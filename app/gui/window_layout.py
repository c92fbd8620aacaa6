"""The main window's centre (the grid above the transport bar), its docks
(Scene; pseudo-code, variables, tables and the depth buffer) and its status
bar: built once, by ``MainWindow.__init__``."""
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
from widgets.panels import CodePanel, VariablesPanel
from widgets.tables import TablesPanel
from widgets.transport import TransportBar
from widgets.vertex_table import VertexTable

from app.gui.look import coverage_rows, legend, legend_rows, section
from app.render.compose import OUTLINE_STYLE, PALETTE


class WindowLayout:
    """The widgets of the main window, laid out (a part of ``MainWindow``)."""

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
        self._add_input_sections(panel, layout)
        self._add_grid_section(panel, layout)
        self._add_display_section(panel, layout)
        layout.addStretch(1)

        scroll = QScrollArea()
        scroll.setWidget(panel)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.scene_dock = panel_dock("Scene", "sceneDock", scroll, self)
        self.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, self.scene_dock)
        panel.setMinimumWidth(240)

    def _add_input_sections(self, panel, layout) -> None:
        """Algorithm, Options and Points: what the run takes."""
        layout.addWidget(section("Algorithm"))
        self.picker_search = QLineEdit(panel)
        self.picker_search.setPlaceholderText("Search algorithms\u2026")
        self.picker_search.setClearButtonEnabled(True)
        self.picker_search.setToolTip("Type part of a name, family or idea (\"edge\", "
                                      "\"circle\"); Enter picks the first one listed")
        layout.addWidget(self.picker_search)
        self.picker = AlgorithmPicker(panel)
        self.picker.setMinimumHeight(300)
        self.picker.setMaximumHeight(420)  # about ten of the algorithms at once
        layout.addWidget(self.picker)
        self.picker_search.textChanged.connect(self.picker.set_filter)
        self.picker_search.returnPressed.connect(self.picker.choose_first_shown)

        layout.addWidget(section("Options"))
        self.options = OptionsEditor(panel)
        layout.addWidget(self.options)

        layout.addWidget(section("Points"))
        self.points = VertexTable(panel)  # one row per vertex: x, y, colour, z, w
        layout.addWidget(self.points)
        self.hint = QLabel(panel)
        self.hint.setObjectName("summary")
        self.hint.setWordWrap(True)
        layout.addWidget(self.hint)

    def _add_grid_section(self, panel, layout) -> None:
        layout.addWidget(section("Grid"))
        self.grid_editor = GridEditor(MAX_GRID, panel)
        layout.addWidget(self.grid_editor)
        fit = QPushButton("Fit grid to view", panel)
        fit.setToolTip("Zoom and pan so that the whole grid is in view (F)")
        fit.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        fit.clicked.connect(self.grid.fit)
        layout.addWidget(fit)

    def _add_display_section(self, panel, layout) -> None:
        layout.addWidget(section("Display"))
        self.show_primitive = QCheckBox("Ideal primitive", panel)
        self.show_primitive.setChecked(True)
        self.show_primitive.setToolTip("Draw the exact primitive the pixels stand for")
        self.compare = QCheckBox("Compare with previous algorithm", panel)
        self.compare.setChecked(False)  # on when asked: its outlines are noise otherwise
        self.compare.setToolTip("After switching algorithm, outline the pixels where the "
                                "previous algorithm's final result differs")
        self.coverage = QCheckBox("Coverage counts", panel)
        self.coverage.setToolTip("Colour every pixel by how many times it has been written "
                                 "so far (0, 1, 2, 3+): overlaps in a mesh stand out")
        for box in (self.show_primitive, self.compare, self.coverage):
            layout.addWidget(box)
        self.legend = legend(legend_rows(PALETTE))
        self.coverage_legend = legend(coverage_rows(PALETTE))
        self.coverage_legend.hide()
        layout.addWidget(self.legend)
        layout.addWidget(self.coverage_legend)

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
        self.error_scale = ErrorScale(self)  # the coverage-error map's colours and sign
        self.error_scale.hide()
        status.addPermanentWidget(self.error_scale)
        status.addPermanentWidget(self.difference_label)
        status.addPermanentWidget(self.cursor_label)
