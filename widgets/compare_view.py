"""Compare mode's views: pixel grids side by side with linked zoom and pan,
a header per pane to choose its algorithm and options, and a diff pane with
its legend and counts.

These widgets display what they are given (images, cells, titles, counts)
and report what the person chose; the runs and the diff are worked out in
``app.compare``.
"""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QBrush, QColor, QPainter, QPixmap
from PySide6.QtWidgets import (QComboBox, QGridLayout, QHBoxLayout, QLabel, QLineEdit,
                               QSizePolicy, QToolButton, QVBoxLayout, QWidget)

from app.model.colours import DIFF_PATTERNS

from .grid_view import PixelGridView
from .pattern_layer import PatternLayer

ERROR_STYLE = "color: #c92a2a;"
TITLE_STYLE = "font-weight: bold; color: #1d2733;"


class ReadOnlyGridView(PixelGridView):
    """The pixel grid without the drawing tools: clicks and drags pan,
    the wheel zooms. The ideal primitive is drawn from given paths."""

    def __init__(self, palette, outline_styles, parent=None):
        super().__init__(palette, outline_styles, parent)
        self.handles.hide()
        self.ideal = pg.PlotCurveItem(pen=pg.mkPen(palette.primitive, width=2.0),
                                      antialias=True, connect="finite")
        self.ideal.setZValue(3)
        self.view_box.addItem(self.ideal)

    def set_grid(self, width: int, height: int, fit: bool = True) -> None:
        # Panes are narrow and tall: a long, flat grid needs more room above
        # and below it than the main grid allows, or the fit is cropped.
        margin = 2 * max(width, height) + 2
        self.view_box.setLimits(xMin=-margin, xMax=width + margin, yMin=-margin,
                                yMax=height + margin)
        super().set_grid(width, height, fit)
        self.view_box.setLimits(xMin=-margin, xMax=width + margin, yMin=-margin,
                                yMax=height + margin)
        if fit:
            self.fit()

    def show_paths(self, paths) -> None:
        """The ideal primitive as [(points, closed), ...] in grid units."""
        xs, ys = [], []
        for points, closed in paths or ():
            points = list(points)
            if not points:
                continue
            if closed:
                points.append(points[0])
            xs += [float(p[0]) for p in points] + [math.nan]
            ys += [float(p[1]) for p in points] + [math.nan]
        self.ideal.setData(np.array(xs, float), np.array(ys, float))

    # Nothing is drawn here: a click does nothing, every drag pans.
    def _clicked(self, scene_pos, modifiers=None, double=False) -> None:
        return

    def _drag_target(self, scene_pos, modifiers):
        return None

    def _context_menu(self, scene_pos, screen_pos) -> None:
        return

    def keyPressEvent(self, event):  # noqa: N802
        # Enter and Backspace edit points in the main grid; here they are
        # left to the window (playback keys).
        event.ignore()


