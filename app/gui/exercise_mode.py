"""Run > Exercise: predict each next step of the run on show, graded at once.

``ExerciseMode(window)`` adds the checkable action and the "Exercise" dock.
While it is on, the grid shows the run only up to the step before the
current question (stepping further is held back), a click on the grid
answers a pixel or span question instead of drawing, and the panel takes
branch choices and typed values. The questions and grading are
app/teaching/exercise.py's; a new recording (the scene edited or undone, the
origin switched) starts the exercise again on the new run, and says so,
naming the algorithm when that was switched.

The student's name is asked once (the panel's Student field, remembered in
the settings); the questions wait for it. Every answer and every undo is
appended, as it happens, to exercise-attempts.csv in the program's data
folder (app/teaching/attempts.py), with the name, scene, algorithm and time.
"""
from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QApplication, QFileDialog

from widgets.docks import panel_dock
from widgets.exercise_panel import ExercisePanel

from app.gui.appdata import data_dir, open_settings
from app.teaching.attempts import FILE_NAME, AttemptLog
from app.teaching.exercise import Exercise
from app.model.files import write_atomically

STUDENT_KEY = "exercise/student"
PLACEHOLDERS = {"value": "the value, e.g. -3", "span": "or type: first, last",
                "pixel": "or type: x, y"}


