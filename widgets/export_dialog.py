"""The export dialog: which steps, how fast, how large, what is drawn, where.

The dialog only collects choices and shows progress. Whoever opens it runs
the export: it listens to ``exportRequested`` and ``cancelRequested``, reads
``values()``, and reports back with ``set_progress``, ``set_running`` and
``set_message``.
"""
from __future__ import annotations

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (QButtonGroup, QCheckBox, QComboBox, QDialog, QDoubleSpinBox,
                               QFileDialog, QFormLayout, QGridLayout, QGroupBox, QHBoxLayout,
                               QLabel, QLineEdit, QProgressBar, QPushButton, QRadioButton,
                               QSpinBox, QVBoxLayout, QWidget)

RANGES = ("all", "current", "custom")
PANELS = (("auto", "Automatic (pseudo-code where it fits)"), ("code", "Pseudo-code"),
          ("variables", "Variables"), ("both", "Pseudo-code and variables"),
          ("tables", "Tables (ET and AET)"), ("none", "None"))
UNITS = (("auto", "Automatic"), ("step", "Step"), ("decision", "Decision"),
         ("pixel", "Pixel written"), ("scanline", "Scan line"), ("primitive", "Primitive"))
THEMES = (("light", "Light"), ("dark", "Dark"))
PER = (("auto", "Automatic"), ("step", "Step"), ("animation", "Animation frame"))
# The further formats: (key, label, placeholder, file filter; None for a folder).
MORE_OUTPUTS = (
    ("mp4", "MP4 video", "optional: video.mp4 (H.264, for slides)", "MP4 video (*.mp4)"),
    ("webm", "WebM video", "optional: video.webm", "WebM video (*.webm)"),
    ("pdf", "PDF", "optional: frames.pdf (a vector page per frame)", "PDF (*.pdf)"),
    ("svg_dir", "SVG frames", "optional: a folder for frame_0000.svg, ...", None),
    ("html", "Interactive page", "optional: run.html (opens in any browser)", "Web page (*.html)"),
)


def _label(text: str, buddy, parent) -> QLabel:
    """A label whose Alt+letter takes the keyboard to ``buddy``."""
    label = QLabel(text, parent)
    label.setBuddy(buddy)
    return label


