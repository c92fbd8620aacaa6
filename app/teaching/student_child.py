"""Run one case of a student's algorithm. Executed as a process of its own.

RasterLab never imports a student's file: app/teaching/student.py copies
this script and the student's file into the case's scratch folder, starts
it there with ``python -I -S`` (in a sandbox where there is one, see
sandbox.py) and sends one request as JSON on stdin (the file, the
function, its arguments, the limits). This script first writes the line
HELLO on its stdout (the sign that the process started; without it the
failure is RasterLab's), sets the limits on itself before it reads the
student's code, runs the generator and writes one JSON object as the next
line: the steps, or the error. The student's own prints go to stderr.
Standard library only, and self-contained: nothing of RasterLab is
visible where it runs.

Which limits a system lets a process set differs: Windows has no
``resource`` module (no CPU-time or memory limit here; the parent's
wall-clock timeout still ends the process), and macOS may refuse
RLIMIT_AS, where the data segment (RLIMIT_DATA) is limited instead. A
request with ``"probe": true`` only sets the limits and answers which hold.

A request with ``"exec"`` (a program in any language, see
app/teaching/student_command.py) sets the limits, then replaces this
process with that program (on Windows: runs it and passes on its status),
its stdin the request's ``"input"``: its stdout is then the answer. Its
memory is limited by the data segment (RLIMIT_DATA), not the address
space: runtimes such as node and the JVM reserve far more address space
than they use.
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import traceback

try:
    import resource
except ImportError:  # Windows
    resource = None


FILE_LIMIT = 16 << 20  # the largest file the student's code may write
OPEN_FILES = 64
PROCESSES = 64  # counted per user; root is exempt (a sandbox's pid namespace still ends them)
HELLO = "rasterlab-runner 1"


class Shape(Exception):
    """A yielded item that is not ``x, y`` or ``x, y, {name: number}``."""


MEMORY_LIMITS = (("RLIMIT_AS", "address space"), ("RLIMIT_DATA", "data segment"))


def set_limits(memory: int, cpu_seconds: int, rlimits=resource, kinds=MEMORY_LIMITS) -> dict:
    """Set on this process the limits that ``rlimits`` (the ``resource``
    module, None where there is none) lets it set, the memory as the first
    of ``kinds`` that holds, and say which hold:
    {"cpu": bool, "memory": "address space", "data segment" or None}."""
    if rlimits is None:
        return {"cpu": False, "memory": None}
    held = {"cpu": _limit(rlimits, "RLIMIT_CPU", cpu_seconds, cpu_seconds + 1), "memory": None}
    for name, what in kinds:
        if _limit(rlimits, name, memory, memory):
            held["memory"] = what
            break
    _limit(rlimits, "RLIMIT_CORE", 0, 0)
    _limit(rlimits, "RLIMIT_FSIZE", FILE_LIMIT, FILE_LIMIT)
    _limit(rlimits, "RLIMIT_NOFILE", OPEN_FILES, OPEN_FILES)
    _limit(rlimits, "RLIMIT_NPROC", PROCESSES, PROCESSES)
    return held


def _limit(rlimits, name: str, soft: int, hard: int) -> bool:
    """Set one limit, kept within a lower hard limit already in force (a
    process cannot raise its own); False where the system has or allows none."""
    number = getattr(rlimits, name, None)
    if number is None:
        return False
    try:
        current = rlimits.getrlimit(number)[1]
        if current != rlimits.RLIM_INFINITY:
            hard = min(hard, current)
        rlimits.setrlimit(number, (min(soft, hard), hard))
    except (ValueError, OSError):  # macOS refuses RLIMIT_AS so
        return False
    return True


def whole(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def checked(item, n: int, value_name=None) -> list:
    """One step as [x, y, {name: number}], or Shape with what is wrong. With
    ``value_name``, ``x, y, number`` is [x, y, {value_name: number}]."""
    if not isinstance(item, (tuple, list)) or len(item) not in (2, 3):
        expected = f"x, y, {value_name}" if value_name else "x, y or x, y, {name: value}"
        raise Shape(f"step {n}: yielded {brief(item)}; expected {expected}")
    if value_name and len(item) == 3 and not isinstance(item[2], dict):
        item = (item[0], item[1], {value_name: item[2]})
    x, y = item[0], item[1]
    if not (whole(x) and whole(y)):
        raise Shape(f"step {n}: yielded ({brief(x)}, {brief(y)}); pixel coordinates must be "
                     "whole numbers (int)")
    names = item[2] if len(item) == 3 else {}
    if not isinstance(names, dict):
        raise Shape(f"step {n}: the third item is {brief(names)}; expected a dict of named values")
    values = {}
    for name, value in names.items():
        number = isinstance(value, (int, float)) and not isinstance(value, bool)
        if not isinstance(name, str) or not number or not math.isfinite(value):
            raise Shape(f"step {n}: variable {brief(name)} = {brief(value)}; expected a name and "
                        "a finite number")
        values[name] = value
    return [x, y, values]


def brief(value) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def student_traceback(error: BaseException, path: str) -> str:
    """The traceback from the student's own frames on: it is their code."""
    frames = traceback.extract_tb(error.__traceback__)
    own = [frame for frame in frames if frame.filename == path]
    lines = traceback.format_list(own) + traceback.format_exception_only(type(error), error)
    return "".join(lines).rstrip()