class ExerciseMode(QObject):
    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.exercise: Exercise | None = None
        self.span_start = None
        self._holding = False
        self._variables_shown = True
        self.panel = ExercisePanel(window)
        self.dock = panel_dock("Exercise", "exerciseDock", self.panel, window)
        window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.dock)
        self.dock.hide()
        self.action = QAction("E&xercise", window, checkable=True)
        self.action.setToolTip("Predict each next step before it is shown: "
                               "click the pixel, choose the branch or type the value")
        self.action.toggled.connect(self.set_active)
        window.menus["run"].addSeparator()
        window.menus["run"].addAction(self.action)
        self.panel.answered.connect(self.answer)
        self.panel.typed.connect(self.answer_typed)
        self.panel.hintRequested.connect(self.hint)
        self.panel.undoRequested.connect(self.undo)
        self.panel.saveRequested.connect(self.save)
        self.panel.settingsChanged.connect(self.restart)
        self.panel.studentNamed.connect(self.set_student)
        self.panel.student.setText(self.student)
        self.log = AttemptLog(data_dir() / FILE_NAME)
        self._log_failed = False
        window.player.traceChanged.connect(self._trace_changed)
        window.player.frameChanged.connect(self._hold_back)
        window.grid.viewport().installEventFilter(self)

    @property
    def active(self) -> bool:
        """On (Run > Exercise checked), the questions asked or waiting for the name."""
        return self.action.isChecked()

    def set_active(self, on: bool) -> None:
        self.dock.setVisible(on)
        # The variables panel plots the decision variable over the whole run
        # and the steps table lists every step to come: either would give the
        # answers away, so they are put aside meanwhile (and cannot be opened).
        docks = self._revealing_docks()
        if on:
            self._shown = {dock: dock.isVisible() for dock in docks}
            for dock in docks:
                dock.hide()
                dock.toggleViewAction().setEnabled(False)
            self.restart()
        else:
            self.exercise = None
            for dock in docks:
                dock.toggleViewAction().setEnabled(True)
                dock.setVisible(getattr(self, "_shown", {}).get(dock, False))

    def _revealing_docks(self) -> list:
        steps = getattr(self.window, "steps", None)
        return [self.window.variables_dock] + ([steps.dock] if steps is not None else [])

    @property
    def student(self) -> str:
        return str(open_settings().value(STUDENT_KEY, "") or "").strip()

    def set_student(self, name: str) -> None:
        """The name typed in the panel: remembered; the questions start if they waited."""
        if not name or name == self.student and self.exercise is not None:
            return
        settings = open_settings()
        settings.setValue(STUDENT_KEY, name)
        settings.sync()
        self.restart(f"Answers are recorded for {name}.")

    def _scene(self) -> str:
        files = self.window.file_actions
        if files is not None and files.path is not None:
            return str(files.path)
        return "unsaved: " + " ".join(f"({x:g}, {y:g})" for x, y in self.window.player.points)

    def restart(self, message: str = "") -> None:
        if not self.action.isChecked():
            return
        trace = self.window.player.trace
        if not self.student:
            self.exercise = None
            if trace is not None:
                self._show(0)  # the run's end would show every answer meanwhile
            self.panel.show_question("Type your name in the Student field below, then Enter: "
                                     "it is recorded with every answer.")
            self.panel.student.setFocus()
            return
        if trace is None:
            self.exercise = None
            self.panel.show_question("The run is still being recorded: start the exercise "
                                     "again when it is done.")
            return
        frequency, percent, answer_with = self.panel.settings()
        spec = self.window.player.spec
        context = {"student": self.student, "scene": self._scene(), "algorithm": spec.name}
        self.exercise = Exercise(trace, frequency, percent, answer_with,
                                 explain=spec.explain, context=context)
        self.panel.show_note(self.exercise.note())
        self.panel.show_feedback(message, None)
        self._ask()

    def _trace_changed(self) -> None:
        if not self.action.isChecked():
            return
        before = None if self.exercise is None else self.exercise.context["algorithm"]
        now = self.window.player.spec.name
        kept = "" if self.exercise is None or not self.exercise.attempts else (
            " (the answers given so far stay in the record)")
        if before is not None and before != now:
            message = (f"The algorithm changed from {before} to {now}: "
                       f"the exercise starts again on {now}{kept}.")
            self.window.statusBar().showMessage(message, 8000)
        else:
            message = f"The run changed: the exercise starts again{kept}."
        self.restart(message)

    # ------------------------------------------------------------ asking
    def _ask(self) -> None:
        exercise = self.exercise
        self.span_start = None
        self._show(exercise.reveal_until())
        right, asked = exercise.score
        self.panel.show_score(right, asked, len(exercise.questions) - asked)
        question = exercise.current
        if question is None:
            summary = exercise.summary()
            missed = ", ".join(map(str, summary["missed"])) or "none"
            self.panel.show_question(
                f"Done: {summary['right']} of {summary['asked']} right in "
                f"{summary['seconds']:.0f} s. Steps missed: {missed}. Save the summary as CSV, "
                "or change a setting to start again.")
            return
        typed = question.kind in PLACEHOLDERS
        focus = QApplication.focusWidget()
        answering = focus is not None and self.panel.isAncestorOf(focus)
        self.panel.show_question(question.prompt, question.choices, typed,
                                 PLACEHOLDERS.get(question.kind, ""))
        if answering:  # the keyboard to the new question's first choice or the entry
            self.panel.focus_answer()

    def _show(self, index: int) -> None:
        self._holding = True
        try:
            self.window.player.pause()
            self.window.player.seek(max(0, index))
        finally:
            self._holding = False

    def _hold_back(self, index: int) -> None:
        """Stepping past the question would show its answer: stay before it."""
        if self.exercise is None or self._holding or self.exercise.finished:
            return
        if index > self.exercise.reveal_until():
            self._show(self.exercise.reveal_until())
            self.window.statusBar().showMessage("Answer the question first (Run > Exercise).",
                                                4000)

    # ----------------------------------------------------------- answers
    def answer(self, given) -> None:
        if self.exercise is None or self.exercise.finished:
            return
        grade = self.exercise.answer(given)
        self._record(grade, "answer")
        self.panel.show_feedback(grade.text(), grade.right)
        self._ask()

    def answer_typed(self, text: str) -> None:
        question = None if self.exercise is None else self.exercise.current
        if question is None:
            return
        if question.kind in ("pixel", "span"):
            parts = [part.strip() for part in text.replace("..", ",").split(",")]
            try:
                self.answer(tuple(int(part) for part in parts))
            except ValueError:
                self.panel.show_feedback(f"{text!r}: type two whole numbers such as 3, 7", None)
            return
        self.answer(text)

    def clicked(self, pixel) -> None:
        """A click on the grid: a pixel answer, or one end of a span."""
        question = None if self.exercise is None else self.exercise.current
        if question is None:
            return
        if question.kind == "pixel":
            self.answer(pixel)
        elif question.kind == "span":
            if self.span_start is None:
                self.span_start = pixel[0]
                self.panel.show_feedback(f"First pixel: x = {pixel[0]}; now click the last.", None)
            else:
                first, self.span_start = self.span_start, None
                self.answer((min(first, pixel[0]), max(first, pixel[0])))
        else:
            self.panel.show_feedback("Answer with the buttons of the panel.", None)

    def eventFilter(self, watched, event) -> bool:
        """While the exercise is on, a left click on the grid answers, and draws nothing."""
        if self.exercise is None or event.type() not in (
                QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonRelease,
                QEvent.Type.MouseButtonDblClick):
            return False
        if event.button() != Qt.MouseButton.LeftButton:
            return False
        if event.type() == QEvent.Type.MouseButtonPress:
            grid = self.window.grid
            self.clicked(grid.pixel_at(grid.mapToScene(event.position().toPoint())))
        return True

    def _record(self, grade, event: str) -> None:
        try:
            self.log.append(self.exercise.row(grade, event))
        except OSError as error:
            if not self._log_failed:  # said once, not at every answer
                self.window.say_error(f"Could not record the answer in {self.log.path}: "
                                      f"{error.strerror or error}")
            self._log_failed = True

    def undo(self) -> None:
        grade = None if self.exercise is None else self.exercise.undo()
        if grade is None:
            return
        self._record(grade, "undo")
        self.panel.show_feedback("The last answer was taken back; it stays in the record, "
                                 "and the question is asked again.", None)
        self._ask()

    def hint(self) -> None:
        if self.exercise is not None:
            self.panel.show_hint(self.exercise.hint())

    def save(self, path: str | None = None) -> None:
        if self.exercise is None:
            return
        if path is None:
            path, _ = QFileDialog.getSaveFileName(self.window, "Save the exercise summary",
                                                  "exercise.csv", "CSV files (*.csv)")
            if not path:
                return
        try:
            write_atomically(Path(path), self.exercise.csv_text().encode("utf-8"))
        except OSError as error:
            self.window.say_error(f"Could not save {path}: {error.strerror or error}")
            return
        self.window.statusBar().showMessage(f"Saved {path}", 4000)
