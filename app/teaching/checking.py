"""Check a student's algorithm against a built-in one and the exact oracle.

For each case (the hard-case catalogue, seeded random inputs, or the inputs
of saved scenes) the student's generator runs in its own process
(student.py); its pixels are compared with the reference algorithm's trace,
in order for lines (and the named variables the student yields with the
reference's names), as a multiset for circles, whose eight mirror images
may come in any order. The exact oracle is compared as well where one
exists for the reference. A case passes when both agree with the student.
"""
from __future__ import annotations

import random
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from algorithms.core import cases as catalogue
from algorithms.core import registry
from algorithms.core.errors import InputError
from algorithms.core.trace import DEFAULT_STEP_CAP
from algorithms.exact import circles as exact_circles
from algorithms.exact import lines as exact_lines
from algorithms.exact import polygons as exact_polygons
from algorithms.exact import triangles as exact_triangles

from app.model import budget
from app.teaching import check_families as families
from app.teaching import explain
from app.teaching.student import Limits, Outcome, run_student
from app.teaching.student_command import Program, run_program

# What the student's draw() takes, per family: the template's signature.
SIGNATURES = {"lines": "draw(x0, y0, x1, y1)", "circles": "draw(xc, yc, r)",
              "ellipse": "draw(xc, yc, rx, ry)", "triangles": "draw(x0, y0, x1, y1, x2, y2)",
              "polygons": "draw(contours)", **families.SIGNATURES}
CIRCLE_CENTRE = (16, 16)
ORACLE_GRID = (64, 64)


@dataclass(frozen=True)
class Case:
    """One input: its name, the reference's points and options, and draw()'s arguments."""

    name: str
    points: tuple
    options: dict
    args: tuple


@dataclass(frozen=True)
class Divergence:
    """The first step where the student and a reference differ."""

    step: int          # the student's pixel, counted from 0
    expected: str
    got: str
    pixel: tuple | None = None  # the pixel of an unordered divergence
    extra: bool = False         # ... yielded but not expected (else expected, not yielded)
    where: str = ""    # as reports name it: "step S" as the window numbers a line's steps
    why: str = ""      # the values that decide it (explain.py)

    def text(self) -> str:
        head = f"{self.where or f'step {self.step}'}: expected {self.expected}, got {self.got}"
        return f"{head}. {self.why}" if self.why else head


@dataclass(frozen=True)
class CaseResult:
    case: Case
    outcome: Outcome
    reference: Divergence | None  # None: agrees with the reference algorithm
    exact: Divergence | None      # None: agrees with the exact oracle (or there is none)
    has_exact: bool
    compared: tuple = ()          # the variable names compared

    @property
    def passed(self) -> bool:
        return self.outcome.ok and self.reference is None and self.exact is None

    def message(self) -> str:
        """One line: why the case failed ("" when it passed)."""
        if not self.outcome.ok:
            return self.outcome.error.strip().splitlines()[-1] if self.outcome.error else self.outcome.kind
        if self.reference is not None:
            return f"differs from the reference: {self.reference.text()}"
        if self.exact is not None:
            return f"differs from the exact result: {self.exact.text()}"
        return ""


def kind_of(spec) -> str:
    """The protocol a spec's student takes: lines, circles or ellipse."""
    if spec.family == "lines":
        return "lines"
    if spec.name == "ellipse-midpoint":
        return "ellipse"
    if spec.family in ("circles", "triangles", "polygons"):
        return spec.family
    if families.kind_of(spec):
        return families.kind_of(spec)
    raise InputError(f"check compares lines, circles, triangles, polygons, flood-fill, zbuffer, "
                     f"painter, line-wu and line-area; {spec.name} is in the {spec.family} family")


# -------------------------------------------------------------------- cases
def parse_selectors(words: list[str]) -> list:
    """``hard``, ``random N`` and SCENE.json paths, in order, as (what, value) pairs."""
    selectors, words = [], list(words)
    while words:
        word = words.pop(0)
        if word == "hard":
            selectors.append(("hard", None))
        elif word == "random":
            count = words.pop(0) if words else ""
            if not count.isdigit() or not 1 <= int(count) <= 10_000:
                raise InputError(f"--cases random takes a count 1 .. 10000, got {count!r}")
            selectors.append(("random", int(count)))
        elif word.endswith(".json"):
            selectors.append(("scene", word))
        else:
            raise InputError(f"--cases: {word!r} is not hard, random N or a SCENE.json")
    return selectors or [("hard", None)]


def make_cases(spec, selectors, seed: int = 0) -> list[Case]:
    kind = kind_of(spec)
    made = []
    for what, value in selectors:
        if what == "hard":
            made += hard_cases(kind)
        elif what == "random":
            made += random_cases(kind, value, seed)
        else:
            made.append(scene_case(spec, kind, value))
    return made