class ExportDialog(QDialog):
    """Choices for exporting the run on show as an animated GIF (and,
    optionally, numbered PNG frames)."""

    #: The person pressed Export.
    exportRequested = Signal()
    #: The person pressed Cancel while an export runs.
    cancelRequested = Signal()
    #: A choice changed (to update the summary line).
    changed = Signal()

    def __init__(self, parent=None, max_fps: float = 50.0, max_scale: int = 64,
                 max_hold: float = 600.0):
        super().__init__(parent)
        self.setWindowTitle("Export animation")
        self.setObjectName("exportDialog")
        self._running = False
        self._last = 0
        self._current = 0

        steps = self._steps_box()
        timing = self._timing_box(max_fps, max_scale, max_hold)
        drawn = self._drawn_box()
        output = self._output_box()
        buttons = self._buttons()
        main = QVBoxLayout(self)
        top = QHBoxLayout()
        left, right = QVBoxLayout(), QVBoxLayout()
        left.addWidget(steps)
        left.addWidget(timing)
        right.addWidget(drawn)
        right.addWidget(output)
        top.addLayout(left)
        top.addLayout(right)
        main.addLayout(top)
        main.addWidget(self.size_label)
        main.addWidget(self.progress)
        main.addWidget(self.message)
        main.addLayout(buttons)
        self._inputs: list[QWidget] = [steps, timing, drawn, output]
        self._connect_changes()

    def _steps_box(self) -> QGroupBox:
        """Which steps: all, from the current one, a range or two bookmarks."""
        steps = QGroupBox("Steps", self)
        self.range_all = QRadioButton("All steps", steps)
        self.range_current = QRadioButton("From the current step to the end", steps)
        self.range_custom = QRadioButton("From", steps)
        self.range_all.setChecked(True)
        self.range_group = QButtonGroup(self)
        for button in (self.range_all, self.range_current, self.range_custom):
            self.range_group.addButton(button)
        self.first = QSpinBox(steps)
        self.last = QSpinBox(steps)
        for box in (self.first, self.last):
            box.setRange(0, 0)
            box.setAccelerated(True)
        self.first.valueChanged.connect(lambda v: self.range_custom.setChecked(True))
        self.last.valueChanged.connect(lambda v: self.range_custom.setChecked(True))
        custom = QHBoxLayout()
        custom.addWidget(self.range_custom)
        custom.addWidget(self.first)
        custom.addWidget(QLabel("to", steps))
        custom.addWidget(self.last)
        custom.addStretch(1)
        layout = QVBoxLayout(steps)
        layout.addWidget(self.range_all)
        layout.addWidget(self.range_current)
        layout.addLayout(custom)
        self._bookmark_row(steps, layout)
        self._per_row(steps, layout)
        return steps

    def _bookmark_row(self, steps, layout) -> None:
        """The scene's bookmarks as ends of the range (shown when it has any)."""
        self.mark_first = QComboBox(steps)
        self.mark_last = QComboBox(steps)
        self.mark_first.setToolTip("Start the range at a bookmark of the scene")
        self.mark_last.setToolTip("End the range at a bookmark of the scene (included)")
        self.mark_first.activated.connect(lambda _i: self._mark_chosen(self.mark_first, self.first))
        self.mark_last.activated.connect(lambda _i: self._mark_chosen(self.mark_last, self.last))
        self.marks_row = QWidget(steps)
        marks = QHBoxLayout(self.marks_row)
        marks.setContentsMargins(0, 0, 0, 0)
        marks.addWidget(QLabel("Bookmarks", self.marks_row))
        marks.addWidget(self.mark_first)
        marks.addWidget(QLabel("to", self.marks_row))
        marks.addWidget(self.mark_last)
        marks.addStretch(1)
        layout.addWidget(self.marks_row)
        self.marks_row.hide()

    def _per_row(self, steps, layout) -> None:
        """One frame per step or per animation frame."""
        self.per = QComboBox(steps)
        for key, text in PER:
            self.per.addItem(text, key)
        self.per.setToolTip("Step: one frame per step of the run. Animation frame: one frame "
                            "per frame of an animated run (aa-temporal), each fully drawn. "
                            "Automatic: animation frames where the run has them.")
        per_row = QHBoxLayout()
        per_row.addWidget(QLabel("One frame per", steps))
        per_row.addWidget(self.per)
        self.unit = QComboBox(steps)
        for key, text in UNITS:
            self.unit.addItem(text, key)
        self.unit.setToolTip("What a frame stands for. Automatic: every step of a short run; "
                             "for a long one the finest unit that keeps it within 240 frames.")
        per_row.addWidget(QLabel("unit", steps))
        per_row.addWidget(self.unit)
        per_row.addStretch(1)
        layout.addLayout(per_row)

    def _timing_box(self, max_fps, max_scale, max_hold) -> QGroupBox:
        """Speed, the hold of the last frame, the scale, looping."""
        timing = QGroupBox("Timing and size", self)
        self.fps = QDoubleSpinBox(timing)
        self.fps.setRange(0.1, max_fps)
        self.fps.setDecimals(1)
        self.fps.setValue(4.0)
        self.fps.setSuffix(" frames/s")
        self.hold = QDoubleSpinBox(timing)
        self.hold.setRange(0.0, max_hold)
        self.hold.setDecimals(1)
        self.hold.setValue(2.0)
        self.hold.setSuffix(" s")
        self.hold.setToolTip("Extra time the last frame stays on screen")
        self.scale = QSpinBox(timing)
        self.scale.setRange(1, max_scale)
        self.scale.setValue(16)
        self.scale.setSuffix(" px per cell")
        self.loop = QCheckBox("Loop forever (otherwise play once)", timing)
        self.loop.setChecked(True)
        self.size_label = QLabel(timing)
        self.size_label.setObjectName("summary")
        form = QFormLayout(timing)
        form.addRow("Speed", self.fps)
        form.addRow("Hold last frame", self.hold)
        form.addRow("Scale", self.scale)
        form.addRow("", self.loop)
        return timing

    def _drawn_box(self) -> QGroupBox:
        """What is drawn into the frames."""
        drawn = QGroupBox("Drawn into the frames", self)
        self.grid_lines = QCheckBox("Grid lines", drawn)
        self.primitive = QCheckBox("Ideal primitive", drawn)
        self.highlight = QCheckBox("Current and candidate pixels", drawn)
        self.caption = QCheckBox("Caption: step, pseudo-code line, values", drawn)
        self.reasoning = QCheckBox("Reasoning: scan line, midpoint M, samples", drawn)
        self.axes = QCheckBox("Axes with coordinates", drawn)
        self.vertex_labels = QCheckBox("Vertex labels", drawn)
        for box in (self.grid_lines, self.primitive, self.highlight, self.caption,
                    self.reasoning):
            box.setChecked(True)
        self.text_size = QSpinBox(drawn)
        self.text_size.setRange(0, 96)
        self.text_size.setSpecialValueText("Automatic")
        self.text_size.setSuffix(" px")
        self.panel = QComboBox(drawn)
        for key, text in PANELS:
            self.panel.addItem(text, key)
        self.theme = QComboBox(drawn)
        for key, text in THEMES:
            self.theme.addItem(text, key)
        grid = QGridLayout(drawn)
        grid.addWidget(self.grid_lines, 0, 0)
        grid.addWidget(self.primitive, 0, 1)
        grid.addWidget(self.highlight, 1, 0)
        grid.addWidget(self.caption, 1, 1)
        grid.addWidget(self.reasoning, 2, 0)
        grid.addWidget(self.axes, 2, 1)
        grid.addWidget(self.vertex_labels, 3, 0)
        grid.addWidget(QLabel("Side panel", drawn), 4, 0)
        grid.addWidget(self.panel, 4, 1)
        grid.addWidget(QLabel("Theme", drawn), 5, 0)
        grid.addWidget(self.theme, 5, 1)
        grid.addWidget(QLabel("Text size", drawn), 6, 0)
        grid.addWidget(self.text_size, 6, 1)
        QWidget.setTabOrder(self.theme, self.text_size)  # made before them, shown under them
        return drawn

    def _output_box(self) -> QGroupBox:
        """Where: the GIF file and an optional folder of PNG frames."""
        output = QGroupBox("Output", self)
        self.path = QLineEdit(output)
        self.path.setPlaceholderText("animation.gif")
        self.browse = QPushButton("Browse\u2026", output)
        self.browse.clicked.connect(self._choose_gif)
        self.frames_dir = QLineEdit(output)
        self.frames_dir.setPlaceholderText("optional: a folder for frame_0000.png, ...")
        self.browse_frames = QPushButton("Browse\u2026", output)
        self.browse_frames.clicked.connect(self._choose_folder)
        where = QGridLayout(output)
        where.addWidget(_label("&GIF file", self.path, output), 0, 0)
        where.addWidget(self.path, 0, 1)
        where.addWidget(self.browse, 0, 2)
        where.addWidget(_label("P&NG frames", self.frames_dir, output), 1, 0)
        where.addWidget(self.frames_dir, 1, 1)
        where.addWidget(self.browse_frames, 1, 2)
        self.more: dict[str, QLineEdit] = {}
        for row, (key, label, placeholder, pattern) in enumerate(MORE_OUTPUTS, 2):
            edit = self.more[key] = QLineEdit(output)
            edit.setPlaceholderText(placeholder)
            browse = QPushButton("Browse\u2026", output)
            browse.clicked.connect(lambda _=False, e=edit, t=label, p=pattern: self._choose(e, t, p))
            where.addWidget(QLabel(label, output), row, 0)
            where.addWidget(edit, row, 1)
            where.addWidget(browse, row, 2)
        self.transcript = QCheckBox("Transcript: the steps in words beside the GIF (.txt) "
                                    "and the videos (.vtt captions)", output)
        self.transcript.setToolTip("For a person who cannot see the pictures: each exported "
                                   "step described in words, in a file beside the animation")
        self.transcript.setChecked(True)
        where.addWidget(self.transcript, len(MORE_OUTPUTS) + 2, 0, 1, 3)
        return output

    def _choose(self, edit: QLineEdit, title: str, pattern: str | None) -> None:
        if pattern is None:
            path = QFileDialog.getExistingDirectory(self, title, edit.text())
        else:
            path, _ = QFileDialog.getSaveFileName(self, title, edit.text(), pattern)
            suffix = pattern[pattern.index("*") + 1:-1]
            if path and not path.lower().endswith(suffix):
                path += suffix
        if path:
            edit.setText(path)

    def _buttons(self) -> QHBoxLayout:
        """Progress, the message line and the Export, Cancel and Close buttons."""
        self.progress = QProgressBar(self)
        self.progress.setRange(0, 1)
        self.progress.setValue(0)
        self.progress.setTextVisible(True)
        self.message = QLabel(self)
        self.message.setObjectName("exportMessage")
        self.message.setWordWrap(True)
        self.message.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.export_button = QPushButton("Export", self)
        self.export_button.setDefault(True)
        self.export_button.clicked.connect(self._export_clicked)
        self.cancel_button = QPushButton("Cancel", self)
        self.cancel_button.setEnabled(False)
        self.cancel_button.clicked.connect(self.cancelRequested.emit)
        self.close_button = QPushButton("Close", self)
        self.close_button.clicked.connect(self.reject)
        buttons = QHBoxLayout()
        buttons.addStretch(1)
        buttons.addWidget(self.export_button)
        buttons.addWidget(self.cancel_button)
        buttons.addWidget(self.close_button)
        return buttons

    def _connect_changes(self) -> None:
        """Every choice that changes what is exported emits ``changed``."""
        def changed(*_args):
            self.changed.emit()

        for box in (self.first, self.last, self.scale, self.fps, self.hold, self.text_size):
            box.valueChanged.connect(changed)
        for button in (self.range_all, self.range_current, self.range_custom, self.loop,
                       self.grid_lines, self.primitive, self.highlight, self.caption,
                       self.reasoning, self.axes, self.vertex_labels):
            button.toggled.connect(changed)
        for combo in (self.panel, self.theme, self.per, self.unit):
            combo.currentIndexChanged.connect(changed)

    # ------------------------------------------------------------ set-up
    def set_steps(self, current: int, last: int) -> None:
        """The run's current step and its last step."""
        self._current, self._last = int(current), int(last)
        for box in (self.first, self.last):
            box.blockSignals(True)
            box.setRange(0, self._last)
            box.blockSignals(False)
        self.first.blockSignals(True)
        self.last.blockSignals(True)
        self.first.setValue(self._current)
        self.last.setValue(self._last)
        self.first.blockSignals(False)
        self.last.blockSignals(False)
        self.range_current.setText(f"From the current step ({self._current}) to the end "
                                   f"({self._last})")
        self.range_all.setText(f"All steps (0 to {self._last})")

    def set_bookmarks(self, bookmarks) -> None:
        """The scene's bookmarks ({"name", "step"}), offered as range ends;
        those past the last step are left out."""
        marks = [(str(m["name"]), int(m["step"])) for m in bookmarks
                 if 0 <= int(m["step"]) <= self._last]
        for combo in (self.mark_first, self.mark_last):
            combo.clear()
            combo.addItem("(choose)", None)
            for name, step in marks:
                combo.addItem(f"{name} (step {step})", step)
        self.marks_row.setVisible(bool(marks))

    def _mark_chosen(self, combo: QComboBox, box: QSpinBox) -> None:
        step = combo.currentData()
        if step is not None:
            box.setValue(step)
            self.range_custom.setChecked(True)

    def set_size_text(self, text: str) -> None:
        self.size_label.setText(text)

    # ------------------------------------------------------------ values
    def values(self) -> dict:
        """The choices: plain values, steps as numbers."""
        if self.range_current.isChecked():
            first, last, kind = self._current, self._last, "current"
        elif self.range_custom.isChecked():
            first, last, kind = self.first.value(), self.last.value(), "custom"
        else:
            first, last, kind = 0, self._last, "all"
        return {
            "range": kind, "first": first, "last": last,
            "fps": self.fps.value(), "hold": self.hold.value(), "scale": self.scale.value(),
            "loop": self.loop.isChecked(), "grid_lines": self.grid_lines.isChecked(),
            "primitive": self.primitive.isChecked(), "highlight": self.highlight.isChecked(),
            "caption": self.caption.isChecked(), "panel": self.panel.currentData(),
            "theme": self.theme.currentData(), "gif": self.path.text().strip(),
            "frames_dir": self.frames_dir.text().strip(), "per": self.per.currentData(),
            "unit": self.unit.currentData(), "reasoning": self.reasoning.isChecked(),
            "axes": self.axes.isChecked(), "vertex_labels": self.vertex_labels.isChecked(),
            "text_size": self.text_size.value() or None,
            "transcript": self.transcript.isChecked(),
            **{key: edit.text().strip() for key, edit in self.more.items()},
        }

    def set_values(self, values: dict) -> None:
        """Set any of the choices ``values()`` returns (the range excepted)."""
        for name, box in (("fps", self.fps), ("hold", self.hold), ("scale", self.scale)):
            if name in values:
                box.setValue(values[name])
        for name, box in (("loop", self.loop), ("grid_lines", self.grid_lines),
                          ("primitive", self.primitive), ("highlight", self.highlight),
                          ("caption", self.caption), ("reasoning", self.reasoning),
                          ("axes", self.axes), ("vertex_labels", self.vertex_labels),
                          ("transcript", self.transcript)):
            if name in values:
                box.setChecked(bool(values[name]))
        if "text_size" in values:
            self.text_size.setValue(values["text_size"] or 0)
        for name, combo in (("panel", self.panel), ("theme", self.theme), ("per", self.per),
                            ("unit", self.unit)):
            if name in values:
                index = combo.findData(values[name])
                if index >= 0:
                    combo.setCurrentIndex(index)
        if "gif" in values:
            self.path.setText(values["gif"])
        if "frames_dir" in values:
            self.frames_dir.setText(values["frames_dir"])
        for key, edit in self.more.items():
            if key in values:
                edit.setText(values[key])

    # ------------------------------------------------------------ running
    @property
    def running(self) -> bool:
        return self._running

    def set_running(self, running: bool) -> None:
        self._running = bool(running)
        for widget in self._inputs:
            widget.setEnabled(not running)
        self.export_button.setEnabled(not running)
        self.close_button.setEnabled(not running)
        self.cancel_button.setEnabled(running)
        if running:
            self.progress.setRange(0, 1)
            self.progress.setValue(0)

    def set_progress(self, done: int, total: int) -> None:
        self.progress.setRange(0, max(1, total))
        self.progress.setValue(done)
        self.progress.setFormat(f"{done} / {total} frames" if done < total
                                else f"{total} frames, writing the file")

    def finish_progress(self, text: str, done: bool = True) -> None:
        """The bar once the export is over: full with ``text`` ("done")
        when it was written, empty with ``text`` when it was not."""
        self.progress.setRange(0, 1)
        self.progress.setValue(1 if done else 0)
        self.progress.setFormat(text)

    def set_message(self, text: str, error: bool = False) -> None:
        self.message.setStyleSheet("color: #b0245f;" if error else "")
        self.message.setText(text)

    # ------------------------------------------------------------ private
    def _export_clicked(self) -> None:
        values = self.values()
        if not any(values[key] for key in ("gif", "frames_dir", *self.more)):
            self.set_message("Choose where to export first: a GIF file, a folder for PNG "
                             "frames, or one of the further formats.", error=True)
            return
        self.exportRequested.emit()

    def _choose_gif(self) -> None:
        path, _ = QFileDialog.getSaveFileName(self, "Export animation as", self.path.text(),
                                              "GIF animations (*.gif)")
        if path:
            if not path.lower().endswith(".gif"):
                path += ".gif"
            self.path.setText(path)

    def _choose_folder(self) -> None:
        path = QFileDialog.getExistingDirectory(self, "Folder for PNG frames",
                                                self.frames_dir.text())
        if path:
            self.frames_dir.setText(path)

    def reject(self) -> None:
        # Escape or closing the dialog while an export runs cancels it first.
        if self._running:
            self.cancelRequested.emit()
            return
        super().reject()

    def closeEvent(self, event):  # noqa: N802
        if self._running:
            self.cancelRequested.emit()
            event.ignore()
            return
        super().closeEvent(event)
