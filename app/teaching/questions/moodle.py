"""A question bank as Moodle XML (docs.moodle.org, "Moodle XML format").

The root ``quiz`` holds, per group, a ``category`` question
($course$/top/RasterLab/<student id, or "seed S">) followed by the group's
questions: NUMERICAL as ``numerical`` (the tolerance of lms.tolerance),
SHORT as ``shortanswer`` (the canonical text and each other spelling at
100 %), CHOICE as ``multichoice`` (one right choice, shuffled). The picture
is a base64 ``file`` of the question text, shown by ``@@PLUGINFILE@@``; the
general feedback holds the worked steps. The same bank gives the same bytes.
"""
from __future__ import annotations

import base64
import xml.etree.ElementTree as ET
from pathlib import Path

from app.model import escape
from app.model.files import Output, check_outputs, not_ours, write_atomically
from app.teaching.questions import lms
from app.teaching.questions.model import CHOICE, NUMERICAL, SHORT, Bank, Question

TYPES = {NUMERICAL: "numerical", SHORT: "shortanswer", CHOICE: "multichoice"}


def outputs(bank: Bank, path) -> list[Output]:
    """What ``write`` writes, for the output policy (app/model/files.py)."""
    return [Output("--out", Path(path), foreign=not_ours("xml"))]


def write(bank: Bank, path: Path, force: bool = False) -> list[Path]:
    """Write ``bank`` to ``path`` (whole or not at all); the files written.
    OutputRefused (one line) when the policy refuses the file."""
    check_outputs(outputs(bank, path), force=force)
    write_atomically(Path(path), xml_bytes(bank))
    return [Path(path)]


def xml_bytes(bank: Bank) -> bytes:
    """The file: per group its category question, then its questions."""
    quiz = ET.Element("quiz")
    quiz.append(ET.Comment(f" RasterLab question bank, seed {int(bank.seed)} "))
    for group, members in bank.groups:
        quiz.append(_category(lms.group_name(bank, group)))
        for question in members:
            quiz.append(_question(question))
    ET.indent(quiz)
    return ET.tostring(quiz, encoding="utf-8", xml_declaration=True) + b"\n"


def _category(name: str) -> ET.Element:
    question = ET.Element("question", type="category")
    category = ET.SubElement(question, "category")
    _sub(category, "text", f"$course$/top/RasterLab/{escape.moodle_category(name)}")
    return question


def _question(question: Question) -> ET.Element:
    answer = question.answer
    element = ET.Element("question", type=TYPES[answer.kind])
    _sub(ET.SubElement(element, "name"), "text", question.title)
    body = lms.question_html(question, picture=f"@@PLUGINFILE@@/{lms.PICTURE}"
                             if question.picture else None)
    text = ET.SubElement(element, "questiontext", format="html")
    _sub(text, "text", body)
    if question.picture:
        picture = ET.SubElement(text, "file", name=lms.PICTURE, path="/", encoding="base64")
        picture.text = base64.b64encode(question.picture).decode("ascii")
    feedback = ET.SubElement(element, "generalfeedback", format="html")
    _sub(feedback, "text", lms.worked_html(question.worked, "generaltable"))
    _sub(element, "defaultgrade", "1")
    _sub(element, "penalty", "0.3333333")
    _sub(element, "hidden", "0")
    if answer.kind == NUMERICAL:
        element.append(_answer(100, lms.decimal_text(answer), "moodle_auto_format",
                               tolerance=f"{lms.tolerance(answer):g}"))
    elif answer.kind == CHOICE:
        for key, value in (("single", "true"), ("shuffleanswers", "true"),
                           ("answernumbering", "abc")):
            _sub(element, key, value)
        for index, choice in enumerate(answer.choices):
            element.append(_answer(100 if index == answer.value else 0,
                                   escape.html_text(choice), "html"))
    else:
        _sub(element, "usecase", "0")  # "ne" is "NE"
        for spelling in dict.fromkeys((answer.value, *answer.also)):
            element.append(_answer(100, escape.shortanswer(spelling), "moodle_auto_format"))
    return element


def _answer(fraction: int, text: str, fmt: str, tolerance: str | None = None) -> ET.Element:
    answer = ET.Element("answer", fraction=str(fraction), format=fmt)
    _sub(answer, "text", text)
    _sub(ET.SubElement(answer, "feedback", format="html"), "text", "")
    if tolerance is not None:
        _sub(answer, "tolerance", tolerance)
    return answer


def _sub(parent: ET.Element, tag: str, text: str) -> ET.Element:
    child = ET.SubElement(parent, tag)
    child.text = _text(text)
    return child


def _text(text: str) -> str:
    return escape.xml_chars(text)
