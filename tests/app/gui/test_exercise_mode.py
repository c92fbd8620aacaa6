"""Run > Exercise driven with qtbot: answers by button, by typing and by
clicking the grid, graded as the trace says; stepping held back; undo of an
answer and of a scene edit; the origin switched; the CSV summary; the
student's name asked once; the append-only record of every attempt; a
switch of algorithm said."""
from __future__ import annotations

import csv

import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from tests.support.gui import settle

LINE = ((2, 3), (9, 6))
pytestmark = pytest.mark.window("line-bresenham", LINE, grid=(16, 12), settled=True)


@pytest.fixture(autouse=True)
def own_files(tmp_path, monkeypatch):
    """Settings and data folder of the test's own (made before the window)."""
    monkeypatch.setenv("RASTERLAB_SETTINGS", str(tmp_path / "settings.ini"))
    monkeypatch.setenv("RASTERLAB_DATA_DIR", str(tmp_path / "data"))
    return tmp_path


def plotted(trace):
    """Written pixels by step, from the trace's columns."""
    writes = trace.written()
    return dict(zip(writes.steps.tolist(), map(tuple, writes.pixels.tolist())))


def direction(trace, step):
    """E or NE from the pixels themselves: NE moves both coordinates."""
    pixels = plotted(trace)
    before = max(s for s in pixels if s < step)
    (x0, y0), (x1, y1) = pixels[before], pixels[step]
    return "NE" if x0 != x1 and y0 != y1 else "E"


def start(window):
    mode = window.exercise_mode
    assert mode.action in window.menus["run"].actions()
    mode.action.trigger()
    assert mode.action.isChecked() and mode.dock.isVisible()
    if mode.exercise is None:  # the name is asked first
        mode.panel.student.setText("Ada Lovelace")
        mode.panel.student.editingFinished.emit()
    assert mode.exercise is not None
    return mode


