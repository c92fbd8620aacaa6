"""`rasterlab check`: exit status 0 / 1 / 2, JSON and JUnit XML that validates."""
from __future__ import annotations

import json
import os
import select
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from algorithms.core.cases import LINE_CASES
from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
SCENE = ROOT / "resources" / "scenes" / "line-reversed.json"


def test_the_correct_sample_passes_every_hard_case(run_cli):
    status, out, err = run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                               "line-bresenham")
    assert status == 0, err
    lines = out.splitlines()
    # The limits line names each limit, enforced or not (which hold: tests/app/test_platforms.py).
    assert lines[1].startswith("limits per case: wall clock 3 s (then the process is ended); ")
    assert ("CPU time 2 s" in lines[1]) != ("CPU-time limit not enforced" in lines[1])
    assert ("memory 256 MiB" in lines[1]) != ("memory limit not enforced" in lines[1])
    assert sum(line.startswith("PASS ") for line in lines) == len(LINE_CASES)
    assert lines[-1] == f"{len(LINE_CASES)} of {len(LINE_CASES)} cases pass"


def test_failures_exit_1_with_json(run_cli):
    status, out, _ = run_cli("check", SAMPLES / "off_by_one.py", "--against", "line-bresenham",
                             "--cases", str(SCENE), "random", "2", "--json")
    result = json.loads(out)
    assert status == 1
    assert [case["name"] for case in result["cases"]][0] == "line-reversed.json"
    assert result["failed"] == sum(not case["passed"] for case in result["cases"]) >= 1
    assert result["limits"]["wall_clock_seconds"] == 3
    assert result["limits"]["cpu_seconds"] in (2, None)
    assert result["limits"]["memory_bytes"] in (256 << 20, None)
    failed = next(case for case in result["cases"] if not case["passed"])
    assert failed["reference_divergence"]["got"] == "the end"
    assert failed["reference_divergence"]["step"] == failed["steps"]


def test_random_cases_repeat_with_their_seed(run_cli):
    runs = [json.loads(run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                               "line-bresenham", "--cases", "random", "3", "--seed", seed,
                               "--json")[1])
            for seed in ("7", "7", "8")]
    names = [[case["name"] for case in run["cases"]] for run in runs]
    assert names[0] == names[1] != names[2]
    assert all(run["failed"] == 0 for run in runs)


JUNIT_CASE_ATTRIBUTES = {"name", "classname", "time"}


def test_junit_xml_validates(run_cli, tmp_path):
    out_file = tmp_path / "report.xml"
    status, out, _ = run_cli("check", SAMPLES / "raises.py", "--against", "line-bresenham",
                             "--cases", "hard", "--junit", out_file)
    assert status == 1
    root = ET.parse(out_file).getroot()
    assert root.tag == "testsuites"
    (suite,) = root
    assert suite.tag == "testsuite"
    properties, *cases = list(suite)
    assert properties.tag == "properties"  # first, as the JUnit schema has it
    limits, isolation = properties
    assert limits.attrib["name"] == "limits"
    assert limits.attrib["value"].startswith("limits per case: wall clock 3 s")
    assert isolation.attrib["name"] == "isolation"
    assert isolation.attrib["value"].startswith("isolation: ")
    assert {case.tag for case in cases} == {"testcase"} and len(cases) == len(LINE_CASES)
    assert all(JUNIT_CASE_ATTRIBUTES <= set(case.attrib) for case in cases)
    for case in cases:
        assert len(case) <= 1 and all(child.tag in ("failure", "error") for child in case)
        assert all("message" in child.attrib and "type" in child.attrib for child in case)
        float(case.attrib["time"])
    errors = [case for case in cases if case.find("error") is not None]
    failures = [case for case in cases if case.find("failure") is not None]
    vertical = {n for n, (p, q) in enumerate(LINE_CASES) if p[0] == q[0]}
    assert {cases.index(case) for case in errors} == vertical  # ZeroDivisionError
    assert all("ZeroDivisionError" in case.find("error").text for case in errors)
    assert suite.attrib["errors"] == str(len(errors)) == root.attrib["errors"]
    assert suite.attrib["failures"] == str(len(failures))
    assert suite.attrib["tests"] == str(len(LINE_CASES))
    assert sum(line.startswith("FAIL ") for line in out.splitlines()) == len(errors) + len(failures)


