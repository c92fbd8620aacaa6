"""File > Export questions…: the dialog that asks what to export.

Display only: it is given the templates (name, title) and the formats, and
returns the choices; app/gui/question_actions.py draws and writes the bank.
"""
from __future__ import annotations

from PySide6.QtWidgets import (QCheckBox, QComboBox, QDialog, QDialogButtonBox, QFormLayout,
                               QHBoxLayout, QLineEdit, QPushButton, QSpinBox, QVBoxLayout,
                               QFileDialog, QLabel)

MAX_COUNT = 500
MAX_SEED = 2**31 - 1


class QuestionDialog(QDialog):
    def __init__(self, templates, formats, algorithm: str, parent=None):
        super().__init__(parent)
        self.setWindowTitle("Export questions")
        self.setAccessibleName("Export questions")
        layout = QVBoxLayout(self)
        intro = QLabel(f"Questions about {algorithm}: each variant's answer is computed by "
                       "running the algorithm; the same seed gives the same bank.", wordWrap=True)
        layout.addWidget(intro)
        form = QFormLayout()
        self.template = QComboBox()
        for name, title in templates:
            self.template.addItem(f"{title} ({name})", name)
        self.this_scene = QCheckBox("Ask about the scene on show")
        self.this_scene.setToolTip("Every variant asks about the points on the grid; the seed "
                                   "picks only the step or the pixel. Off: new numbers per variant")
        self.count = QSpinBox(minimum=1, maximum=MAX_COUNT, value=10)
        self.seed = QSpinBox(minimum=0, maximum=MAX_SEED, value=1)
        self.format = QComboBox()
        for name in formats:
            self.format.addItem(name, name)
        self.students = QLineEdit(placeholderText="optional: a CSV of student ids, one bank each")
        browse = QPushButton("Browse…")
        browse.setAccessibleName("Browse for the student ids file")
        browse.clicked.connect(self._browse)
        students_row = QHBoxLayout()
        students_row.addWidget(self.students)
        students_row.addWidget(browse)
        for label, widget in (("&Template", self.template), ("", self.this_scene),
                              ("&Variants", self.count), ("&Seed", self.seed),
                              ("&Format", self.format)):
            form.addRow(label, widget)
            if label:
                widget.setAccessibleName(label.replace("&", ""))
        students_label = QLabel("Per &student")
        students_label.setBuddy(self.students)  # a row of a layout takes no mnemonic itself
        form.addRow(students_label, students_row)
        self.students.setAccessibleName("Student ids file")
        layout.addLayout(form)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout.addWidget(buttons)

    def _browse(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, "Student ids", "", "CSV files (*.csv)")
        if path:
            self.students.setText(path)

    def choices(self) -> dict:
        return {"template": self.template.currentData(), "this_scene": self.this_scene.isChecked(),
                "count": self.count.value(), "seed": self.seed.value(),
                "format": self.format.currentData(), "students": self.students.text().strip()}
