"""View > Exact fractions: the tables, the variables panel and the steps
table change together, and the setting is kept for the next window."""
from algorithms.core.steps import Table
from app.gui.window import MainWindow
from tests.app.gui.test_window_families import settle


def open_window(qtbot, algorithm):
    window = MainWindow(algorithm)
    qtbot.addWidget(window)
    window.show()
    qtbot.waitExposed(window)
    settle(qtbot, window)
    return window


def et_column(window, column):
    et = next(t for t in window.tables.tables() if t.name == "ET")
    return sorted(row[et.columns.index(column)] for row in et.rows)


def test_the_setting_changes_every_panel_at_once(qtbot, tmp_path, monkeypatch):
    monkeypatch.setenv("RASTERLAB_SETTINGS", str(tmp_path / "settings.ini"))
    w = open_window(qtbot, "polygon-scanline")
    w.set_points([(8, 1), (10, 6), (3, 3)])
    qtbot.waitUntil(lambda: w.player.trace is not None and len(w.player.trace) > 10)
    et_step = next(i for i, t in w.player.trace.records_of(Table) if t.name == "ET")
    w.transport.timeline.setValue(et_step)
    w.steps.action.trigger()  # the steps table, shown
    # (8, 1) -> (3, 3): -5/2; (8, 1) -> (10, 6): 2/5; (3, 3) -> (10, 6): 7/3.
    assert et_column(w, "1/m") == sorted(["-2.5", "0.4", "\u22482.3333"])
    assert not w.numbers.action.isChecked()
    w.numbers.action.trigger()
    assert et_column(w, "1/m") == sorted(["-5/2", "2/5", "7/3"])
    steps_text = w.steps.table.text_row(et_step)
    assert any("1/m=-5/2" in cell for cell in steps_text)
    w.numbers.action.trigger()
    assert et_column(w, "1/m") == sorted(["-2.5", "0.4", "\u22482.3333"])
    assert not any("-5/2" in cell for cell in w.steps.table.text_row(et_step))


def test_the_variables_panel_and_memory(qtbot, tmp_path, monkeypatch):
    monkeypatch.setenv("RASTERLAB_SETTINGS", str(tmp_path / "settings.ini"))
    w = open_window(qtbot, "line-bresenham")
    w.set_points([(1, 1), (25, 12)])
    qtbot.waitUntil(lambda: w.player.trace is not None)
    w.transport.timeline.setValue(2)
    assert "m" not in dict(w.variables.rows())
    w.numbers.action.trigger()
    assert dict(w.variables.rows())["m"] == "11/24"  # dy / dx = 11 / 24
    again = open_window(qtbot, "line-bresenham")
    assert again.numbers.numbers == "exact" and again.numbers.action.isChecked()
