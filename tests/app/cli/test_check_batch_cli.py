"""`rasterlab check` on a class: ids, --jobs, --give-up-after, points, CSV,
JUnit, the output policy before any case runs, and the Gradescope zip.
The formats' schemas are checked in tests/app/teaching/test_grade_formats.py."""
from __future__ import annotations

import csv
import io
import json
import stat
import xml.etree.ElementTree as ET
import zipfile

import pytest

from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
SCENE = ROOT / "resources" / "scenes" / "line-reversed.json"
LOOPS = "def draw(x0, y0, x1, y1):\n    while True:\n        pass\n    yield x0, y0\n"
CRASHES = ("import os\n\ndef draw(x0, y0, x1, y1):\n    print('before \\x01 the end')\n"
           "    os._exit(9)\n    yield x0, y0\n")
FAST = ["--against", "line-bresenham", "--cases", "random", "2", "--time-limit", "0.2"]


@pytest.fixture
def klass(tmp_path):
    """A class of four, one folder each: correct, wrong, looping, crashing."""
    texts = {"ann": (SAMPLES / "bresenham_correct.py").read_text(),
             "ben": (SAMPLES / "off_by_one.py").read_text(), "cid": LOOPS, "dee": CRASHES}
    for name, text in texts.items():
        (tmp_path / "class" / name).mkdir(parents=True)
        (tmp_path / "class" / name / "line.py").write_text(text)
    return [tmp_path / "class" / name for name in texts]


def _json(run_cli, *argv):
    status, out, err = run_cli("check", *argv, "--json")
    return status, json.loads(out), err


def test_a_class_gets_a_line_each_and_exit_1(run_cli, klass, tmp_path):
    status, out, err = run_cli("check", *klass, *FAST, "--csv", tmp_path / "marks.csv")
    assert status == 1, err
    lines = out.splitlines()
    assert lines[0] == "grading 4 submissions against line-bresenham: 2 cases, 2 points each"
    verdicts = {line.split()[1].rstrip(":"): line.split()[0] for line in lines[3:7]}
    assert verdicts == {"ann": "PASS", "ben": "FAIL", "cid": "FAIL", "dee": "FAIL"}
    assert lines[-1].startswith("4 submissions: 1 pass every case, 3 fail some; ")
    rows = list(csv.reader(io.StringIO((tmp_path / "marks.csv").read_text())))
    assert rows[0] == ["id", "passed", "failed", "score", "max_score", "first_failing_case",
                       "seconds"]
    assert [row[:5] for row in rows[1:]] == [["ann", "2", "0", "2", "2"], ["ben", "0", "2", "0", "2"],
                                             ["cid", "0", "2", "0", "2"], ["dee", "0", "2", "0", "2"]]
    assert rows[1][5] == "" and rows[2][5].startswith("random 1: ")
    float(rows[1][6])


def test_every_submission_passing_exits_0(run_cli, klass):
    status, out, _ = run_cli("check", klass[0], klass[0].parent.parent / "class" / "ann" / "line.py",
                             *FAST, "--id-from", r"(ann)/")
    assert status == 2  # one id twice
    status, out, _ = run_cli("check", klass[0], *FAST, "--jobs", "1")
    assert status == 0 and "PASS  ann: 2/2 cases" in out


def test_ids_from_folders_files_and_a_pattern(run_cli, tmp_path):
    for name in ("s101_ann", "s102_ben"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "bresenham.py").write_text((SAMPLES / "bresenham_correct.py").read_text())
    (tmp_path / "cid.py").write_text((SAMPLES / "bresenham_correct.py").read_text())
    args = ["--against", "line-bresenham", "--cases", "random", "1"]
    _, result, _ = _json(run_cli, tmp_path / "s101_ann", tmp_path / "s102_ben",
                         tmp_path / "cid.py", *args)
    assert [s["id"] for s in result["submissions"]] == ["s101_ann", "s102_ben", "cid"]
    _, result, _ = _json(run_cli, tmp_path / "s101_ann", tmp_path / "s102_ben", *args,
                         "--id-from", r"s(\d+)_")
    assert [s["id"] for s in result["submissions"]] == ["101", "102"]
    status, _, err = run_cli("check", tmp_path / "cid.py", *args, "--id-from", r"s(\d+)_")
    assert status == 2 and "finds no id" in err
    status, _, err = run_cli("check", tmp_path / "cid.py", *args, "--id-from", r"\d+")
    assert status == 2 and "exactly one group" in err


def test_a_folder_holds_one_file(run_cli, tmp_path):
    (tmp_path / "two").mkdir()
    for name in ("a.py", "b.py"):
        (tmp_path / "two" / name).write_text("def draw(): yield 0, 0\n")
    (tmp_path / "none").mkdir()
    for folder in ("two", "none"):
        status, out, err = run_cli("check", tmp_path / folder, "--against", "line-bresenham")
        assert status == 2 and out == "" and "holds one .py file" in err


@pytest.mark.parametrize("give_up, ran", [(1, 1), (2, 2)])
def test_a_looping_submission_stops_after_k_time_outs(run_cli, tmp_path, give_up, ran):
    (tmp_path / "loops.py").write_text(LOOPS)
    status, result, _ = _json(run_cli, tmp_path / "loops.py", "--against", "line-bresenham",
                              "--cases", "random", "4", "--time-limit", "0.1",
                              "--give-up-after", str(give_up))
    (graded,) = result["submissions"]
    outcomes = [case["outcome"] for case in graded["cases"]]
    assert status == 1
    assert outcomes == ["time"] * ran + ["skipped"] * (4 - ran)
    assert all("--give-up-after" in case["message"] for case in graded["cases"][ran:])


