"""The pseudo-code panel: the listing with the line being run marked, and
the algorithm's notes under it."""
from __future__ import annotations

from PySide6.QtCore import Qt, QTimer, Signal
from PySide6.QtGui import QBrush, QFont, QFontMetrics
from PySide6.QtWidgets import (QAbstractItemView, QFrame, QHeaderView, QLabel, QScrollArea,
                               QStyle, QTableWidget, QTableWidgetItem, QVBoxLayout, QWidget)

from .dirty import fill_own_background
from .panels import (CURRENT_EDGE, CURRENT_LINE, CURRENT_TEXT, LINE_NUMBER, NOTES_MAX_HEIGHT,
                     monospace_font)


class _WrappingTable(QTableWidget):
    """A table whose rows grow and shrink with its width, for wrapped text;
    ``rowsFitted`` says when the rows have their new heights."""

    rowsFitted = Signal()

    def resizeEvent(self, event):  # noqa: N802
        super().resizeEvent(event)
        self.resizeRowsToContents()
        self.rowsFitted.emit()


class CodePanel(QWidget):
    """An algorithm's pseudo-code with the current step's line marked,
    and the algorithm's notes under it. Long lines wrap under their text,
    clear of the line numbers."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.lines = _WrappingTable(0, 2, self)
        self.lines.setObjectName("codeLines")
        self.lines.setAccessibleName("Pseudo-code")
        self.lines.setAccessibleDescription("The algorithm's lines; the line the step runs is "
                                            "selected")
        self.lines.setFont(monospace_font())
        self.lines.horizontalHeader().setVisible(False)
        self.lines.verticalHeader().setVisible(False)
        self.lines.setShowGrid(False)
        self.lines.setWordWrap(True)
        self.lines.setTextElideMode(Qt.TextElideMode.ElideNone)  # wrapped, never cut
        self.lines.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.lines.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
        self.lines.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        # Its marked line moves every step; a scroll bar that comes or goes
        # as rows change height repaints the table alone.
        fill_own_background(self.lines, self.lines.viewport())
        self.lines.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.lines.setVerticalScrollMode(QAbstractItemView.ScrollMode.ScrollPerPixel)
        header = self.lines.horizontalHeader()
        # The numbers' column is as wide as the widest marked number, set
        # once per code (``_fit_numbers``): sized to its contents, it would
        # measure every row and rewrap them all on every step.
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.Fixed)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.Stretch)
        header.sectionResized.connect(lambda *_: self._fit_rows())
        # Rows change height as the panel narrows or widens (a dock opens
        # beside it): the marked line is brought back into view each time.
        self.lines.rowsFitted.connect(self._reveal_later)
        # The scroll range follows the heights later still.
        self.lines.verticalScrollBar().rangeChanged.connect(self._reveal_later)
        self.notes = QLabel()
        self.notes.setObjectName("codeNotes")
        self.notes.setWordWrap(True)
        self.notes.setTextFormat(Qt.TextFormat.PlainText)
        self.notes.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        # Long notes scroll rather than squeeze the code.
        self.notes_area = QScrollArea(self)
        self.notes_area.setWidget(self.notes)
        self.notes_area.setWidgetResizable(True)
        self.notes_area.setFrameShape(QFrame.Shape.NoFrame)
        self.notes_area.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 6, 6, 6)
        layout.setSpacing(6)
        layout.addWidget(self.lines, 1)
        layout.addWidget(self.notes_area)
        self._texts: tuple[str, ...] = ()
        self._current: int | None = None

    def set_code(self, texts, notes=()) -> None:
        """The lines (strings) and the notes shown under them."""
        texts = tuple(texts)
        if texts != self._texts:
            self._texts = texts
            self._current = None
            self.lines.setRowCount(len(texts))
            for row, text in enumerate(texts):
                number = QTableWidgetItem(f"  {row + 1}")
                number.setForeground(QBrush(LINE_NUMBER))
                number.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignTop)
                code = QTableWidgetItem(text)
                code.setTextAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
                code.setToolTip(text)
                self.lines.setItem(row, 0, number)
                self.lines.setItem(row, 1, code)
            self._fit_numbers()
            self.lines.resizeRowsToContents()
        self.notes.setText("\n".join(notes))
        self.notes_area.setVisible(bool(notes))
        self._fit_notes()

    def resizeEvent(self, event):  # noqa: N802
        super().resizeEvent(event)
        self._fit_notes()

    def _fit_notes(self) -> None:
        """As tall as the notes need, up to NOTES_MAX_HEIGHT and a third of
        the panel: on a short screen the code keeps most of the room."""
        width = max(50, self.notes_area.viewport().width())
        needed = self.notes.heightForWidth(width)
        if needed <= 0:
            needed = self.notes.sizeHint().height()
        room = max(40, self.height() // 3)
        self.notes_area.setFixedHeight(min(NOTES_MAX_HEIGHT, room, needed + 2))

    def set_current(self, line: int | None) -> None:
        """Mark line ``line`` (0-based), or none, and scroll it into view."""
        if line != self._current:
            if self._current is not None and self._current < self.lines.rowCount():
                self._paint(self._current, False)
            self._current = line
            if line is not None and 0 <= line < self.lines.rowCount():
                self._paint(line, True)
        self.reveal()

    def restyle(self) -> None:
        """The table's font changed (the window's zoom, presentation): the
        marked line carries a font of its own, so it is set again."""
        line = self._current
        if line is not None and 0 <= line < self.lines.rowCount():
            self._paint(line, True)
        self._fit_numbers()

    def _fit_numbers(self) -> None:
        """The numbers' column as wide as the last line's number marked
        (in bold, after the marker), in the table's type."""
        bold = QFont(self.lines.font())
        bold.setBold(True)
        last = str(max(1, len(self._texts)))
        text = max(QFontMetrics(bold).horizontalAdvance("\u25b6 " + last),
                   QFontMetrics(self.lines.font()).horizontalAdvance("  " + last))
        margin = self.lines.style().pixelMetric(QStyle.PixelMetric.PM_FocusFrameHMargin) + 1
        self.lines.setColumnWidth(0, text + 2 * margin + 4)

    def reveal(self) -> None:
        """Scroll the marked line (all of it, if it fits) into view."""
        line = self._current
        if line is not None and 0 <= line < self.lines.rowCount():
            self.lines.scrollToItem(self.lines.item(line, 1),
                                    QAbstractItemView.ScrollHint.EnsureVisible)

    def _fit_rows(self) -> None:
        self.lines.resizeRowsToContents()
        self._reveal_later()

    def _reveal_later(self) -> None:
        # After the layout has settled: heights change once more on the way.
        QTimer.singleShot(0, self, self.reveal)

    @property
    def current(self) -> int | None:
        return self._current

    def line_text(self, line: int) -> str:
        return self._texts[line]

    def _paint(self, row: int, current: bool) -> None:
        number, code = self.lines.item(row, 0), self.lines.item(row, 1)
        # The highlight is light in either theme: its text stays dark.
        code.setForeground(QBrush(CURRENT_TEXT) if current else QBrush())
        for item in (number, code):
            item.setBackground(QBrush(CURRENT_LINE) if current else QBrush())
            if current:
                font = QFont(self.lines.font())  # the table's, at the window's zoom
                font.setBold(True)
                item.setFont(font)
            else:
                # No font of its own: the line follows the table's as it zooms.
                item.setData(Qt.ItemDataRole.FontRole, None)
        number.setText(("\u25b6 " if current else "  ") + str(row + 1))
        number.setForeground(QBrush(CURRENT_EDGE if current else LINE_NUMBER))
        # Bold text is wider: the row wraps again rather than lose its end.
        self.lines.resizeRowToContents(row)
