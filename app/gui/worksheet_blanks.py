"""File > Export worksheet…'s second question: which columns the student fills in.

``BlankColumns(columns, blank)`` is a dialog with a box per column of the
sheet, ticked for the columns left blank; it starts with the default
(app/teaching/worksheet.py: every column but the step, since each of the
others gives answers away). ``chosen()`` is the ticked columns.
"""
from __future__ import annotations

from PySide6.QtWidgets import QCheckBox, QDialog, QDialogButtonBox, QLabel, QVBoxLayout


class BlankColumns(QDialog):
    def __init__(self, columns, blank, parent=None):
        super().__init__(parent)
        self.setWindowTitle("Export worksheet: blank columns")
        layout = QVBoxLayout(self)
        layout.addWidget(QLabel("Columns the student fills in (left blank on the sheet; "
                                "the answer key fills them):", wordWrap=True))
        self.boxes = {}
        for column in columns:
            box = QCheckBox(column, checked=column in blank)
            box.setObjectName(f"blank-{column}")
            layout.addWidget(box)
            self.boxes[column] = box
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout.addWidget(buttons)

    def chosen(self) -> list[str]:
        return [column for column, box in self.boxes.items() if box.isChecked()]
