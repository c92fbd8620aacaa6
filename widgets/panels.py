"""The variables panel, and the colours and fonts the panels share (the
pseudo-code panel is in code_panel.py)."""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QEvent, Qt
from PySide6.QtGui import QBrush, QColor, QFont, QFontDatabase, QFontMetrics
from PySide6.QtWidgets import (QAbstractItemView, QFrame, QGraphicsEllipseItem,
                               QGraphicsItem, QHeaderView, QLabel, QScrollArea, QTableWidget,
                               QTableWidgetItem, QVBoxLayout, QWidget)

from app.model.colours import BRANCH_GLYPHS, BRANCH_SYMBOLS, LIGHT, UNDECIDED_SYMBOL

from .axes_frame import axes_frame
from .dirty import cache_drawing, fill_own_background
from .series_points import plot_points

CURRENT_LINE = QColor("#ffe8b3")
CURRENT_TEXT = QColor("#1d2733")
CURRENT_EDGE = QColor("#f08c00")
CHANGED_VALUE = QColor("#b35900")
LINE_NUMBER = QColor("#8a94a1")
NOTES_MAX_HEIGHT = 120
# Values whose sign or range matters: text colours by tone (app/model/colours.py,
# the set of the panel's theme: ``set_meanings``), and a positive value shows
# its "+" so that the sign is written, not only coloured.
TONES = ("positive", "negative", "zero")
# Chips of the step summary: (background, text) by tone; the chip's text says its meaning.
CHIP_COLORS = {"positive": ("#dcecf7", "#005a8c"), "negative": ("#fbe4d5", "#9c4500"),
               "zero": ("#ececec", "#3d3d3d"), "in": ("#007a5a", "#ffffff"),
               "out": ("#868e96", "#ffffff"), "info": ("#e7ecf2", "#3d4754")}


ROWS_BEFORE_PLOT = 4  # rows the table keeps in sight before the plot gets room
SERIES_DOTS = 300  # more steps than this: no dot per step on the plot over the run
# A decision variable's dots by the branch its step took (E, NE, ...: the
# k-th branch of a decision takes the k-th colour and marker shape), and the
# steps that decide nothing. These are the light theme's; the dark theme's
# come from app/model/colours.py DARK the same way.
BRANCH_COLORS = LIGHT.branches
UNDECIDED_COLOR = LIGHT.undecided
DOT_SYMBOLS = (UNDECIDED_SYMBOL, *BRANCH_SYMBOLS)


def branch_legend(names, colors=BRANCH_COLORS) -> str:
    """Rich text naming each branch beside a marker of its shape and colour."""
    return ", ".join(f"<span style='color:{colors[k % len(colors)]}'>"
                     f"{BRANCH_GLYPHS[k % len(BRANCH_GLYPHS)]} {name}</span>"
                     for k, name in enumerate(names))


def _with_sign(text: str, tone) -> str:
    """A positive value with its "+" written, so its sign is not told by colour alone."""
    if tone == "positive" and text[:1] not in ("+", ""):
        return "+" + text
    return text


def monospace_font(scale: float = 1.0) -> QFont:
    font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
    if scale != 1.0 and font.pointSizeF() > 0:
        font.setPointSizeF(font.pointSizeF() * scale)
    return font


def _value_fonts(like: QFont) -> tuple[QFont, QFont]:
    """The values' type, plain and bold (a value the step changed): the
    fixed-width face at the size of ``like``."""
    plain = monospace_font()
    if like.pointSizeF() > 0:
        plain.setPointSizeF(like.pointSizeF())
    bold = QFont(plain)
    bold.setBold(True)
    return plain, bold


