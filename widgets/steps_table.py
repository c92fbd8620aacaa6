"""The table of every step: a QTableView over a model that makes rows on demand.

``StepsModel`` shows an ``app.model.steptable.StepTable``. It tells the view
about rows a block at a time (``canFetchMore``/``fetchMore``), so a run of a
million steps costs nothing until it is scrolled, and it makes the text of a
row only when the view paints it, keeping the last few thousand. The step on
show is drawn highlighted; the view follows it.

``StepsView`` adds Copy and Save buttons and emits what the person did:
``stepRequested(i)`` for a clicked row, ``copyRequested(rows)`` and
``saveRequested()``. Writing files and the clipboard is the window's job.
"""
from __future__ import annotations

from PySide6.QtCore import QAbstractTableModel, QModelIndex, Qt, Signal
from PySide6.QtGui import QBrush, QColor, QFont, QFontMetrics, QKeySequence, QShortcut
from PySide6.QtWidgets import (QAbstractItemView, QHBoxLayout, QHeaderView, QLabel, QPushButton,
                               QTableView, QVBoxLayout, QWidget)

CURRENT = QColor("#ffe8a3")
MAX_COLUMN = 480  # px: a column wider than this is cut (its tooltip holds the whole text)
CODE_COLUMN = "pseudo-code"  # never cut: the line is what a row is read for


class StepsModel(QAbstractTableModel):
    """Rows of a StepTable, told to the view BLOCK at a time."""

    BLOCK = 2048
    KEEP = 4096  # rows of text kept made

    def __init__(self, parent=None):
        super().__init__(parent)
        self.table = None
        self.fetched = 0
        self.current = -1
        self._texts: dict[int, list[str]] = {}
        self._bold = QFont()
        self._bold.setBold(True)

    def set_table(self, table) -> None:
        self.beginResetModel()
        self.table = table
        self.fetched = 0 if table is None else min(self.BLOCK, len(table))
        self.current = -1
        self._texts.clear()
        self.endResetModel()

    def text(self, row: int) -> list[str]:
        texts = self._texts.get(row)
        if texts is None:
            if len(self._texts) >= self.KEEP:
                self._texts.clear()
            texts = self._texts[row] = self.table.text_row(row)
        return texts

    # ------------------------------------------------ QAbstractTableModel
    def rowCount(self, parent=QModelIndex()) -> int:
        return 0 if parent.isValid() else self.fetched

    def columnCount(self, parent=QModelIndex()) -> int:
        return 0 if parent.isValid() or self.table is None else len(self.table.columns)

    def data(self, index, role=Qt.ItemDataRole.DisplayRole):
        if not index.isValid() or self.table is None:
            return None
        row = index.row()
        if role in (Qt.ItemDataRole.DisplayRole, Qt.ItemDataRole.ToolTipRole):
            return self.text(row)[index.column()]
        if role == Qt.ItemDataRole.BackgroundRole and row == self.current:
            return QBrush(CURRENT)
        if role == Qt.ItemDataRole.FontRole and row == self.current:
            return self._bold
        return None

    def headerData(self, section, orientation, role=Qt.ItemDataRole.DisplayRole):
        if (role == Qt.ItemDataRole.DisplayRole and orientation == Qt.Orientation.Horizontal
                and self.table is not None):
            return self.table.columns[section].title
        return None

    def canFetchMore(self, parent=QModelIndex()) -> bool:
        return not parent.isValid() and self.table is not None and self.fetched < len(self.table)

    def fetchMore(self, parent=QModelIndex()) -> None:
        if self.canFetchMore(parent):
            self.reach(self.fetched + self.BLOCK - 1)

    # ---------------------------------------------------------- helpers
    def reach(self, row: int) -> None:
        """Tell the view of every row up to ``row`` (and no further than the table)."""
        last = min(row, len(self.table) - 1)
        if last < self.fetched:
            return
        self.beginInsertRows(QModelIndex(), self.fetched, last)
        self.fetched = last + 1
        self.endInsertRows()

    def set_current(self, row: int) -> None:
        old, self.current = self.current, row
        for changed in (old, row):
            if 0 <= changed < self.fetched:
                self.dataChanged.emit(self.index(changed, 0),
                                      self.index(changed, self.columnCount() - 1))