def _without_times(result: dict) -> dict:
    """The results without the times they took, nor what a time-out's
    message says of them (the CPU-time limit or the wall clock, whichever
    the machine's load makes come first)."""
    for graded in result["submissions"]:
        graded.pop("seconds")
        for case in graded["cases"]:
            case.pop("seconds")
            if case["outcome"] == "time":
                case.pop("message")
    return result


def test_two_jobs_give_the_results_of_one(run_cli, klass):
    one = _json(run_cli, *klass, *FAST, "--jobs", "1")
    two = _json(run_cli, *klass, *FAST, "--jobs", "2")
    assert one[0] == two[0] == 1
    assert _without_times(one[1]) == _without_times(two[1])
    assert [s["id"] for s in two[1]["submissions"]] == ["ann", "ben", "cid", "dee"]


def test_points_per_kind_and_their_total(run_cli, klass):
    status, result, _ = _json(run_cli, klass[0], klass[1], "--against", "line-bresenham",
                              "--cases", SCENE, "random", "1", "--points", "scene=3,random=2")
    ann, ben = result["submissions"]
    assert [case["kind"] for case in ann["cases"]] == ["scene", "random"]
    assert (ann["score"], ann["max_score"]) == (5, 5)
    assert (ben["score"], ben["max_score"]) == (0, 5)
    for bad in ("hard=x", "easy=2", "hard", "hard=-1"):
        status, out, err = run_cli("check", *klass, *FAST, "--points", bad)
        assert status == 2 and out == "" and "--points" in err


def test_junit_has_a_suite_per_student_with_the_capped_output(run_cli, klass, tmp_path):
    out_file = tmp_path / "class.xml"
    status, _, _ = run_cli("check", *klass, *FAST, "--junit", out_file)
    root = ET.parse(out_file).getroot()  # parses: the crashing one printed \x01
    assert status == 1 and root.tag == "testsuites"
    suites = {suite.attrib["name"]: suite for suite in root}
    assert list(suites) == ["ann", "ben", "cid", "dee"]
    assert suites["ann"].attrib["failures"] == suites["ann"].attrib["errors"] == "0"
    assert suites["ben"].attrib["failures"] == "2"
    cid = suites["cid"].findall("testcase")
    assert cid[0].find("error").attrib["type"] == "time"
    assert cid[1].find("error").attrib["type"] == "time"  # --give-up-after 2: both ran
    printed = suites["dee"].find("testcase/system-out").text
    assert "before \ufffd the end" in printed


def test_outputs_are_checked_before_any_case_runs(run_cli, klass, tmp_path):
    (tmp_path / "notes.csv").write_text("my own marks\n")
    (tmp_path / "folder.xml").mkdir()
    for option, path in (("--csv", tmp_path / "notes.csv"), ("--junit", tmp_path / "folder.xml"),
                         ("--csv", klass[0] / "line.py")):
        status, out, err = run_cli("check", *klass, *FAST, option, path)
        assert status == 2 and out == "", err
        assert err.startswith(f"rasterlab: {option} ")
    assert (tmp_path / "notes.csv").read_text() == "my own marks\n"


def test_formats_for_several_submissions_need_a_folder(run_cli, klass, tmp_path):
    status, out, err = run_cli("check", *klass[:2], *FAST, "--format", "gradescope")
    assert status == 2 and "--out FOLDER" in err
    status, out, err = run_cli("check", *klass[:2], *FAST, "--format", "gradescope",
                               "--out", tmp_path / "results")
    assert status == 1
    written = sorted(path.name for path in (tmp_path / "results").iterdir())
    assert written == ["ann.json", "ben.json"]
    assert json.loads((tmp_path / "results" / "ann.json").read_text())["score"] == 2


def test_a_format_on_stdout_is_stdouts_only_text(run_cli, klass):
    status, out, _ = run_cli("check", klass[1], *FAST, "--format", "coderunner")
    assert status == 1
    assert json.loads(out)["fraction"] == 0


def test_the_gradescope_zip(run_cli, tmp_path):
    wheel = tmp_path / "rasterlab-0.1.0-py3-none-any.whl"
    wheel.write_bytes(b"PK\x05\x06" + bytes(18))
    zip_path = tmp_path / "autograder.zip"
    status, out, err = run_cli("grader", "gradescope", "--against", "circle-midpoint",
                               "--cases", "hard", SCENE, "--points", "hard=2",
                               "--wheel", wheel, "--out", zip_path)
    assert status == 2 and "line-reversed.json: a lines scene" in err  # refused before writing
    assert not zip_path.exists()
    status, out, err = run_cli("grader", "gradescope", "--against", "line-bresenham",
                               "--cases", "hard", SCENE, "--points", "hard=2",
                               "--wheel", wheel, "--out", zip_path)
    assert status == 0, err
    with zipfile.ZipFile(zip_path) as archive:
        names = set(archive.namelist())
        assert {"setup.sh", "run_autograder", "scenes/line-reversed.json", wheel.name} <= names
        for name in ("setup.sh", "run_autograder"):
            mode = archive.getinfo(name).external_attr >> 16
            assert stat.S_ISREG(mode) and mode & stat.S_IXUSR
        run = archive.read("run_autograder").decode()
        setup = archive.read("setup.sh").decode()
    assert run.startswith("#!") and setup.startswith("#!")
    assert ("rasterlab check /autograder/submission --against line-bresenham --cases hard "
            "/autograder/source/scenes/line-reversed.json") in run
    assert "--format gradescope --out /autograder/results/results.json" in run
    assert "--points hard=2" in run
    assert f"pip install /autograder/source/{wheel.name}" in setup
