"""`rasterlab check --cmd`: a program in any language, fed each case as a
JSON line, its JSON lines of steps read as untrusted input. The shipped C,
C++ and JavaScript templates are built (where a compiler or node is
installed) with a correct Bresenham spliced in, which passes, and a wrong
one, which fails; programs that write garbage, flood stdout or never end
fail their cases (exit 1) with valid JSON and JUnit."""
from __future__ import annotations

import json
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from algorithms.core.errors import InputError
from app.model import shipped
from app.teaching import student_answer, student_command
from app.teaching.sandbox import Ran
from app.teaching.student_answer import NoAnswer

HELLO = student_answer.HELLO + b"\n"
FROM, TO = "---- your algorithm: from here ----", "---- to here ----"

# Bresenham's line in every octant; WRONG turns the tie (d = 0) the wrong way.
C_DRAW = """
static void draw(long x0, long y0, long x1, long y1)
{
    long dx = labs(x1 - x0), dy = labs(y1 - y0), sx = x1 >= x0 ? 1 : -1, sy = y1 >= y0 ? 1 : -1;
    int steep = dy > dx;
    if (steep) { long t = dx; dx = dy; dy = t; }
    long d = 2 * dy - dx, x = x0, y = y0;
    step(x, y, d);
    for (long i = 0; i < dx; i++) {
        long decided = d;
        if (d <= 0) d += 2 * dy;
        else { d += 2 * (dy - dx); if (steep) x += sx; else y += sy; }
        if (steep) y += sy; else x += sx;
        step(x, y, decided);
    }
}
"""
JS_DRAW = """
function draw(x0, y0, x1, y1) {
    let dx = Math.abs(x1 - x0), dy = Math.abs(y1 - y0);
    const sx = x1 >= x0 ? 1 : -1, sy = y1 >= y0 ? 1 : -1, steep = dy > dx;
    if (steep) [dx, dy] = [dy, dx];
    let d = 2 * dy - dx, x = x0, y = y0;
    step(x, y, { d });
    for (let i = 0; i < dx; i++) {
        const decided = d;
        if (d <= 0) d += 2 * dy;
        else { d += 2 * (dy - dx); if (steep) x += sx; else y += sy; }
        if (steep) y += sy; else x += sx;
        step(x, y, { d: decided });
    }
}
"""
WRONG = ("if (d <= 0)", "if (d < 0)")


def spliced(template: str, body: str) -> str:
    """The shipped template with its draw() replaced by ``body``."""
    text = (shipped.TEMPLATES / template).read_text(encoding="utf-8")
    start, end = text.index(FROM), text.index(TO)
    return text[:text.index("\n", start) + 1] + body + text[text.rindex("\n", 0, end):]


def tool(*names: str) -> str:
    found = next((shutil.which(name) for name in names if shutil.which(name)), None)
    if found is None:
        print(f"skipped: none of {', '.join(names)} is installed")
        pytest.skip(f"none of {', '.join(names)} is installed")
    return found


def built(tmp_path, compiler: str, template: str, body: str, name: str) -> Path:
    """A submission folder holding the program ``raster`` built from the template."""
    folder = tmp_path / name
    folder.mkdir()
    source = folder / template
    source.write_text(spliced(template, body), encoding="utf-8")
    subprocess.run([compiler, "-O1", "-o", str(folder / "raster"), str(source)], check=True,
                   capture_output=True, timeout=300)
    return folder


def check(run_cli, *words, junit=None):
    extra = ["--junit", junit] if junit else []
    status, out, err = run_cli("check", *words, "--against", "line-bresenham", "--json", *extra)
    return status, (json.loads(out) if out.strip() else None), err


@pytest.mark.parametrize("template, compilers", [("line.c", ("cc", "gcc")),
                                                 ("line.cpp", ("c++", "g++"))])
