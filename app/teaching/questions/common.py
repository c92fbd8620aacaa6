"""What the templates of every family share: running a scene, the worked
steps from its step table, the check that a given scene suits a template,
and the Question put together with its picture. Qt-free."""
from __future__ import annotations

from fractions import Fraction

from algorithms.core.trace import DEFAULT_STEP_CAP

from app.model import runs
from app.model.steptable import StepTable
from app.teaching import worksheet
from app.teaching.questions.model import Answer, Question, Worked, SHORT
from app.teaching.questions.picture import CELL, picture

MAX_TRIES = 200  # redraws of a variant's inputs before a template gives up
PICTURE_SIDE = 640  # screen pixels across the longest side of a picture, at most


def trace_of(scene):
    """The recorded run of ``scene`` (its algorithm, points, options and grid)."""
    return runs.record(scene.spec, scene.points, scene.options, scene.grid, DEFAULT_STEP_CAP)


def suited(template_name: str, algorithms, scene) -> None:
    """Refuse (ValueError, one line) a scene whose algorithm the template does not ask about."""
    if scene.algorithm not in algorithms:
        raise ValueError(f"{template_name} asks about {', '.join(algorithms)}; the scene runs "
                         f"{scene.algorithm}")


def drawn(seed: int, draw, well_posed):
    """The first inputs ``draw(rng)`` gives that ``well_posed`` accepts,
    from one Random seeded by ``seed``: the same seed, the same inputs."""
    import random
    rng = random.Random(seed)
    for _ in range(MAX_TRIES):
        inputs = draw(rng)
        if well_posed(inputs):
            return inputs, rng
    raise ValueError(f"no well-posed inputs found for seed {seed} in {MAX_TRIES} draws")


def step_rows(trace, steps, keys, numbers: str = "exact") -> tuple[tuple[str, ...], ...]:
    """The step table's cells (worksheet.sheet_row: "d after" too) of ``steps``."""
    table = StepTable(trace, numbers)
    return tuple(worksheet.sheet_row(table, i, list(keys)) for i in steps)


def fraction_text(value) -> str:
    """An exact number as the key writes it: "3", "-7/4"."""
    value = Fraction(value)
    return str(value.numerator) if value.denominator == 1 else f"{value.numerator}/{value.denominator}"


def pixel_text(pixel) -> str:
    return f"({pixel[0]}, {pixel[1]})"


def short(text: str, *also: str) -> Answer:
    """A SHORT answer in its canonical text; ``also``: other spellings it accepts."""
    spellings = tuple(dict.fromkeys(s for s in also if s != text))
    return Answer(SHORT, text, text, also=spellings)


def question(template: str, seed: int, title: str, text: str, answer: Answer, worked: Worked,
             scene) -> Question:
    """The Question, with the picture of its scene."""
    return Question(template, seed, title, text, answer, worked, scene,
                    picture(scene, picture_cell(scene)))


def picture_cell(scene) -> int:
    """Screen pixels per grid cell: CELL, smaller for a grid that would be
    wider or taller than PICTURE_SIDE."""
    return max(1, min(CELL, PICTURE_SIDE // max(scene.width, scene.height)))


def exact(value):
    """A trace value (a float holding an integer or quarters exactly) as an
    int or a Fraction: the float is the exact binary value the run kept."""
    value = Fraction(value)
    return value.numerator if value.denominator == 1 else value