def student_args(kind: str, points, options: dict) -> tuple:
    """draw()'s arguments for a run on these points and options."""
    if kind in families.SIGNATURES:
        return families.student_args(kind, points, options)
    if kind == "triangles":
        return tuple(v for point in points for v in point)
    if kind == "polygons":
        return ([[list(p) for p in contour] for contour in points],)
    if kind == "lines":
        (x0, y0), (x1, y1) = points
        return (x0, y0, x1, y1)
    (cx, cy), = points
    if kind == "ellipse":
        return (cx, cy, options["rx"], options["ry"])
    return (cx, cy, options["radius"])


def line_case(name, p, q) -> Case:
    return Case(name, (tuple(p), tuple(q)), {}, (p[0], p[1], q[0], q[1]))


def circle_case(name, kind, centre, r, ry=None) -> Case:
    if kind == "ellipse":
        return Case(name, (centre,), {"rx": r, "ry": ry}, (centre[0], centre[1], r, ry))
    return Case(name, (centre,), {"radius": r}, (centre[0], centre[1], r))


def triangle_case(name, triangle) -> Case:
    return Case(name, tuple(triangle), {}, tuple(v for point in triangle for v in point))


def polygon_case(name, contours) -> Case:
    return Case(name, tuple(contours), {}, ([[list(p) for p in c] for c in contours],))


def hard_cases(kind: str) -> list[Case]:
    if kind in families.SIGNATURES:
        return families.hard_cases(Case, kind)
    if kind == "triangles":
        return [triangle_case(f"hard {n + 1}: " + " ".join(f"({x:g},{y:g})" for x, y in t), t)
                for n, t in enumerate(catalogue.TRIANGLE_CASES)]
    if kind == "polygons":
        return [polygon_case(f"hard {n + 1}: {sum(map(len, c))} points", c)
                for n, c in enumerate(catalogue.POLYGON_CASES)]
    if kind == "lines":
        return [line_case(f"hard {n + 1}: ({p[0]},{p[1]})->({q[0]},{q[1]})", p, q)
                for n, (p, q) in enumerate(catalogue.LINE_CASES)]
    if kind == "ellipse":
        return [circle_case(f"hard {n + 1}: rx={rx} ry={ry}", kind, CIRCLE_CENTRE, rx, ry)
                for n, (rx, ry) in enumerate(catalogue.ELLIPSE_AXES)]
    return [circle_case(f"hard {n + 1}: r={r}", kind, CIRCLE_CENTRE, r)
            for n, r in enumerate(catalogue.CIRCLE_RADII)]


def random_cases(kind: str, count: int, seed: int) -> list[Case]:
    """``count`` inputs from a seeded generator: the same seed, the same cases."""
    if kind in families.SIGNATURES:
        return families.random_cases(Case, kind, count, seed)
    rng = random.Random(seed)
    made = []
    for n in range(count):
        if kind == "triangles":
            t = tuple((rng.randint(0, 255) / 8, rng.randint(0, 191) / 8) for _ in range(3))
            made.append(triangle_case(f"random {n + 1}: " + " ".join(
                f"({x:g},{y:g})" for x, y in t), t))
        elif kind == "polygons":
            c = (tuple((rng.randint(0, 127) / 4, rng.randint(0, 95) / 4)
                       for _ in range(rng.randint(3, 6))),)
            made.append(polygon_case(f"random {n + 1}: {len(c[0])} points", c))
        elif kind == "lines":
            p = (rng.randint(0, 31), rng.randint(0, 31))
            q = (rng.randint(0, 31), rng.randint(0, 31))
            made.append(line_case(f"random {n + 1}: ({p[0]},{p[1]})->({q[0]},{q[1]})", p, q))
        elif kind == "ellipse":
            rx, ry = rng.randint(0, 15), rng.randint(0, 15)
            made.append(circle_case(f"random {n + 1}: rx={rx} ry={ry}", kind, CIRCLE_CENTRE, rx, ry))
        else:
            r = rng.randint(0, 15)
            made.append(circle_case(f"random {n + 1}: r={r}", kind, CIRCLE_CENTRE, r))
    return made


