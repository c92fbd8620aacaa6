"""The PrairieLearn writer: info.json against the fields PrairieLearn documents
(tests/support/schemas/prairielearn-info-question.json, see the README
there), server.py run with a stand-in ``rasterlab`` module (its documented
entry points: generate, file, grade), question.html rendered by a small
Mustache reader (sections, variables, escaping) with the data generate
made."""
from __future__ import annotations

import html
import json
import re
import runpy
import sys
import types
import uuid

import jsonschema
import pytest

from app.teaching.questions import prairielearn
from app.teaching.questions.model import Bank
from tests.support import ROOT
from tests.support import question_bank as qb

SCHEMA = ROOT / "tests" / "support" / "schemas" / "prairielearn-info-question.json"


@pytest.fixture
def course(tmp_path):
    prairielearn.write(qb.bank(), tmp_path)
    return tmp_path / "questions"


@pytest.fixture
def fake_rasterlab(monkeypatch):
    """``rasterlab.question(template, seed)`` giving the bank's questions, and
    ``prairielearn.set_weighted_score_data`` as PrairieLearn's library does
    (the weighted mean of the partial scores)."""
    calls = []
    by_template = {}
    for _, question in reversed(prairielearn.lms.questions(qb.bank())):
        by_template[question.template] = question

    def question(template, seed, scene=None):
        calls.append((template, seed))
        return by_template[template]

    def weighted(data):
        scores = data["partial_scores"].values()
        data["score"] = (sum(s["score"] * s.get("weight", 1) for s in scores)
                         / sum(s.get("weight", 1) for s in scores))

    monkeypatch.setitem(sys.modules, "rasterlab", types.SimpleNamespace(question=question))
    monkeypatch.setitem(sys.modules, "prairielearn",
                        types.SimpleNamespace(set_weighted_score_data=weighted))
    return calls


def run(course, template: str, variant_seed: int = 123456789012) -> tuple[dict, dict]:
    server = runpy.run_path(str(course / template / "server.py"))
    data = {"variant_seed": variant_seed, "params": {}, "correct_answers": {}}
    server["generate"](data)
    return server, data


def test_info_json_is_valid_under_prairielearns_schema(course):
    schema = json.loads(SCHEMA.read_text(encoding="utf-8"))
    validator = jsonschema.Draft7Validator(schema, format_checker=jsonschema.FormatChecker())
    folders = sorted(path.name for path in course.iterdir())
    assert folders == ["antialias-coverage", "line-decision-after-step", "line-pixel-at-step",
                       "line-step-choice", "triangle-barycentric"]
    for folder in folders:
        info = json.loads((course / folder / "info.json").read_text(encoding="utf-8"))
        assert list(validator.iter_errors(info)) == []
        assert info["type"] == "v3" and uuid.UUID(info["uuid"]).version == 5
    info = json.loads((course / "line-decision-after-step" / "info.json").read_text())
    assert info["title"] == "Bresenham: d after step 2"  # without the variant's number
    assert list(validator.iter_errors({**info, "uuid": "not-a-uuid"}))  # the check can fail


def test_the_uuid_is_the_templates_own(course, tmp_path):
    again = tmp_path / "again"
    prairielearn.write(Bank(groups=(("", qb.every_kind()[::-1]),), seed=99), again)
    for template in ("line-decision-after-step", "line-step-choice"):
        first, second = (json.loads((root / template / "info.json").read_text())["uuid"]
                         for root in (course, again / "questions"))
        assert first == second
    uuids = {json.loads((f / "info.json").read_text())["uuid"] for f in course.iterdir()}
    assert len(uuids) == 5


def test_server_py_compiles_and_generates_each_kind(course, fake_rasterlab):
    for folder in course.iterdir():
        compile((folder / "server.py").read_text(encoding="utf-8"), "server.py", "exec")
    _, data = run(course, "line-decision-after-step")
    assert fake_rasterlab == [("line-decision-after-step", 123456789012 % 2**31)]
    assert data["correct_answers"] == {"answer": -3.0} and data["params"]["atol"] == 0
    assert data["params"]["rows"][2] == {"cells": ["2", "(2, 1)", "-3", "E"]}
    _, third = run(course, "triangle-barycentric")  # the bank's first: -3/4
    assert third["correct_answers"]["answer"] == -0.75 and 0 < third["params"]["atol"] < 1e-6
    _, coverage = run(course, "antialias-coverage")
    assert coverage["params"]["atol"] == 0.001
    _, pixel = run(course, "line-pixel-at-step")
    assert pixel["correct_answers"] == {"answer": "(2, 1)"}
    assert pixel["params"]["accepted"] == ["(2, 1)", "(2,1)", "2, 1"]
    _, choice = run(course, "line-step-choice")
    assert choice["params"]["choices"] == [{"text": "E", "correct": "false"},
                                           {"text": "NE", "correct": "true"},
                                           {"text": "neither", "correct": "false"}]


