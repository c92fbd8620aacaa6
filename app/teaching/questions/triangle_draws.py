"""What the triangle-based templates share: drawing a triangle a person can
work with by hand, running an algorithm on it and reading the frames of one
pixel, and the text of exact numbers.

Vertices lie on a 1/2 px grid inside a small grid, so edge values at pixel
centres are multiples of 1/4 and every recorded edge value is a float
exactly. Answers are read from the run (app/model/runs.py), never worked
out again here.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from algorithms.core import registry
from algorithms.core.steps import NO_PIXEL

from app.model import runs
from app.model.scene import Scene
from app.teaching.questions.model import Question, Template
from app.teaching.questions import common

GRID = (10, 8)          # small enough to read coordinates off the picture
STEP_CAP = 200_000      # far above what a 16x12 grid needs
MIN_AREA2 = 8           # twice the area, in px^2: no sliver triangles
ATTEMPTS = 500          # draws before a template gives up on a seed
CENTRE_TEXT = ("Pixel (i, j) is the square [i, i+1) x [j, j+1) with its centre at "
               "(i + 1/2, j + 1/2), y up.")


def run(algorithm: str, points, options: dict, grid):
    """The trace of ``algorithm`` on ``points`` (the real run, within its budget)."""
    spec = registry.get(algorithm)
    points = [(float(x), float(y)) for x, y in points]  # exact: on the 1/2 px grid
    return runs.record(spec, points, dict(options), tuple(grid), STEP_CAP)


def frames_at(trace, pixel) -> list:
    """The frames (steps without a rich record) that name ``pixel``, in order."""
    hits = np.flatnonzero((trace.x == pixel[0]) & (trace.y == pixel[1]) & (trace.x != NO_PIXEL))
    steps = [trace.step(int(i)) for i in hits]
    return [step for step in steps if step.record is None]


def half_grid_point(rng, grid) -> tuple[Fraction, Fraction]:
    """A point on the 1/2 px grid within the grid's extent."""
    return (Fraction(rng.randint(0, 2 * grid[0]), 2), Fraction(rng.randint(0, 2 * grid[1]), 2))


def area2(p0, p1, p2):
    """Twice the signed area of p0 p1 p2 (positive: counter-clockwise); for
    drawing well-posed inputs only, never for an answer."""
    return (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1])


def draw_triangle(rng, grid=GRID, min_area2=MIN_AREA2):
    """A counter-clockwise triangle on the 1/2 px grid, not a sliver: the
    algorithms keep its vertex order, so P0, P1, P2 mean what the text says."""
    for _ in range(ATTEMPTS):
        p = [half_grid_point(rng, grid) for _ in range(3)]
        twice = area2(*p)
        if twice < 0:
            p = [p[0], p[2], p[1]]
        if abs(twice) >= min_area2 and _not_thin(p):
            return p
    raise ValueError("no well-posed triangle found")  # not reached on these grids


def _not_thin(p) -> bool:
    """Every side at least 2 px long, so no angle is a needle's."""
    return all((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 >= 4
               for a, b in ((p[0], p[1]), (p[1], p[2]), (p[2], p[0])))


def scene_triangles(scene, template: Template, count: int | None = 3) -> tuple[list, tuple]:
    """(points, grid) of a given scene, checked to suit ``template``."""
    if scene.algorithm not in template.algorithms:
        raise ValueError(f"template {template.name} asks about scenes of "
                         f"{', '.join(template.algorithms)}, not {scene.algorithm}")
    points = [tuple(Fraction(c) for c in p) for p in scene.flat]
    if count is not None and len(points) < count:
        raise ValueError(f"template {template.name} needs a scene with {count} points")
    if area2(*points[:3]) == 0:
        raise ValueError(f"template {template.name}: the scene's first triangle has no area")
    return points, scene.grid


def make_scene(algorithm: str, points, options: dict, grid, title: str) -> Scene:
    return Scene(algorithm=algorithm, points=tuple((float(x), float(y)) for x, y in points),
                 options=options, width=grid[0], height=grid[1], title=title)


def question(template: Template, seed: int, title: str, text: str, answer, worked,
             scene) -> Question:
    return common.question(template.name, seed, title, text, answer, worked, scene)


# ------------------------------------------------------------- numbers
def exact(value) -> Fraction:
    """A recorded float that holds an exact dyadic value, as a Fraction."""
    return Fraction(value)


def fraction_text(value: Fraction) -> str:
    """3, -1/2, 7/4: the canonical exact form."""
    value = Fraction(value)
    if value.denominator == 1:
        return str(value.numerator)
    return f"{value.numerator}/{value.denominator}"


def decimal_text(value: Fraction) -> str:
    """A dyadic value in decimal, exactly: 2.25, -0.75, 3."""
    value = Fraction(value)
    if value.denominator == 1:
        return str(value.numerator)
    digits = 0
    while (value * 10 ** digits).denominator != 1:
        digits += 1
        if digits > 12:
            return fraction_text(value)
    return f"{float(value):.{digits}f}"


def point_text(p) -> str:
    return f"({decimal_text(p[0])}, {decimal_text(p[1])})"


def vertices_text(points, names=("P0", "P1", "P2")) -> str:
    return ", ".join(f"{name} = {point_text(p)}" for name, p in zip(names, points))


def spellings(values, form=fraction_text) -> tuple[str, tuple[str, ...]]:
    """The canonical "(a, b, c)" and other accepted spellings of a tuple of numbers."""
    parts = [form(v) for v in values]
    canonical = "(" + ", ".join(parts) + ")"
    others = {", ".join(parts), ",".join(parts), "(" + ",".join(parts) + ")",
              " ".join(parts)}
    alternates = [fraction_text(v) for v in values]
    others |= {"(" + ", ".join(alternates) + ")", ", ".join(alternates)}
    others.discard(canonical)
    return canonical, tuple(sorted(others))
