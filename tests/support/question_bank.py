"""Question banks for the tests of the quiz-tool writers: real Questions
(a real scene and its picture) of every answer kind, with keys and worked
steps written here by hand, and one question whose every text is awkward.

The line from (0, 0) to (7, 3) under Bresenham: dx = 7, dy = 3, d starts
at 2dy - dx = -1 and grows by 2dy = 6 after an E step, by 2(dy - dx) = -8
after a NE step."""
from __future__ import annotations

from fractions import Fraction
from functools import lru_cache

from app.model.scene import Scene
from app.teaching.questions.model import CHOICE, NUMERICAL, SHORT, Answer, Bank, Question, Worked
from app.teaching.questions.picture import picture

# Every mark some format reads: XML and HTML, GIFT, Moodle's wildcard, TeX,
# a lone surrogate (from a JSON scene title) and a control character.
AWKWARD = "a < b & c > d {e} = f ~ g # h : i \"j\" 'k' \\l *m* \ud800 n\x01o"

WORKED = Worked(columns=("step", "pixel", "d", "choice"),
                rows=(("0", "(0, 0)", "-1", "E"), ("1", "(1, 0)", "5", "NE"),
                      ("2", "(2, 1)", "-3", "E")),
                summary="d after step 2 is -3: the step from (1, 0) chose NE, so d grew by -8.")


@lru_cache(maxsize=1)
def scene_and_picture() -> tuple:
    scene = Scene(algorithm="line-bresenham", points=((0, 0), (7, 3)), width=10, height=6)
    return scene, picture(scene)


def question(template: str, seed: int, title: str, text: str, answer: Answer,
             worked: Worked = WORKED) -> Question:
    scene, png = scene_and_picture()
    return Question(template=template, seed=seed, title=title, text=text, answer=answer,
                    worked=worked, scene=scene, picture=png)


def every_kind() -> tuple[Question, ...]:
    """One question per kind of key: an int, a fraction whose decimal ends,
    one whose decimal does not, a real value with a tolerance, a short text
    with other spellings, a choice."""
    return (
        question("line-decision-after-step", 11, "Bresenham: d after step 2 (#1)",
                 "The line from (0, 0) to (7, 3) is drawn with Bresenham's algorithm.\n"
                 "What is d after step 2?", Answer(NUMERICAL, -3, "-3")),
        question("triangle-barycentric", 12, "Barycentric weight (#1)",
                 "What is the weight of A at p?", Answer(NUMERICAL, Fraction(-3, 4), "-3/4")),
        question("triangle-barycentric", 13, "Barycentric weight (#2)",
                 "What is the weight of B at p?", Answer(NUMERICAL, Fraction(1, 3), "1/3")),
        question("antialias-coverage", 14, "Coverage (#1)",
                 "What share of the pixel does the line cover?",
                 Answer(NUMERICAL, Fraction(2, 7), "0.2857", tolerance=0.001)),
        question("line-pixel-at-step", 15, "Bresenham: pixel at step 2 (#1)",
                 "Which pixel is plotted at step 2? Write it as (x, y).",
                 Answer(SHORT, "(2, 1)", "(2, 1)", also=("(2,1)", "2, 1"))),
        question("line-step-choice", 16, "Bresenham: the choice at step 1 (#1)",
                 "Which pixel does step 1 choose?",
                 Answer(CHOICE, 1, "NE", choices=("E", "NE", "neither"))),
    )


def awkward() -> tuple[Question, ...]:
    """Every text holds AWKWARD: the title, the question, the key, the
    choices and the worked steps."""
    worked = Worked(columns=("step", AWKWARD), rows=(("0", AWKWARD),), summary=AWKWARD)
    return (
        question("line-pixel-at-step", 21, "Awkward " + AWKWARD, "Type " + AWKWARD,
                 Answer(SHORT, "x*y {z}: =1", "x*y {z}: =1", also=("<a&b>",)), worked),
        question("line-step-choice", 22, "Awkward choice " + AWKWARD, AWKWARD,
                 Answer(CHOICE, 0, "=1 <b>", choices=("=1 <b>", "~2 {c}", "#3 : &d;")), worked),
    )


def bank(seed: int = 7) -> Bank:
    """One group of every kind of question and the awkward ones."""
    return Bank(groups=(("", every_kind() + awkward()),), seed=seed)


def per_student(seed: int = 7) -> Bank:
    """Two students' groups, one id holding a slash and a colon."""
    kinds = every_kind()
    return Bank(groups=(("s1/a:b", kinds[:3]), ("s2", kinds[3:])), seed=seed)


def as_written(text: str) -> str:
    """``text`` as an XML or HTML writer gives it back: what XML cannot
    hold (the lone surrogate, the control character) as U+FFFD."""
    return text.replace("\ud800", "\ufffd").replace("\x01", "\ufffd")


def html_fragment(html: str):
    """The elements of an HTML fragment the writers made (well-formed XHTML),
    inside a <div>: parsing fails on any markup the escaping let through."""
    import xml.etree.ElementTree as ET
    return ET.fromstring(f"<div>{html}</div>")


def table_cells(html: str) -> list[list[str]]:
    """The rows of the first table of ``html``, header row first."""
    table = html_fragment(html).find(".//table")
    return [["".join(cell.itertext()) for cell in row] for row in table.iter("tr")]


def worked_cells(worked: Worked) -> list[list[str]]:
    return [list(worked.columns)] + [list(row) for row in worked.rows]
