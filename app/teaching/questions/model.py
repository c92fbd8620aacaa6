"""What a question bank is made of: templates, the questions they draw, and
the answers (with the worked steps) the real algorithms give.

Qt-free. A ``Template`` draws the inputs of one variant from a
``random.Random`` seeded by the variant's seed, runs the algorithm (through
app/model/runs.py, never a second formula) and returns a ``Question``: the
text a student reads, a picture of the scene without the answer, the
``Answer`` the key holds and the worked steps that explain it. Writers
(Moodle XML, QTI, GIFT, PrairieLearn, PDF, Markdown) read only these
records, so every format carries the same numbers.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable

# How an answer is asked for, and so which question type each format uses.
NUMERICAL = "numerical"  # a number; ``tolerance`` where the answer is real
SHORT = "short"          # a text in a stated canonical form, e.g. "(3, 1)"
CHOICE = "choice"        # one of ``choices``; ``value`` is the right one's index
KINDS = (NUMERICAL, SHORT, CHOICE)


@dataclass(frozen=True)
class Answer:
    """The key of one question.

    kind: NUMERICAL, SHORT or CHOICE.
    value: a Fraction or int (NUMERICAL), the canonical text (SHORT), the index
        of the right choice (CHOICE).
    text: the answer as the key prints it, e.g. "-3/2" or "(4, 2) (5, 2)".
    tolerance: the absolute error accepted for a NUMERICAL answer (0: exact).
    choices: the options of a CHOICE question, in the order shown.
    also: other spellings a SHORT answer accepts (e.g. without spaces).
    """
    kind: str
    value: object
    text: str
    tolerance: float = 0.0
    choices: tuple[str, ...] = ()
    also: tuple[str, ...] = ()

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"unknown answer kind {self.kind!r}")
        if self.kind == CHOICE and not 0 <= self.value < len(self.choices):
            raise ValueError("a choice answer needs the index of one of its choices")
        if self.kind == NUMERICAL and not isinstance(self.value, (int, Fraction)):
            raise ValueError("a numerical answer is an int or a Fraction (exact)")


@dataclass(frozen=True)
class Worked:
    """The steps that lead to the answer: a step table up to the asked step
    (or the table the answer is read from), with a sentence that says how
    the answer follows. Shown as feedback in an LMS and on the key."""
    columns: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    summary: str


@dataclass(frozen=True)
class Question:
    """One variant of one template.

    template: the template's name (``rasterlab questions --list``).
    seed: the variant's seed; ``template.make(seed)`` gives this question again.
    title: a short name, unique within a bank, e.g. "Bresenham: d after step 3 (#2)".
    text: the question in plain text (inputs stated in full; how to write the answer).
    answer, worked: the key and how it follows.
    scene: the scene drawn (app/model/scene.py), for pictures and for the window.
    picture: a PNG of the scene without the answer (the grid and the primitive).
    """
    template: str
    seed: int
    title: str
    text: str
    answer: Answer
    worked: Worked
    scene: object
    picture: bytes = field(repr=False, default=b"")


@dataclass(frozen=True)
class Template:
    """A question a person can answer by hand from the lecture notes.

    name: e.g. "line-decision-after-step"; family: "lines", "circles", "fill",
    "triangles", "visibility", "antialias" or "textures"; title: one line for
    ``--list``; algorithms: the algorithms whose scenes it asks about (the
    first is the one its drawn variants run).
    make(seed, scene=None) -> Question: the same seed gives the same question.
    With a scene (of one of ``algorithms``), its inputs are asked about and
    the seed picks only what the template chooses within them (the step k,
    the pixel p); ValueError with one line when the scene does not suit.
    """
    name: str
    family: str
    title: str
    algorithms: tuple[str, ...]
    make: Callable[..., Question]


@dataclass(frozen=True)
class Bank:
    """The questions of one export, in groups: one group per student
    (``--per-student``, named by the student's id) or one group named "".
    seed: the seed the bank was drawn with (stated in each file's header)."""
    groups: tuple[tuple[str, tuple[Question, ...]], ...]
    seed: int
