"""Grading a class: many submissions against one reference algorithm.

Each submission is a student's .py file, or a folder holding exactly one
(the student's id is the folder's name, the file's name without .py, or
the one group of an ``--id-from`` pattern searched in the path); with
``--cmd``, a folder or file that the command runs (student_command.py). Every
submission gets the same cases (``Plan``), whose reference steps are made
once; ``grade_all`` grades ``jobs`` submissions at a time (threads that
each drive one case's child process at a time: the children do the work).
After ``give_up_after`` cases of a submission ran out of time, its other
cases are not run but marked "skipped", so a submission that loops costs a
few time limits, not one per case. The results (``Graded``) are the one
model every format is written from (grade_formats.py).
"""
from __future__ import annotations

import re
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from algorithms.core import registry
from algorithms.core.registry import InputError, parse_number
from app.teaching import checking, student, student_command
from app.teaching.checking import CaseResult
from app.teaching.student import Outcome

KINDS = ("hard", "random", "scene")  # the kinds of case --cases makes, as --points names them
MAX_JOBS = 64


@dataclass(frozen=True)
class Submission:
    """One student's id and file (or folder, for --cmd), and the
    student_command.Program that runs it, for --cmd."""

    id: str
    path: Path
    program: object = None


@dataclass(frozen=True)
class Plan:
    """What every submission is graded on: the reference, its options, the
    cases with their kind and reference steps, the limits, the points per
    kind, after how many time-outs a submission's other cases are skipped
    (0: never) and the command that runs each submission (--cmd)."""

    spec: object
    options: dict
    cases: tuple       # (kind, checking.Case, reference steps) per case
    limits: student.Limits
    points: dict
    give_up_after: int
    command: object = None  # the student_command.Command of --cmd

    @property
    def max_score(self) -> float:
        return sum(self.points[kind] for kind, _, _ in self.cases)


@dataclass(frozen=True)
class GradedCase:
    """One case of one submission, with its kind and the points it is worth."""

    result: CaseResult
    kind: str
    max_points: float

    @property
    def name(self) -> str:
        return self.result.case.name

    @property
    def passed(self) -> bool:
        return self.result.passed

    @property
    def points(self) -> float:
        return self.max_points if self.passed else 0

    @property
    def skipped(self) -> bool:
        return self.result.outcome.kind == "skipped"

    @property
    def seconds(self) -> float:
        return self.result.outcome.seconds

    @property
    def output(self) -> str:
        """What the student's code printed in this case (the sandbox keeps 1 MB)."""
        return self.result.outcome.output

    def message(self) -> str:
        return self.result.message()


@dataclass(frozen=True)
class Graded:
    """A submission's results, case by case, and the time its grading took."""

    submission: Submission
    cases: tuple
    seconds: float

    @property
    def id(self) -> str:
        return self.submission.id

    @property
    def passed(self) -> int:
        return sum(case.passed for case in self.cases)

    @property
    def failed(self) -> int:
        return len(self.cases) - self.passed

    @property
    def score(self) -> float:
        return sum(case.points for case in self.cases)

    @property
    def max_score(self) -> float:
        return sum(case.max_points for case in self.cases)

    @property
    def skipped(self) -> int:
        return sum(case.skipped for case in self.cases)

    def first_failing(self) -> GradedCase | None:
        return next((case for case in self.cases if not case.passed), None)


# ------------------------------------------------------------- submissions
def find_submissions(words: list[str], id_from: str | None = None,
                     command=None) -> list[Submission]:
    """The submissions the words name, in their order (InputError for a
    missing or unusable one, and for two with one id); with ``command``
    (a student_command.Command) each is a folder or a file that it runs."""
    pattern = _id_pattern(id_from)
    found, seen = [], {}
    for word in words:
        if command is None:
            made = Submission(student_id(word, pattern), submission_file(word))
        else:
            program = student_command.program_for(command, word)
            made = Submission(student_id(word, pattern), program.path, program)
        if made.id in seen:
            raise InputError(f"{word}: its id {made.id!r} is also that of {seen[made.id]}; "
                             "give --id-from a pattern that tells them apart")
        seen[made.id] = word
        found.append(made)
    return found


def submission_file(word: str) -> Path:
    """The student's file: ``word`` itself, or the one .py file in the folder ``word``."""
    path = Path(word)
    if not path.is_dir():
        return student.check_file(path)
    files = sorted(entry for entry in path.iterdir() if entry.suffix == ".py" and entry.is_file())
    if len(files) != 1:
        names = ", ".join(entry.name for entry in files[:5])
        raise InputError(f"{path}: a submission folder holds one .py file; this one holds "
                         f"{len(files)}{': ' + names if names else ''}")
    return student.check_file(files[0])