class PaneHeader(QWidget):
    """Algorithm picker, options field and a remove button for one pane."""

    algorithmChosen = Signal(str)
    optionsTyped = Signal(str)
    removeRequested = Signal()

    def __init__(self, parent=None):
        super().__init__(parent)
        self.algorithm = QComboBox(self)
        self.algorithm.setToolTip("The algorithm this pane runs on the shared primitives")
        self.algorithm.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
        self.algorithm.setMinimumContentsLength(10)
        self.algorithm.setSizeAdjustPolicy(
            QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        self.algorithm.activated.connect(
            lambda _i: self.algorithmChosen.emit(self.algorithm.currentData()))
        self.options = QLineEdit(self)
        self.options.setAccessibleName("Options of this pane")
        self.options.setPlaceholderText("options: key=value ...")
        self.options.setClearButtonEnabled(True)
        self.options.editingFinished.connect(lambda: self.optionsTyped.emit(self.options.text()))
        self.remove = QToolButton(self)
        self.remove.setText("\u2715")
        self.remove.setAutoRaise(True)
        self.remove.setToolTip("Remove this pane (at least two stay)")
        self.remove.clicked.connect(self.removeRequested.emit)
        layout = QGridLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(3)
        layout.addWidget(self.algorithm, 0, 0)
        layout.addWidget(self.remove, 0, 1)
        layout.addWidget(self.options, 1, 0, 1, 2)

    def set_algorithms(self, items) -> None:
        """(name, title) pairs."""
        self.algorithm.blockSignals(True)
        self.algorithm.clear()
        for name, title in items:
            self.algorithm.addItem(title, name)
            self.algorithm.setItemData(self.algorithm.count() - 1, name,
                                       Qt.ItemDataRole.ToolTipRole)
        self.algorithm.blockSignals(False)

    def set_current(self, name: str, options_text: str, options_help: str) -> None:
        index = self.algorithm.findData(name)
        self.algorithm.blockSignals(True)
        self.algorithm.setCurrentIndex(index)
        self.algorithm.blockSignals(False)
        if self.options.text() != options_text:
            self.options.setText(options_text)
        self.options.setToolTip("Options this pane sets, as key=value separated by spaces; "
                                "the rest take the scene's or the defaults.\n" + options_help)

    def show_options_error(self, message: str) -> None:
        self.options.setStyleSheet("border: 1px solid #c92a2a;" if message else "")


class ComparePane(QWidget):
    """A title, a read-only pixel grid and a message line."""

    def __init__(self, palette, outline_styles, top: QWidget | None = None, parent=None):
        super().__init__(parent)
        # The header (or the diff's legend) above the grid. Every pane's top
        # and message line take the same height, so that the grids, which
        # are linked in x and y, are the same size too.
        self.header = PaneHeader(self) if top is None else None
        self.top = self.header if top is None else top
        self.top.setParent(self)
        self.title = QLabel(self)
        self.title.setStyleSheet(TITLE_STYLE)
        self.title.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.title.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Fixed)
        self.grid = ReadOnlyGridView(palette, outline_styles, self)
        self.grid.setAccessibleName("Pixel grid of this pane")
        self.grid.setMinimumSize(160, 140)
        self.patterns = PatternLayer(self.grid.view_box)
        self.message = QLabel(self)
        self.message.setWordWrap(True)
        self.message.setObjectName("paneMessage")
        self.message.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.message.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Fixed)
        self.message.setFixedHeight(3 * self.message.fontMetrics().lineSpacing() + 4)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(2, 2, 2, 2)
        layout.setSpacing(3)
        layout.addWidget(self.top)
        layout.addWidget(self.title)
        layout.addWidget(self.grid, 1)
        layout.addWidget(self.message)

    def set_title(self, text: str, tooltip: str = "") -> None:
        self.title.setText(text)
        self.title.setToolTip(tooltip or text)

    def set_message(self, text: str, error: bool = False) -> None:
        self.message.setText(text)
        self.message.setToolTip(text)
        self.message.setStyleSheet(ERROR_STYLE if error else "color: #55606d;")

    def show_frame(self, image, current=(), candidates=(), spans=(), differences=None,
                   patterned=None) -> None:
        """Show ``image`` (one pixel per cell) and the step's highlights;
        ``patterned``: the same cells enlarged with a pattern in each, shown
        over them."""
        self.grid.set_image(image)
        if patterned is None:
            self.patterns.clear()
        else:
            self.patterns.show_cells(patterned, image.shape[1], image.shape[0])
        self.grid.set_highlights(current, candidates, spans)
        self.grid.set_differences(differences)


# Qt's brush patterns nearest to the diff cells' patterns (app/render/patterns.py).
CHIP_PATTERNS = {"stripes /": Qt.BrushStyle.BDiagPattern, "stripes \\": Qt.BrushStyle.FDiagPattern,
                 "cross": Qt.BrushStyle.DiagCrossPattern}


def _chip(color: str, pattern: str = "plain") -> QLabel:
    pixmap = QPixmap(14, 14)
    pixmap.fill(Qt.GlobalColor.transparent)
    painter = QPainter(pixmap)
    painter.fillRect(1, 1, 12, 12, QColor(color))
    if pattern in CHIP_PATTERNS:
        painter.fillRect(1, 1, 12, 12, QBrush(QColor("#ffffff"), CHIP_PATTERNS[pattern]))
    painter.setPen(QColor("#8a939e"))
    painter.drawRect(1, 1, 12, 12)
    painter.end()
    label = QLabel()
    label.setPixmap(pixmap)
    return label


