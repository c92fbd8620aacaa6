"""A student's own algorithm, run in a separate process with limits.

The protocol (see resources/templates/): a plain Python file defines a
generator function that takes the family's inputs and yields each pixel as
``x, y`` or ``x, y, {"d": d}``. RasterLab never imports that file: every
case runs a fresh ``python -I -S`` process (student_child.py, the runner)
in a scratch folder of its own, in a sandbox where this system has one
(sandbox.py), with a wall-clock timeout here, after which every process of
the case is ended, on every system; where the system lets a process limit
itself, also CPU time (RLIMIT_CPU), memory (RLIMIT_AS, or RLIMIT_DATA on a
macOS that refuses it), file size, open files and processes. Windows has
no such limits: ``limits_in_force`` asks the runner which hold, and the
check's report says so. Nothing the child says is trusted beyond the
runner's answer, read capped and checked by student_answer.py. Whatever
the student's code does (raises, loops, crashes, allocates without bound,
writes without end, yields garbage), the case ends as an ``Outcome`` with
a message, never as an exception in RasterLab; a child that could not
start at all raises sandbox.SandboxFailure, RasterLab's own failure.
"""
from __future__ import annotations

import json
import math
import signal
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

from algorithms.core.errors import InputError
from app.teaching import sandbox, student_answer
from app.teaching.sandbox import Ran

CHILD = Path(__file__).with_name("student_child.py")
FUNCTION = "draw"


@dataclass(frozen=True)
class Limits:
    """Per case: CPU seconds, address space in bytes, and yielded pixels."""

    seconds: float = 2.0
    memory: int = 256 << 20
    max_steps: int = 100_000

    def steps_for(self, expected: int) -> "Limits":
        """A pixel limit for a case whose reference plots ``expected`` pixels:
        an endless loop is cut off long before the general limit."""
        return replace(self, max_steps=min(self.max_steps, 4 * expected + 1000))


@dataclass(frozen=True)
class Outcome:
    """What one run of the student's generator gave: its steps, or an error.

    ``steps`` holds (x, y, {name: value}) per yielded pixel (the steps before
    the error when there is one); ``kind`` is "ok", "exception", "shape",
    "protocol", "too-long", "time", "memory" or "crash".
    """

    kind: str
    steps: tuple = ()
    error: str = ""
    seconds: float = 0.0
    output: str = field(default="", compare=False)  # what the student printed

    @property
    def ok(self) -> bool:
        return self.kind == "ok"


def cpu_limit_statuses(signals=signal) -> frozenset:
    """The return codes of a child ended by its CPU-time limit: SIGXCPU at
    the soft limit, SIGKILL at the hard one (neither exists on Windows)."""
    return frozenset(-getattr(signals, name) for name in ("SIGXCPU", "SIGKILL")
                     if hasattr(signals, name))


CPU_LIMIT_STATUSES = cpu_limit_statuses()


def check_file(path) -> Path:
    """The student's file, if it is a readable regular .py file (else InputError)."""
    path = Path(path)
    if path.suffix != ".py":
        raise InputError(f"{path}: a student's algorithm is a Python file ending in .py")
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    try:
        with open(path, "rb"):
            pass
    except OSError as error:
        raise InputError(f"{path}: {error.strerror}") from None
    return path.resolve()


def wall_seconds(limits: Limits) -> float:
    """The wall-clock time after which a case's process is ended."""
    return limits.seconds + 1.0


def _child(request: dict, limits: Limits, path: Path | None = None) -> Ran:
    """Run the runner on ``request`` with a copy of the student's file
    ``path`` beside it, under the same name (the runner's tracebacks show it)."""
    request = {**request, "memory": limits.memory, "cpu_seconds": max(1, math.ceil(limits.seconds))}
    files = {sandbox.RUNNER: CHILD}
    if path is not None:
        request["file"] = path.name if path.name != sandbox.RUNNER else "submission.py"
        files[request["file"]] = path
    return sandbox.run_case(files, json.dumps(request).encode("utf-8"), wall_seconds(limits),
                            sandbox.isolation())


def limits_in_force(limits: Limits = Limits()) -> dict:
    """Which limits hold for a case on this system, as the runner sets them:
    {"cpu": bool, "memory": "address space", "data segment" or None}."""
    ran = _child({"probe": True}, limits)
    held = student_answer.probe_answer(ran)
    return held if held is not None else {"cpu": False, "memory": None}  # unknown: not enforced


def limits_record(limits: Limits, held: dict) -> dict:
    """The limits of each case as plain data; None where this system does not enforce one."""
    return {"wall_clock_seconds": wall_seconds(limits),
            "cpu_seconds": limits.seconds if held["cpu"] else None,
            "memory_bytes": limits.memory if held["memory"] else None,
            "memory_limits": held["memory"]}


def limits_text(record: dict) -> str:
    """One line on the limits of each case, naming those this system does not enforce."""
    parts = [f"wall clock {record['wall_clock_seconds']:g} s (then the process is ended)"]
    cpu, memory = record["cpu_seconds"], record["memory_bytes"]
    parts.append(f"CPU time {cpu:g} s" if cpu is not None
                 else "CPU-time limit not enforced on this system")
    parts.append(f"memory {memory >> 20} MiB ({record['memory_limits']})" if memory is not None
                 else "memory limit not enforced on this system")
    return "limits per case: " + "; ".join(parts)


def run_student(path, args, limits: Limits = Limits(), function: str = FUNCTION,
                value_name: str | None = None) -> Outcome:
    """Run ``function(*args)`` of the file in a child process and collect its pixels.
    With ``value_name``, a step may also be ``x, y, number``: the number is
    kept under that name (an antialiased line's ``x, y, intensity``)."""
    request = {"function": function, "args": list(args), "value": value_name,
               "max_steps": limits.max_steps}
    started = time.perf_counter()
    ran = _child(request, limits, Path(path))
    return _outcome(ran, limits, time.perf_counter() - started)


def timed_out(ran: Ran, limits: Limits, seconds: float, printed: str) -> Outcome | None:
    """The "time" outcome of a child ended by the wall clock or its CPU-time limit, else None."""
    if ran.status is None:
        return Outcome("time", error=f"no result within {limits.seconds:g} s: does the loop end?",
                       seconds=seconds, output=printed)
    if ran.status in CPU_LIMIT_STATUSES:
        return Outcome("time", error=f"the CPU-time limit of {limits.seconds:g} s was reached: "
                                     "does the loop end?", seconds=seconds, output=printed)
    return None


def _outcome(ran: Ran, limits: Limits, seconds: float) -> Outcome:
    printed = student_answer.printed(ran)
    timed = timed_out(ran, limits, seconds, printed)
    if timed is not None:
        return timed
    try:
        kind, steps, error = student_answer.case_answer(ran, limits.max_steps)
    except student_answer.NoAnswer as missing:
        if "MemoryError" in printed:
            return Outcome("memory", error="the memory limit was reached (MemoryError)",
                           seconds=seconds, output=printed)
        last = printed.strip().splitlines()[-1:] or [""]
        return Outcome("crash", error=f"the process ended with status {ran.status} and "
                                      f"{missing} {last[0]}".rstrip(),
                       seconds=seconds, output=printed)
    return Outcome(kind, steps, error, seconds, printed)