class StepsView(QWidget):
    """The table, a line saying what it shows, and Copy / Save CSV buttons."""

    stepRequested = Signal(int)
    copyRequested = Signal(list)
    saveRequested = Signal()

    def __init__(self, parent=None):
        super().__init__(parent)
        self.model = StepsModel(self)
        self.view = QTableView(self)
        self.view.setObjectName("stepsView")
        self.view.setAccessibleName("Steps")
        self.view.setAccessibleDescription("One row per step: its line, pixel, choice and values")
        self.view.setModel(self.model)
        self.view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.view.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.view.setWordWrap(False)
        self.view.verticalHeader().hide()
        # Fixed row heights: the view never measures a million rows. One line
        # of text each, so that a dock of a third of the window shows a dozen.
        self.view.verticalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Fixed)
        self.view.verticalHeader().setDefaultSectionSize(self.view.fontMetrics().lineSpacing() + 6)
        self.view.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
        self.view.clicked.connect(lambda index: self.stepRequested.emit(index.row()))
        self.summary = QLabel(self)
        copy = QPushButton("Copy", self)
        copy.setToolTip("Copy the selected rows as CSV (Ctrl+C in the table)")
        copy.clicked.connect(self._copy)
        save = QPushButton("Save CSV…", self)
        save.setToolTip("Save every step as a CSV file")
        save.clicked.connect(self.saveRequested)
        QShortcut(QKeySequence.StandardKey.Copy, self.view, self._copy,
                  context=Qt.ShortcutContext.WidgetShortcut)
        buttons = QHBoxLayout()
        buttons.addWidget(self.summary, 1)
        buttons.addWidget(copy)
        buttons.addWidget(save)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(buttons)
        layout.addWidget(self.view)

    def set_table(self, table, why: str = "") -> None:
        self.model.set_table(table)
        if table is None:
            self.summary.setText(why)
            return
        # Numbered as the transport numbers them ("step 5 / 417"): from 0 to the last.
        self.summary.setText(f"steps 0 to {len(table) - 1:,}")
        self._size_columns()

    def follow(self, row: int) -> None:
        """Highlight step ``row`` and scroll it into view."""
        if self.model.table is None or not 0 <= row < len(self.model.table):
            return
        self.model.reach(row + self.model.BLOCK // 4)
        self.model.set_current(row)
        self.view.scrollTo(self.model.index(row, 0), QAbstractItemView.ScrollHint.EnsureVisible)

    def _copy(self) -> None:
        rows = sorted({index.row() for index in self.view.selectionModel().selectedRows()})
        if not rows and self.model.current >= 0:
            rows = [self.model.current]
        if rows:
            self.copyRequested.emit(rows)

    def _size_columns(self) -> None:
        # Fitted to the first and the last rows only (the widest step numbers and,
        # as a rule, pixels): measuring them all would make every row.
        # Measured in bold, as the row on show is drawn.
        bold = self.view.font()
        bold.setBold(True)
        metrics = QFontMetrics(bold)
        total = len(self.model.table)
        rows = sorted(set(range(min(32, total))) | set(range(max(0, total - 32), total)))
        sample = [self.model.table.text_row(i) for i in rows]
        for c, column in enumerate(self.model.table.columns):
            texts = [column.title] + [row[c] for row in sample]
            width = max(metrics.horizontalAdvance(t) for t in texts) + 16
            self.view.setColumnWidth(c, width if column.title == CODE_COLUMN
                                     else min(width, MAX_COLUMN))

    def rows_shown(self) -> int:
        """How many whole rows the table shows at its present height."""
        return self.view.viewport().height() // max(1, self.view.verticalHeader().defaultSectionSize())
