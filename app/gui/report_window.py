"""Run > Report: the speed-against-error measurements in the window.

The measuring runs in a worker thread with a progress bar and a Cancel
button; the results are shown as interactive pyqtgraph plots (any metric
against any other, per variant, pan and zoom with the mouse) and can be
saved as the same files `rasterlab report` writes.
"""
from __future__ import annotations

import math
import time
from collections import defaultdict

import pyqtgraph as pg
from PySide6.QtCore import QObject, QThread, Signal
from PySide6.QtWidgets import (QCheckBox, QComboBox, QDialog, QFileDialog, QFormLayout,
                               QHBoxLayout, QLabel, QMessageBox, QProgressBar, QPushButton,
                               QRadioButton, QVBoxLayout)


PARAMETER = "(swept parameter)"


class Cancelled(Exception):
    """The person pressed Cancel while measuring."""


class MeasureWorker(QObject):
    """Runs measure.run in a thread; reports progress, rows or an error."""

    progressed = Signal(int, int, str)
    finished = Signal(object, object, object)  # config, rows, seconds
    failed = Signal(str)

    def __init__(self, quick: bool):
        super().__init__()
        self.quick = quick
        self.cancelled = False

    def run(self) -> None:
        from app.analysis import measure  # loaded with the first report, not the window
        config = measure.settings(self.quick)
        try:
            rows, seconds = measure.run(config, self._progress)
        except Cancelled:
            self.failed.emit("Cancelled.")
            return
        except Exception as error:  # noqa: BLE001 - shown to the person, the window stays
            self.failed.emit(f"Measuring failed: {error}")
            return
        self.finished.emit(config, rows.rows, seconds)

    def _progress(self, done: int, total: int, label: str) -> None:
        if self.cancelled:
            raise Cancelled
        self.progressed.emit(done, total, label)


def series(rows: list, family: str, experiment: str, x_metric: str, y_metric: str) -> dict:
    """Variant -> [(x, y)] pairing the two metrics at each parameter value."""
    values = defaultdict(dict)
    for row in rows:
        if (row["family"], row["experiment"]) != (family, experiment):
            continue
        key = (row["variant"], repr(row["parameter_value"]))
        values[key][row["metric"]] = row["value"]
        values[key][PARAMETER] = row["parameter_value"]
    result = defaultdict(list)
    for (variant, _), metrics in values.items():
        x, y = metrics.get(x_metric), metrics.get(y_metric)
        if _plottable(x) and _plottable(y):
            result[variant].append((float(x), float(y)))
    return {variant: sorted(points) for variant, points in result.items()}