def _id_pattern(text: str | None):
    if text is None:
        return None
    try:
        pattern = re.compile(text)
    except re.error as error:
        raise InputError(f"--id-from {text!r}: not a regular expression ({error})") from None
    if pattern.groups != 1:
        raise InputError(f"--id-from {text!r}: give a pattern with exactly one group (...), "
                         f"the id; it has {pattern.groups}")
    return pattern


def student_id(word: str, pattern=None) -> str:
    """A submission's id: the group of ``pattern`` found in its path as
    given, else its folder's name or its file's name without .py."""
    path = Path(word)
    if pattern is not None:
        found = pattern.search(path.as_posix())
        if found is None or not found.group(1):
            raise InputError(f"{word}: --id-from {pattern.pattern!r} finds no id in this path")
        return found.group(1)
    name = Path(path.resolve()).name if path.is_dir() else path.stem
    return name or str(word)


# ------------------------------------------------------------------- plan
def parse_points(text: str | None) -> dict:
    """Points per kind of case from ``hard=2,random=1`` (1 for a kind not named)."""
    points = dict.fromkeys(KINDS, 1.0)
    for part in (text or "").split(","):
        if not part.strip():
            continue
        kind, equals, value = part.partition("=")
        kind = kind.strip()
        if not equals or kind not in KINDS:
            raise InputError(f"--points takes KIND=POINTS, comma-separated, with KIND one of "
                             f"{', '.join(KINDS)}; got {part.strip()!r}")
        number = parse_number(value.strip(), "--points")
        if not 0 <= number <= 1000:
            raise InputError(f"--points {kind}: 0 .. 1000 points per case, got {value.strip()!r}")
        points[kind] = float(number)
    return points


def parse_count(text: str | None, option: str, default: int, low: int, high: int) -> int:
    if text is None:
        return default
    if not str(text).isdigit() or not low <= int(text) <= high:
        raise InputError(f"{option} takes a whole number {low} .. {high}, got {text!r}")
    return int(text)


def plan(against: str, words: list[str], seed: str = "0", time_limit: str = "2",
         memory_limit: str = "256M", points: str | None = None, give_up_after: int = 2) -> Plan:
    """The cases every submission is graded on, checked before any runs:
    each selector of ``words`` makes cases of its kind."""
    from app.teaching.check_run import limits
    spec = registry.get(against)
    checking.kind_of(spec)
    number = parse_number(seed, "--seed", integer=True)
    case_limits = limits(time_limit, memory_limit)
    options = spec.resolve({})
    cases = []
    for what, value in checking.parse_selectors(words):
        for case in checking.make_cases(spec, [(what, value)], number):
            expected = checking.reference_steps(spec, checking.with_options(options, case))
            cases.append((what, case, expected))
    return Plan(spec, options, tuple(cases), case_limits, parse_points(points), give_up_after)


# ---------------------------------------------------------------- grading
def grade(submission: Submission, plan: Plan, on_case=None) -> Graded:
    """Every case of ``plan`` on one submission; ``on_case()`` hears each end."""
    started = time.perf_counter()
    graded, timeouts = [], 0
    for kind, case, expected in plan.cases:
        if plan.give_up_after and timeouts >= plan.give_up_after:
            result = checking.skipped_result(case, timeouts)
        else:
            result = checking.check_case(plan.spec, plan.options,
                                         submission.program or submission.path, case,
                                         plan.limits, expected)
            timeouts += result.outcome.kind == "time"
        graded.append(GradedCase(result, kind, plan.points[kind]))
        if on_case is not None:
            on_case()
    return Graded(submission, tuple(graded), time.perf_counter() - started)


def grade_all(submissions: list[Submission], plan: Plan, jobs: int = 1, on_case=None,
              on_done=None) -> list[Graded]:
    """Every submission's results, in the order given; ``jobs`` are graded
    at a time. ``on_done(graded)`` hears each submission as it finishes
    (in the order they finish) and ``on_case()`` each case's end, one call
    at a time. The first failure of
    RasterLab itself ends the grading and is raised."""
    lock = threading.Lock()

    def case_done() -> None:
        if on_case is not None:
            with lock:
                on_case()

    def one(submission: Submission) -> Graded:
        graded = grade(submission, plan, case_done)
        if on_done is not None:
            with lock:
                on_done(graded)
        return graded

    if jobs <= 1:
        return [one(submission) for submission in submissions]
    pool = ThreadPoolExecutor(max_workers=jobs, thread_name_prefix="rasterlab-grade")
    try:
        futures = [pool.submit(one, submission) for submission in submissions]
        return [future.result() for future in futures]
    finally:
        # On an interrupt or a failure the queued submissions are dropped; the
        # running ones end with their case's wall-clock limit.
        pool.shutdown(wait=False, cancel_futures=True)