def scene_case(spec, kind: str, path: str) -> Case:
    from app.model import scene as scenes
    try:
        scene = scenes.load(path)
    except scenes.SceneError as error:
        raise InputError(str(error)) from None
    if kind_of(scene.spec) != kind:
        raise InputError(f"{path}: a {scene.spec.family} scene; {spec.name} takes {kind}")
    name = f"{Path(path).name}"
    if kind in families.SIGNATURES:
        made = families.scene_case(Case, kind, scene, name, scene.spec.resolve(scene.options))
        if made is None:
            raise InputError(f"{path}: check needs the scene's seed as a point, not auto")
        return made
    if kind == "triangles":
        if len(scene.points) != 3:
            raise InputError(f"{path}: check takes one triangle, the scene has "
                             f"{len(scene.points) // 3}")
        return triangle_case(name, scene.points)
    if kind == "polygons":
        return polygon_case(name, scene.points)
    if kind == "lines":
        p, q = scene.points
        return line_case(name, p, q)
    options = scene.spec.resolve(scene.options)
    if kind == "ellipse":
        return circle_case(name, kind, scene.points[0], options["rx"], options["ry"])
    return circle_case(name, kind, scene.points[0], options["radius"])


# --------------------------------------------------------------- comparing
def reference_steps(spec, case: Case) -> list:
    """(x, y, {variables}) per pixel the reference writes, in order."""
    # the reference's own run is held to the default budget (a case's scene
    # may be any size); over it, the check is refused before it starts
    budget.check_budget(spec, case.points, case.options, ORACLE_GRID, DEFAULT_STEP_CAP)
    trace = spec.record(case.points, case.options, grid=ORACLE_GRID, step_cap=DEFAULT_STEP_CAP)
    if kind_of(spec) in families.SIGNATURES:
        return families.reference(spec, trace, kind_of(spec))
    writes = trace.written()
    steps = writes.steps.tolist()
    return explain.ReferenceSteps([(int(x), int(y), trace.variables_at(int(step)))
                                   for step, (x, y) in zip(steps, writes.pixels.tolist())],
                                  steps, len(trace) - 1)


def exact_pixels(spec, case: Case, options: dict) -> list | None:
    """The exact oracle's pixels for the reference's convention, or None."""
    if spec.name == "line-bresenham":
        tie = "down" if options.get("symmetric") else "toward-P"
        return exact_lines.nearest_pixel_line(*case.points, tie)
    oracles = {"circle-midpoint": exact_circles.midpoint_circle,
               "circle-sqrt8": exact_circles.sqrt8_circle,
               "circle-sqrt4": exact_circles.sqrt4_circle}
    if spec.family == "triangles":
        return exact_triangle(case, options)
    if spec.name == "polygon-scanline":
        return exact_polygon(case, options)
    if spec.name in oracles and options.get("start", "integer") == "integer":
        (cx, cy), r = case.points[0], case.options["radius"]
        return [(cx + x, cy + y) for x, y in sorted(oracles[spec.name](r))]
    return None


def exact_triangle(case: Case, options: dict) -> list | None:
    if options.get("precision", "fixed") != "fixed" or tuple(options.get("offset", (0, 0))) != (0, 0):
        return None
    counts = exact_triangles.coverage(case.points, options.get("subpixel_bits", 8),
                                      options.get("fill_rule", "top-left"),
                                      (0, 0) + ORACLE_GRID, options.get("cull", False))
    return [pixel for pixel, count in sorted(counts.items()) for _ in range(count)]


def exact_polygon(case: Case, options: dict) -> list | None:
    if options.get("arithmetic", "exact") != "exact":
        return None
    snapped = exact_polygons.snap_polygon(case.points)
    winding, i0, j0 = exact_polygons.winding_grid(snapped)
    rule = options.get("fill_rule", "evenodd")
    return [(i0 + int(i), j0 + int(j)) for j, i in zip(*winding.nonzero())
            if exact_polygons.is_covered(int(winding[j, i]), rule)]


def ordered_divergence(expected: list, got: list, names=()) -> Divergence | None:
    """The first step whose pixel (or a named variable) differs, or where one run ends first."""
    for n, (want, have) in enumerate(zip(expected, got)):
        if tuple(want[:2]) != tuple(have[:2]):
            return Divergence(n, f"pixel {pixel_text(want)}", f"pixel {pixel_text(have)}")
        for name in names:
            if name in have[2] and name in want[2] and float(have[2][name]) != float(want[2][name]):
                return Divergence(n, f"{name} = {number_text(want[2][name])}",
                                  f"{name} = {number_text(have[2][name])}")
    return _length_divergence(expected, got)


def unordered_divergence(expected: list, got: list) -> Divergence | None:
    """The first step whose pixel the reference does not have (or has fewer times);
    then the first pixel the student never yields."""
    left = Counter(tuple(p[:2]) for p in expected)
    for n, have in enumerate(got):
        pixel = tuple(have[:2])
        if left[pixel] <= 0:
            times = Counter(tuple(p[:2]) for p in expected)[pixel]
            want = f"{pixel_text(pixel)} only {times} time{'s' if times > 1 else ''}" if times \
                else f"no pixel {pixel_text(pixel)}"
            return Divergence(n, want, f"pixel {pixel_text(pixel)}", pixel, True)
        left[pixel] -= 1
    missing = [p for p in expected if left[tuple(p[:2])] > 0]
    if missing:
        more = f" (and {len(missing) - 1} more)" if len(missing) > 1 else ""
        return Divergence(len(got), f"pixel {pixel_text(missing[0])}{more}", "the end",
                          tuple(missing[0][:2]))
    return None


