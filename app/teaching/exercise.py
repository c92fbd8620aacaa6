"""Exercise mode: predict the algorithm's next step, graded against its trace.

Qt-free. An ``Exercise`` reads a recorded trace only through its queries and
picks the steps to ask about (every step, every decision, every scan line,
or a seeded random k %). Each question has one kind:

- ``branch``: the step's code line stands for a decision outcome (E or NE,
  pass or fail, hit or miss); the student chooses it.
- ``inside``: the algorithm tests pixels and writes only some of them (a
  triangle's bounding box): is this pixel inside (written) or outside?
- ``value``: type the decision variable the step carries (Bresenham's d).
- ``span``: the first and last pixel of the run a scan line fills.
- ``pixel``: the pixel the step writes next (click it).

The answer is graded at once: right or wrong, with the numbers that decide
it (app/teaching/exercise_reasons.py) and, when wrong, the pseudo-code line.
An answer can be undone (its question is asked again), but every attempt
stays in ``attempts``: the CSV lists each one with the student, scene,
algorithm and time, and app/teaching/attempts.py appends it to a file as it
happens, so that a record for grading is never rewritten.
"""
from __future__ import annotations

import csv
import io
import random
import time
from dataclasses import dataclass, field
from datetime import datetime

from algorithms.core.steps import PLOT, VISIT, Span

from app.model.escape import csv_row
from app.teaching.exercise_reasons import reason, shown

FREQUENCIES = ("step", "decision", "scanline", "random")
MAX_SCAN = 20_000  # steps looked at for questions: an exercise is a few hundred at most
ANSWER_WITH = ("auto", "value")
DECIDING = ("branch", "inside", "value")


@dataclass(frozen=True)
class Question:
    step: int
    kind: str            # branch, inside, value, span or pixel
    answer: object       # the right answer: a branch name, a pixel, a number, (x0, x1)
    prompt: str
    choices: tuple = ()  # for branch and inside
    line: int = 0        # the pseudo-code line that decides it
    line_text: str = ""


@dataclass(frozen=True)
class Grade:
    question: Question
    given: object
    right: bool
    seconds: float
    reason: str = ""    # the numbers that decide the answer, ending in it
    attempt: int = 1    # the how-manieth answer to this question
    at: datetime = field(default_factory=datetime.now)

    def text(self) -> str:
        why = self.reason or f"the answer is {self.answer_text}"
        if self.right:
            return f"Right: {why}."
        return (f"Wrong: you gave {self.given_text}; {why} "
                f"(line {self.question.line + 1}: {self.question.line_text.strip()}).")

    @property
    def answer_text(self) -> str:
        return shown(self.question.kind, self.question.answer)

    @property
    def given_text(self) -> str:
        return shown(self.question.kind, self.given)


# Columns of the CSV: one row per attempt, undone ones included.
ATTEMPT_FIELDS = ("time", "student", "scene", "algorithm", "step", "kind", "attempt",
                  "answer", "given", "right", "seconds", "event")


def show(answer) -> str:
    """A value as a person reads it (a pixel as (x, y))."""
    return shown("", answer)


def branches_of(trace) -> tuple[str, ...]:
    """The decision outcomes the pseudo-code names, in the order of its lines."""
    seen = []
    for line in trace.code:
        if line.branch and line.branch not in seen:
            seen.append(line.branch)
    return tuple(seen)


def tests_pixels(trace) -> bool:
    """Does the algorithm look at pixels it may not write (an inside test)?"""
    kinds = {line.kind for line in trace.code}
    return VISIT in kinds and PLOT in kinds


