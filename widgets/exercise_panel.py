"""The exercise panel: shows a question, takes the answer, shows the grade.

Display only: it emits what the person did (an answer, a hint, undo, the
settings, save) and shows what it is given. The grading is app/teaching/exercise.py's.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, Qt, Signal
from PySide6.QtWidgets import (QComboBox, QFormLayout, QHBoxLayout, QLabel, QLineEdit,
                               QPushButton, QSpinBox, QVBoxLayout, QWidget)

FREQUENCY_TEXT = (("decision", "every decision"), ("step", "every step"),
                  ("scanline", "every scan line"), ("random", "random k %"))
ANSWER_TEXT = (("auto", "pixel, branch or span"), ("value", "the decision variable"))
RIGHT_COLOUR, WRONG_COLOUR = "#2b8a3e", "#c92a2a"


class AnswerEntry(QLineEdit):
    """A line edit that keeps Enter for itself: the window binds Return to
    closing a contour, which would take the key from it."""

    def event(self, event):
        if event.type() == QEvent.Type.ShortcutOverride and event.key() in (
                Qt.Key.Key_Return, Qt.Key.Key_Enter):
            event.accept()
            return True
        return super().event(event)


class ExercisePanel(QWidget):
    answered = Signal(object)      # a choice (str) or typed text (str, from the entry)
    typed = Signal(str)
    hintRequested = Signal()
    undoRequested = Signal()
    saveRequested = Signal()
    settingsChanged = Signal()
    studentNamed = Signal(str)     # the name typed in the Student field
    practiceRequested = Signal()   # "Practice: new numbers": a new scene drawn for the algorithm

    def __init__(self, parent=None):
        super().__init__(parent)
        layout = QVBoxLayout(self)
        self.note = QLabel(wordWrap=True)
        self.question = QLabel(wordWrap=True)
        self.question.setStyleSheet("font-weight: bold")
        self.choices = QHBoxLayout()
        entry_row = QHBoxLayout()
        self.entry = AnswerEntry(placeholderText="type the answer, then Enter")
        self.entry.setAccessibleName("Answer")
        self.entry.returnPressed.connect(self._typed)
        self.answer_button = QPushButton("Answer")
        self.answer_button.clicked.connect(self._typed)
        entry_row.addWidget(self.entry)
        entry_row.addWidget(self.answer_button)
        self.feedback = QLabel(wordWrap=True)
        self.score = QLabel("Score: 0 / 0")
        self.hint = QLabel(wordWrap=True)
        # Hint, Undo and Save first: nothing above them changes height, so
        # they stay where they are when feedback of any length appears.
        layout.addLayout(self._buttons())
        for widget in (self.note, self.question):
            layout.addWidget(widget)
        layout.addLayout(self.choices)
        layout.addLayout(entry_row)
        for widget in (self.feedback, self.score):
            layout.addWidget(widget)
        layout.addWidget(self.hint)
        layout.addLayout(self._settings())
        layout.addStretch(1)
        self._choice_buttons: list[QPushButton] = []

    def _buttons(self) -> QHBoxLayout:
        row = QHBoxLayout()
        self.hint_button = QPushButton("Hint")
        self.hint_button.setToolTip("Show the values that decide the next step")
        self.undo_button = QPushButton("Undo answer")
        self.save_button = QPushButton("Save summary…")
        self.save_button.setToolTip("Save every answer and the totals as CSV")
        self.practice_button = QPushButton("Practice: new numbers")
        self.practice_button.setToolTip("Start again on a new scene for this algorithm, drawn "
                                        "by the question generator")
        self.hint_button.clicked.connect(self.hintRequested)
        self.undo_button.clicked.connect(self.undoRequested)
        self.save_button.clicked.connect(self.saveRequested)
        self.practice_button.clicked.connect(self.practiceRequested)
        for button in (self.hint_button, self.undo_button, self.save_button,
                       self.practice_button):
            row.addWidget(button)
        return row

    def _settings(self) -> QFormLayout:
        form = QFormLayout()
        self.frequency = QComboBox()
        for key, text in FREQUENCY_TEXT:
            self.frequency.addItem(text, key)
        self.percent = QSpinBox(minimum=1, maximum=100, value=30, suffix=" %")
        self.answer_with = QComboBox()
        for key, text in ANSWER_TEXT:
            self.answer_with.addItem(text, key)
        form.addRow("Ask at", self.frequency)
        form.addRow("Random share", self.percent)
        form.addRow("Answer with", self.answer_with)
        self.student = QLineEdit(placeholderText="your name, then Enter")
        self.student.setToolTip("Recorded with every answer")
        self.student.editingFinished.connect(
            lambda: self.studentNamed.emit(self.student.text().strip()))
        form.addRow("Student", self.student)
        self.frequency.currentIndexChanged.connect(self._settings_changed)
        self.percent.valueChanged.connect(self._settings_changed)
        self.answer_with.currentIndexChanged.connect(self._settings_changed)
        self.percent.setEnabled(False)
        return form

    def _settings_changed(self, *_):
        self.percent.setEnabled(self.frequency.currentData() == "random")
        self.settingsChanged.emit()

    def settings(self) -> tuple[str, int, str]:
        return self.frequency.currentData(), self.percent.value(), self.answer_with.currentData()

    def _typed(self) -> None:
        text = self.entry.text().strip()
        if text:
            self.typed.emit(text)

    # ------------------------------------------------------------ showing
    def show_question(self, prompt: str, choices=(), typed: bool = False,
                      placeholder: str = "") -> None:
        self.question.setText(prompt)
        for button in self._choice_buttons:
            self.choices.removeWidget(button)
            button.deleteLater()
        self._choice_buttons = []
        for choice in choices:
            button = QPushButton(choice)
            button.setObjectName(f"choice-{choice}")
            button.clicked.connect(lambda _=False, c=choice: self.answered.emit(c))
            self.choices.addWidget(button)
            button.show()  # now, not when the layout next runs: the focus may go to it
            # Tab goes from the question's choices on to the entry, as they are laid out.
            QWidget.setTabOrder(self._choice_buttons[-1] if self._choice_buttons
                                else self.save_button, button)
            self._choice_buttons.append(button)
        if self._choice_buttons:
            QWidget.setTabOrder(self._choice_buttons[-1], self.entry)
        self.entry.clear()
        self.entry.setEnabled(typed)
        self.answer_button.setEnabled(typed)
        self.entry.setPlaceholderText(placeholder or "type the answer, then Enter")
        self.hint.clear()

    def focus_answer(self) -> None:
        """The keyboard to the first choice, else the entry when it is open."""
        first = self._choice_buttons[0] if self._choice_buttons else None
        if first is None and self.entry.isEnabled():
            first = self.entry
        if first is not None:
            first.setFocus(Qt.FocusReason.OtherFocusReason)

    def choice_button(self, choice: str) -> QPushButton | None:
        return next((b for b in self._choice_buttons if b.text() == choice), None)

    def show_feedback(self, text: str, right: bool | None) -> None:
        colour = "" if right is None else (RIGHT_COLOUR if right else WRONG_COLOUR)
        self.feedback.setStyleSheet(f"color: {colour}" if colour else "")
        self.feedback.setText(text)

    def show_score(self, right: int, asked: int, left: int) -> None:
        self.score.setText(f"Score: {right} / {asked}   ({left} questions left)")

    def show_hint(self, rows) -> None:
        self.hint.setText(";  ".join(f"{name} = {value}" for name, value in rows))

    def show_note(self, text: str) -> None:
        self.note.setText(text)
        self.note.setVisible(bool(text))