def _plottable(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


class ReportDialog(QDialog):
    """Measure, then explore the measurements as plots."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setWindowTitle("Speed against error")
        self.resize(900, 640)
        self.rows: list = []
        self.config = None
        self.seconds: dict = {}
        self.thread: QThread | None = None
        self.worker: MeasureWorker | None = None
        self._build()

    # ----------------------------------------------------------- layout
    def _build(self) -> None:
        layout = QVBoxLayout(self)
        top = QHBoxLayout()
        self.quick = QRadioButton("Quick (seconds)")
        self.full = QRadioButton("Full (a few minutes)")
        self.quick.setChecked(True)
        self.run_button = QPushButton("Measure")
        self.cancel_button = QPushButton("Cancel")
        self.cancel_button.setEnabled(False)
        self.save_button = QPushButton("Save report files…")
        self.save_button.setEnabled(False)
        for widget in (self.quick, self.full, self.run_button, self.cancel_button):
            top.addWidget(widget)
        top.addStretch(1)
        top.addWidget(self.save_button)
        layout.addLayout(top)
        self.progress = QProgressBar()
        self.status = QLabel("Press Measure to time every family and compare its errors with "
                             "the exact results.")
        layout.addWidget(self.progress)
        layout.addWidget(self.status)
        layout.addLayout(self._choosers())
        self.plot = pg.PlotWidget(background="w")
        self.plot.setAccessibleName("Chart of speed against error")
        self.plot.addLegend(offset=(10, 10))
        self.plot.showGrid(x=True, y=True, alpha=0.2)
        layout.addWidget(self.plot, 1)
        self.run_button.clicked.connect(self.start)
        self.cancel_button.clicked.connect(self.cancel)
        self.save_button.clicked.connect(self.save)

    def _choosers(self) -> QFormLayout:
        form = QFormLayout()
        self.family = QComboBox()
        self.experiment = QComboBox()
        self.x_metric = QComboBox()
        self.y_metric = QComboBox()
        axes = QHBoxLayout()
        self.log_x = QCheckBox("log x")
        self.log_y = QCheckBox("log y")
        axes.addWidget(self.log_x)
        axes.addWidget(self.log_y)
        axes.addStretch(1)
        form.addRow("Family", self.family)
        form.addRow("Experiment", self.experiment)
        form.addRow("x (cost)", self.x_metric)
        form.addRow("y (error)", self.y_metric)
        form.addRow("Axes", axes)
        self.family.currentTextChanged.connect(self._fill_experiments)
        self.experiment.currentTextChanged.connect(self._fill_metrics)
        for widget in (self.x_metric, self.y_metric):
            widget.currentTextChanged.connect(self.redraw)
        for box in (self.log_x, self.log_y):
            box.toggled.connect(self.redraw)
        return form

    # ---------------------------------------------------------- running
    def start(self) -> None:
        if self.thread is not None:
            return
        self.worker = MeasureWorker(self.quick.isChecked())
        self.thread = QThread(self)
        self.worker.moveToThread(self.thread)
        self.thread.started.connect(self.worker.run)
        self.worker.progressed.connect(self._progressed)
        self.worker.finished.connect(self._finished)
        self.worker.failed.connect(self._failed)
        self._started = time.perf_counter()
        self.run_button.setEnabled(False)
        self.cancel_button.setEnabled(True)
        self.status.setText("Measuring…")
        self.thread.start()

    def cancel(self) -> None:
        if self.worker is not None:
            self.worker.cancelled = True
            self.status.setText("Cancelling after the current measurement…")

    def _progressed(self, done: int, total: int, label: str) -> None:
        self.progress.setMaximum(max(1, total))
        self.progress.setValue(done)
        self.status.setText(f"Measuring: {label}")

    def _finished(self, config, rows, seconds) -> None:
        self._stop_thread()
        self.config, self.rows, self.seconds = config, rows, seconds
        elapsed = time.perf_counter() - self._started
        self.status.setText(f"{len(rows):,} measurements in {elapsed:.0f} s. Choose what to plot.")
        self.save_button.setEnabled(True)
        self._fill_families()

    def _failed(self, message: str) -> None:
        self._stop_thread()
        self.status.setText(message)

    def _stop_thread(self) -> None:
        if self.thread is not None:
            self.thread.quit()
            self.thread.wait()
        self.thread, self.worker = None, None
        self.run_button.setEnabled(True)
        self.cancel_button.setEnabled(False)

    def closeEvent(self, event) -> None:
        self.cancel()
        self._stop_thread()
        super().closeEvent(event)

    # ---------------------------------------------------------- choices
    def _fill_families(self) -> None:
        self.family.clear()
        self.family.addItems(sorted({row["family"] for row in self.rows}))

    def _fill_experiments(self, family: str) -> None:
        self.experiment.clear()
        self.experiment.addItems(sorted({row["experiment"] for row in self.rows
                                         if row["family"] == family}))

    def _fill_metrics(self, experiment: str) -> None:
        metrics = sorted({row["metric"] for row in self.rows
                          if (row["family"], row["experiment"]) == (self.family.currentText(),
                                                                    experiment)})
        for combo, preferred in ((self.x_metric, ("ops", "kernel time", "time")),
                                 (self.y_metric, ())):
            combo.blockSignals(True)
            combo.clear()
            combo.addItems([PARAMETER] + metrics)
            choice = next((m for m in preferred if m in metrics), PARAMETER)
            if combo is self.y_metric:
                choice = next((m for m in metrics if m not in ("ops", "kernel time", "time")),
                              metrics[0] if metrics else PARAMETER)
            combo.setCurrentText(choice)
            combo.blockSignals(False)
        self.redraw()

    def redraw(self) -> None:
        self.plot.clear()
        curves = series(self.rows, self.family.currentText(), self.experiment.currentText(),
                        self.x_metric.currentText(), self.y_metric.currentText())
        log_x, log_y = self.log_x.isChecked(), self.log_y.isChecked()
        for n, (variant, points) in enumerate(sorted(curves.items())):
            points = [(x, y) for x, y in points if (x > 0 or not log_x) and (y > 0 or not log_y)]
            if not points:
                continue
            xs, ys = zip(*points)
            pen = pg.mkPen(pg.intColor(n, hues=max(8, len(curves))), width=2)
            self.plot.plot(xs, ys, pen=pen, symbol="o", symbolSize=7,
                           symbolBrush=pen.color(), name=variant)
        self.plot.setLogMode(log_x, log_y)
        self.plot.setLabel("bottom", self.x_metric.currentText())
        self.plot.setLabel("left", self.y_metric.currentText())
        self.curves = curves

    # ----------------------------------------------------------- saving
    def save(self) -> None:
        folder = QFileDialog.getExistingDirectory(self, "Save the report into")
        if not folder:
            return
        from app.analysis import report
        try:
            written = report.write_files(folder, self.config, self.rows, self.seconds)
        except report.ReportError as error:
            QMessageBox.warning(self, "Report not saved", str(error))
            return
        self.status.setText(f"Saved {', '.join(written['files'])} in {written['folder']}.")