@pytest.mark.parametrize("argv, words", [
    (["missing.py", "--against", "line-bresenham"], "no such file"),
    ([SAMPLES / "raises.py", "--against", "no-such"], "unknown algorithm"),
    ([SAMPLES / "raises.py", "--against", "aa-supersample"], "check compares lines, circles"),
    ([SAMPLES / "raises.py", "--against", "line-dda", "--cases", "random", "x"], "count"),
    ([SAMPLES / "raises.py", "--against", "line-dda", "--cases", "easy"], "not hard"),
    ([SAMPLES / "raises.py", "--against", "circle-midpoint", "--cases", SCENE], "lines scene"),
    ([SAMPLES / "raises.py", "--against", "line-dda", "--time-limit", "0"], "--time-limit"),
    ([SAMPLES / "raises.py", "--against", "line-dda", "--memory-limit", "1K"], "--memory-limit"),
    ([ROOT / "README.md", "--against", "line-dda"], ".py"),
])
def test_bad_input_exits_2_with_one_line(run_cli, argv, words):
    status, out, err = run_cli("check", *argv)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and words in err


def test_junit_xml_parses_whatever_the_file_is_called(run_cli, tmp_path):
    # Control characters (and, on POSIX, an undecodable byte) in the student's
    # file name: XML cannot hold them, the report names them as U+FFFD.
    name = "a\x01\x1b" + ("\udcff" if os.name == "posix" else "") + ".py"
    student = tmp_path / name
    student.write_bytes((SAMPLES / "bresenham_correct.py").read_bytes())
    out_file = tmp_path / "report.xml"
    status, _, err = run_cli("check", student, "--against", "line-bresenham",
                             "--cases", "hard", "--junit", out_file)
    assert status == 0, err
    (suite,) = ET.parse(out_file).getroot()
    assert suite.attrib["name"].startswith("a\ufffd\ufffd")


@pytest.mark.parametrize("outputs", [["--junit", "{missing}/out.xml"],
                                     ["--csv", "{missing}/marks.csv", "--junit", "{tmp}/out.xml"]])
def test_an_output_in_a_missing_folder_is_refused_before_any_case_runs(run_cli, tmp_path,
                                                                       outputs):
    missing = tmp_path / "not here"
    words = [word.format(missing=missing, tmp=tmp_path) for word in outputs]
    # two submissions (a batch) when --csv is given, else one file
    submissions = [SAMPLES / "off_by_one.py"] * (2 if "--csv" in words else 1)
    if len(submissions) == 2:
        submissions = [tmp_path / name for name in ("ann", "bob")]
        for folder in submissions:
            folder.mkdir()
            (folder / "line.py").write_text((SAMPLES / "off_by_one.py").read_text())
    status, out, err = run_cli("check", *submissions, "--against", "line-bresenham", *words)
    assert status == 2
    assert out == ""  # not one case ran
    assert err.strip() == f"rasterlab: {words[0]} {words[1]}: the folder {missing} does not exist"
    assert list(tmp_path.glob("*.xml")) == []


def test_one_file_that_loops_costs_two_time_limits_not_one_per_case(run_cli, tmp_path):
    loops = tmp_path / "loops.py"
    loops.write_text("def draw(x0, y0, x1, y1):\n    while True:\n        pass\n", "utf-8")
    junit = tmp_path / "grades.xml"
    status, out, err = run_cli("check", loops, "--against", "line-bresenham", "--cases",
                               "hard", "--time-limit", "0.3", "--json", "--junit", junit)
    assert status == 1, err
    kinds = [case["outcome"] for case in json.loads(out)["cases"]]
    assert len(kinds) == len(LINE_CASES) > 2
    assert kinds[:2] == ["time", "time"] and set(kinds[2:]) == {"skipped"}
    suite = ET.parse(junit).getroot().find("testsuite")
    assert suite.get("skipped") == str(len(LINE_CASES) - 2) and suite.get("errors") == "2"


@pytest.mark.skipif(sys.platform == "win32", reason="select() on a pipe: POSIX only")
def test_each_case_is_printed_as_it_ends(tmp_path):
    # A second per case: after the first case's line nothing more may be
    # waiting in the pipe (a report printed at the end arrives all at once).
    slow = tmp_path / "slow.py"
    slow.write_text("import time\n\ndef draw(x0, y0, x1, y1):\n    time.sleep(1)\n"
                    "    yield x0, y0\n", "utf-8")
    child = subprocess.Popen([sys.executable, "-m", "rasterlab", "check", str(slow), "--against",
                              "line-bresenham", "--cases", "random", "3"], cwd=ROOT,
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, bufsize=0)
    out = child.stdout.fileno()

    def line() -> bytes:
        read = b""
        while not read.endswith(b"\n"):
            byte = os.read(out, 1)
            assert byte, "the command ended before printing a case"
            read += byte
        return read
    try:
        while not line().startswith((b"PASS", b"FAIL")):
            pass
        waiting, _, _ = select.select([out], [], [], 0.3)
        assert not waiting, "the other cases were printed with the first, at the end"
        rest = b"".join(iter(lambda: os.read(out, 4096), b""))
    finally:
        child.kill()
        child.wait()
    assert b"FAIL  random 3" in rest
