"""Exercise mode's grading, against independent scans of the trace: the pixels
a run writes, the direction each Bresenham step moves, the spans, and the
decision variable."""
from __future__ import annotations

import csv
import io

import pytest

from algorithms.core import registry

from app.teaching.exercise import Exercise
from tests.support import record
from tests.support.bresenham import bresenham_run

LINE = ((2, 3), (17, 9))
TRIANGLE = ((2.0, 2.0), (12.0, 3.0), (5.0, 10.0))
POLYGON = (((2.0, 2.0), (14.0, 4.0), (8.0, 11.0)),)


class Clock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        self.now += 1.5
        return self.now


def written_in_order(trace):
    writes = trace.written()
    return dict(zip(writes.steps.tolist(), map(tuple, writes.pixels.tolist())))


def test_bresenham_decisions_are_the_steps_that_move_along_or_across():
    trace = record("line-bresenham", LINE)
    exercise = Exercise(trace, "decision")
    pixels = written_in_order(trace)
    steps = sorted(pixels)
    # Every plotted pixel after the first is one decision: NE when both coordinates move.
    expected = {}
    for before, after in zip(steps, steps[1:]):
        (x0, y0), (x1, y1) = pixels[before], pixels[after]
        expected[after] = "NE" if x1 != x0 and y1 != y0 else "E"
    assert {q.step: q.answer for q in exercise.questions} == expected
    assert all(q.kind == "branch" and set(q.choices) == {"E", "NE"} for q in exercise.questions)
    assert exercise.note() == ""


def test_grading_score_undo_and_summary():
    trace = record("line-bresenham", LINE)
    exercise = Exercise(trace, "decision", clock=Clock())
    wrong = {"E": "NE", "NE": "E"}
    missed = []
    for n in range(5):
        question = exercise.current
        assert exercise.reveal_until() == question.step - 1
        given = question.answer if n % 2 else wrong[question.answer]
        grade = exercise.answer(given)
        assert grade.right == bool(n % 2)
        if not grade.right:
            missed.append(question.step)
            assert f"line {question.line + 1}" in grade.text()
            assert trace.code[trace.step(question.step).line].text.strip() in grade.text()
    assert exercise.score == (2, 5)
    undone = exercise.undo()  # the fifth answer, a wrong one, is asked again
    assert undone.question.step == missed[-1] and not undone.right
    assert exercise.current == undone.question and exercise.score == (2, 4)
    exercise.answer(undone.question.answer)
    summary = exercise.summary()
    assert (summary["asked"], summary["right"]) == (5, 3)
    assert summary["missed"] == missed[:2]
    rows = list(csv.DictReader(io.StringIO(exercise.csv_text())))
    # Every attempt, the undone one and its undo included, in the order they happened.
    assert [(row["right"], row["event"]) for row in rows[:-1]] == [
        ("no", "answer"), ("yes", "answer"), ("no", "answer"), ("yes", "answer"),
        ("no", "answer"), ("no", "undo"), ("yes", "answer")]
    assert [row["attempt"] for row in rows[:-1]] == ["1", "1", "1", "1", "1", "1", "2"]
    assert rows[-1]["right"] == "3/5" and all(float(row["seconds"]) == 1.5 for row in rows[:-1])


def test_the_decision_variable_can_be_typed():
    trace = record("line-bresenham", LINE)
    exercise = Exercise(trace, "decision", answer_with="value")
    dx, dy = LINE[1][0] - LINE[0][0], LINE[1][1] - LINE[0][1]
    # The start's d, then the d that decides each pixel after the first.
    decided = [2 * dy - dx] + bresenham_run(*LINE)[1]
    assert [q.answer for q in exercise.questions] == decided
    first = exercise.current
    assert exercise.answer(str(decided[0])).right
    assert not exercise.answer("not a number").right
    assert first.kind == "value"


def test_an_algorithm_without_decisions_asks_for_pixels_and_says_so():
    trace = record("line-dda", LINE)
    exercise = Exercise(trace, "decision")
    assert "no decision" in exercise.note()
    pixels = written_in_order(trace)
    assert [(q.step, q.answer) for q in exercise.questions] == sorted(pixels.items())
    assert exercise.answer(pixels[exercise.current.step]).right
    assert not exercise.answer((0, 0)).right


def test_a_triangle_asks_inside_or_outside_for_every_tested_pixel():
    trace = record("triangle-bbox", TRIANGLE)
    exercise = Exercise(trace, "step")
    written = set(written_in_order(trace).values())
    assert exercise.questions
    for question in exercise.questions:
        pixel = trace.step(question.step).pixel
        assert question.answer == ("inside" if pixel in written else "outside")


