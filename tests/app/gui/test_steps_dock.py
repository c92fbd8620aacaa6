"""The Steps dock: a row per step, the step on show highlighted and
followed, a click goes to a step, Copy and Save CSV."""
import csv
import io

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QFontMetrics, QGuiApplication
from PySide6.QtTest import QTest

from tests.support.gui import WAIT_MS

P, Q = (1, 2), (17, 8)
pytestmark = pytest.mark.window("line-bresenham-textbook", [P, Q], grid=(20, 12), settled=True)


def shown_dock(window):
    window.steps.action.trigger()
    assert window.steps.dock.isVisible()
    return window.steps.view


def test_a_row_per_step_and_the_step_on_show_is_followed(window, qtbot):
    view = shown_dock(window)
    trace = window.player.trace
    model = view.model
    assert model.table is not None and len(model.table) == len(trace)
    titles = [model.headerData(c, Qt.Orientation.Horizontal) for c in range(model.columnCount())]
    assert titles[:5] == ["step", "line", "pseudo-code", "pixel", "choice"]
    assert {"d", "s", "n"} <= set(titles)
    window.player.seek(5)
    assert model.current == 5
    cell = model.index(5, titles.index("pixel"))
    assert model.data(cell) == str(trace.step(5).pixel)
    assert model.data(cell, Qt.ItemDataRole.BackgroundRole) is not None
    assert model.data(model.index(4, 0), Qt.ItemDataRole.BackgroundRole) is None
    window.player.to_last()
    last = len(trace) - 1
    assert model.current == last and model.fetched == len(trace)
    rect = view.view.visualRect(model.index(last, 0))
    assert view.view.viewport().rect().intersects(rect), "the last row is not scrolled to"


def test_clicking_a_row_goes_to_its_step(window, qtbot):
    view = shown_dock(window)
    window.player.seek(0)
    rect = view.view.visualRect(view.model.index(3, 0))
    QTest.mouseClick(view.view.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    qtbot.waitUntil(lambda: window.player.index == 3, timeout=WAIT_MS)
    assert view.model.current == 3


def test_copy_and_save_write_the_rows_as_csv(window, tmp_path):
    view = shown_dock(window)
    window.player.seek(4)
    view.view.selectRow(2)
    text = window.steps.copy([2, 3])
    assert QGuiApplication.clipboard().text() == text
    rows = list(csv.reader(io.StringIO(text)))
    assert rows[0][:3] == ["step", "line", "pseudo-code"] and [r[0] for r in rows[1:]] == ["2", "3"]
    path = tmp_path / "steps.csv"
    assert window.steps.save(str(path))
    saved = list(csv.DictReader(path.open(encoding="utf-8")))
    assert len(saved) == len(window.player.trace)
    pixels = [r["pixel"] for r in saved if r["pixel"]]
    assert pixels[0] == str(P) and pixels[-1] == str(Q)


def test_a_failed_save_says_so_in_the_window(window, tmp_path, monkeypatch):
    shown_dock(window)
    said = []
    monkeypatch.setattr("app.gui.steps_dock.QMessageBox.warning",
                        lambda parent, title, text: said.append(text))
    assert not window.steps.save(str(tmp_path / "no-such-folder" / "steps.csv"))
    assert len(said) == 1 and "no-such-folder" in said[0]


def test_s_and_n_are_drawn_at_the_step_on_show(window):
    overlay = window.derivation
    window.player.seek(5)
    marks = {name: (start, end) for name, _, start, end in overlay.segments()}
    for name, (curve, label) in overlay.items.items():
        assert curve.isVisible() and label.isVisible()
        xs, ys = curve.getData()
        assert (xs[0], ys[0]) == marks[name][0] and (xs[1], ys[1]) == marks[name][1]
    window.player.seek(1)  # the first pixel decides nothing
    assert not any(curve.isVisible() for curve, _ in overlay.items.values())


def test_the_table_follows_a_new_run(window, qtbot):
    view = shown_dock(window)
    before = view.model.table
    window.set_scene("line-supercover", [(1.5, 1.25), (9.75, 6.5)], {}, (20, 12))
    qtbot.waitUntil(lambda: window.player.trace is not None
                    and view.model.table is not None and view.model.table is not before,
                    timeout=WAIT_MS)
    assert view.model.table.trace is window.player.trace
    titles = [column.title for column in view.model.table.columns]
    assert "y_lo" in titles and "d" not in titles
    assert not any(curve.isVisible() for curve, _ in window.derivation.items.values())


@pytest.mark.parametrize("size", [(1280, 720), (1920, 1080)])
def test_the_table_opens_at_a_useful_size_and_counts_as_the_transport(make_window, qtbot, size):
    window = make_window("line-bresenham", [(2, 3), (60, 40)], grid=(64, 48), settled=True)
    window.resize(*size)
    qtbot.wait(50)
    view = shown_dock(window)
    row = view.view.verticalHeader().defaultSectionSize()
    # Eight rows at least (a dozen where the window has room): not a strip of three.
    qtbot.waitUntil(lambda: view.view.viewport().height() // row >= 8, timeout=WAIT_MS)
    # One line of text per row, not room for two.
    assert row < 2 * view.view.fontMetrics().lineSpacing()
    # The pseudo-code is shown whole: its column is as wide as its widest line.
    model = view.model
    code = [model.headerData(c, Qt.Orientation.Horizontal)
            for c in range(model.columnCount())].index("pseudo-code")
    bold = view.view.font()
    bold.setBold(True)  # as the row on show is drawn
    widest = max(QFontMetrics(bold).horizontalAdvance(model.text(r)[code])
                 for r in range(len(model.table)))
    assert view.view.columnWidth(code) >= widest
    # The count agrees with the transport's "step 0 / last".
    last = len(window.player.trace) - 1
    assert f"/ {last}" in window.transport.counter.text()
    assert str(last) in view.summary.text() and str(last + 1) not in view.summary.text()
