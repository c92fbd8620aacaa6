"""File > Export questions… and the exercise's "Practice: new numbers".

Both draw from the question templates (app/teaching/questions): the export
writes a bank of seeded variants, for the algorithm on show, in a quiz
tool's format; practice shows the scene of a freshly drawn variant, so the
exercise starts again on new numbers.
"""
from __future__ import annotations

import random
from pathlib import Path

from PySide6.QtCore import QObject
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QDialog, QFileDialog

from algorithms.core.errors import InputError

FOLDER_FORMATS = ("prairielearn", "pdf", "md")  # written as a folder of files
SUFFIXES = {"moodle-xml": ".xml", "qti": ".zip", "gift": ".txt"}


class QuestionActions(QObject):
    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.export_action = QAction("Export q&uestions…", window)
        self.export_action.setToolTip("Write seeded variants of a question about this algorithm, "
                                      "with answer keys, for Moodle, Canvas, PrairieLearn or paper")
        self.export_action.triggered.connect(lambda: self.export_dialog())
        menu = window.menus["file"]
        menu.insertAction(menu.actions()[-1], self.export_action)
        window.exercise_mode.panel.practiceRequested.connect(lambda: self.practice())

    def templates(self) -> list:
        """The templates that ask about the algorithm on show (all, when none does)."""
        from app.teaching.questions import registry
        spec = self.window.player.spec
        found = registry.for_algorithm(spec.name) if spec is not None else []
        return found or list(registry.TEMPLATES.values())

    def export_dialog(self) -> list[Path] | None:
        from app.teaching.questions.writers import WRITERS
        from widgets.question_dialog import QuestionDialog
        spec = self.window.player.spec
        dialog = QuestionDialog([(t.name, t.title) for t in self.templates()], list(WRITERS),
                                spec.name if spec is not None else "no algorithm", self.window)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return None
        choices = dialog.choices()
        path = self._ask_path(choices["format"])
        return self.export(choices, path) if path else None

    def _ask_path(self, fmt: str) -> str:
        if fmt in FOLDER_FORMATS:
            return QFileDialog.getSaveFileName(self.window, "Export questions (a folder is made)",
                                               "questions")[0]
        suffix = SUFFIXES.get(fmt, "")
        return QFileDialog.getSaveFileName(self.window, "Export questions", "questions" + suffix,
                                           f"{fmt} (*{suffix})")[0]

    def export(self, choices: dict, path) -> list[Path] | None:
        """Draw the bank the choices name and write it; says what it wrote or why not."""
        from app.teaching.questions import bank
        from app.teaching.questions.writers import WRITERS
        scene = self.window.player.scene if choices["this_scene"] else None
        try:
            if choices["students"]:
                ids = bank.read_ids(choices["students"])
                drawn = bank.per_student([choices["template"]], choices["count"], ids,
                                         choices["seed"], scene)
            else:
                drawn = bank.draw([choices["template"]], choices["count"], choices["seed"],
                                  scene=scene)
            # The save dialog has asked before replacing a file.
            written = WRITERS[choices["format"]](drawn, Path(path), force=True)
        except (ValueError, InputError, OSError) as error:
            self.window.say_error(f"Could not export the questions: {error}")
            return None
        self.window.statusBar().showMessage(
            f"Wrote {len(written)} file(s) of questions to {path}", 8000)
        return written

    def practice(self, seed: int | None = None) -> bool:
        """Show the scene of a new variant for the algorithm on show; the
        exercise restarts on it (a new recording always restarts it)."""
        templates = self.templates()
        seed = random.SystemRandom().randrange(2**31) if seed is None else seed
        template = templates[seed % len(templates)]
        try:
            scene = template.make(seed).scene
            self.window.set_scene(scene.algorithm, scene.points, scene.options,
                                  (scene.width, scene.height))
        except (ValueError, InputError) as error:
            self.window.say_error(f"No new numbers for this algorithm: {error}")
            return False
        self.window.statusBar().showMessage(
            f"New numbers: {scene.algorithm} on {_points(scene.points)}", 8000)
        return True


def _points(points) -> str:
    flat = points[0] if points and isinstance(points[0][0], (list, tuple)) else points
    return " ".join(f"({x:g}, {y:g})" for x, y in flat)