def _length_divergence(expected, got) -> Divergence | None:
    n = min(len(expected), len(got))
    if len(expected) > n:
        return Divergence(n, f"pixel {pixel_text(expected[n])}", "the end")
    if len(got) > n:
        return Divergence(n, "the end", f"pixel {pixel_text(got[n])}")
    return None


def pixel_text(pixel) -> str:
    return f"({pixel[0]}, {pixel[1]})"


def number_text(value) -> str:
    return registry.format_value(float(value))


def with_options(options: dict, case: Case) -> Case:
    """``case`` with the reference's options under its own."""
    return Case(case.name, case.points, {**options, **case.options}, case.args)


def check_case(spec, options: dict, path, case: Case, limits: Limits,
               expected: list | None = None) -> CaseResult:
    """One case's result; ``path`` is the student's Python file, or a
    student_command.Program; ``expected`` is the reference's steps on it when
    known already (a class's submissions share them), else they are made."""
    case = with_options(options, case)
    expected = reference_steps(spec, case) if expected is None else expected
    kind = kind_of(spec)
    if isinstance(path, Program):
        outcome = run_program(path, spec.name, case.args, limits.steps_for(len(expected)))
    else:
        outcome = run_student(path, case.args, limits.steps_for(len(expected)),
                              value_name="intensity" if kind == "antialias" else None)
    if kind in families.SIGNATURES:
        return family_result(spec, case, outcome, expected)
    exact = exact_pixels(spec, case, spec.resolve(case.options))
    got = list(outcome.steps)
    if kind_of(spec) == "lines":
        names = tuple(sorted({name for step in got for name in step[2]}
                             & {name for step in expected for name in step[2]}))
        reference = ordered_divergence(expected, got, names)
        versus_exact = None if exact is None else ordered_divergence(
            [(x, y, {}) for x, y in exact], got)
    else:
        names = ()
        reference = unordered_divergence(expected, got)
        versus_exact = None if exact is None else unordered_divergence(
            [(x, y, {}) for x, y in exact], got)
    if not outcome.ok:
        reference = versus_exact = None
    resolved = spec.resolve(case.options)
    reference = explain.explained(kind, spec, case, expected, got, reference, resolved)
    versus_exact = None if exact is None else explain.explained(
        kind, spec, case, [(x, y, {}) for x, y in exact], got, versus_exact, resolved, expected)
    return CaseResult(case, outcome, reference, versus_exact, exact is not None, names)


def family_result(spec, case: Case, outcome: Outcome, expected: list) -> CaseResult:
    """A fill, visibility or antialias case: compared as check_families says."""
    kind, got = kind_of(spec), list(outcome.steps)
    exact = families.exact(spec, case, spec.resolve(case.options))
    reference = versus_exact = None
    if outcome.ok:
        reference = families.divergence(kind, expected, got, Divergence)
        versus_exact = None if exact is None else families.divergence(kind, exact, got, Divergence)
    reference, versus_exact = (None if found is None else explain.explained(
        kind, spec, case, expected, got, found, {}) for found in (reference, versus_exact))
    return CaseResult(case, outcome, reference, versus_exact, exact is not None)


def check(path, against: str, made: list[Case], options: dict | None = None,
          limits: Limits = Limits(), progress=None, give_up_after: int = 0,
          on_result=None) -> list[CaseResult]:
    """Every case's result (cases from ``make_cases``); ``on_result(result)``
    and ``progress(done, total)`` hear each case end. After ``give_up_after`` cases ran out of time (0:
    never) the others are not run but marked skipped, so code that loops
    costs a few time limits, not one per case."""
    spec = registry.get(against)
    options = spec.resolve(options or {})
    results, timeouts = [], 0
    for case in made:
        if give_up_after and timeouts >= give_up_after:
            results.append(skipped_result(case, timeouts))
        else:
            results.append(check_case(spec, options, path, case, limits))
            timeouts += results[-1].outcome.kind == "time"
        if on_result is not None:
            on_result(results[-1])
        if progress is not None:
            progress(len(results), len(made))
    return results


def skipped_result(case, timeouts: int) -> CaseResult:
    """A case not run because ``timeouts`` cases before it ran out of time."""
    outcome = Outcome("skipped", error=f"not run: {timeouts} cases of this submission ran out "
                                       "of time before it (--give-up-after)")
    return CaseResult(case, outcome, None, None, False)
