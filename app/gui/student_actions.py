"""File > Save algorithm template…, File > Open algorithm…, File > Export
worksheet… and Run > First divergence (D).

A template is the starting file of a student's own algorithm. A student's
file (a filled-in template) joins the algorithm
list as "FILE (yours)" and runs on the scene like a built-in algorithm, in
a separate process. The algorithm on show before it becomes its reference:
the grid's "compare with previous algorithm" marks the cells that differ,
View > Compare… can put it beside the exact result, and D jumps to the
first step where its pixels part from the reference's or the exact ones.
"""
from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QObject, Qt
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QFileDialog, QInputDialog

from algorithms.core import registry
from algorithms.core.errors import InputError
from app.model import shipped
from app.model.files import write_atomically



FILTERS = {"pdf": "PDF (*.pdf)", "md": "Markdown with PNG grids (*.md)",
           "tex": "LaTeX tabular (*.tex)", "csv": "CSV (*.csv)"}


def reference_names() -> list[str]:
    """The algorithms a student's file can be checked against."""
    from app.teaching import checking  # with the first student file, not the window
    names = []
    for spec in registry.all_specs():
        try:
            checking.kind_of(spec)
        except InputError:
            continue
        if not spec.name.startswith("student-"):
            names.append(spec.name)
    return names


class StudentActions(QObject):
    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.against: dict[str, str] = {}  # student algorithm -> its reference
        self.template_action = QAction("Save algorithm &template…", window)
        self.template_action.setToolTip("Save the starting file of your own line, circle, fill, "
                                        "... algorithm: a draw() generator to fill in")
        self.template_action.triggered.connect(lambda: self.save_template())
        self.open_action = QAction("Open &algorithm…", window)
        self.open_action.setToolTip("Run your own draw() generator (File > Save algorithm "
                                    "template… gives a start) on the scene and compare it with "
                                    "a built-in algorithm")
        self.open_action.triggered.connect(lambda: self.open())
        self.worksheet_action = QAction("Export &worksheet…", window)
        self.worksheet_action.setToolTip("Write the run's step table with blank columns, a grid "
                                         "to shade and the answer key (PDF, Markdown, LaTeX, CSV)")
        self.worksheet_action.triggered.connect(lambda: self.export_worksheet())
        quit_action = window.menus["file"].actions()[-1]
        window.menus["file"].insertAction(quit_action, self.template_action)
        window.menus["file"].insertAction(quit_action, self.open_action)
        window.menus["file"].insertAction(quit_action, self.worksheet_action)
        self.divergence_action = QAction("First &divergence", window)
        self.divergence_action.setShortcut(QKeySequence("D"))
        self.divergence_action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
        self.divergence_action.setToolTip("Jump to the first step where your algorithm's pixels "
                                          "differ from the reference's or the exact ones (D)")
        self.divergence_action.triggered.connect(lambda: self.first_divergence())
        window.menus["run"].addAction(self.divergence_action)
        window.addAction(self.divergence_action)

    def save_template(self, name: str | None = None, path: str | None = None) -> str | None:
        """Save a template where the student chooses; returns the path (None: cancelled)."""
        window = self.window
        found = shipped.templates()
        if name is None:
            titles = [f"{key}: {shipped.template_title(file)}" for key, file in found.items()]
            chosen, ok = QInputDialog.getItem(window, "Save algorithm template",
                                              "Template:", titles, 0, False)
            if not ok:
                return None
            name = chosen.split(":")[0]
        if path is None:
            path, _ = QFileDialog.getSaveFileName(window, "Save the template as", f"{name}.py",
                                                  "Python files (*.py)")
            if not path:
                return None
        try:
            write_atomically(Path(path), found[name].read_bytes())
        except OSError as error:
            window.say_error(f"Could not save the template: {error}")
            return None
        window.statusBar().showMessage(f"Saved the {name} template as {path}", 8000)
        return path

    def open(self, path: str | None = None, against: str | None = None) -> str | None:
        """Load a student's file; returns the new algorithm's name (None: cancelled or refused)."""
        window = self.window
        if path is None:
            path, _ = QFileDialog.getOpenFileName(
                window, "Open your algorithm", "", "Python files (*.py)")
            if not path:
                return None
        names = reference_names()
        if against is None:
            current = window.player.spec.name if window.player.spec else names[0]
            start = names.index(current) if current in names else 0
            against, ok = QInputDialog.getItem(window, "Check against",
                                               "Compare your algorithm with:", names, start, False)
            if not ok:
                return None
        from app.teaching.student_algorithm import student_spec
        try:
            spec = student_spec(path, against)
        except InputError as error:
            window.say_error(str(error))
            return None
        self.against[spec.name] = against
        window.picker.set_specs(registry.all_specs())
        if window.player.spec is None or window.player.spec.name != against:
            window.set_algorithm(against)
        window.set_algorithm(spec.name)
        window.picker.set_current(spec.name)
        return spec.name

    def export_worksheet(self, folder: str | None = None, fmt: str | None = None,
                         blank=None) -> list:
        """Write worksheet.FORMAT and answers.FORMAT for the scene on show; the
        files. Without a folder, dialogs ask for it and for the blank columns
        (``blank``; None: the default, every column but the step)."""
        window = self.window
        # Worksheets (and Pillow, which draws their grid) load on first use.
        from app.gui.worksheet_pdf import write_pdf
        from app.teaching import worksheet
        if folder is None:
            path, chosen = QFileDialog.getSaveFileName(
                window, "Export worksheet (a folder is made for it)", "worksheet",
                ";;".join(FILTERS.values()))
            if not path:
                return []
            folder, fmt = path, next(k for k, v in FILTERS.items() if v == chosen)
            blank = self._ask_blank(worksheet)
            if blank is None:
                return []
        try:
            sheet = worksheet.build(window.player.scene, blank)
            files = worksheet.write(sheet, folder, fmt or "pdf", write_pdf)
        except (InputError, OSError) as error:
            window.say_error(f"Could not export the worksheet: {error}")
            return []
        window.statusBar().showMessage(f"Wrote {', '.join(p.name for p in files)} in {folder}",
                                       8000)
        return files

    def _ask_blank(self, worksheet) -> list[str] | None:
        """The columns to leave blank, chosen in a dialog; None when cancelled."""
        from app.gui.worksheet_blanks import BlankColumns
        try:
            columns, default = worksheet.blank_choices(self.window.player.scene)
        except (InputError, OSError) as error:
            self.window.say_error(f"Could not export the worksheet: {error}")
            return None
        dialog = BlankColumns(columns, default, self.window)
        return dialog.chosen() if dialog.exec() else None

    def first_divergence(self) -> int | None:
        """Seek to the first divergence of the student's run on show; the step, or None."""
        window, player = self.window, self.window.player
        against = self.against.get(player.spec.name) if player.spec else None
        if against is None or player.trace is None:
            window.statusBar().showMessage("First divergence: open your algorithm first "
                                           "(File > Open algorithm…).", 5000)
            return None
        from app.teaching.student_algorithm import first_divergence
        step, text = first_divergence(player.trace, against, player.scene.points, player.options,
                                      player.grid)
        if step is not None:
            player.pause()
            player.seek(step)
        window.statusBar().showMessage(text, 10000)
        return step
