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

from algorithms.core import registry
from algorithms.antialias.lines import ink_grey
from algorithms.core.code import Code, listing
from algorithms.core.registry import AlgorithmSpec
from algorithms.core.steps import PLOT, Note, Start

from app.teaching import check_families, checking, student

# The options draw() takes as arguments (a fill's seed, the depths of a z-buffer's vertices).
INPUT_OPTIONS = ("radius", "rx", "ry", "seed", "z")


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

    value_name = "intensity" if kind == "antialias" else None

    def generator(points, options, grid=None):
        options = with_seed(reference, kind, points, options, grid)
        outcome = student.run_student(path, checking.student_args(kind, points, options), limits,
                                      value_name=value_name)
        return frames(outcome, student_listing(points, options).at, value_name)

    spec = AlgorithmSpec(
        name=student_name(path), title=f"{path.name} (yours)", family=reference.family,
        summary=f"draw() of {path.name}, run in a separate process; "
                f"checked against {reference.name}",
        inputs=reference.inputs,
        options=tuple(o for o in reference.options if o.name in INPUT_OPTIONS),
        code=student_code, generator=generator, uses_grid=reference.uses_grid,
        notes=(f"Reference: {reference.title} ({reference.name}).", f"File: {path}"))
    registry.register(spec, replace=True)
    return spec


def with_seed(reference, kind: str, points, options: dict, grid) -> dict:
    """A fill's options with the seed the reference takes when it is "auto"."""
    if kind != "fill" or options.get("seed", "auto") != "auto":
        return options
    trace = reference.record(points, {"seed": "auto"}, grid=grid or checking.ORACLE_GRID)
    return {**options, "seed": tuple(trace.start.constants["seed"])}


def frames(outcome: student.Outcome, at, value_name: str | None = None):
    names = tuple(sorted({name for _, _, values in outcome.steps for name in values}))
    if value_name not in names:
        yield Start(line=at["run"], values=names)
        for x, y, values in outcome.steps:
            yield (at["plot_yield"], x, y, *(float(values.get(n, math.nan)) for n in names))
    else:
        # Intensities show as grey ink on white, as the built-in antialiased lines do.
        yield Start(line=at["run"], values=names + ("rgb",), pixel_value=value_name,
                    color_value="rgb")
        for x, y, values in outcome.steps:
            shade = values.get(value_name, math.nan)
            yield (at["plot_yield"], x, y, *(float(values.get(n, math.nan)) for n in names),
                   ink_grey(min(max(shade, 0.0), 1.0)) if shade == shade else math.nan)
    if not outcome.ok:
        yield Note(line=at["done"], text=outcome.error.strip().splitlines()[-1])


def first_divergence(trace, against: str, points, options: dict, grid) -> tuple:
    """(step of the student's run, text) of the first difference from the
    reference and from the exact result; step None when they agree."""
    reference = registry.get(against)
    kind = checking.kind_of(reference)
    ref_options = with_seed(reference, kind, points, dict(options), grid)
    args = checking.student_args(kind, points, ref_options)
    case = checking.Case("window", tuple(points), ref_options, args)
    expected = checking.reference_steps(reference, case)
    writes = trace.written()
    if kind in check_families.SIGNATURES:
        got = written_values(trace, writes)
        exact = check_families.exact(reference, case, reference.resolve(ref_options))

        def compare(want, have):
            return check_families.divergence(kind, want, have, checking.Divergence)
    else:
        got = [(int(x), int(y), {}) for x, y in writes.pixels.tolist()]
        exact = checking.exact_pixels(reference, case, reference.resolve(ref_options))
        exact = None if exact is None else [(x, y, {}) for x, y in exact]
        compare = checking.ordered_divergence if kind == "lines" else checking.unordered_divergence
    found = compare(expected, got)
    versus_exact = None if exact is None else compare(exact, got)
    if found is None and versus_exact is None:
        what = "pixels and intensities" if kind == "antialias" else "pixels"
        return None, f"Same {what} as {against}" + (" and the exact result." if exact else ".")
    which, divergence = (against, found) if found is not None else ("the exact result", versus_exact)
    steps = writes.steps.tolist()
    step = steps[divergence.step] if divergence.step < len(steps) else len(trace) - 1
    return step, (f"First divergence from {which}: pixel {divergence.step} (step {step}): "
                  f"expected {divergence.expected}, got {divergence.got}")


def written_values(trace, writes) -> list:
    """(x, y, {name: value}) per pixel the student's run wrote, NaN left out."""
    columns = {name: trace.series(name)[writes.steps].tolist() for name in trace.start.values}
    return [(int(x), int(y), {name: v[n] for name, v in columns.items() if v[n] == v[n]})
            for n, (x, y) in enumerate(writes.pixels.tolist())]
