"""The Moodle XML writer, checked against the structure Moodle's
documentation gives (docs.moodle.org, "Moodle XML format"): a root ``quiz``
of ``question`` elements with a ``type``; a category question holds
``category/text``; every other one ``name/text``, ``questiontext`` (with a
``format``) holding ``text`` and any ``file`` (name, base64 encoding)
its text shows through ``@@PLUGINFILE@@/name``, and ``answer`` elements
with a ``fraction`` in -100..100 and a ``text``; a numerical answer may hold
a ``tolerance``; a multichoice one says ``single``."""
from __future__ import annotations

import base64
import xml.etree.ElementTree as ET

from app.teaching.questions import moodle
from tests.support import question_bank as qb

TYPES = {"category", "multichoice", "truefalse", "shortanswer", "matching", "cloze", "essay",
         "numerical", "description", "calculated"}


def structure_problems(root: ET.Element) -> list[str]:
    """What breaks the documented structure, one line each."""
    problems = [] if root.tag == "quiz" else [f"root is {root.tag}, not quiz"]
    for number, question in enumerate(root, 1):
        where = f"question {number}"
        if question.tag != "question" or question.get("type") not in TYPES:
            problems.append(f"{where}: {question.tag} of type {question.get('type')}")
            continue
        if question.get("type") == "category":
            if not (question.findtext("category/text") or "").startswith("$course$/"):
                problems.append(f"{where}: no category/text in $course$")
            continue
        problems += [f"{where}: no {path}" for path in ("name/text", "questiontext/text")
                     if not question.findtext(path)]
        if question.find("questiontext").get("format") not in ("html", "moodle_auto_format",
                                                               "plain_text", "markdown"):
            problems.append(f"{where}: questiontext has no format")
        problems += _file_problems(question, where)
        problems += _answer_problems(question, where)
    return problems


def _file_problems(question: ET.Element, where: str) -> list[str]:
    problems = []
    text = question.findtext("questiontext/text")
    for file in question.findall("questiontext/file"):
        if file.get("encoding") != "base64" or not file.get("name"):
            problems.append(f"{where}: a file without name or base64 encoding")
        elif f"@@PLUGINFILE@@/{file.get('name')}" not in text:
            problems.append(f"{where}: the text does not show {file.get('name')}")
        base64.b64decode(file.text, validate=True)
    return problems


def _answer_problems(question: ET.Element, where: str) -> list[str]:
    answers = question.findall("answer")
    if not answers:
        return [f"{where}: no answer"]
    problems = [f"{where}: an answer's fraction {answer.get('fraction')}" for answer in answers
                if not -100 <= float(answer.get("fraction", "nan")) <= 100]
    problems += [f"{where}: an answer without text" for answer in answers
                 if answer.find("text") is None]
    if question.get("type") == "multichoice" and question.findtext("single") not in ("true",
                                                                                      "false"):
        problems.append(f"{where}: multichoice without single")
    return problems


def parsed(bank) -> ET.Element:
    data = moodle.xml_bytes(bank)
    assert data.startswith(b"<?xml")  # Moodle wants the declaration on the first line
    root = ET.fromstring(data)
    assert structure_problems(root) == []
    return root


def test_every_kind_of_answer_has_its_question_type_and_key():
    root = parsed(qb.bank())
    questions = root.findall("question")[1:7]
    assert [q.get("type") for q in questions] == ["numerical"] * 4 + ["shortanswer",
                                                                       "multichoice"]
    keys = [(q.findtext("answer/text"), q.findtext("answer/tolerance")) for q in questions[:4]]
    # -3 and -3/4 exact; 1/3 to six decimals within 0.0005; 2/7 within its own 0.001.
    assert keys == [("-3", "0"), ("-0.75", "0"), ("0.333333", "0.0005"), ("0.285714", "0.001")]
    assert [a.get("fraction") for a in questions[4].findall("answer")] == ["100"] * 3
    assert [a.findtext("text") for a in questions[4].findall("answer")] == ["(2, 1)", "(2,1)",
                                                                            "2, 1"]
    choice = questions[5]
    assert [(a.get("fraction"), a.findtext("text")) for a in choice.findall("answer")] == [
        ("0", "E"), ("100", "NE"), ("0", "neither")]
    assert choice.findtext("single") == "true" and choice.findtext("shuffleanswers") == "true"


def test_a_fraction_whose_decimal_does_not_end_says_how_to_write_it():
    root = parsed(qb.bank())
    third, coverage, integer = (root.findall("question")[i].findtext("questiontext/text")
                                for i in (3, 4, 1))
    assert "at least three correct decimals" in third
    assert "within 0.001" in coverage
    assert "decimal" not in integer


def test_the_picture_is_embedded_and_the_feedback_holds_the_worked_steps():
    root = parsed(qb.bank())
    _, png = qb.scene_and_picture()
    for question in root.findall("question")[1:]:
        file = question.find("questiontext/file")
        assert base64.b64decode(file.text) == png
        assert qb.html_fragment(question.findtext("questiontext/text")).find(".//img").get(
            "src") == "@@PLUGINFILE@@/picture.png"
        assert question.find("generalfeedback").get("format") == "html"
    feedback = root.findall("question")[1].findtext("generalfeedback/text")
    assert qb.table_cells(feedback) == qb.worked_cells(qb.WORKED)
    assert "d grew by -8" in "".join(qb.html_fragment(feedback).itertext())


def test_each_student_has_a_category_and_a_slash_in_an_id_is_doubled():
    root = parsed(qb.per_student())
    categories = [q.findtext("category/text") for q in root if q.get("type") == "category"]
    assert categories == ["$course$/top/RasterLab/s1//a:b", "$course$/top/RasterLab/s2"]
    assert [q.get("type") for q in root].index("category", 1) == 4  # after s1's 3 questions
    assert parsed(qb.bank()).find("question/category/text").text == \
        "$course$/top/RasterLab/seed 7"


def test_awkward_text_comes_back_as_written():
    root = parsed(qb.bank())
    short, choice = root.findall("question")[7:9]
    assert short.findtext("name/text") == qb.as_written("Awkward " + qb.AWKWARD)
    text = "".join(qb.html_fragment(short.findtext("questiontext/text")).find("p").itertext())
    assert text == qb.as_written("Type " + qb.AWKWARD)
    # Moodle reads * as a wildcard in a short answer; \* is the character.
    assert [a.findtext("text") for a in short.findall("answer")] == ["x\\*y {z}: =1", "<a&b>"]
    assert ["".join(qb.html_fragment(a.findtext("text")).itertext())
            for a in choice.findall("answer")] == ["=1 <b>", "~2 {c}", "#3 : &d;"]
    cells = qb.table_cells(choice.findtext("generalfeedback/text"))
    assert cells == [["step", qb.as_written(qb.AWKWARD)], ["0", qb.as_written(qb.AWKWARD)]]