def test_a_compiled_correct_bresenham_passes_and_a_wrong_one_fails(run_cli, tmp_path, template,
                                                                   compilers):
    compiler = tool(*compilers)
    right = built(tmp_path, compiler, template, C_DRAW, "alice")
    wrong = built(tmp_path, compiler, template, C_DRAW.replace(*WRONG), "bob")
    status, report, err = check(run_cli, "--cmd", "./raster", right / "raster")
    assert status == 0, err
    assert report["cases"] and all(case["passed"] for case in report["cases"])
    junit = tmp_path / "class.xml"
    status, report, err = check(run_cli, "--cmd", "./raster", right, wrong, junit=junit)
    assert status == 1, err
    by_id = {entry["id"]: entry for entry in report["submissions"]}
    assert by_id["alice"]["failed"] == 0 and by_id["bob"]["failed"] > 0
    assert {suite.attrib["name"] for suite in ET.parse(junit).getroot()} == {"alice", "bob"}


@pytest.mark.parametrize("template", ["line.c", "line.cpp"])
def test_the_shipped_templates_build_and_fail_as_they_stand(run_cli, tmp_path, template):
    compiler = tool(*(("cc", "gcc") if template == "line.c" else ("c++", "g++")))
    folder = tmp_path / "student"
    folder.mkdir()
    shutil.copyfile(shipped.TEMPLATES / template, folder / template)
    subprocess.run([compiler, "-o", str(folder / "raster"), str(folder / template)], check=True,
                   capture_output=True, timeout=300)
    status, report, err = check(run_cli, "--cmd", "./raster", folder / "raster")
    assert status == 1, err
    first = report["cases"][0]
    assert first["outcome"] == "ok" and not first["passed"]  # the protocol holds; the pixels don't


def test_a_javascript_bresenham_runs_under_node(run_cli, tmp_path):
    tool("node")
    right, wrong = tmp_path / "alice.js", tmp_path / "bob.js"
    right.write_text(spliced("line.js", JS_DRAW), encoding="utf-8")
    wrong.write_text(spliced("line.js", JS_DRAW.replace(*WRONG)), encoding="utf-8")
    status, report, err = check(run_cli, "--cmd", "node {}", right)
    assert status == 0, err
    status, report, err = check(run_cli, "--cmd", "node {}", wrong)
    assert status == 1, err
    assert "differs from the reference" in json.dumps(report)


HOSTILE = {
    "garbage": "printf 'not json \\001\\n'",
    "flood": "while :; do echo '{\"x\": 1, \"y\": 1}'; done",
    "huge line": "while :; do printf xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx; done",
    "never ends": "while :; do :; done",
    "no end marker": "echo '{\"x\": 0, \"y\": 0}'",
}


@pytest.mark.parametrize("name", HOSTILE)
def test_a_hostile_program_fails_its_cases_and_is_contained(run_cli, tmp_path, name):
    shell = tool("sh")
    script = tmp_path / "raster.sh"
    script.write_text(HOSTILE[name] + "\n", encoding="utf-8")
    junit = tmp_path / "report.xml"
    status, report, err = run_cli("check", "--cmd", f"{shell} {{}}", script, "--against",
                                  "line-bresenham", "--cases", "random", "2", "--time-limit",
                                  "0.5", "--json", "--junit", junit)
    assert status == 1, err
    cases = json.loads(report)["cases"]
    assert len(cases) == 2 and not any(case["passed"] for case in cases)
    suite = ET.parse(junit).getroot().attrib
    assert int(suite["failures"]) + int(suite["errors"]) == 2


# ------------------------------------------------------------- the protocol
def answer(*lines: bytes, dropped: int = 0, status: int = 0) -> Ran:
    return Ran(status, HELLO + b"".join(line + b"\n" for line in lines), dropped, b"", 0)


def test_steps_up_to_the_end_marker_are_read():
    kind, steps, error = student_answer.program_answer(answer(
        b'{"x": 3, "y": 1, "vars": {"d": -2}}', b"", b'{"x": 4, "y": 1}', b'{"done": true}'), 10)
    assert (kind, error) == ("ok", "")
    assert steps == ((3, 1, {"d": -2}), (4, 1, {}))


