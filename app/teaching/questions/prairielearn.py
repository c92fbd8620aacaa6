"""A question bank as PrairieLearn questions (prairielearn.readthedocs.io,
"Question" pages): a folder per template, ``questions/<template>/``.

PrairieLearn draws its own variants, so a folder holds no numbers: its
``server.py`` imports RasterLab and calls ``rasterlab.question(template,
seed)`` with a seed taken from the variant's, and fills ``data["params"]``
(the text, the worked steps, the input's settings) and
``data["correct_answers"]``; ``file()`` serves the picture that ``pl-figure``
shows. ``question.html`` holds the input of the template's kind of answer:
``pl-number-input`` (fractions allowed; exact, or within the answer's
tolerance), ``pl-string-input`` (``grade()`` accepts the other spellings)
or ``pl-multiple-choice``; the answer panel shows the worked steps.
``info.json`` has a uuid made from the template's name, so a course that
imports the folder again keeps its questions' history.

Each folder is written whole (app/model/staging.py); the bank's seed and
groups have no place here, as PrairieLearn gives each student a variant.
"""
from __future__ import annotations

import json
import re
import uuid
from pathlib import Path

from app.model import escape
from app.model.files import Output, check_outputs, listed
from app.model.staging import write_bytes, write_folder
from app.teaching.questions import lms
from app.teaching.questions.model import CHOICE, NUMERICAL, SHORT, Bank, Question

MANIFEST = ".rasterlab-prairielearn.json"  # the files the last export wrote into a folder
FILES = ("info.json", "question.html", "server.py")
NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "rasterlab:questions")  # of the uuids made here
_NAME = re.compile(r"[a-z0-9][a-z0-9-]*")


def outputs(bank: Bank, path) -> list[Output]:
    """What ``write`` writes, for the output policy (app/model/files.py)."""
    path = Path(path)
    found = [Output("--out", path, folder=True), Output("--out", path / "questions", folder=True)]
    for template in _templates(bank):
        folder = path / "questions" / template
        found.append(Output("--out", folder, folder=True))
        found += [Output("--out", folder / name, foreign=listed(MANIFEST)) for name in FILES]
    return found


def write(bank: Bank, path: Path, force: bool = False) -> list[Path]:
    """Write a question folder per template of ``bank`` under
    ``path/questions``; the files written. OutputRefused (one line) when the
    policy refuses a file, ValueError when a template's questions differ in
    their kind of answer."""
    check_outputs(outputs(bank, path), force=force)
    written = []
    for template, first in _templates(bank).items():
        folder = Path(path) / "questions" / template
        folder.mkdir(parents=True, exist_ok=True)
        contents = files(first)
        written += write_folder(folder, "prairielearn", list(contents), write_bytes(contents),
                                MANIFEST)
    return written


def files(question: Question) -> dict[str, bytes]:
    """The files of the folder of ``question``'s template."""
    info = {"uuid": str(uuid.uuid5(NAMESPACE, question.template)),
            "title": escape.json_text(_title(question)),
            "topic": "RasterLab", "tags": ["rasterlab"], "type": "v3"}
    return {"info.json": (json.dumps(info, indent=2, ensure_ascii=True) + "\n").encode(),
            "question.html": question_html(question.answer.kind).encode(),
            "server.py": SERVER.replace("TEMPLATE_NAME", repr(question.template)).encode()}


def _title(question: Question) -> str:
    """The template's title (the folder serves every variant), or the
    question's own without its number for a template not registered."""
    from app.teaching.questions import registry
    template = registry.TEMPLATES.get(question.template)
    return template.title if template else re.sub(r"\s*\(#\d+\)$", "", question.title)