class Exercise:
    """The questions of one run, the answers given so far, and the score."""

    def __init__(self, trace, frequency: str = "decision", percent: int = 30,
                 answer_with: str = "auto", seed: int = 0, clock=time.monotonic,
                 explain=None, context: dict | None = None):
        """``explain`` is the algorithm's AlgorithmSpec.explain (the numbers
        of the feedback); ``context`` the student, scene and algorithm the
        record names."""
        if frequency not in FREQUENCIES:
            raise ValueError(f"frequency: one of {', '.join(FREQUENCIES)}")
        self.trace = trace
        self.explain = explain
        self.context = {"student": "", "scene": "", "algorithm": "", **(context or {})}
        self.answer_with = answer_with
        self.clock = clock
        self.branches = branches_of(trace)
        self.tests = tests_pixels(trace)
        self.decision = trace.start.decision
        self.has_decisions = bool(self.branches) or self.tests or (
            answer_with == "value" and self.decision is not None)
        self.scanned = min(len(trace), MAX_SCAN)
        every = [q for q in (self.question_at(i) for i in range(1, self.scanned)) if q is not None]
        self.questions = self._choose(every, frequency, percent, seed)
        self.grades: list[Grade] = []    # the answers that count (undo takes one back)
        self.attempts: list[tuple[Grade, str]] = []  # every answer and undo, in order
        self.started = clock()
        self._asked_at = self.started

    # ------------------------------------------------------------ questions
    def question_at(self, i: int) -> Question | None:
        """The question step i poses, or None when it has nothing to ask."""
        step = self.trace.step(i)
        code = self.trace.code[step.line]
        base = {"step": i, "line": step.line, "line_text": code.text}
        deciding = step.branch or step.writes
        if self.answer_with == "value" and deciding and self.decision in step.values:
            return Question(kind="value", answer=float(step.values[self.decision]),
                            prompt=f"Step {i}: type {self.decision}, the value that decides it",
                            **base)
        if step.branch:
            return Question(kind="branch", answer=step.branch, choices=self.branches,
                            prompt=f"Step {i}: which branch comes next?", **base)
        if isinstance(step.record, Span):
            span = step.record
            if span.x_end <= span.x_start:
                return None
            return Question(kind="span", answer=(span.x_start, span.x_end - 1),
                            prompt=f"Step {i}: mark the span row {span.y} fills "
                                   "(click its first and its last pixel)", **base)
        if step.pixel is not None and self.tests and step.kind in (PLOT, VISIT):
            where = show(step.pixel)
            return Question(kind="inside", answer="inside" if step.writes else "outside",
                            choices=("inside", "outside"),
                            prompt=f"Step {i}: is pixel {where} inside or outside?", **base)
        if step.writes:
            return Question(kind="pixel", answer=step.pixel,
                            prompt=f"Step {i}: click the pixel plotted next", **base)
        return None

    def _choose(self, every: list, frequency: str, percent: int, seed: int) -> list[Question]:
        if frequency == "decision" and self.has_decisions:
            return [q for q in every if q.kind in DECIDING]
        if frequency == "scanline":
            return self._first_per_row(every)
        if frequency == "random":
            rng = random.Random(seed)
            return [q for q in every if rng.random() * 100 < percent]
        return every

    def _first_per_row(self, every: list) -> list[Question]:
        chosen, row = [], None
        for question in every:
            step = self.trace.step(question.step)
            y = step.record.y if isinstance(step.record, Span) else (
                step.pixel[1] if step.pixel is not None else None)
            if y is not None and y != row:
                chosen.append(question)
                row = y
        return chosen

    def note(self) -> str:
        """What the person should know about this algorithm's questions."""
        notes = []
        if not self.has_decisions:
            notes.append("This algorithm makes no decision at its steps: "
                         "predict what each step plots instead.")
        if self.scanned < len(self.trace):
            notes.append(f"The questions cover the first {self.scanned:,} of "
                         f"{len(self.trace):,} steps.")
        return " ".join(notes)

    # ------------------------------------------------------------- answers
    @property
    def current(self) -> Question | None:
        """The next question not yet answered, or None at the end."""
        n = len(self.grades)
        return self.questions[n] if n < len(self.questions) else None

    def reveal_until(self) -> int:
        """The step to show while the current question waits: the one before it."""
        current = self.current
        return len(self.trace) - 1 if current is None else current.step - 1

    def answer(self, given) -> Grade:
        question = self.current
        if question is None:
            raise ValueError("the exercise is over")
        now = self.clock()
        tries = sum(g.question == question for g, event in self.attempts if event == "answer")
        grade = Grade(question, given, is_right(question, given), now - self._asked_at,
                      reason(self.trace, self.explain, question, self.decision), tries + 1)
        self.grades.append(grade)
        self.attempts.append((grade, "answer"))
        self._asked_at = now
        return grade

    def undo(self) -> Grade | None:
        """Take back the last answer; its question is asked again. The
        attempt stays in ``attempts``, followed by an "undo" entry."""
        if not self.grades:
            return None
        self._asked_at = self.clock()
        grade = self.grades.pop()
        self.attempts.append((grade, "undo"))
        return grade

    def row(self, grade: Grade, event: str) -> list:
        """One attempt as a row of ATTEMPT_FIELDS."""
        context = self.context
        return [grade.at.isoformat(timespec="seconds"), context["student"], context["scene"],
                context["algorithm"], grade.question.step, grade.question.kind, grade.attempt,
                grade.answer_text, grade.given_text, "yes" if grade.right else "no",
                f"{grade.seconds:.1f}", event]

    def hint(self) -> list[tuple[str, str]]:
        """The values that decide the current question: the numbers known before
        it and, where the algorithm has one, the decision variable it tests
        now. (Not the pseudo-code line: that line is the answer.)"""
        question = self.current
        if question is None:
            return []
        before = self.trace.variables_at(max(0, question.step - 1))
        rows = [(name, show(value)) for name, value in before.items()
                if isinstance(value, (int, float)) and not isinstance(value, bool)]
        tested = self.trace.step(question.step).values.get(self.decision)
        if tested is not None and question.kind != "value":
            rows = [row for row in rows if row[0] != self.decision]
            rows.append((f"{self.decision} (tested now)", show(float(tested))))
        return rows

    @property
    def score(self) -> tuple[int, int]:
        return sum(grade.right for grade in self.grades), len(self.grades)

    @property
    def finished(self) -> bool:
        return self.current is None

    def summary(self) -> dict:
        right, asked = self.score
        return {"asked": asked, "right": right,
                "missed": [grade.question.step for grade in self.grades if not grade.right],
                "seconds": round(self.clock() - self.started, 1)}

    def csv_text(self) -> str:
        """One row per attempt (an undone one too, and its undo), then the
        totals of the answers that count; an answer typed as a formula
        (=, +, -, @) is written as text (``escape.csv_row``)."""
        out = io.StringIO()
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(ATTEMPT_FIELDS)
        for grade, event in self.attempts:
            writer.writerow(csv_row(self.row(grade, event)))
        summary = self.summary()
        totals = dict.fromkeys(ATTEMPT_FIELDS, "")
        totals.update(time="total", student=self.context["student"],
                      right=f"{summary['right']}/{summary['asked']}",
                      seconds=f"{summary['seconds']:.1f}")
        writer.writerow(csv_row(list(totals.values())))
        return out.getvalue()


def is_right(question: Question, given) -> bool:
    if question.kind == "value":
        try:
            return float(given) == question.answer
        except (TypeError, ValueError):
            return False
    if question.kind in ("pixel", "span"):
        try:
            return tuple(int(v) for v in given) == tuple(question.answer)
        except (TypeError, ValueError):
            return False
    return given == question.answer