def test_file_serves_the_picture_of_the_variant(course, fake_rasterlab):
    server, data = run(course, "line-decision-after-step", variant_seed=5)
    _, png = qb.scene_and_picture()
    assert server["file"]({**data, "filename": "picture.png"}) == png
    assert fake_rasterlab[-1] == ("line-decision-after-step", 5)
    assert server["file"]({**data, "filename": "other.png"}) is None


def test_grade_accepts_the_other_spellings_of_a_short_answer(course, fake_rasterlab):
    server, data = run(course, "line-pixel-at-step")
    for typed, expected in (("(2,1)", 1), (" 2, 1 ", 1), ("(1, 2)", 0)):
        graded = {**data, "submitted_answers": {"answer": typed}, "score": 0,
                  "partial_scores": {"answer": {"score": 0, "weight": 1}}}
        server["grade"](graded)
        assert graded["partial_scores"]["answer"]["score"] == expected
        assert graded["score"] == expected


def mustache(template: str, stack: list) -> str:
    """Mustache's sections ({{#x}}...{{/x}}: once per list item, once if
    true) and escaped variables ({{x}}, {{x.y}}, {{.}})."""
    def lookup(name):
        if name == ".":
            return stack[-1]
        first, *rest = name.split(".")
        value = next(frame[first] for frame in reversed(stack)
                     if isinstance(frame, dict) and first in frame)
        for part in rest:
            value = value[part]
        return value

    def section(match):
        value = lookup(match.group(1))
        items = value if isinstance(value, list) else [value] if value else []
        return "".join(mustache(match.group(2), stack + [item]) for item in items)

    template = re.sub(r"{{#([\w.]+)}}(.*?){{/\1}}", section, template, flags=re.S)
    return re.sub(r"{{([\w.]+|\.)}}", lambda m: html.escape(str(lookup(m.group(1)))), template)


def test_question_html_shows_the_text_the_input_and_the_worked_steps(course, fake_rasterlab):
    _, data = run(course, "line-decision-after-step")
    page = mustache((course / "line-decision-after-step" / "question.html").read_text(),
                    [data])
    assert "{{" not in page
    assert "<p>What is d after step 2?</p>" in page
    assert '<pl-number-input answers-name="answer"' in page and 'atol="0"' in page
    assert '<pl-figure file-name="picture.png" type="dynamic"' in page
    assert "<td>(2, 1)</td><td>-3</td>" in page and "d grew by -8" in page
    _, choice = run(course, "line-step-choice")
    page = mustache((course / "line-step-choice" / "question.html").read_text(), [choice])
    assert '<pl-answer correct="true">NE</pl-answer>' in page
    assert "<pl-string-input" in (course / "line-pixel-at-step" / "question.html").read_text()


def test_awkward_text_is_escaped_by_mustache(tmp_path, fake_rasterlab, monkeypatch):
    awkward = qb.awkward()[1]
    monkeypatch.setitem(sys.modules, "rasterlab", types.SimpleNamespace(
        question=lambda template, seed, scene=None: awkward))
    prairielearn.write(Bank(groups=(("", (awkward,)),), seed=1), tmp_path)
    _, data = run(tmp_path / "questions", "line-step-choice")
    page = mustache((tmp_path / "questions" / "line-step-choice" / "question.html").read_text(),
                    [data])
    assert "<b>" not in page and "=1 &lt;b&gt;" in page
    info = json.loads((tmp_path / "questions" / "line-step-choice" / "info.json").read_text())
    assert info["title"] == "Awkward choice " + qb.as_written(qb.AWKWARD)


def test_a_template_whose_questions_ask_for_different_kinds_is_refused(tmp_path):
    kinds = qb.every_kind()
    mixed = kinds[4].__class__(**{**kinds[4].__dict__, "template": kinds[5].template})
    with pytest.raises(ValueError, match="line-step-choice: its questions ask for choice and "
                                         "short answers"):
        prairielearn.write(Bank(groups=(("", (kinds[5], mixed)),), seed=1), tmp_path)
    assert not (tmp_path / "questions").exists()
