"""A student's algorithm in any language: a program run by ``--cmd``.

The program reads one case as one JSON line on stdin,

    {"against": "line-bresenham", "args": [0, 0, 5, 3]}

(``args`` are what the Python template's draw() takes, in its order), and
writes one JSON line per step on stdout, then the end marker:

    {"x": 0, "y": 0, "vars": {"d": 1}}
    {"x": 1, "y": 1}
    {"done": true}

or, in place of the end marker, ``{"error": "why"}`` for a failure of its
own. Blank lines are skipped; anything else on stdout breaks the protocol:
the program's own messages go to stderr (shown with the case, capped).

``--cmd`` is run in each submission: a folder (a compiled program and what
it needs) is copied whole into the case's scratch folder, a single file
under its own name; ``{}`` in the command stands for that file's name. The
command's first word is a path into the submission (``./raster``) or a
program of this system (``node``, ``java``, found on PATH), which the
sandbox then shows read-only with its installation; never one in the
user's home or in RasterLab. The runner (student_child.py) sets the
limits and then becomes the program; what it writes is read as untrusted
input (student_answer.py), with the same caps as the Python runner's answer.
"""
from __future__ import annotations

import json
import math
import os
import shlex
import shutil
import time
from dataclasses import dataclass
from pathlib import Path

from algorithms.core.errors import InputError
from app.model import shipped
from app.teaching import sandbox, student, student_answer
from app.teaching.student import Limits, Outcome

PLACEHOLDER = "{}"
MAX_FILES = 1000
MAX_BYTES = 64 << 20  # a submission folder, copied for every case
HOMES = ("/", "/usr", "/usr/local")  # a bin/ folder here is no program's own installation


@dataclass(frozen=True)
class Command:
    """``--cmd`` as given, its words, and the system program its first word
    names (resolved, with what the sandbox must show of it), if it names one."""

    text: str
    words: tuple
    program: str | None = None
    shown: tuple = ()


@dataclass(frozen=True)
class Program:
    """One submission's program: the command's words for it, the folder
    copied into the scratch folder, or the file (copied under its own name)."""

    command: Command
    words: tuple
    path: Path

    @property
    def name(self) -> str:
        return self.path.name


def parse(text: str) -> Command:
    """``--cmd``'s text as a Command (InputError for one that cannot run)."""
    try:
        words = tuple(shlex.split(text))
    except ValueError as error:
        raise InputError(f"--cmd {text!r}: {error}") from None
    if not words:
        raise InputError("--cmd needs a command, e.g. --cmd ./raster or --cmd \"node raster.js\"")
    first = words[0]
    if "/" in first and not os.path.isabs(first):
        if ".." in Path(first).parts:
            raise InputError(f"--cmd {text!r}: {first} must lie inside the submission")
        return Command(text, words)
    found = shutil.which(first)
    if found is None:
        raise InputError(f"--cmd {text!r}: no program {first!r} on this system; name a file of "
                         "the submission as ./NAME")
    program = os.path.realpath(found)
    refused = _refused(program)
    if refused:
        raise InputError(f"--cmd {text!r}: {program} is {refused}, which the sandbox never "
                         "shows; use a program installed for the whole system")
    return Command(text, (program, *words[1:]), program, _installation(program))


def _refused(path: str) -> str:
    """Why the sandbox may not show ``path`` ("" when it may)."""
    checks = (("in your home folder", Path.home()), ("part of RasterLab", shipped.PROGRAM))
    for what, folder in checks:
        try:
            if Path(path).is_relative_to(Path(folder).resolve()):
                return what
        except OSError:
            continue
    return ""


def _installation(program: str) -> tuple:
    """What the sandbox shows of a system program: the installation it lies
    in when it has one of its own (the JVM's /usr/lib/jvm/NAME for its
    bin/java), else the program and its package's folders named after it
    (/usr/lib/python3.11 for /usr/bin/python3.11); the system's shared
    libraries are shown anyway."""
    folder = os.path.dirname(program)
    home = os.path.dirname(folder)
    if os.path.basename(folder) == "bin" and home not in HOMES and not _refused(home):
        return (home,)
    name = os.path.basename(program)
    own = [os.path.join(home, part, name) for part in ("lib", "share")]
    return (program, *(path for path in own if os.path.isdir(path)))


def program_for(command: Command, submission) -> Program:
    """The program of one submission (a folder or a file), checked before any case runs."""
    path = Path(submission)
    if not path.exists():
        raise InputError(f"{path}: no such file or folder")
    if path.is_dir():
        if any(PLACEHOLDER in word for word in command.words):
            raise InputError(f"{path}: {PLACEHOLDER} in --cmd stands for a submission file; "
                             "this is a folder")
        _check_size(path)
        words = command.words
    else:
        words = tuple(word.replace(PLACEHOLDER, path.name) for word in command.words)
    return Program(command, words, path.resolve())


def _check_size(folder: Path) -> None:
    files = size = 0
    for root, _, names in os.walk(folder):
        for name in names:
            files += 1
            try:
                size += os.lstat(os.path.join(root, name)).st_size
            except OSError:
                continue
    if files > MAX_FILES or size > MAX_BYTES:
        raise InputError(f"{folder}: {files} files, {size >> 20} MiB; a submission folder is "
                         f"copied for every case, so it may hold {MAX_FILES} files and "
                         f"{MAX_BYTES >> 20} MiB at most")


def request_line(against: str, args) -> str:
    """The case as the program reads it: one JSON line."""
    return json.dumps({"against": against, "args": list(args)}) + "\n"


def run_program(program: Program, against: str, args, limits: Limits = Limits()) -> Outcome:
    """The program's steps on one case, as an Outcome (student.Outcome's kinds);
    a named value such as line-wu's intensity comes in ``vars``."""
    request = {"exec": list(program.words), "input": request_line(against, args),
               "memory": limits.memory, "cpu_seconds": max(1, math.ceil(limits.seconds))}
    if program.path.is_dir():
        files, tree = {sandbox.RUNNER: student.CHILD}, program.path
    else:
        files, tree = {program.name: program.path, sandbox.RUNNER: student.CHILD}, None
    started = time.perf_counter()
    ran = sandbox.run_case(files, json.dumps(request).encode("utf-8"),
                           student.wall_seconds(limits), sandbox.isolation(), tree,
                           program.command.shown)
    return outcome(ran, limits, time.perf_counter() - started)


def outcome(ran: sandbox.Ran, limits: Limits, seconds: float) -> Outcome:
    """What the program's run gave: its steps up to the end marker, or why not."""
    printed = student_answer.printed(ran)
    timed = student.timed_out(ran, limits, seconds, printed)
    if timed is not None:
        return timed
    try:
        kind, steps, error = student_answer.program_answer(ran, limits.max_steps)
    except student_answer.NoAnswer as missing:
        return Outcome("protocol", error=f"the program wrote {missing}", seconds=seconds,
                       output=printed)
    if kind == "ok" and ran.status != 0:
        kind, error = "crash", f"the program ended with status {ran.status} after {{\"done\": true}}"
    elif kind == "unfinished":
        last = printed.strip().splitlines()[-1:] or [""]
        kind = "crash"
        error = (f"the program ended with status {ran.status} after {len(steps)} steps without "
                 f"{{\"done\": true}} {last[0]}").rstrip()
    return Outcome(kind, steps, error, seconds, printed)
