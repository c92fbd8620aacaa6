"""A question bank as GIFT text (docs.moodle.org, "GIFT format"), for a
Moodle whose lecturers paste or import plain text.

GIFT cannot carry a picture, so its questions have none (the file's first
comment says so); each one's general feedback (``####``) holds the worked
steps. Per group a ``$CATEGORY:`` line; NUMERICAL as ``{#value:tolerance}``
(the decimal and tolerance of lms.py), SHORT as ``{=a =b}``, CHOICE as
``{=right ~wrong}``. Texts are HTML (``[html]``), escaped for HTML and then
for GIFT (escape.gift_text). The same bank gives the same bytes.
"""
from __future__ import annotations

from pathlib import Path

from app.model import escape
from app.model.files import Output, check_outputs, not_ours, write_atomically
from app.teaching.questions import lms
from app.teaching.questions.model import CHOICE, NUMERICAL, Bank, Question

HEADER = """// RasterLab question bank, seed {seed}.
// GIFT cannot carry pictures: these questions are shown without the picture of
// their scene (the Moodle XML, QTI and PrairieLearn exports include it).
// Each question's general feedback holds the worked steps.
"""


def outputs(bank: Bank, path) -> list[Output]:
    """What ``write`` writes, for the output policy (app/model/files.py)."""
    return [Output("--out", Path(path), foreign=not_ours("gift"))]


def write(bank: Bank, path: Path, force: bool = False) -> list[Path]:
    """Write ``bank`` to ``path`` (whole or not at all); the files written.
    OutputRefused (one line) when the policy refuses the file."""
    check_outputs(outputs(bank, path), force=force)
    write_atomically(Path(path), gift_bytes(bank))
    return [Path(path)]


def gift_bytes(bank: Bank) -> bytes:
    """The file: the header, then per group its category line and questions."""
    parts = [HEADER.format(seed=int(bank.seed))]
    for group, members in bank.groups:
        category = escape.moodle_category(lms.group_name(bank, group))
        parts.append(f"$CATEGORY: $course$/top/RasterLab/{category}\n")
        parts.extend(question_text(question) for question in members)
    return "\n".join(parts).encode("utf-8")


def question_text(question: Question) -> str:
    """One question: title, HTML text and the answer block, on one line."""
    answer = question.answer
    if answer.kind == NUMERICAL:
        keys = f"#{lms.decimal_text(answer)}:{lms.tolerance(answer):g}"
    elif answer.kind == CHOICE:
        keys = " ".join(("=" if index == answer.value else "~")
                        + escape.gift_text(escape.html_text(choice))
                        for index, choice in enumerate(answer.choices))
    else:
        keys = " ".join("=" + escape.gift_text(escape.shortanswer(spelling))
                        for spelling in dict.fromkeys((answer.value, *answer.also)))
    title = escape.gift_text(question.title)
    text = escape.gift_text(lms.question_html(question))
    feedback = escape.gift_text(lms.worked_html(question.worked))
    return f"::{title}::[html]{text}{{{keys} ####{feedback}}}\n"
