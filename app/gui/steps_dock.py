"""The "Steps" dock: the table of every step of the run on show.

``StepsDock(window)`` adds the dock (hidden until asked for, from View >
Steps table, Ctrl+T) and wires it to the player: the row of the step on
show is highlighted and followed; a click on a row goes to that step; Copy
puts the selected rows on the clipboard as CSV, Save CSV… writes every step.
The table is made only while the dock is on show, and its rows only as they
are painted.
"""
from __future__ import annotations

import csv
import io
from pathlib import Path

from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QGuiApplication, QKeySequence
from PySide6.QtWidgets import QFileDialog, QMessageBox

from widgets.docks import panel_dock
from widgets.steps_table import StepsView

from app.model.escape import csv_row
from app.model.files import write_atomically
from app.model.steptable import StepTable, write_csv


# Rows the table shows at least when it opens, if the window has the room
# (up to this share of its height); a smaller dock is a strip to squint at.
OPEN_ROWS = 12
OPEN_SHARE = 0.4


class StepsDock:
    """The dock, its View action, and what its buttons do."""

    def __init__(self, window):
        self.window = window
        self.table = None
        self.view = StepsView(window)
        self.dock = panel_dock("Steps", "stepsDock", self.view, window)
        window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, self.dock)
        self.dock.hide()
        self.action = self.dock.toggleViewAction()
        self.action.setText("Steps table")
        self.action.setShortcut(QKeySequence("Ctrl+T"))
        self.action.setToolTip("Every step of the run in a table: line, pixel, choice and "
                               "variables (Ctrl+T)")
        window.addAction(self.action)
        window.menus["view"].addAction(self.action)
        player = window.player
        player.frameChanged.connect(lambda _index: self.follow())
        player.traceChanged.connect(self._trace_changed)
        self.view.stepRequested.connect(self._go)
        self.view.copyRequested.connect(self.copy)
        self.view.saveRequested.connect(self.save)
        self.dock.visibilityChanged.connect(self._visibility_changed)

    def _visibility_changed(self, visible: bool) -> None:
        if visible:
            self.refresh()
            QTimer.singleShot(0, self.window, self.open_size)

    def open_size(self) -> None:
        """Make the dock tall enough for OPEN_ROWS rows (or OPEN_SHARE of the
        window, whichever is less); a dock already taller keeps its height."""
        if not self.dock.isVisible() or self.dock.isFloating():
            return
        row = self.view.view.verticalHeader().defaultSectionSize()
        if self.view.rows_shown() >= OPEN_ROWS:
            return
        around = self.dock.height() - self.view.view.viewport().height()
        wanted = min(OPEN_ROWS * row + around, int(self.window.height() * OPEN_SHARE))
        if wanted > self.dock.height():
            self.window.resizeDocks([self.dock], [wanted], Qt.Orientation.Vertical)

    def _trace_changed(self) -> None:
        self.table = None
        self.refresh()

    def refresh(self) -> None:
        """Show the table of the trace on show (made now if it is not yet)."""
        if not self.dock.isVisible():
            return
        trace = self.window.player.trace
        if trace is None:
            self.view.set_table(None, "No run: place the points first.")
            return
        numbers = self.window.numbers_shown  # View > Exact fractions
        if self.table is None or self.table.trace is not trace or self.table.numbers != numbers:
            self.table = StepTable(trace, numbers)
            self.view.set_table(self.table)
        self.follow()

    def follow(self) -> None:
        if self.dock.isVisible() and self.table is not None:
            self.view.follow(self.window.player.index)

    def _go(self, row: int) -> None:
        self.window.player.pause()
        self.window.player.seek(row)

    def copy(self, rows: list[int]) -> str:
        """The heading and the given rows as CSV, put on the clipboard."""
        text = io.StringIO()
        writer = csv.writer(text, lineterminator="\n")
        writer.writerow(csv_row(column.title for column in self.table.columns))
        for row in rows:
            writer.writerow(csv_row(self.table.text_row(row)))
        QGuiApplication.clipboard().setText(text.getvalue())
        return text.getvalue()

    def save(self, path: str | None = None) -> bool:
        """Write every step as CSV to ``path`` (asked for when not given)."""
        if self.table is None:
            return False
        if path is None:
            path, _ = QFileDialog.getSaveFileName(self.window, "Save the steps as CSV",
                                                  "steps.csv", "CSV files (*.csv)")
            if not path:
                return False
        text = io.StringIO()
        write_csv(self.table, text)
        try:
            write_atomically(Path(path), text.getvalue().encode("utf-8"))
        except OSError as error:
            QMessageBox.warning(self.window, "Save the steps",
                                f"The steps were not saved: {error}")
            return False
        return True