def click_cell(window, pixel):
    grid = window.grid
    QTest.mouseClick(grid.viewport(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                     grid.widget_pos_of((pixel[0] + 0.5, pixel[1] + 0.5)))


def test_branches_graded_at_once_and_stepping_held_back(window, qtbot):
    mode = start(window)
    trace = window.player.trace
    right = wrong = 0
    for n in range(4):
        question = mode.exercise.current
        assert window.player.index == question.step - 1  # the answer is not on show yet
        correct = direction(trace, question.step)
        choice = correct if n % 2 == 0 else {"E": "NE", "NE": "E"}[correct]
        qtbot.mouseClick(mode.panel.choice_button(choice), Qt.MouseButton.LeftButton)
        right, wrong = right + (n % 2 == 0), wrong + (n % 2 == 1)
        feedback = mode.panel.feedback.text()
        assert feedback.startswith("Right" if n % 2 == 0 else "Wrong")
        if n % 2:
            assert trace.code[trace.step(question.step).line].text.strip() in feedback
    assert mode.exercise.score == (right, right + wrong)
    assert mode.panel.score.text().startswith(f"Score: {right} / {right + wrong}")
    waiting = window.player.index
    window.player.forward()
    assert window.player.index == waiting  # held back before the question
    qtbot.mouseClick(mode.panel.undo_button, Qt.MouseButton.LeftButton)
    assert mode.exercise.score == (right, right + wrong - 1)


def test_typing_the_decision_variable(window):
    mode = start(window)
    mode.panel.answer_with.setCurrentIndex(mode.panel.answer_with.findData("value"))
    (x0, y0), (x1, y1) = LINE
    d0 = 2 * (y1 - y0) - (x1 - x0)  # the textbook's first d
    assert mode.exercise.current.kind == "value"
    mode.panel.entry.setText(str(d0))
    QTest.keyClick(mode.panel.entry, Qt.Key.Key_Return)
    assert mode.exercise.score == (1, 1)


@pytest.mark.window("line-dda", LINE, grid=(16, 12), settled=True)
def test_clicking_the_next_pixel_and_the_origin_switched(window, qtbot):
    mode = start(window)
    assert "no decision" in mode.panel.note.text()
    points = list(window.player.points)
    pixels = plotted(window.player.trace)
    click_cell(window, pixels[mode.exercise.current.step])
    click_cell(window, (15, 0))  # surely not the next pixel of this line
    assert mode.exercise.score == (1, 2)
    assert window.player.points == points  # the clicks answered; they drew nothing
    following = pixels[mode.exercise.current.step]
    shown_at = window.grid.widget_pos_of((following[0] + 0.5, following[1] + 0.5))
    window.y_down_action.trigger()
    settle(qtbot, window)
    # The origin is how the grid is shown: the same run, the same questions, the
    # pixel drawn elsewhere, and a click where it is drawn now is right.
    assert window.grid.widget_pos_of((following[0] + 0.5, following[1] + 0.5)) != shown_at
    assert mode.exercise.score == (1, 2)
    click_cell(window, following)
    assert mode.exercise.score == (2, 3)


def test_a_scene_edit_undone_restarts_and_the_summary_is_saved(window, tmp_path):
    mode = start(window)
    mode.answer("E")
    window.points.type_value(1, "x", "5")  # an edit of the scene: a new run
    assert window.player.points == [LINE[0], (5, LINE[1][1])]
    assert mode.exercise.score == (0, 0) and "starts again" in mode.panel.feedback.text()
    mode.answer("E")
    window.undo()
    assert window.player.points == list(LINE)
    assert mode.exercise.score == (0, 0) and mode.exercise.trace is window.player.trace
    trace = window.player.trace
    asked = len(mode.exercise.questions)
    for question in list(mode.exercise.questions):
        mode.answer(direction(trace, question.step))
    assert mode.exercise.finished and "Done" in mode.panel.question.text()
    assert window.player.index == len(trace) - 1
    mode.save(str(tmp_path / "summary.csv"))
    rows = list(csv.reader(open(tmp_path / "summary.csv")))
    assert len(rows) == asked + 2 and rows[-1][rows[0].index("right")] == f"{asked}/{asked}"
    mode.action.setChecked(False)
    assert not mode.dock.isVisible() and window.variables_dock.isVisible()


POLYGON = [[(2.0, 2.0), (13.0, 3.0), (7.0, 10.0)]]


@pytest.mark.window("polygon-scanline", POLYGON, grid=(16, 12), settled=True)
def test_a_span_is_marked_with_two_clicks(window):
    mode = start(window)
    mode.panel.frequency.setCurrentIndex(mode.panel.frequency.findData("scanline"))
    question = mode.exercise.current
    assert question.kind == "span"
    run = window.player.trace.step(question.step).record  # the Span the step writes
    click_cell(window, (run.x_end - 1, run.y))  # either end first
    assert mode.exercise.score == (0, 0) and "now click the last" in mode.panel.feedback.text()
    click_cell(window, (run.x_start, run.y))
    assert mode.exercise.score == (1, 1)
    wrong = mode.exercise.current
    mode.panel.entry.setText("0, 1")  # Enter answers, though it closes a contour elsewhere
    QTest.keyClick(mode.panel.entry, Qt.Key.Key_Return)
    assert mode.exercise.score == (1, 2) and wrong.kind == "span"


def test_the_steps_table_is_put_aside_while_an_exercise_runs(window):
    steps = window.steps
    steps.dock.show()
    assert steps.dock.isVisible()
    mode = start(window)
    # The table lists every step to come: it would give the answers away.
    assert not steps.dock.isVisible() and not steps.action.isEnabled()
    mode.action.setChecked(False)
    assert steps.dock.isVisible() and steps.action.isEnabled()


def test_the_buttons_stay_put_after_an_answer(window, qtbot):
    """The next click after an answer (Hint, say) lands on the button that
    was there before the answer: the feedback does not push it down."""
    mode = start(window)
    panel = mode.panel
    qtbot.waitUntil(lambda: panel.isVisible() and panel.hint_button.isVisible())

    def places():
        QTest.qWait(20)
        return [b.mapTo(panel, b.rect().center()) for b in
                (panel.hint_button, panel.undo_button, panel.save_button)]
    before = places()
    question = mode.exercise.current
    wrong = {"E": "NE", "NE": "E"}[direction(window.player.trace, question.step)]
    qtbot.mouseClick(panel.choice_button(wrong), Qt.MouseButton.LeftButton)
    assert panel.feedback.text().startswith("Wrong")  # several lines of feedback
    assert places() == before
    panel.show_feedback("a longer explanation\nover\nseveral\nlines", False)
    assert places() == before


def record_rows(tmp_path):
    return list(csv.DictReader(open(tmp_path / "data" / "exercise-attempts.csv",
                                    encoding="utf-8")))


def test_the_name_is_asked_once_and_every_attempt_is_recorded(window, qtbot, own_files):
    mode = window.exercise_mode
    mode.action.trigger()
    assert mode.exercise is None and "name" in mode.panel.question.text()
    assert window.player.index == 0  # nothing of the run is shown while the name is asked
    mode.panel.student.setText("Ada Lovelace")
    mode.panel.student.editingFinished.emit()
    trace = window.player.trace
    first = mode.exercise.current
    wrong = {"E": "NE", "NE": "E"}[direction(trace, first.step)]
    qtbot.mouseClick(mode.panel.choice_button(wrong), Qt.MouseButton.LeftButton)
    qtbot.mouseClick(mode.panel.undo_button, Qt.MouseButton.LeftButton)
    assert mode.exercise.score == (0, 0)
    mode.answer(direction(trace, first.step))
    rows = record_rows(own_files)
    # The wrong attempt is not erased by the undo: it stays, then the undo, then the retry.
    assert [(r["step"], r["given"], r["right"], r["event"], r["attempt"]) for r in rows] == [
        (str(first.step), wrong, "no", "answer", "1"),
        (str(first.step), wrong, "no", "undo", "1"),
        (str(first.step), direction(trace, first.step), "yes", "answer", "2")]
    assert {(r["student"], r["algorithm"]) for r in rows} == {("Ada Lovelace", "line-bresenham")}
    assert all("(2, 3) (9, 6)" in r["scene"] and r["time"] for r in rows)
    mode.save(str(own_files / "export.csv"))
    exported = list(csv.DictReader(open(own_files / "export.csv", encoding="utf-8")))
    assert [r["event"] for r in exported[:-1]] == ["answer", "undo", "answer"]
    mode.action.setChecked(False)
    mode.action.setChecked(True)  # asked once: the name is remembered
    assert mode.exercise is not None and mode.exercise.context["student"] == "Ada Lovelace"


def test_switching_the_algorithm_says_so(window):
    mode = start(window)
    mode.answer("E")
    window.player.set_algorithm("line-dda")
    settle_recording(window)
    text = mode.panel.feedback.text()
    assert "line-bresenham" in text and "line-dda" in text and "stay in the record" in text
    assert mode.exercise.context["algorithm"] == "line-dda"


def settle_recording(window):
    from PySide6.QtCore import QCoreApplication
    for _ in range(50):
        QCoreApplication.processEvents()
        if window.player.trace is not None:
            return


def test_the_feedback_gives_the_deciding_numbers(window):
    mode = start(window)
    trace = window.player.trace
    (x0, y0), (x1, y1) = LINE
    dx, dy = x1 - x0, y1 - y0
    d = 2 * dy - dx  # the textbook's d0, then d += 2dy or 2(dy - dx): written here
    question = mode.exercise.current
    correct = direction(trace, question.step)
    mode.answer({"E": "NE", "NE": "E"}[correct])
    feedback = mode.panel.feedback.text()
    assert f"= {d}" in feedback and feedback.count(correct) >= 1
    assert ("< 0" if d < 0 else "> 0" if d > 0 else "0") in feedback
