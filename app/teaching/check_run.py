"""A check as a person asks for it: the student's file, the reference
algorithm, the cases, the seed and the limits, as the words of
`rasterlab check` give them, checked and run. The command prints the
results (app/cli_teaching.py); the Python API returns them (app/api.py).
"""
from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

from algorithms.core import registry
from algorithms.core.registry import InputError, parse_number
from app.model import budget
from app.teaching import checking, sandbox, student, student_command


class Checked(NamedTuple):
    """Every case's result, the file's name as reports show it, the
    reference's name, the limits that held (student.limits_record) and the
    line on the isolation in force (sandbox.Isolation.line)."""

    results: list
    file: str
    against: str
    limits: dict
    isolation: str


def run_check(file, against: str, cases: list[str], seed: str = "0", time_limit: str = "2",
              memory_limit: str = "256M", progress=None, require_sandbox: bool = False,
              command: str | None = None, give_up_after: int = 2, echo=None) -> Checked:
    """Check ``file`` against the algorithm ``against`` on ``cases`` (hard,
    random N and SCENE.json words); with ``command`` (--cmd), ``file`` is the
    file or folder that the command runs. Bad input raises InputError before
    any case runs, as does ``require_sandbox`` where there is no sandbox; each
    case runs the student's code in its own process (sandbox.py); after
    ``give_up_after`` time-outs the other cases are skipped (0: never).
    ``echo(lines)`` hears the report's head before the first case and each
    case's lines as it ends (the text report, as it goes)."""
    if command is None:
        path = student.check_file(file)
    else:
        path = student_command.program_for(student_command.parse(command), file)
    spec = registry.get(against)
    checking.kind_of(spec)
    selectors = checking.parse_selectors(cases)
    number = parse_number(seed, "--seed", integer=True)
    case_limits = limits(time_limit, memory_limit)
    made = checking.make_cases(spec, selectors, number)  # bad scenes are refused before any run
    where = isolation(require_sandbox)
    held = student.limits_record(case_limits, limits_held(case_limits, command))
    on_result = None
    if echo is not None:
        from app.teaching import check_report
        echo(check_report.head_lines(Path(file).name, spec.name, len(made), held, where.line()))
        on_result = lambda result: echo(check_report.case_lines(result))  # noqa: E731
    results = checking.check(path, spec.name, made, limits=case_limits, progress=progress,
                             give_up_after=give_up_after, on_result=on_result)
    return Checked(results, Path(file).name, spec.name, held, where.line())


def limits_held(case_limits: student.Limits, command) -> dict:
    """Which limits hold for each case (student.limits_in_force); a --cmd
    program's memory is limited as its data segment (student_child.launch)."""
    held = student.limits_in_force(case_limits)
    if command is not None and held["memory"]:
        held = {**held, "memory": "data segment"}
    return held


def isolation(required: bool = False) -> sandbox.Isolation:
    """The isolation cases run in; InputError when ``required`` and there is none."""
    where = sandbox.isolation()
    if required and not where.sandboxed:
        raise InputError(f"--require-sandbox: no sandbox on this system ({where.reason})")
    return where


def limits(time_limit: str, memory_limit: str) -> student.Limits:
    """The limits per case, from the texts of --time-limit and --memory-limit."""
    seconds = parse_number(time_limit, "--time-limit")
    if not 0.1 <= seconds <= 60:
        raise InputError(f"--time-limit must be 0.1 .. 60 seconds, got {time_limit!r}")
    memory = budget.parse_size(memory_limit)
    if not 64 << 20 <= memory <= 8 << 30:
        raise InputError(f"--memory-limit must be 64M .. 8G, got {memory_limit!r}")
    return student.Limits(seconds=seconds, memory=memory)
