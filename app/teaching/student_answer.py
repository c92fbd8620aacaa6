"""The runner's answer (student_child.py), read as untrusted input.

The student's code runs in the same process as the runner and may write
anything on the runner's channel, so the answer is taken only as far as
the protocol goes: the HELLO line, then one JSON object of known kinds
whose steps are whole-number pixels with at most MAX_NAMES named finite
numbers, names and texts of bounded length. Every text in it, and every
print of the student's, goes through escape.foreign_text before a report
sees it.
"""
from __future__ import annotations

import json
import math

from app.model.escape import foreign_text
from app.teaching.sandbox import OUTPUT_LIMIT, Ran, SandboxFailure

HELLO = b"rasterlab-runner 1"  # student_child.HELLO
KINDS = frozenset({"ok", "exception", "shape", "protocol", "too-long", "memory"})
MAX_NAMES = 16
MAX_NAME = 64
MAX_ERROR = 16_000
MAX_COORDINATE = 1 << 31


class NoAnswer(Exception):
    """The runner gave no answer the protocol allows (the text says what it gave)."""


def _lines(ran: Ran) -> list[bytes]:
    """The answer's lines after HELLO; SandboxFailure when there is no HELLO."""
    first, _, rest = ran.answer.partition(b"\n")
    if first != HELLO:
        said = foreign_text(ran.output.decode("utf-8", "replace")).strip().splitlines()
        raise SandboxFailure("the case's process did not start" + (f": {said[-1]}" if said else ""))
    return rest.splitlines()


def probe_answer(ran: Ran) -> dict | None:
    """Which limits the runner set, from a probe's answer (None: no answer)."""
    lines = _lines(ran)
    try:
        held = json.loads(lines[0])
        memory = held["memory"]
        if memory not in (None, "address space", "data segment"):
            return None
        return {"cpu": bool(held["cpu"]), "memory": memory}
    except (IndexError, ValueError, KeyError, TypeError):
        return None


def case_answer(ran: Ran, max_steps: int) -> tuple[str, tuple, str]:
    """(kind, steps, error) of a case's answer, or NoAnswer."""
    lines = _lines(ran)
    if ran.answer_dropped:
        raise NoAnswer(f"an answer over {len(ran.answer) >> 20} MiB")
    if len(lines) != 1:
        raise NoAnswer("no result" if not lines else "more than one result")
    try:
        result = json.loads(lines[0])
    except (ValueError, RecursionError):
        raise NoAnswer("a result that is not JSON") from None
    if not isinstance(result, dict) or result.get("kind") not in KINDS:
        raise NoAnswer("a result of no known kind")
    steps = result.get("steps", [])
    if not isinstance(steps, list) or len(steps) > max_steps:
        raise NoAnswer("a result with more steps than allowed")
    error = result.get("error", "")
    if not isinstance(error, str):
        raise NoAnswer("a result whose error is not text")
    try:
        kept = tuple(_step(step) for step in steps)
    except OverflowError:  # a whole number too large for a float
        raise NoAnswer("a named value that is not a finite number") from None
    return result["kind"], kept, foreign_text(error, MAX_ERROR)


def _step(step) -> tuple:
    if not (isinstance(step, list) and len(step) == 3 and isinstance(step[2], dict)):
        raise NoAnswer("a step that is not [x, y, {name: value}]")
    x, y, values = step
    for v in (x, y):
        if not (isinstance(v, int) and not isinstance(v, bool) and abs(v) < MAX_COORDINATE):
            raise NoAnswer("a pixel that is not a pair of whole numbers")
    if len(values) > MAX_NAMES:
        raise NoAnswer(f"a step with more than {MAX_NAMES} named values")
    kept = {}
    for name, value in values.items():
        number = isinstance(value, (int, float)) and not isinstance(value, bool)
        if len(name) > MAX_NAME or not number or not math.isfinite(value):
            raise NoAnswer("a named value that is not a short name and a finite number")
        kept[foreign_text(name)] = value
    return x, y, kept


def program_answer(ran: Ran, max_steps: int) -> tuple[str, tuple, str]:
    """(kind, steps, error) of a --cmd program's lines (student_command.py):
    "ok" at {"done": true}, "exception" at {"error": text}, "too-long" past
    ``max_steps``, "unfinished" when its output ends first; NoAnswer for a
    line the protocol does not allow, and for an answer over the cap."""
    lines = _lines(ran)
    if ran.answer_dropped:
        lines = lines[:-1]  # the last line kept is cut short
    steps = []
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        if len(steps) >= max_steps:
            return "too-long", tuple(steps), (f"wrote more than {max_steps:,} steps: "
                                              "does the loop end?")
        item = _program_line(line, number)
        if "done" in item:
            return "ok", tuple(steps), ""
        if "error" in item:
            return "exception", tuple(steps), foreign_text(item["error"], MAX_ERROR)
        steps.append(item["step"])
    if ran.answer_dropped:
        raise NoAnswer(f"over {len(ran.answer) >> 20} MiB on stdout")
    return "unfinished", tuple(steps), ""


def _program_line(line: bytes, number: int) -> dict:
    """One line as {"done"}, {"error": text} or {"step": (x, y, values)}."""
    try:
        item = json.loads(line)
    except (ValueError, RecursionError):
        text = line.decode("utf-8", "replace")
        shown = foreign_text(text[:40]).replace("\n", " ") + ("..." if len(text) > 40 else "")
        raise NoAnswer(f"line {number} that is not JSON: {shown}") from None
    if item == {"done": True}:
        return {"done": True}
    if isinstance(item, dict) and set(item) == {"error"} and isinstance(item["error"], str):
        return item
    if not isinstance(item, dict) or not {"x", "y"} <= set(item) <= {"x", "y", "vars"}:
        raise NoAnswer(f"line {number} that is not a step " + '{"x": X, "y": Y, "vars": {...}}, '
                       '{"done": true} or {"error": TEXT}')
    if not isinstance(item.get("vars", {}), dict):
        raise NoAnswer(f"line {number} whose \"vars\" is not an object {{name: number}}")
    try:
        return {"step": _step([item["x"], item["y"], item.get("vars", {})])}
    except NoAnswer as wrong:
        raise NoAnswer(f"line {number} with {wrong}") from None
    except OverflowError:
        raise NoAnswer(f"line {number} with a named value that is not a finite number") from None


def printed(ran: Ran) -> str:
    """The student's own prints as far as kept, safe to show, with the count
    of bytes dropped beyond the cap."""
    text = foreign_text(ran.output.decode("utf-8", "replace"))
    if ran.output_dropped:
        text += (f"\n[{ran.output_dropped:,} more bytes of output not kept: the first "
                 f"{OUTPUT_LIMIT >> 20} MiB are]")
    return text
