"""The keyboard shortcuts sheet (Help > Keyboard shortcuts, F1)."""
from __future__ import annotations

from PySide6.QtWidgets import (QDialog, QDialogButtonBox, QHeaderView, QLabel, QTableWidget,
                               QTableWidgetItem, QVBoxLayout)

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
    ("Arrows, Shift+arrows (grid cursor)", "Move the cell cursor one cell, five cells (K or "
     "Tab to the grid turns it on; the arrows step the run again when it is off)"),
    ("Enter (grid cursor)", "Place the next point (the seed, with the seed tool); on a point, "
     "the seed or a circle's square handle: pick it up, move it with the arrows, Enter "
     "drops it, Esc puts it back"),
    ("Shift+Enter (grid cursor)", "Start a new contour at the cursor, as Shift+click does"),
    ("Enter or Space (a button)", "Press the button that Tab or F6 moved to (after a "
     "click, Space plays)"),
    ("Tab, Enter (vertex table)", "Next cell; typing replaces the value"),
    ("Insert, Delete (vertex table)", "Add a vertex after the selected one, remove it"),
    ("F2 (bookmarks)", "Rename the selected bookmark"),
    ("Esc (while recording)", "Cancel the recording; the previous run stays"),
)


class ShortcutsDialog(QDialog):
    def __init__(self, parent=None, rows=GESTURES):
        super().__init__(parent)
        self.setWindowTitle("Keyboard shortcuts")
        self.rows = list(rows)
        table = QTableWidget(len(self.rows), 2, self)
        table.setHorizontalHeaderLabels(["Key", "Action"])
        table.setAccessibleName("Keyboard shortcuts")
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
