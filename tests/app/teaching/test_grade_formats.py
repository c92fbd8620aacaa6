"""Each grader format of `rasterlab check` against a schema written from the
format's documentation, and the pixel-difference pictures they carry.

Sources of the schemas:
- Gradescope: gradescope-autograders.readthedocs.io/en/latest/specs/ ("Output
  format", "Controlling Test Case Visibility", "Test case status").
- PrairieLearn: prairielearn.readthedocs.io/en/latest/externalGrading/
  ("Grading results": score in [0, 1], gradable, images as data URLs, tests
  with points and max_points, the 1 MB limit on the file).
- CodeRunner: coderunner.org.nz documentation, "Combinator-template grading"
  (fraction, testresults: a list of lists whose first row is the header, with
  the special column "iscorrect" holding 0 or 1, prologuehtml/epiloguehtml).
"""
from __future__ import annotations

import base64
import io
import json
import xml.etree.ElementTree as ET

import jsonschema
import pytest
from PIL import Image

from app.teaching import grade_pictures
from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
CASES = ["--against", "line-bresenham", "--cases", "random", "3", "--time-limit", "0.5"]
VISIBILITY = {"enum": ["hidden", "after_due_date", "after_published", "visible"]}
TEXT = {"type": "string"}
NUMBER = {"type": "number"}

GRADESCOPE = {
    "type": "object",
    "required": ["score", "tests"],
    "properties": {
        "score": NUMBER, "execution_time": NUMBER, "output": TEXT,
        "output_format": {"enum": ["text", "html", "simple_format", "md", "ansi"]},
        "visibility": VISIBILITY, "stdout_visibility": VISIBILITY,
        "tests": {"type": "array", "items": {
            "type": "object",
            "required": ["name", "score", "max_score", "status", "output", "visibility"],
            "properties": {"name": TEXT, "score": NUMBER, "max_score": NUMBER,
                           "status": {"enum": ["passed", "failed"]}, "output": TEXT,
                           "visibility": VISIBILITY, "number": TEXT,
                           "tags": {"type": "array", "items": TEXT}},
            "additionalProperties": False}},
    },
    "additionalProperties": False,
}

IMAGE = {"type": "object", "required": ["url"],
         "properties": {"url": {"type": "string", "pattern": "^data:image/png;base64,"},
                        "label": TEXT}}
PRAIRIELEARN = {
    "type": "object",
    "required": ["score", "gradable", "message", "tests"],
    "properties": {
        "score": {"type": "number", "minimum": 0, "maximum": 1},
        "gradable": {"type": "boolean"}, "message": TEXT, "output": TEXT,
        "images": {"type": "array", "items": IMAGE},
        "tests": {"type": "array", "items": {
            "type": "object",
            "required": ["name", "points", "max_points", "message", "output"],
            "properties": {"name": TEXT, "description": TEXT, "points": NUMBER,
                           "max_points": NUMBER, "message": TEXT, "output": TEXT,
                           "images": {"type": "array", "items": IMAGE}},
            "additionalProperties": False}},
    },
}

CODERUNNER = {
    "type": "object",
    "required": ["fraction", "testresults", "epiloguehtml"],
    "properties": {
        "fraction": {"type": "number", "minimum": 0, "maximum": 1},
        "prologuehtml": TEXT, "epiloguehtml": TEXT, "showdifferences": {"type": "boolean"},
        "testresults": {"type": "array", "minItems": 1,
                        "prefixItems": [{"type": "array", "items": TEXT,
                                         "contains": {"const": "iscorrect"}}],
                        "items": {"type": "array"}},
    },
    "additionalProperties": False,
}

PRINTS = ("def draw(x0, y0, x1, y1):\n    print('x' * 3_000_000)\n"
          "    yield x0, y0\n")


def _valid(schema: dict, value) -> None:
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.Draft202012Validator(schema).validate(value)


@pytest.fixture
def wrong(tmp_path):
    path = tmp_path / "ben.py"
    path.write_text((SAMPLES / "off_by_one.py").read_text())
    return path


def test_gradescope_results_follow_the_documented_format(run_cli, wrong, tmp_path):
    out = tmp_path / "results.json"
    status, _, _ = run_cli("check", wrong, *CASES, "--points", "random=2", "--format",
                           "gradescope", "--out", out)
    result = json.loads(out.read_text())
    _valid(GRADESCOPE, result)
    assert status == 1
    assert result["score"] == sum(test["score"] for test in result["tests"]) == 0
    assert [test["max_score"] for test in result["tests"]] == [2, 2, 2]
    assert {test["status"] for test in result["tests"]} == {"failed"}