def test_every_scan_line_asks_its_span():
    trace = record("polygon-scanline", POLYGON)
    exercise = Exercise(trace, "scanline")
    spans = trace.spans()
    rows = [(int(s["step"]), int(s["x_start"]), int(s["x_end"]) - 1) for s in spans
            if s["x_end"] > s["x_start"]]
    first_per_row, seen = [], set()
    for step, x0, x1 in rows:
        y = trace.step(step).record.y
        if y not in seen:
            seen.add(y)
            first_per_row.append((step, (x0, x1)))
    assert [(q.step, q.answer) for q in exercise.questions] == first_per_row
    assert exercise.answer(first_per_row[0][1]).right


@pytest.mark.parametrize("percent", [0, 40, 100])
def test_random_questions_repeat_with_the_seed(percent):
    trace = record("line-bresenham", LINE)
    every = Exercise(trace, "step").questions
    picked = [Exercise(trace, "random", percent, seed=seed).questions for seed in (3, 3)]
    assert picked[0] == picked[1]
    assert set(q.step for q in picked[0]) <= set(q.step for q in every)
    if percent in (0, 100):
        assert len(picked[0]) == (len(every) if percent else 0)


def test_the_hint_shows_the_values_before_the_step():
    trace = record("line-bresenham", LINE)
    exercise = Exercise(trace, "decision")
    hint = dict(exercise.hint())
    assert "line" not in hint  # the deciding line would give the branch away
    assert hint["dx"] == str(LINE[1][0] - LINE[0][0])
    assert "choice" not in hint  # the branch taken before is not a number, and not shown
    # The d this step tests: the textbook's d0 = 2 dy - dx for the first decision.
    dy, dx = LINE[1][1] - LINE[0][1], LINE[1][0] - LINE[0][0]
    assert hint["d (tested now)"] == str(2 * dy - dx)


def test_a_depth_test_passes_exactly_where_the_step_writes():
    triangles = ((2.0, 2.0), (12.0, 3.0), (5.0, 10.0), (3.0, 1.0), (13.0, 8.0), (4.0, 9.0))
    trace = record("zbuffer", triangles, {"z": (0.5, 0.5, 0.5, 0.2, 0.9, 0.9)})
    exercise = Exercise(trace, "decision")
    written = set(written_in_order(trace))
    assert {q.answer for q in exercise.questions} == {"pass", "fail"}
    assert all((q.answer == "pass") == (q.step in written) for q in exercise.questions)


def test_a_long_run_asks_about_its_first_steps_and_says_so(monkeypatch):
    from app.teaching import exercise as module
    monkeypatch.setattr(module, "MAX_SCAN", 10)
    trace = record("line-dda", LINE)
    exercise = Exercise(trace, "step")
    assert max(q.step for q in exercise.questions) < 10
    assert f"first 10 of {len(trace)} steps" in exercise.note()


def test_the_feedback_says_the_numbers_that_decide():
    trace = record("line-bresenham", LINE)
    exercise = Exercise(trace, "decision", explain=registry.get("line-bresenham").explain)
    for d in bresenham_run(*LINE)[1][:4]:  # the d that chooses each pixel after the first
        answer = exercise.current.answer
        text = exercise.answer("NE" if answer == "E" else "E").text()
        sign = "<" if d < 0 else ">"
        assert f"= {d} {sign} 0, so {answer}" in text


def test_dda_feedback_shows_the_rounding():
    line = ((2, 3), (8, 10))  # y steps by 1, x by 6/7: x = 2 + 6k/7
    trace = record("line-dda", line)
    exercise = Exercise(trace, "decision")
    exercise.answer((0, 0))  # the first pixel, (2, 3), has nothing to round
    text = exercise.answer((0, 0)).text()
    assert "x = 2.8571 -> 3, y = 4, so (3, 4)" in text


def test_a_span_reads_as_a_span():
    trace = record("polygon-scanline", POLYGON)
    exercise = Exercise(trace, "scanline", explain=registry.get("polygon-scanline").explain)
    x0, x1 = exercise.current.answer
    text = exercise.answer((x0 + 1, x1 + 1)).text()
    assert f"so x = {x0}..{x1}" in text and f"you gave x = {x0 + 1}..{x1 + 1}" in text
    assert f"({x0}, {x1})" not in text