def run(request: dict) -> dict:
    path, name = request["file"], request["function"]
    namespace = {"__name__": "student", "__file__": path}
    with open(path, encoding="utf-8") as source:
        code = compile(source.read(), path, "exec")
    exec(code, namespace)
    function = namespace.get(name)
    if not callable(function):
        return {"kind": "protocol", "error": f"the file defines no function {name}()"}
    steps = []
    produced = function(*request["args"])
    if not hasattr(produced, "__next__"):
        return {"kind": "protocol",
                "error": f"{name}() returned {brief(produced)}, not a generator: yield each pixel"}
    for n, item in enumerate(produced):
        if n >= request["max_steps"]:
            return {"kind": "too-long", "steps": steps,
                    "error": f"yielded more than {request['max_steps']:,} pixels: "
                             "does the loop end?"}
        steps.append(checked(item, n, request.get("value")))
    return {"kind": "ok", "steps": steps}


def launch(request: dict) -> None:
    """Become the program ``request["exec"]`` with ``request["input"]`` as
    its stdin; where it cannot start, answer so as the protocol's error line."""
    argv = request["exec"]
    with tempfile.TemporaryFile() as given:  # in the case's own TMPDIR
        given.write(request["input"].encode("utf-8"))
        given.seek(0)
        os.dup2(given.fileno(), 0)
    sys.stdout.flush()
    try:
        if os.name == "nt":  # no exec there: the parent's wall clock must see the program
            sys.exit(subprocess.call(argv))
        os.execv(argv[0], argv)
    except OSError as error:
        print(json.dumps({"error": f"could not start {argv[0]}: {error.strerror}"}))


def main() -> None:
    sys.stdout.write(HELLO + "\n")
    sys.stdout.flush()
    request = json.loads(sys.stdin.read())
    if "exec" in request:
        set_limits(request["memory"], request["cpu_seconds"], kinds=MEMORY_LIMITS[1:])
        launch(request)
        return
    held = set_limits(request["memory"], request["cpu_seconds"])
    if request.get("probe"):
        print(json.dumps(held))
        return
    out = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)  # the student's prints go to stderr, not into the result
    # UTF-8 whatever the locale (a Windows pipe's is a code page): print("≤") works.
    sys.stderr.reconfigure(encoding="utf-8", errors="backslashreplace")
    sys.stdout = sys.stderr
    try:
        result = run(request)
    except Shape as error:
        result = {"kind": "shape", "error": str(error)}
    except MemoryError:
        result = {"kind": "memory", "error": "the memory limit was reached (MemoryError)"}
    except BaseException as error:  # the student's exception, whatever it is
        result = {"kind": "exception", "error": student_traceback(error, request["file"])}
    out.write(json.dumps(result))
    out.flush()


if __name__ == "__main__":
    main()
