"""A student's file as an algorithm of the list, run in a separate process.

``student_spec(path, against)`` makes and registers an AlgorithmSpec that
takes the reference algorithm's inputs: each run starts the student's
draw() in a child process (student.py, with its limits) and turns the
pixels it yields into frames; an error ends the run with a note. The
file is read anew at every run, so an edit shows at the next one.
``first_divergence`` finds the first step where the student's run and the
reference's (or the exact result) part.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

from algorithms import registry
from algorithms.code import Code, listing
from algorithms.registry import AlgorithmSpec
from algorithms.steps import PLOT, Note, Start

from . import checking, student

INPUT_OPTIONS = ("radius", "rx", "ry")  # the options draw() takes as arguments


def student_listing(points, options) -> Code:
    code = Code()
    code.add("run", "run draw(...) of your file in a separate process")
    code.add("plot_yield", "yield x, y  (or x, y, {names: values}): plot(x, y)", PLOT)
    code.add("done", "done (or stopped: the note says why)")
    return code


student_code = listing(student_listing)


def student_name(path) -> str:
    return "student-" + (re.sub(r"[^a-z0-9]+", "-", Path(path).stem.lower()).strip("-") or "file")


def student_spec(path, against: str, limits: student.Limits = student.Limits()) -> AlgorithmSpec:
    """Register the file's draw() as an algorithm of ``against``'s family."""
    path = student.check_file(path)
    reference = registry.get(against)
    kind = checking.kind_of(reference)

    def generator(points, options):
        outcome = student.run_student(path, checking.student_args(kind, points, options), limits)
        return frames(outcome, student_listing(points, options).at)

    spec = AlgorithmSpec(
        name=student_name(path), title=f"{path.name} (yours)", family=reference.family,
        summary=f"draw() of {path.name}, run in a separate process; "
                f"checked against {reference.name}",
        inputs=reference.inputs,
        options=tuple(o for o in reference.options if o.name in INPUT_OPTIONS),
        code=student_code, generator=generator,
        notes=(f"Reference: {reference.title} ({reference.name}).", f"File: {path}"))
    registry.register(spec, replace=True)
    return spec


def frames(outcome: student.Outcome, at):
    names = tuple(sorted({name for _, _, values in outcome.steps for name in values}))
    yield Start(line=at["run"], values=names)
    for x, y, values in outcome.steps:
        yield (at["plot_yield"], x, y, *(float(values.get(n, math.nan)) for n in names))
    if not outcome.ok:
        yield Note(line=at["done"], text=outcome.error.strip().splitlines()[-1])


def first_divergence(trace, against: str, points, options: dict, grid) -> tuple:
    """(step of the student's run, text) of the first difference from the
    reference and from the exact result; step None when they agree."""
    reference = registry.get(against)
    kind = checking.kind_of(reference)
    args = checking.student_args(kind, points, options)
    ref_options = dict(options)
    case = checking.Case("window", tuple(points), ref_options, args)
    expected = checking.reference_steps(reference, case)
    writes = trace.written()
    got = [(int(x), int(y), {}) for x, y in writes.pixels.tolist()]
    exact = checking.exact_pixels(reference, case, reference.resolve(ref_options))
    compare = checking.ordered_divergence if kind == "lines" else checking.unordered_divergence
    found = compare(expected, got)
    versus_exact = None if exact is None else compare([(x, y, {}) for x, y in exact], got)
    if found is None and versus_exact is None:
        return None, f"Same pixels as {against}" + (" and the exact result." if exact else ".")
    which, divergence = (against, found) if found is not None else ("the exact result", versus_exact)
    steps = writes.steps.tolist()
    step = steps[divergence.step] if divergence.step < len(steps) else len(trace) - 1
    return step, (f"First divergence from {which}: pixel {divergence.step} (step {step}): "
                  f"expected {divergence.expected}, got {divergence.got}")
