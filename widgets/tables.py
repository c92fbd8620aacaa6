"""The tables panel: snapshots of an algorithm's tables (edge table, active
edge table, ...) as of the step on show.

The panel only displays what it is given (``ShownTable``: the text of every
cell and which rows and cells changed); the window decides which snapshot
of each table belongs to the step.
"""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QBrush, QColor, QFont
from PySide6.QtWidgets import (QAbstractItemView, QBoxLayout, QFrame, QHeaderView, QLabel,
                               QScrollArea, QSizePolicy, QTableWidget, QTableWidgetItem,
                               QVBoxLayout, QWidget)

from app.model.tables import ShownTable

from .panels import CHANGED_VALUE, monospace_font

CHANGED_ROW = QColor("#fff3bf")
# The text of a changed row: dark on its light ground in either theme (the
# dark theme's light text would all but vanish on it).
CHANGED_ROW_TEXT = QColor("#1d2733")
FRESH_TITLE = "#b35900"


class _Block(QWidget):
    """A title and a table: exactly as tall as its rows when the panel
    stacks tables (the panel scrolls), or as tall as the panel with rows
    that scroll when the tables stand side by side."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.title = QLabel(self)
        self.title.setObjectName("tableTitle")
        self.title.setTextFormat(Qt.TextFormat.RichText)
        self.table = QTableWidget(0, 0, self)
        self.table.setObjectName("snapshot")
        self.table.setAccessibleName("Table at the step on show")
        self.table.verticalHeader().setVisible(False)
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
        self.table.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.table.setShowGrid(False)
        self.table.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAsNeeded)
        self._stacked = True
        header = self.table.horizontalHeader()
        header.setDefaultAlignment(Qt.AlignmentFlag.AlignLeft)
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        header.setStretchLastSection(True)
        self.table.verticalHeader().setDefaultSectionSize(self.fontMetrics().height() + 6)
        self.empty = QLabel("(empty)", self)
        self.empty.setObjectName("summary")
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 6)
        layout.setSpacing(2)
        layout.addWidget(self.title)
        layout.addWidget(self.table)
        layout.addWidget(self.empty)
        self._font = monospace_font()
        self._last: ShownTable | None = None
        self.set_stacked(True)

    def set_stacked(self, stacked: bool) -> None:
        self._stacked = stacked
        table = self.table
        table.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff if stacked
                                         else Qt.ScrollBarPolicy.ScrollBarAsNeeded)
        table.setSizePolicy(QSizePolicy.Policy.Expanding,
                            QSizePolicy.Policy.Fixed if stacked else QSizePolicy.Policy.Expanding)
        if stacked:
            self._fit_height()
        else:
            table.setMinimumHeight(0)
            table.setMaximumHeight(16777215)

    def show_table(self, shown: ShownTable) -> None:
        if shown is self._last:
            return  # the same snapshot as on show: nothing to redraw
        self._last = shown
        when = ("updated at this step" if shown.fresh else f"as of step {shown.step:,}")
        color = FRESH_TITLE if shown.fresh else "#66707c"
        count = len(shown.rows)
        self.title.setText(f"<b>{_escape(shown.name)}</b> &nbsp;<span style='color:{color}'>"
                           f"{when}</span> &nbsp;<span style='color:#66707c'>"
                           f"{count} row{'s' if count != 1 else ''}</span>")
        table = self.table
        table.setUpdatesEnabled(False)
        if table.columnCount() != len(shown.columns):
            table.setColumnCount(len(shown.columns))
        table.setHorizontalHeaderLabels(list(shown.columns))
        table.setRowCount(len(shown.rows))
        for r, row in enumerate(shown.rows):
            for c, text in enumerate(row):
                self._set(r, c, text, shown)
        table.setUpdatesEnabled(True)
        self.empty.setVisible(not shown.rows)
        if self._stacked:
            self._fit_height()

    def _set(self, r: int, c: int, text: str, shown: ShownTable) -> None:
        item = self.table.item(r, c)
        if item is None:
            item = QTableWidgetItem()
            self.table.setItem(r, c, item)
        item.setText(text)
        item.setToolTip(shown.tooltips.get((r, c), text))
        row_changed = r in shown.changed_rows
        cell_changed = (r, c) in shown.changed_cells
        item.setBackground(QBrush(CHANGED_ROW) if row_changed else QBrush())
        font = QFont(self._font)
        font.setBold(cell_changed)
        item.setFont(font)
        text = CHANGED_VALUE if cell_changed else CHANGED_ROW_TEXT if row_changed else None
        item.setForeground(QBrush(text) if text is not None else QBrush())

    def _fit_height(self) -> None:
        table = self.table
        rows = sum(table.rowHeight(r) for r in range(table.rowCount()))
        scroll = table.horizontalScrollBar()
        extra = scroll.sizeHint().height() if scroll.isVisible() else 0
        table.setFixedHeight(table.horizontalHeader().height() + rows + 2 * table.frameWidth()
                             + extra)


class TablesPanel(QWidget):
    """Every table of the run as of the step on show: one under another in
    a narrow panel, side by side in a wide one (``set_side_by_side``)."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.caption = QLabel(self)
        self.caption.setObjectName("summary")
        self.caption.setWordWrap(True)
        self._body = QWidget()
        self._layout = QBoxLayout(QBoxLayout.Direction.TopToBottom, self._body)
        self._layout.setContentsMargins(0, 0, 0, 0)
        self._layout.setSpacing(10)
        self._layout.addStretch(1)
        self.scroll = scroll = QScrollArea(self)
        scroll.setWidget(self._body)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self._side_by_side = False
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 6, 6, 6)
        layout.setSpacing(4)
        layout.addWidget(self.caption)
        layout.addWidget(scroll, 1)
        self._blocks: dict[str, _Block] = {}
        self._shown: list[ShownTable] = []
        self.set_tables([])

    def set_side_by_side(self, side_by_side: bool) -> None:
        """Tables next to each other, each scrolling its own rows (a panel
        under the grid), or stacked in one scrolling column (at a side)."""
        self._side_by_side = bool(side_by_side)
        self._layout.setDirection(QBoxLayout.Direction.LeftToRight if side_by_side
                                  else QBoxLayout.Direction.TopToBottom)
        self.scroll.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff
                                               if side_by_side
                                               else Qt.ScrollBarPolicy.ScrollBarAsNeeded)
        for block in self._blocks.values():
            block.set_stacked(not side_by_side)

    def set_tables(self, tables) -> None:
        """Show these tables in this order; tables not listed disappear."""
        tables = list(tables)
        names = [t.name for t in tables]
        for name in list(self._blocks):
            if name not in names:
                block = self._blocks.pop(name)
                self._layout.removeWidget(block)
                block.hide()
                block.setParent(None)
                block.deleteLater()
        for position, shown in enumerate(tables):
            block = self._blocks.get(shown.name)
            if block is None:
                block = self._blocks[shown.name] = _Block(self._body)
                block.set_stacked(not self._side_by_side)
            if self._layout.indexOf(block) != position:
                self._layout.removeWidget(block)
                self._layout.insertWidget(position, block)
            block.show_table(shown)
            self._layout.setStretch(position, 1)
        self._layout.setStretch(len(tables), 0 if self._side_by_side else 1)
        self._shown = tables
        self.caption.setText("No table yet at this step." if not tables else
                             "Shaded: rows new or changed since the table's previous "
                             "snapshot; bold: the values that changed.")

    def fitting_height(self, max_rows: int = 8) -> int:
        """Height that shows every table with up to ``max_rows`` rows when
        they stand side by side."""
        rows = max([len(t.rows) for t in self._shown] or [1])
        row = self.fontMetrics().height() + 6
        block = (self.fontMetrics().height() + 6) * 2 + row * max(1, min(rows, max_rows)) + 12
        margins = self.layout().contentsMargins()
        return (self.caption.sizeHint().height() + block + margins.top() + margins.bottom()
                + self.layout().spacing())

    def tables(self) -> list[ShownTable]:
        return list(self._shown)

    def table_widget(self, name: str) -> QTableWidget:
        return self._blocks[name].table


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
