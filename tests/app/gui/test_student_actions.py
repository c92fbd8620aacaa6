"""File > Open algorithm…: a student's file joins the list, runs on the scene
in a separate process, and D jumps to its first divergence."""
from __future__ import annotations

import csv
from fractions import Fraction

import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from algorithms.core.steps import Note
from tests.support import ROOT
from tests.support.bresenham import bresenham_pixels
from tests.support.gui import WAIT_MS

SAMPLES = ROOT / "resources" / "students"
LINE = ((2, 3), (9, 6))
pytestmark = [pytest.mark.window("line-bresenham", LINE, grid=(16, 12), settled=True),
              pytest.mark.usefixtures("forget_student_algorithms")]


def test_a_student_file_runs_as_an_algorithm_and_d_finds_its_divergence(window, qtbot):
    name = window.student_actions.open(str(SAMPLES / "truncates.py"), "line-bresenham")
    assert name == "student-truncates" and window.player.spec.name == name
    assert window.picker.current_name() == name
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    (x0, y0), (x1, y1) = LINE
    cut = [(x, int(y0 + Fraction(x - x0, x1 - x0) * (y1 - y0))) for x in range(x0, x1 + 1)]
    trace = window.player.trace
    assert [tuple(p) for p in trace.written_pixels().tolist()] == cut
    first = next(n for n, (a, b) in enumerate(zip(bresenham_pixels(*LINE), cut)) if a != b)
    window.player.first()
    QTest.keyClick(window, Qt.Key.Key_D)
    assert window.player.index == trace.written().steps.tolist()[first]
    assert f"pixel {first}" in window.statusBar().currentMessage()


def test_the_correct_file_agrees_and_an_error_becomes_a_note(window, qtbot):
    window.student_actions.open(str(SAMPLES / "bresenham_correct.py"), "line-bresenham")
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    assert window.student_actions.first_divergence() is None
    assert "Same pixels" in window.statusBar().currentMessage()
    window.student_actions.open(str(SAMPLES / "raises.py"), "line-bresenham")
    window.player.set_points([(4, 2), (4, 9)])  # vertical: the file divides by zero
    qtbot.waitUntil(lambda: window.player.trace is not None and len(window.player.trace) == 2,
                    timeout=WAIT_MS)
    notes = window.player.trace.records_of(Note)
    assert notes and "ZeroDivisionError" in notes[0][1].text


def test_a_bad_file_is_refused_with_a_message(window, tmp_path):
    assert window.student_actions.open(str(tmp_path / "missing.py"), "line-bresenham") is None
    assert window.player.spec.name == "line-bresenham"


def test_export_worksheet_from_the_window(window, tmp_path):
    files = window.student_actions.export_worksheet(str(tmp_path / "sheet"), "csv")
    assert sorted(p.name for p in files) == ["answers.csv", "worksheet.csv"]
    rows = (tmp_path / "sheet" / "answers.csv").read_text().splitlines()
    trace = window.player.trace
    assert len(rows) - 1 == len(trace.written_pixels())  # Bresenham: one row per pixel


def test_the_compare_view_puts_the_file_beside_its_reference(window, qtbot):
    name = window.student_actions.open(str(SAMPLES / "off_by_one.py"), "line-bresenham")
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    compare = window.compare_entry.open()
    assert [pane.algorithm for pane in compare.panes] == [name, "line-bresenham"]
    qtbot.waitUntil(lambda: compare.current_diff is not None, timeout=WAIT_MS)
    compare.seek(compare.last, pause=True)
    # At the end, the reference's last pixel, Q, is the one cell only it has.
    assert len(compare.current_diff.cells()) == 1 and compare.next_difference() == LINE[1]
    compare.close()


def test_save_template_writes_the_shipped_file(window, tmp_path):
    target = tmp_path / "my_fill.py"
    assert window.student_actions.save_template("fill", str(target)) == str(target)
    assert target.read_bytes() == (ROOT / "resources" / "templates" / "fill.py").read_bytes()
    names = [a.text() for a in window.menus["file"].actions()]
    assert names.index("Save algorithm &template…") < names.index("Open &algorithm…")


def test_save_template_into_a_missing_folder_says_why(window, tmp_path, monkeypatch):
    said = []
    monkeypatch.setattr(window, "say_error", said.append)
    assert window.student_actions.save_template("line", str(tmp_path / "no" / "x.py")) is None
    assert len(said) == 1 and "does not exist" in said[0]


def test_the_lecturer_chooses_the_blank_columns(window, qtbot, tmp_path):
    from app.gui.worksheet_blanks import BlankColumns
    from app.teaching import worksheet
    columns, default = worksheet.blank_choices(window.player.scene)
    dialog = BlankColumns(columns, default, window)
    qtbot.addWidget(dialog)
    # The default: every column but the step (the line and d give the branch away).
    assert [c for c, box in dialog.boxes.items() if box.isChecked()] == \
        [c for c in columns if c != "step"]
    assert {"line", "pixel", "choice", "d"} <= set(dialog.chosen())
    dialog.boxes["d"].click()  # the lecturer gives d
    chosen = dialog.chosen()
    assert "d" not in chosen
    window.student_actions.export_worksheet(str(tmp_path / "sheet"), "csv", chosen)
    rows = list(csv.DictReader(open(tmp_path / "sheet" / "worksheet.csv")))
    assert all(row["d"] != "" and row["pixel"] == "" and row["line"] == "" for row in rows)
