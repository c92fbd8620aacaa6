"""`rasterlab check` on a class: many submissions (app/teaching/batch.py),
their outputs checked before any case runs, one line per submission as it
finishes, then the formats asked for (app/teaching/grade_formats.py).

A format of one submission (gradescope, prairielearn, coderunner) goes to
--out FILE, or to stdout; for several submissions --out names a folder
that gets ID.json per submission. When a format or --json fills stdout,
the per-submission lines are left out, so stdout is that JSON alone.
"""
from __future__ import annotations

import json
import sys
import time
from dataclasses import dataclass, replace
from pathlib import Path

from algorithms.core.registry import InputError
from app.model.files import Output, check_folders, check_outputs, not_ours, write_atomically
from app.teaching import batch, grade_formats, student_command

FORMATS = ("gradescope", "prairielearn", "coderunner")
BATCH_OPTIONS = ("format", "out", "csv", "points", "id_from", "jobs", "give_up_after")


@dataclass(frozen=True)
class Prepared:
    """What the batch grades and where each output goes, all checked."""

    submissions: list
    plan: batch.Plan
    jobs: int
    outs: dict  # submission id -> the path of its format's file (empty: stdout)


def is_batch(args) -> bool:
    """Whether check grades as a class: several submissions, a folder, or a batch option."""
    return (len(args.submissions) != 1 or Path(args.submissions[0]).is_dir()
            or any(getattr(args, name) is not None for name in BATCH_OPTIONS))


def prepare(args) -> Prepared:
    """Everything check needs, checked before any case runs (InputError,
    OutputRefused): the submissions, the cases, the outputs."""
    if args.out is not None and args.format is None:
        raise InputError("--out names where --format writes; give --format too")
    if args.json and args.format is not None:
        raise InputError("--json and --format both print to stdout; give one of them")
    command = None if args.cmd is None else student_command.parse(args.cmd)
    submissions = batch.find_submissions(args.submissions, args.id_from, command)
    jobs = batch.parse_count(args.jobs, "--jobs", 1, 1, batch.MAX_JOBS)
    give_up = batch.parse_count(args.give_up_after, "--give-up-after", 2, 0, 10_000)
    plan = batch.plan(args.against, args.cases, args.seed, args.time_limit, args.memory_limit,
                      args.points, give_up)
    plan = replace(plan, command=command)
    outs = _format_outputs(args, submissions)
    outputs = [Output("--junit", args.junit, foreign=not_ours("xml")),
               Output("--csv", args.csv, foreign=not_ours("csv"))]
    if len(submissions) > 1 and args.out is not None:
        outputs.append(Output("--out", args.out, folder=True))
    outputs += [Output("--out", path, foreign=not_ours("json")) for path in outs.values()]
    scenes = [word for word in args.cases if word.endswith(".json") and Path(word).is_file()]
    check_outputs(outputs, [s.path for s in submissions] + scenes, args.force)
    check_folders(outputs)
    return Prepared(submissions, plan, jobs, outs)


def _format_outputs(args, submissions) -> dict:
    if args.format is None or args.out is None:
        if args.format is not None and len(submissions) > 1:
            raise InputError(f"--format {args.format} writes one file per submission: give "
                             "--out FOLDER for several submissions")
        return {}
    if len(submissions) == 1:
        return {submissions[0].id: Path(args.out)}
    return {s.id: Path(args.out) / f"{_file_name(s.id)}.json" for s in submissions}


def _file_name(student_id: str) -> str:
    """An id as a file name: what a file name cannot hold as _."""
    return "".join(c if c.isalnum() or c in "-_.@+" else "_" for c in student_id).lstrip(".") or "_"


def run(args, prepared: Prepared, isolation: str) -> int:
    """Grade every submission, print and write; 0 when all pass, 1 otherwise."""
    from app.progress import GradingBar
    from app.teaching import student
    from app.teaching.check_run import limits_held
    plan = prepared.plan
    quiet = args.json or (args.format is not None and not prepared.outs)
    say = (lambda line: None) if quiet else print
    held = student.limits_record(plan.limits, limits_held(plan.limits, plan.command))
    say(f"grading {grade_formats.counted(len(prepared.submissions), 'submission')} against {plan.spec.name}: "
        f"{len(plan.cases)} cases, {grade_formats.number(plan.max_score)} points each")
    say(student.limits_text(held))
    say(isolation)
    sys.stdout.flush()
    bar = GradingBar(len(prepared.submissions), len(plan.cases), sys.stderr)

    def done(graded) -> None:
        bar.clear()
        say(grade_formats.text_line(graded))
        sys.stdout.flush()
        bar.submission_done()

    started = time.perf_counter()
    try:
        results = batch.grade_all(prepared.submissions, plan, prepared.jobs,
                                  bar.case_done, done)
    finally:
        bar.clear()
    say(grade_formats.totals_line(results, time.perf_counter() - started))
    _write(args, prepared, results, held, isolation)
    return 0 if all(graded.failed == 0 for graded in results) else 1


def _write(args, prepared: Prepared, results: list, held: dict, isolation: str) -> None:
    against = prepared.plan.spec.name
    if args.junit:
        write_atomically(Path(args.junit), grade_formats.junit_xml(results, against, isolation),
                         error=OSError)
    if args.csv:
        write_atomically(Path(args.csv), grade_formats.csv_bytes(results), error=OSError)
    if args.json:
        print(json.dumps(grade_formats.as_json(results, against, held, isolation), indent=2))
    if args.format is None:
        return
    if prepared.outs and len(results) > 1:
        Path(args.out).mkdir(exist_ok=True)
    for graded in results:
        made = _formatted(args.format, graded, prepared.plan, against)
        text = json.dumps(made, indent=2, ensure_ascii=False) + "\n"
        if graded.id in prepared.outs:
            write_atomically(prepared.outs[graded.id], text.encode("utf-8"), error=OSError)
        else:
            sys.stdout.write(text)
    sys.stdout.flush()


def _formatted(name: str, graded, plan, against: str) -> dict:
    if name == "gradescope":
        return grade_formats.gradescope(graded, against)
    if name == "prairielearn":
        return grade_formats.prairielearn(graded, plan, against)
    return grade_formats.coderunner(graded, plan, against)
