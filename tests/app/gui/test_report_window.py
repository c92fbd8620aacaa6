"""Run > Report in the window: measuring in a thread, cancel, plots, saving."""
import math

from app.gui import report_window
from app.gui.report_window import PARAMETER, ReportDialog, series


def row(variant, parameter_value, metric, value, family="lines", experiment="sweep"):
    return {"family": family, "experiment": experiment, "algorithm": "a", "variant": variant,
            "parameter": "length", "parameter_value": parameter_value, "metric": metric,
            "value": value, "unit": ""}


def test_series_pairs_metrics_at_each_parameter_value():
    rows = [row("v1", 10, "ops", 4), row("v1", 10, "error", 0.5),
            row("v1", 100, "ops", 5), row("v1", 100, "error", 0.25),
            row("v2", 10, "ops", 9), row("v2", 10, "error", math.nan),
            row("v1", 10, "ops", 99, experiment="other")]
    curves = series(rows, "lines", "sweep", "ops", "error")
    assert curves == {"v1": [(4.0, 0.5), (5.0, 0.25)]}
    assert series(rows, "lines", "sweep", PARAMETER, "error") == {"v1": [(10.0, 0.5), (100.0, 0.25)]}


def test_measure_cancel_and_plot(qtbot, tmp_path, monkeypatch):
    dialog = ReportDialog()
    qtbot.addWidget(dialog)
    dialog.start()
    dialog.cancel()
    qtbot.waitUntil(lambda: dialog.thread is None, timeout=60_000)
    assert dialog.status.text() == "Cancelled." and not dialog.rows

    dialog.start()
    qtbot.waitUntil(lambda: dialog.thread is None, timeout=120_000)
    assert dialog.rows, dialog.status.text()
    families = [dialog.family.itemText(i) for i in range(dialog.family.count())]
    assert "lines" in families and "triangles" in families
    dialog.family.setCurrentText("lines")
    assert dialog.curves, "the lines family gives at least one curve"
    assert len(dialog.plot.getPlotItem().listDataItems()) == len(
        [c for c in dialog.curves.values() if c])

    monkeypatch.setattr(report_window.QFileDialog, "getExistingDirectory",
                        lambda *args: str(tmp_path))
    dialog.save()
    assert (tmp_path / "report.md").exists() and (tmp_path / "measurements.csv").exists()


def test_run_report_opens_one_dialog_and_brings_it_back(window, qtbot):
    """Run > Report… loads the dialog's module on first use (not with the
    window) and opens the same dialog again after."""
    entry = window.add_report_entry()
    entry.action.trigger()
    dialog = entry.window
    assert isinstance(dialog, ReportDialog) and dialog.isVisible()
    dialog.close()
    entry.action.trigger()
    assert entry.window is dialog and dialog.isVisible()
    dialog.close()