class DiffLegend(QWidget):
    """Chips with their meaning and the count of cells of each class."""

    def __init__(self, names, colours, parent=None):
        super().__init__(parent)
        layout = QGridLayout(self)
        layout.setContentsMargins(0, 2, 0, 0)
        layout.setHorizontalSpacing(6)
        layout.setVerticalSpacing(1)
        self.labels: dict[str, QLabel] = {}
        self.counts: dict[str, QLabel] = {}
        for row, (name, colour, pattern) in enumerate(zip(names, colours, DIFF_PATTERNS)):
            layout.addWidget(_chip(colour, pattern), row, 0)
            label = QLabel(name, self)
            count = QLabel("", self)
            count.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            count.setObjectName(f"count-{name}")
            layout.addWidget(label, row, 1)
            layout.addWidget(count, row, 2)
            self.labels[name], self.counts[name] = label, count
        layout.setColumnStretch(1, 1)

    def set_names(self, names: dict) -> None:
        """Texts for the classes, e.g. {"only A": "only in DDA"}."""
        for key, text in names.items():
            if key in self.labels:
                self.labels[key].setText(text)

    def set_counts(self, counts: dict | None) -> None:
        for key, label in self.counts.items():
            label.setText("" if counts is None or key not in counts else f"{counts[key]:,}")


class CompareView(QWidget):
    """Up to ``most`` panes in a row and the diff pane at the right, all
    with linked zoom and pan."""

    def __init__(self, palette, outline_styles, diff_names, diff_colours, most: int = 4,
                 parent=None):
        super().__init__(parent)
        self._palette, self._styles = palette, outline_styles
        self.panes: list[ComparePane] = []
        self._linked: list = []  # grids whose view range the others follow
        self._row = QHBoxLayout(self)
        self._row.setContentsMargins(0, 0, 0, 0)
        self._row.setSpacing(6)
        self.legend = DiffLegend(diff_names, diff_colours)
        self.diff = ComparePane(palette, outline_styles, top=self.legend, parent=self)
        self._row.addWidget(self.diff, 1)
        self._most = most
        self._following = False

    def set_pane_count(self, count: int) -> None:
        count = max(0, min(count, self._most))
        while len(self.panes) < count:
            pane = ComparePane(self._palette, self._styles, parent=self)
            self._row.insertWidget(len(self.panes), pane, 1)
            self.panes.append(pane)
        while len(self.panes) > count:
            pane = self.panes.pop()
            self._row.removeWidget(pane)
            pane.hide()
            pane.deleteLater()
        self._link()
        height = max(pane.top.sizeHint().height() for pane in self.panes + [self.diff])
        for pane in self.panes + [self.diff]:
            pane.top.setFixedHeight(height)
        for pane in self.panes:
            pane.header.remove.setEnabled(count > 2)

    def grids(self) -> list[ReadOnlyGridView]:
        return [pane.grid for pane in self.panes] + [self.diff.grid]

    def _link(self) -> None:
        # Zoom or pan one view and all follow. (pyqtgraph's setXLink and
        # setYLink fight the locked aspect ratio: a link forces one axis
        # and the aspect lock then shrinks the other, so a fitted wide grid
        # ends up cropped. Copying the whole range keeps both axes.)
        for grid in self.grids():
            if grid not in self._linked:
                self._linked.append(grid)
                box = grid.view_box
                box.sigRangeChanged.connect(lambda *_args, b=box: self._follow(b))
                box.sigRangeChangedManually.connect(self._zoomed_by_hand)

    def _follow(self, source) -> None:
        if self._following:
            return
        self._following = True
        try:
            x_range, y_range = source.viewRange()
            for grid in self.grids():
                if grid.view_box is not source:
                    grid.view_box.setRange(xRange=x_range, yRange=y_range, padding=0)
        finally:
            self._following = False

    def _zoomed_by_hand(self, *_args) -> None:
        # A zoom or pan by hand holds in every view: none of them fits the
        # grid again on its own when the window is resized.
        for grid in self.grids():
            grid.set_auto_fit(False)

    def set_grid(self, width: int, height: int) -> None:
        for grid in self.grids():
            grid.set_grid(width, height)

    def fit(self) -> None:
        # The first view fits; the rest follow it.
        grids = self.grids()
        for grid in grids:
            grid.set_auto_fit(True)
        grids[0].fit()

    def show_region(self, x0: float, y0: float, x1: float, y1: float) -> None:
        """Zoom every view to the cells [x0, x1) x [y0, y1) (grid units)."""
        from PySide6.QtCore import QRectF
        for grid in self.grids():
            grid.set_auto_fit(False)
        self.grids()[0].view_box.setRange(QRectF(x0, y0, x1 - x0, y1 - y0), padding=0)

    def set_y_down(self, y_down: bool) -> None:
        for grid in self.grids():
            grid.set_y_down(y_down)
