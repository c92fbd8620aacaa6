"""Run one case of a student's algorithm. Executed as a process of its own.

RasterLab never imports a student's file: app/teaching/student.py starts this
script with ``python -I -S`` and sends one request as JSON on stdin
(the file, the function, its arguments, the limits). This script sets the
limits on itself before it reads the student's code, runs the generator and
writes one JSON object on its own stdout: the steps, or the error. The
student's own prints go to stderr. Standard library only.
"""
import json
import math
import os
import resource
import sys
import traceback


FILE_LIMIT = 16 << 20  # the largest file the student's code may write


class Shape(Exception):
    """A yielded item that is not ``x, y`` or ``x, y, {name: number}``."""


def set_limits(memory: int, cpu_seconds: int) -> None:
    resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
    resource.setrlimit(resource.RLIMIT_CPU, (cpu_seconds, cpu_seconds + 1))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    resource.setrlimit(resource.RLIMIT_FSIZE, (FILE_LIMIT, FILE_LIMIT))


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


def main() -> None:
    request = json.loads(sys.stdin.read())
    set_limits(request["memory"], request["cpu_seconds"])
    out = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)  # the student's prints go to stderr, not into the result
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