def test_an_error_line_and_a_missing_end_marker_are_told_apart():
    kind, steps, error = student_answer.program_answer(
        answer(b'{"x": 0, "y": 0}', b'{"error": "bad \\u0001 input"}'), 10)
    assert kind == "exception" and steps == ((0, 0, {}),) and "\x01" not in error
    assert student_answer.program_answer(answer(b'{"x": 0, "y": 0}'), 10)[0] == "unfinished"


@pytest.mark.parametrize("line", [b"hello", b'{"x": 1.5, "y": 0}', b'{"x": 1, "y": 0, "z": 2}',
                                  b'{"x": 1, "y": 0, "vars": [1]}', b'[1, 2]',
                                  b'{"x": 1, "y": 0, "vars": {"d": 1e999}}'])
def test_a_line_outside_the_protocol_is_no_answer(line):
    with pytest.raises(NoAnswer, match="line 1"):
        student_answer.program_answer(answer(line, b'{"done": true}'), 10)


def test_more_steps_than_allowed_end_as_too_long():
    lines = [b'{"x": 0, "y": 0}'] * 5
    kind, steps, _ = student_answer.program_answer(answer(*lines, b'{"done": true}'), 3)
    assert kind == "too-long" and len(steps) == 3


def test_an_answer_over_the_cap_is_no_answer():
    with pytest.raises(NoAnswer, match="MiB"):
        student_answer.program_answer(answer(b'{"x": 0, "y": 0}', b'{"x": 1, "y"', dropped=5), 10)


def test_a_program_that_ends_with_a_failure_after_done_fails():
    ran = answer(b'{"done": true}', status=3)
    outcome = student_command.outcome(ran, student_command.Limits(), 0.0)
    assert outcome.kind == "crash" and "status 3" in outcome.error


# ------------------------------------------------------------- the command
def test_a_command_outside_the_submission_or_not_installed_is_refused():
    with pytest.raises(InputError, match="inside the submission"):
        student_command.parse("../raster")
    with pytest.raises(InputError, match="no program"):
        student_command.parse("no-such-program-of-rasterlab")
    with pytest.raises(InputError, match="needs a command"):
        student_command.parse("  ")


def test_a_program_in_the_home_folder_is_never_shown(tmp_path, monkeypatch):
    program = tmp_path / "bin" / "raster"
    program.parent.mkdir()
    program.write_text("#!/bin/sh\n", encoding="utf-8")
    program.chmod(0o755)
    monkeypatch.setattr(Path, "home", classmethod(lambda cls: tmp_path))
    with pytest.raises(InputError, match="home folder"):
        student_command.parse(str(program))


def test_a_system_program_is_shown_with_its_own_installation(tmp_path):
    java = tmp_path / "jvm" / "bin" / "java"
    java.parent.mkdir(parents=True)
    java.write_text("", encoding="utf-8")
    assert student_command._installation(str(java)) == (str(tmp_path / "jvm"),)
    assert student_command._installation("/usr/bin/node")[0] == "/usr/bin/node"


def test_the_placeholder_names_the_submission_file(tmp_path):
    command = student_command.Command("node {} --fast", ("/usr/bin/node", "{}", "--fast"),
                                      "/usr/bin/node")
    submitted = tmp_path / "alice.js"
    submitted.write_text("", encoding="utf-8")
    assert student_command.program_for(command, submitted).words == (
        "/usr/bin/node", "alice.js", "--fast")
    with pytest.raises(InputError, match="folder"):
        student_command.program_for(command, tmp_path)


def test_the_program_templates_are_listed(run_cli):
    status, out, _ = run_cli("template")
    assert status == 0
    names = {line.split()[0] for line in out.splitlines()}
    assert {"line", "line.c", "line.cpp", "line.js"} <= names
    status, out, _ = run_cli("template", "line.c")
    assert status == 0 and '{"done": true}' in out
