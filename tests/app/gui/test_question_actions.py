"""File > Export questions… and the exercise's Practice: new numbers, in the
window: the menu holds the action, a bank is written for the algorithm on
show (from new numbers and from the scene on show), bad ids are said in one
line, and practice puts a new scene on the grid that the exercise restarts on."""
from __future__ import annotations

import pytest

from tests.support.gui import settle

LINE = ((2, 3), (9, 6))
pytestmark = pytest.mark.window("line-bresenham", LINE, grid=(16, 12), settled=True)


@pytest.fixture(autouse=True)
def own_files(tmp_path, monkeypatch):
    monkeypatch.setenv("RASTERLAB_SETTINGS", str(tmp_path / "settings.ini"))
    monkeypatch.setenv("RASTERLAB_DATA_DIR", str(tmp_path / "data"))


def choices(**given):
    base = {"template": "line-bresenham-d", "this_scene": False, "count": 3, "seed": 7,
            "format": "md", "students": ""}
    return {**base, **given}


def test_the_file_menu_offers_it_and_the_templates_ask_about_the_algorithm(window):
    actions = window.question_actions
    assert actions.export_action in window.menus["file"].actions()
    names = [t.name for t in actions.templates()]
    assert "line-bresenham-d" in names
    assert all("line-bresenham" in t.algorithms for t in actions.templates())


def test_a_bank_is_written_and_the_same_seed_writes_the_same_files(window, tmp_path):
    first = window.question_actions.export(choices(), tmp_path / "a")
    again = window.question_actions.export(choices(), tmp_path / "b")
    assert first and again
    assert [p.read_bytes() for p in first] == [p.read_bytes() for p in again]
    sheet = next(p for p in first if p.name == "questions.md").read_text(encoding="utf-8")
    assert [f"### {n}. Bresenham: d after step" in sheet for n in (1, 2, 3)] == [True] * 3


def test_questions_about_the_scene_on_show_use_its_points(window, tmp_path):
    written = window.question_actions.export(choices(this_scene=True), tmp_path / "s")
    sheet = next(p for p in written if p.name == "questions.md").read_text(encoding="utf-8")
    assert sheet.count("P = (2, 3), Q = (9, 6)") == 3


def test_a_missing_ids_file_is_said_in_one_line(window, tmp_path):
    said = []
    window.say_error = said.append
    assert window.question_actions.export(choices(students=str(tmp_path / "none.csv")),
                                          tmp_path / "x") is None
    assert len(said) == 1 and "\n" not in said[0] and "none.csv" in said[0]
    assert not (tmp_path / "x").exists()


def test_practice_puts_new_numbers_on_the_grid_and_the_exercise_starts_again(window, qtbot):
    mode = window.exercise_mode
    mode.panel.student.setText("Ada Lovelace")
    mode.panel.student.editingFinished.emit()
    mode.action.trigger()
    settle(qtbot, window)
    before = tuple(map(tuple, window.player.points))
    mode.panel.practice_button.click()
    qtbot.waitUntil(lambda: tuple(map(tuple, window.player.points)) != before)
    settle(qtbot, window)
    assert window.player.spec.name == "line-bresenham"
    assert mode.exercise is not None and mode.exercise.trace is window.player.trace