def test_a_passing_submission_scores_full_marks_everywhere(run_cli, tmp_path):
    path = tmp_path / "ann.py"
    path.write_text((SAMPLES / "bresenham_correct.py").read_text())
    formats = {}
    for name in ("gradescope", "prairielearn", "coderunner"):
        status, out, _ = run_cli("check", path, *CASES, "--format", name)
        assert status == 0
        formats[name] = json.loads(out)
    _valid(GRADESCOPE, formats["gradescope"])
    _valid(PRAIRIELEARN, formats["prairielearn"])
    _valid(CODERUNNER, formats["coderunner"])
    assert formats["gradescope"]["score"] == 3
    assert {test["status"] for test in formats["gradescope"]["tests"]} == {"passed"}
    assert formats["prairielearn"]["score"] == 1 and "images" not in formats["prairielearn"]
    assert formats["coderunner"]["fraction"] == 1
    assert [row[0] for row in formats["coderunner"]["testresults"][1:]] == [1, 1, 1]


def test_prairielearn_results_carry_the_difference_as_a_png(run_cli, wrong):
    status, out, _ = run_cli("check", wrong, *CASES, "--format", "prairielearn")
    result = json.loads(out)
    _valid(PRAIRIELEARN, result)
    assert status == 1 and result["score"] == 0 and result["gradable"] is True
    (image,) = result["images"]
    png = base64.b64decode(image["url"].split(",", 1)[1])
    picture = Image.open(io.BytesIO(png)).convert("RGB")
    colours = {colour for _, colour in picture.getcolors()}
    # off_by_one stops a pixel early: grey pixels both give, a blue one missing, no red
    assert grade_pictures.COLOURS["both"] in colours
    assert grade_pictures.COLOURS["missing"] in colours
    assert grade_pictures.COLOURS["extra"] not in colours


def test_prairielearn_results_stay_under_a_megabyte(run_cli, tmp_path):
    path = tmp_path / "noisy.py"
    path.write_text(PRINTS)
    status, out, _ = run_cli("check", path, *CASES, "--format", "prairielearn")
    result = json.loads(out)
    _valid(PRAIRIELEARN, result)
    assert status == 1
    assert len(out.encode("utf-8")) < 1 << 20
    assert all(test["output"].startswith("xxxx") for test in result["tests"])


def test_coderunner_outcome_has_a_table_and_an_svg(run_cli, wrong):
    status, out, _ = run_cli("check", wrong, *CASES, "--format", "coderunner")
    result = json.loads(out)
    _valid(CODERUNNER, result)
    header, *rows = result["testresults"]
    assert status == 1 and result["fraction"] == 0
    assert header == ["iscorrect", "Test", "Expected", "Got"]
    assert len(rows) == 3 and all(row[0] == 0 and len(row) == 4 for row in rows)
    assert all(row[3].endswith("the end") for row in rows)
    svg = result["epiloguehtml"][result["epiloguehtml"].index("<svg"):]
    root = ET.fromstring(svg)
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    fills = {rect.attrib["fill"] for rect in root}
    assert {"#9e9e9e", "#1f77b4"} <= fills


def test_the_difference_marks_each_pixel_by_who_gave_it():
    diff = grade_pictures.Difference("case", frozenset({(2, 5), (3, 5), (4, 6)}),
                                     frozenset({(2, 5), (3, 6)}))
    cells, size = diff.cells()
    # columns from x = 2, rows from the top (y = 6) down
    assert size == (3, 2)
    assert cells == {(0, 1): "both", (1, 1): "missing", (2, 0): "missing", (1, 0): "extra"}
    png = base64.b64decode(grade_pictures.png_data_uri(diff).split(",", 1)[1])
    picture = Image.open(io.BytesIO(png)).convert("RGB")
    assert picture.size == (24, 16)
    assert picture.getpixel((4, 12)) == grade_pictures.COLOURS["both"]
    assert picture.getpixel((12, 4)) == grade_pictures.COLOURS["extra"]
    assert picture.getpixel((4, 4)) == (255, 255, 255)