def _as_color(text) -> str:
    """'9851488' -> '#96d2e0'; anything that is not a whole number is kept."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return str(text)
    if not value.is_integer() or not 0 <= value <= 0xFFFFFF:
        return str(text)
    return f"#{int(value):06x}"


def _step_dot() -> QGraphicsEllipseItem:
    """The step's dot on the plot: 9 pixels across whatever the zoom. A
    plain Qt item, moved each step; a one-point ScatterPlotItem measured its
    bounds in Python a dozen times a step."""
    dot = QGraphicsEllipseItem(-4.5, -4.5, 9, 9)
    dot.setFlag(QGraphicsItem.GraphicsItemFlag.ItemIgnoresTransformations)
    dot.setBrush(pg.mkBrush("#f08c00"))
    dot.setPen(pg.mkPen("#ffffff", width=1.5))
    dot.hide()
    return dot


def _dot_brushes(meanings) -> list:
    """Brushes of the decision dots by kind: decides nothing, then each branch."""
    return [pg.mkBrush(color) for color in (meanings.undecided, *meanings.branches)]


class VariablesPanel(QWidget):
    """A table of the current step's named values and a plot of one value
    over the whole run, with a marker at the current step."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.caption = QLabel(self)
        self.caption.setObjectName("stepCaption")
        self.caption.setWordWrap(True)
        self.caption.setContentsMargins(0, 2, 0, 4)
        fill_own_background(self.caption)  # changes every step
        self.chips = QLabel(self)
        self.chips.setObjectName("chips")
        self.chips.setWordWrap(True)
        self.chips.setTextFormat(Qt.TextFormat.RichText)
        self.chips.hide()
        self.table = self._make_table()
        self.table.cellClicked.connect(self._clicked)
        self._value_fonts = _value_fonts(self.font())
        self.meanings = LIGHT  # the colours with a meaning, for the panel's ground
        self._series_shown = (None,)  # set_series's arguments, to draw again in other colours

        self.plot = self._make_plot()
        self.plot_title = QLabel(self)
        self.plot_title.setObjectName("seriesTitle")
        self.plot_title.setWordWrap(True)  # its length must not set the dock's width
        self._plot_wanted = False  # a series to plot
        self._plot_allowed = True  # presentation mode puts the plot aside

        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 6, 6, 6)
        layout.setSpacing(6)
        layout.addWidget(self._caption_area())
        layout.addWidget(self.chips)
        layout.addWidget(self.table, 1)
        layout.addWidget(self.plot_title)
        layout.addWidget(self.plot)
        self._rows: list[tuple[str, str]] = []
        self._names: tuple[str, ...] = ()  # the rows' names as laid out in the table
        self._row_of: dict[str, int] = {}  # name -> its table row
        self._group_row = -1  # the constants' group row, if any
        self._constants: frozenset = frozenset()
        self._folded = True  # the constants: a lecture needs the step's rows in sight
        self._fitted_width = -1  # the value column's width when the rows were fitted
        self._chips: list[tuple[str, str, str]] = []
        self._series: np.ndarray | None = None
        self.set_series(None)

    def _caption_area(self) -> QScrollArea:
        """The caption in a scroll area of two lines' height (``_fit_caption``):
        a label's new text asks its layout for room, and the ask would climb
        to the main window, which lays out and repaints its docks (1 to 2 ms
        a step, measured); a scroll area takes the ask itself."""
        self.caption.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        area = QScrollArea(self)
        area.setWidget(self.caption)
        area.setWidgetResizable(True)
        area.setFrameShape(QFrame.Shape.NoFrame)
        area.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        area.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        area.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.caption_area = area
        self._fit_caption()
        return area

    def _fit_caption(self) -> None:
        margins = self.caption.contentsMargins()
        self.caption_area.setFixedHeight(2 * self.caption.fontMetrics().lineSpacing()
                                         + margins.top() + margins.bottom())

    def _make_table(self) -> QTableWidget:
        """The name/value table of the step's variables."""
        table = QTableWidget(0, 2, self)
        table.setObjectName("variables")
        table.setAccessibleName("Variables")
        table.setAccessibleDescription("Each variable's name and its value at the step on show")
        # Values change every step; a scroll bar that comes or goes as rows
        # are added repaints the table alone.
        fill_own_background(table, table.viewport())
        table.setHorizontalHeaderLabels(["Name", "Value"])
        table.verticalHeader().setVisible(False)
        table.horizontalHeader().setSectionResizeMode(0, QHeaderView.ResizeMode.ResizeToContents)
        table.horizontalHeader().setSectionResizeMode(1, QHeaderView.ResizeMode.Stretch)
        table.horizontalHeader().setDefaultAlignment(Qt.AlignmentFlag.AlignLeft)
        table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        table.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
        table.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        table.setAlternatingRowColors(True)
        table.setShowGrid(False)
        table.verticalHeader().setDefaultSectionSize(self.fontMetrics().height() + 6)
        return table

    def _make_plot(self):
        """The plot of the decision variable over the run, with the step's
        marker: a view box and two axes. A PlotItem would also build its
        options form, a title and two more axes: some 8 ms more of the
        window's start-up."""
        plot = pg.GraphicsView(self)
        plot.setObjectName("series")
        plot.setAccessibleName("Plot of the decision variable")
        plot.setAccessibleDescription("The decision variable at every step of the run, the "
                                      "step on show marked")
        plot.setBackground("#ffffff")
        plot.setMinimumHeight(120)
        plot.setMaximumHeight(190)
        self.plot_view = view = pg.ViewBox(enableMenu=False)  # no view menu is built
        view.setMouseEnabled(x=True, y=False)
        self.plot_axes = {name: pg.AxisItem(name, pen="#8a94a1", textPen="#3d4754")
                          for name in ("left", "bottom")}
        plot.setCentralItem(axes_frame(view, self.plot_axes))
        # No background grid: pyqtgraph redraws it whole whenever the
        # step marker moves, which costs more than the rest of the panel.
        self.zero = pg.InfiniteLine(0, angle=0, pen=pg.mkPen("#9aa5b1", style=Qt.PenStyle.DashLine))
        self.curve = pg.PlotDataItem(pen=pg.mkPen(self.meanings.ink, width=1.5),
                                     connect="finite", symbol="o", symbolSize=4,
                                     symbolBrush=self.meanings.ink,
                                     symbolPen=None, autoDownsample=True,
                                     downsampleMethod="peak", clipToView=True)
        self.marker = pg.InfiniteLine(0, angle=90, pen=pg.mkPen("#f08c00", width=2))
        self.point = _step_dot()
        # A decision variable's dots, coloured by the branch taken: one
        # item with a brush per dot, since pyqtgraph measures each item's
        # bounds on every step.
        self.dots = pg.ScatterPlotItem(pen=None, symbol="o")
        self._dot_brushes = _dot_brushes(self.meanings)
        for part in (self.zero, self.curve, self.dots, self.marker):
            view.addItem(part)
        view.addItem(self.point, ignoreBounds=True)  # it stands on the curve
        self.marker.setZValue(10)
        self.point.setZValue(11)
        # The run's values stay put while the step marker moves over them.
        cache_drawing(self.curve.curve, self.curve.scatter, self.dots)
        return plot

    # ----------------------------------------------------------- table
    def set_caption(self, text: str) -> None:
        self.caption.setText(text)
        # The scroll area fits the label to its new text now, before it is
        # painted: measuring a rich-text label lays its text out again,
        # which after the paint would ask for two more (about 1 ms a step,
        # measured).
        QCoreApplication.sendPostedEvents(self.caption_area.viewport(),
                                          QEvent.Type.LayoutRequest)

    def set_chips(self, chips) -> None:
        """A one-line summary over the table: chips (text, tone, tooltip),
        coloured by tone (see CHIP_COLORS); none hides the line."""
        chips = [tuple(chip) for chip in chips]
        if chips == self._chips:
            return
        self._chips = chips
        parts = []
        for text, tone, _tip in chips:
            background, color = CHIP_COLORS.get(tone, CHIP_COLORS["info"])
            # Non-breaking spaces inside a chip: lines wrap between chips only.
            inner = _escape(text).replace(" ", "&nbsp;")
            parts.append(f"<span style='background-color:{background}; color:{color};'>"
                         f"&nbsp;{inner}&nbsp;</span>")
        self.chips.setText("&nbsp; ".join(parts))
        self.chips.setToolTip("\n".join(f"{text}: {tip}" for text, _tone, tip in chips if tip))
        self.chips.setVisible(bool(chips))

    def chip_texts(self) -> list[str]:
        return [text for text, _tone, _tip in self._chips]

    def set_rows(self, rows, color_names=(), tones=None) -> None:
        """Rows (name, text) of the step on show, in the order given, but
        for the constants (``set_constants``), which follow in a group that
        folds. Values that changed since the rows shown before are set in
        bold and a warmer colour. Rows named in ``color_names`` hold packed
        0xRRGGBB colours: they read as #rrggbb, with a swatch. ``tones``
        (name -> "positive", "negative" or "zero") colour values whose sign
        matters."""
        rows = [(str(name), _as_color(text) if name in color_names else str(text))
                for name, text in rows]
        rows = ([row for row in rows if row[0] not in self._constants]
                + [row for row in rows if row[0] in self._constants])
        tones = tones or {}
        before = dict(self._rows)
        self._lay_out_rows(rows)
        fitted = []
        for name, text in rows:
            row = self._row_of[name]
            self._set_text(self._cell(row, 0), name)
            changed = name in before and before[name] != text
            tone = tones.get(name)
            color = QColor(getattr(self.meanings, tone)) if tone in TONES else (
                CHANGED_VALUE if changed else None)
            text = _with_sign(text, tones.get(name))
            swatch = text if name in color_names and QColor.isValidColorName(text) else None
            if self._set_value(row, text, color, changed, swatch):
                fitted.append(row)
        self._rows = rows
        self._fit_long_rows([self._row_text(row) for row in range(self.table.rowCount())],
                            fitted)
        # Values whose sign matters stay in sight, wherever they are listed.
        toned = [self._row_of[name] for name, _text in rows if name in tones]
        if toned:
            self.table.scrollToItem(self.table.item(max(toned), 1),
                                    QAbstractItemView.ScrollHint.EnsureVisible)
            self.table.scrollToItem(self.table.item(min(toned), 1),
                                    QAbstractItemView.ScrollHint.EnsureVisible)

    def rows(self) -> list[tuple[str, str]]:
        """The rows as listed: the step's, then the constants."""
        return list(self._rows)

    # ------------------------------------------------------ constants
    def set_constants(self, names) -> None:
        """The names of the run's constants: listed last, in a group that
        folds (``set_folded``)."""
        self._constants = frozenset(names)

    @property
    def folded(self) -> bool:
        return self._folded

    def set_folded(self, folded: bool) -> None:
        """Hide (or show) the constants' rows under their group's row."""
        self._folded = bool(folded)
        self._lay_out_rows(self._rows, again=True)

    def shown_names(self) -> list[str]:
        """The names of the rows in view, top to bottom (the constants'
        group row is not a name; rows it folds are not in view)."""
        table, height = self.table, self.table.viewport().height()
        return [name for name, row in sorted(self._row_of.items(), key=lambda item: item[1])
                if not table.isRowHidden(row) and 0 <= table.rowViewportPosition(row)
                and table.rowViewportPosition(row) + table.rowHeight(row) <= height]

    def _lay_out_rows(self, rows, again: bool = False) -> None:
        """Table rows for ``rows``: the step's, then the constants' group
        row (across both columns) and the constants, hidden when folded.
        Laid out only when the names change: this runs on every step."""
        names = tuple(name for name, _text in rows)
        if names == self._names and not again:
            return
        self._names = names
        constants = [name for name in names if name in self._constants]
        step = len(names) - len(constants)
        count = len(names) + (1 if constants else 0)
        table = self.table
        table.clearSpans()
        if table.rowCount() != count:
            table.setRowCount(count)
        self._row_of = {name: k for k, name in enumerate(names[:step])}
        self._row_of.update({name: step + 1 + k for k, name in enumerate(constants)})
        self._group_row = step if constants else -1
        for row in range(count):
            table.setRowHidden(row, self._folded and row > step)
            if row != step:  # the group row's grey may have been on this row
                self._cell(row, 0).setForeground(QBrush())
        if constants:
            self._show_group(step, constants)

    def _show_group(self, row: int, constants) -> None:
        """The constants' group row: a click folds or unfolds them."""
        self.table.setSpan(row, 0, 1, 2)
        group = self._cell(row, 0)
        count = len(constants)
        # Short: the names' column is as wide as its widest text, this one's too.
        group.setText(("\u25b8 " if self._folded else "\u25be ")
                      + f"{count} constant{'s' if count != 1 else ''}")
        group.setToolTip(", ".join(constants) + ": values the run never changes; click to "
                         + ("show them" if self._folded else "fold them away"))
        group.setForeground(QBrush(LINE_NUMBER))
        value = self._cell(row, 1)
        value.setText("")
        value.setData(Qt.ItemDataRole.DecorationRole, None)

    def _row_text(self, row: int) -> str:
        item = self.table.item(row, 1)
        return "" if item is None or row == self._group_row else item.text()

    def _clicked(self, row: int, _column: int) -> None:
        if row == self._group_row >= 0:
            self.set_folded(not self._folded)

    def changeEvent(self, event):  # noqa: N802
        super().changeEvent(event)
        if event.type() == QEvent.Type.FontChange:
            self.fit_type()

    def fit_type(self) -> None:
        """The values in the panel's type (its size, a fixed-width face):
        one size for the header, the names and the values, whatever the
        window's zoom or presentation mode; the caption's two lines fit it."""
        self._value_fonts = _value_fonts(self.font())
        self._fit_caption()
        height = max(QFontMetrics(self._value_fonts[0]).height(), self.fontMetrics().height())
        self.table.verticalHeader().setDefaultSectionSize(height + 6)
        self._fit_plot()

    def _fit_long_rows(self, rows, fitted) -> None:
        """A value too long for its cell (a fill's queue, say) wraps onto a
        second line instead of losing its end; the others keep one line.
        ``fitted``: the rows whose value or its type changed; all of them
        when the column's width did."""
        width = self.table.columnWidth(1) - 10
        if width != self._fitted_width:
            self._fitted_width, fitted = width, range(len(rows))
        metrics = QFontMetrics(self._value_fonts[0])
        default = self.table.verticalHeader().defaultSectionSize()
        for row in fitted:
            text = rows[row]
            if width > 0 and metrics.horizontalAdvance(text) > width:
                self.table.resizeRowToContents(row)
            elif self.table.rowHeight(row) != default:
                self.table.setRowHeight(row, default)

    def value_text(self, name: str) -> str:
        """A row's value as shown (a positive toned value with its "+")."""
        return self.table.item(self._row_of[name], 1).text()

    def value_color(self, name: str) -> QColor | None:
        """The colour a row's value is drawn in (None: the default)."""
        brush = self.table.item(self._row_of[name], 1).foreground()
        return brush.color() if brush.style() != Qt.BrushStyle.NoBrush else None

    def _cell(self, row: int, column: int) -> QTableWidgetItem:
        item = self.table.item(row, column)
        if item is None:
            item = QTableWidgetItem()
            self.table.setItem(row, column, item)
        return item

    @staticmethod
    def _set_text(item: QTableWidgetItem, text: str) -> bool:
        """Show ``text`` in the cell; True when it changed."""
        shown = text.replace(", ", ",\u00a0")  # pairs such as (4, 10) stay whole when wrapped
        if item.text() == shown:
            return False
        item.setText(shown)
        item.setToolTip(text)
        return True

    def _set_value(self, row, text, color, bold, swatch) -> bool:
        """The value's text, colour, type and swatch; True when its text or
        type changed (its row may need another height). Qt repaints the cell
        only for what differs from what it holds."""
        item = self._cell(row, 1)
        refit = self._set_text(item, text)
        font = self._value_fonts[bold]
        if item.font() != font:
            item.setFont(font)
            refit = True
        item.setForeground(QBrush(color) if color is not None else QBrush())
        item.setData(Qt.ItemDataRole.DecorationRole, QColor(swatch) if swatch else None)
        return refit

    # ------------------------------------------------------------ plot
    def set_series(self, values: np.ndarray | None, name: str = "",
                   decision: bool = False, branches=None) -> None:
        """Plot ``values`` against the step index, or hide the plot.

        For a decision variable the zero line is drawn and kept in view,
        and ``branches`` = (codes, names) colours each step's dot by the
        branch it took (code k for the k-th of ``names``; -1 for a step that
        decides nothing), as app/model/branches.py works it out.
        """
        self._series_shown = (values, name, decision, branches)
        finite = values is not None and bool(np.isfinite(values).any())
        self._plot_wanted = finite
        self._fit_plot()
        if not finite:
            self._series = None
            self.curve.setData([], [])
            self._set_dots()
            self.point.hide()
            return
        self._series = values
        coloured = decision and branches is not None
        # Only the steps that carry the value, joined: a value set every
        # other step (a fill's stack size) still reads as one curve. A long
        # run is thinned to each stretch's extremes (widgets/series_points.py).
        steps, known = plot_points(values)
        self._draw_series(steps, known,
                          branches[0][steps.astype(np.int64)] if coloured else None)
        self.plot_title.setText(f"{name} over the run" + (
            f" (the branch taken: {branch_legend(branches[1], self.meanings.branches)})"
            if coloured else ""))
        low, high = float(known.min()), float(known.max())
        self.zero.setVisible(decision)
        if decision:
            low, high = min(low, 0.0), max(high, 0.0)
        pad = max(0.5, (high - low) * 0.08)
        self.plot_view.setRange(
            xRange=(0, max(1, len(values) - 1)), yRange=(low - pad, high + pad), padding=0.02)

    def _draw_series(self, steps, known, taken) -> None:
        """Few steps: a line with a dot per step. Many: the line would be a
        solid block of zigzags, so a decision variable keeps its dots only,
        coloured by the branch each step took (``taken``, per plotted
        step), and another value its line."""
        few = len(known) <= SERIES_DOTS
        if taken is not None:
            self.curve.setPen(pg.mkPen(self.meanings.undecided, width=1))
            self.curve.setData(steps if few else [], known if few else [], symbol=None)
            # 0: decides nothing, 1, 2, ...: the branches. Drawn in that
            # order, so that where dots overlap a branch's lie on top.
            kind = np.where(taken >= 0, taken % len(self.meanings.branches) + 1, 0)
            order = np.argsort(kind, kind="stable")
            self._set_dots(steps[order], known[order], kind[order], 7 if few else 5)
            return
        self._set_dots()
        self.curve.setPen(pg.mkPen(self.meanings.ink, width=1.5))
        self.curve.setData(steps, known, symbol="o" if few else None, symbolSize=4,
                           symbolBrush=self.meanings.ink, symbolPen=None)

    def _set_dots(self, steps=(), values=(), kinds=(), size=3) -> None:
        """The decision variable's dots, each brushed by its kind (see
        ``_dot_brushes``); hidden when there are none."""
        kinds = np.asarray(kinds, dtype=np.int64).tolist()
        brushes = [self._dot_brushes[k] for k in kinds]
        self.dots.setData(steps, values, brush=brushes, symbol=[DOT_SYMBOLS[k] for k in kinds],
                          size=size)
        self.dots.setVisible(len(brushes) > 0)

    def set_meanings(self, meanings) -> None:
        """Draw signed values and the branches' dots in ``meanings``'
        colours (app/model/colours.py LIGHT or DARK, for the theme's ground);
        the rows take them when they are next set."""
        if meanings is self.meanings:
            return
        self.meanings = meanings
        self._dot_brushes = _dot_brushes(meanings)
        self.set_series(*self._series_shown)

    def set_plot_allowed(self, allowed: bool) -> None:
        """Presentation mode gives the plot's room to the rows."""
        self._plot_allowed = allowed
        self._fit_plot()

    def resizeEvent(self, event):  # noqa: N802
        super().resizeEvent(event)
        self._fit_plot()

    def _fit_plot(self) -> None:
        """The plot over the run, when there is one, it is allowed and the
        panel has room for it under the header and ``ROWS_BEFORE_PLOT`` rows:
        on a short screen or at a large zoom the rows come first."""
        rows = self.table.horizontalHeader().sizeHint().height() + ROWS_BEFORE_PLOT * (
            self.table.verticalHeader().defaultSectionSize())
        above = self.caption_area.height() + (self.chips.sizeHint().height()
                                              if self.chips.isVisibleTo(self) else 0)
        room = self.height() - above - self.plot_title.sizeHint().height()
        show = (self._plot_wanted and self._plot_allowed
                and room >= rows + self.plot.minimumHeight())
        if show != self.plot.isVisibleTo(self):
            self.plot.setVisible(show)
            self.plot_title.setVisible(show)

    def set_marker(self, index: int) -> None:
        self.marker.setValue(index)
        if self._series is not None and 0 <= index < len(self._series) \
                and math.isfinite(self._series[index]):
            self.point.setPos(float(index), float(self._series[index]))
            self.point.show()
        else:
            self.point.hide()

    def marker_point(self) -> tuple[float, float] | None:
        """Where the step's dot stands on the plot (step, value), or None."""
        if not self.point.isVisible():
            return None
        return (self.point.pos().x(), self.point.pos().y())

    @property
    def series(self):
        return self._series


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