def _templates(bank: Bank) -> dict[str, Question]:
    """The first question of each template, in the bank's order; one line
    (ValueError) for a name that is no folder name, or mixed kinds."""
    first: dict[str, Question] = {}
    for _, question in lms.questions(bank):
        if not _NAME.fullmatch(question.template):
            raise ValueError(f"template {question.template!r}: not a folder name "
                             "(lower-case letters, digits and -)")
        seen = first.setdefault(question.template, question)
        if seen.answer.kind != question.answer.kind:
            raise ValueError(f"template {question.template}: its questions ask for "
                             f"{seen.answer.kind} and {question.answer.kind} answers")
    return first


INPUTS = {
    NUMERICAL: '<pl-number-input answers-name="answer" comparison="relabs" rtol="0" '
               'atol="{{params.atol}}" allow-fractions="true" label="Answer:"></pl-number-input>',
    SHORT: '<pl-string-input answers-name="answer" remove-leading-trailing="true" '
             'label="Answer:"></pl-string-input>',
    CHOICE: '<pl-multiple-choice answers-name="answer">\n'
            '  {{#params.choices}}<pl-answer correct="{{correct}}">{{text}}</pl-answer>'
            '{{/params.choices}}\n</pl-multiple-choice>',
}


def question_html(kind: str) -> str:
    """The question panel, the input for ``kind`` and the answer panel; every
    text comes from ``data["params"]``, which Mustache escapes."""
    return QUESTION.replace("INPUT", INPUTS[kind])


QUESTION = """<pl-question-panel>
  {{#params.lines}}<p>{{.}}</p>{{/params.lines}}
  <pl-figure file-name="picture.png" type="dynamic" alt="{{params.alt}}"></pl-figure>
</pl-question-panel>

INPUT

<pl-answer-panel>
  <table class="table table-sm">
    <thead><tr>{{#params.columns}}<th>{{.}}</th>{{/params.columns}}</tr></thead>
    <tbody>{{#params.rows}}<tr>{{#cells}}<td>{{.}}</td>{{/cells}}</tr>{{/params.rows}}</tbody>
  </table>
  <p>{{params.summary}}</p>
</pl-answer-panel>
"""


SERVER = '''"""A RasterLab question: each variant is rasterlab.question(TEMPLATE, seed),
drawn and answered by RasterLab's algorithms, with the seed taken from the
variant's. Needs RasterLab installed where the questions run."""
from fractions import Fraction

import rasterlab

TEMPLATE = TEMPLATE_NAME
PICTURE = "picture.png"


def generate(data):
    seed = int(data["variant_seed"]) % 2**31
    question = rasterlab.question(TEMPLATE, seed)
    answer, worked = question.answer, question.worked
    data["params"].update({
        "seed": seed, "title": question.title, "lines": question.text.splitlines(),
        "alt": "The scene: the grid and the primitive, before any step",
        "columns": list(worked.columns), "rows": [{"cells": list(row)} for row in worked.rows],
        "summary": worked.summary})
    if answer.kind == "numerical":
        value = Fraction(answer.value)
        exact = 0 if value.denominator == 1 else 1e-9  # a fraction typed as a fraction
        data["params"]["atol"] = answer.tolerance or exact
        data["correct_answers"]["answer"] = float(value)
    elif answer.kind == "choice":
        data["params"]["choices"] = [{"text": text, "correct": str(i == answer.value).lower()}
                                     for i, text in enumerate(answer.choices)]
        data["correct_answers"]["answer"] = answer.choices[answer.value]
    else:
        data["params"]["accepted"] = [answer.value, *answer.also]
        data["correct_answers"]["answer"] = answer.value


def file(data):
    if data["filename"] == PICTURE:
        return rasterlab.question(TEMPLATE, data["params"]["seed"]).picture
    return None


def grade(data):
    """A short answer may be written in any of its accepted spellings."""
    accepted = data["params"].get("accepted")
    submitted = data["submitted_answers"].get("answer")
    score = data["partial_scores"].get("answer")
    if accepted and isinstance(submitted, str) and submitted.strip() in accepted and score:
        import prairielearn as pl
        score["score"] = 1
        pl.set_weighted_score_data(data)
'''
