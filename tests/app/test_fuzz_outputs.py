"""Fuzzing every output format with adversarial names: whatever a scene's
title, description and bookmark names hold, and whatever an output file is
called, each writer ends with status 0 or 2 and never a traceback, writes
nothing outside its folder, leaves its input as it was, and what it writes
parses back as its reader would.

Titles and names draw on each format's dangerous sequences, control
characters, lone surrogates, line ends and very long text. File names are any
name the operating system can hold (no NUL or '/'), on POSIX undecodable bytes
included (as os.fsdecode gives them). The examples per format are printed at
the end of the run (`pytest -s`), so a run's figures can be quoted.
"""
from __future__ import annotations

import collections
import csv
import hashlib
import os
import shutil
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from app.model.scene import Scene, SceneError, save
from app.model.shipped import STUDENTS
from tests.app.cli.test_fuzz_cli import fuzz_settings
from tests.app.test_escaping import ESCAPES, LINES, Html, render_commonmark, tex_tokens

DANGEROUS = ["<!--<script>", "</script>", "]]>", "\\input{x}", "\\write18{ls}", "\n", "\r\n",
             "%", "![a](http://x/y.png)", "=cmd|' /C calc'!A0", "<img src=x>", "&", "\x00",
             "\x1b[31m", "\u2028", "\ud800", "\udcff", "\ufffe", "^^J", "{", "}", "$", "#"]
EXAMPLES = 15  # per format in the default run
SLOW_EXAMPLES = 60  # per format under -m slow
COUNTS: collections.Counter = collections.Counter()


def adversarial_text(max_size: int = 40):
    anything = st.characters(codec=None, exclude_categories=())
    return st.one_of(
        st.lists(st.one_of(st.sampled_from(DANGEROUS), st.text(alphabet=anything, max_size=6)),
                 max_size=max_size // 4).map("".join),
        st.text(alphabet=anything, max_size=max_size),
        st.sampled_from(DANGEROUS).map(lambda part: part * 300),  # very long
    )


def file_name_or_none(text: str) -> str | None:
    """``text`` when the OS can hold it as one file name, else None."""
    if not text or "\x00" in text or "/" in text or os.sep in text or text in (".", ".."):
        return None
    try:
        os.fsencode(text)
    except UnicodeError:  # a surrogate os.fsdecode never gives
        return None
    return text


def file_names():
    drawn = adversarial_text(60).map(file_name_or_none)
    if sys.platform != "win32":
        undecodable = st.binary(min_size=1, max_size=12).map(
            lambda raw: os.fsdecode(b"\xff" + raw)).map(file_name_or_none)
        drawn = st.one_of(drawn, undecodable)
    return drawn.filter(lambda name: name is not None)


def bookmarks():
    names = st.lists(adversarial_text(), max_size=3)
    return names.map(lambda ns: tuple({"name": n, "step": k + 1} for k, n in enumerate(ns)))


# Each format: the argv after the scene (given the output's base path), and
# the suffix its output gets when the name has none of its own.
FORMATS = {
    "gif": lambda scene, out: ["export", scene, "--gif", out + ".gif", "--to", "2"],
    "mp4": lambda scene, out: ["export", scene, "--mp4", out + ".mp4", "--to", "2"],
    "webm": lambda scene, out: ["export", scene, "--webm", out + ".webm", "--to", "2"],
    "svg-dir": lambda scene, out: ["export", scene, "--svg-dir", out, "--to", "2"],
    "frames-dir": lambda scene, out: ["export", scene, "--frames-dir", out, "--to", "2"],
    "pdf-beamer": lambda scene, out: ["export", scene, "--pdf", out + ".pdf",
                                      "--beamer", out + ".tex", "--to", "2"],
    "html": lambda scene, out: ["export", scene, "--html", out + ".html"],
    "worksheet-pdf": lambda scene, out: ["worksheet", scene, "--out", out, "--format", "pdf"],
    "worksheet-md": lambda scene, out: ["worksheet", scene, "--out", out, "--format", "md"],
    "worksheet-tex": lambda scene, out: ["worksheet", scene, "--out", out, "--format", "tex"],
    "worksheet-csv": lambda scene, out: ["worksheet", scene, "--out", out, "--format", "csv"],
    "run-save": lambda scene, out: ["run", "--scene", scene, "--save", out + ".json"],
    "check-junit": None,  # argv of its own: the student's file is named too
}


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def listing(folder: Path) -> set:
    return {str(p.relative_to(folder)) for p in folder.rglob("*")}


# ------------------------------------------------------------------ readers
def html_parses(page: Path, template_script_ends: int, template_comments: int):
    raw = page.read_text(encoding="utf-8")
    assert raw.count("</script") == template_script_ends and raw.count("<!--") == template_comments


def svg_parses(folder: Path):
    frames = sorted(folder.glob("*.svg"))
    assert frames
    for frame in frames:
        ET.parse(frame)


def tex_holds_no_command(tex: Path, allowed: set):
    commands, _ = tex_tokens(tex.read_text(encoding="utf-8"))
    assert set(commands) <= ESCAPES | allowed, set(commands) - ESCAPES - allowed


def worksheet_tex_parses(folder: Path):
    for name in ("worksheet.tex", "answers.tex"):
        text = (folder / name).read_text(encoding="utf-8")
        tex_holds_no_command(folder / name, {"begin", "end", "hline", "\\"})
        head = text[:text.index("\\begin{tabular}")]
        # Every line of the title and description is a comment of its own
        # (the student's sheet then has its name and date line, fixed text).
        assert all(line.startswith("% ") or line == "%" or line.startswith("Name:")
                   for line in LINES.split(head)[:-1])


def markdown_renders_as_text(folder: Path):
    page = Html(render_commonmark((folder / "worksheet.md").read_text(encoding="utf-8")))
    tags = {tag for tag, _ in page.tags}
    assert tags <= {"h1", "p", "code", "pre", "table", "thead", "tbody", "tr", "th", "td", "img"}
    assert [attrs["src"] for tag, attrs in page.tags if tag == "img"] == ["worksheet-grid.png"]


def csv_reads_back(folder: Path):
    for path in folder.glob("*.csv"):
        with open(path, encoding="utf-8", newline="") as stream:
            assert list(csv.reader(stream))


def check_outputs(kind: str, out: str, template):
    """Parse what a command that ended with status 0 wrote."""
    if kind == "html":
        html_parses(Path(out + ".html"), *template)
    elif kind == "svg-dir":
        svg_parses(Path(out))
    elif kind == "pdf-beamer":
        tex_holds_no_command(Path(out + ".tex"), {"begin", "end", "centering", "only",
                                                  "includegraphics", "linewidth", "textheight"})
    elif kind == "worksheet-tex":
        worksheet_tex_parses(Path(out))
    elif kind == "worksheet-md":
        markdown_renders_as_text(Path(out))
    elif kind == "worksheet-csv":
        csv_reads_back(Path(out))
    elif kind == "check-junit":
        ET.parse(out + ".xml")
    elif kind == "run-save":
        assert Path(out + ".json").is_file()


@pytest.fixture(scope="module")
def html_template(tmp_path_factory):
    """How many </script and <!-- the page holds for a plain scene: the
    template's own, which no user text may add to."""
    folder = tmp_path_factory.mktemp("plain")
    save(Scene(title="plain"), folder / "plain.json")
    from app import cli
    assert cli.main(["export", str(folder / "plain.json"), "--html", str(folder / "p.html")]) == 0
    raw = (folder / "p.html").read_text(encoding="utf-8")
    return raw.count("</script"), raw.count("<!--")


@pytest.fixture(scope="module", autouse=True)
def print_counts():
    yield
    if COUNTS:
        print("\nexamples per format (status 0 / status 2 / scene refused):")
        for kind in FORMATS:
            print(f"  {kind:14} {COUNTS[kind, 0]:4} / {COUNTS[kind, 2]:4} / "
                  f"{COUNTS[kind, 'refused']:4}")


def fuzz_one(kind, title, description, marks, name, run_cli, template):
    with tempfile.TemporaryDirectory() as base:
        base = Path(base)
        inputs, outputs, here = base / "in", base / "out", base / "cwd"
        for folder in (inputs, outputs, here):
            folder.mkdir()
        scene = inputs / "scene.json"
        try:
            save(Scene(title=title, description=description, bookmarks=marks), scene)
        except SceneError:
            COUNTS[kind, "refused"] += 1
            return
        before = digest(scene)
        out = str(outputs / name)
        if kind == "check-junit":
            student = inputs / (name[:200] + ".py")  # the output's name, as the student's file
            try:
                shutil.copyfile(STUDENTS / "bresenham_correct.py", student)
            except OSError:
                student = inputs / "student.py"
                shutil.copyfile(STUDENTS / "bresenham_correct.py", student)
            argv = ["check", student, "--against", "line-bresenham", "--cases", scene,
                    "--junit", out + ".xml"]
        else:
            argv = FORMATS[kind](str(scene), out)
        cwd = os.getcwd()
        os.chdir(here)
        try:
            status, _, err = run_cli(*argv)
        finally:
            os.chdir(cwd)
        COUNTS[kind, status] += 1
        assert "Traceback" not in err, err
        assert status in (0, 2), err
        if status == 2:
            assert len(err.strip().splitlines()) == 1, err
        assert digest(scene) == before
        assert listing(here) == set() and set(os.listdir(base)) == {"in", "out", "cwd"}
        assert {p.name for p in inputs.iterdir()} <= {"scene.json", Path(str(argv[1])).name}
        if status == 0:
            check_outputs(kind, out, template)


def fuzzer(examples):
    @fuzz_settings(examples)
    # Every dangerous sequence at once, and a name longer than a file name may be.
    @example(title="".join(DANGEROUS), description="\n".join(DANGEROUS),
             marks=tuple({"name": part, "step": 1} for part in DANGEROUS[:8]), name="x" * 300)
    @example(title="\\input{x}\n\\write18{ls}", description="", marks=(),
             name="".join(part for part in DANGEROUS if file_name_or_none(part)))
    @given(title=adversarial_text(), description=adversarial_text(), marks=bookmarks(),
           name=file_names())
    def fuzz(kind, run_cli, html_template, title, description, marks, name):
        fuzz_one(kind, title, description, marks, name, run_cli, html_template)
    return fuzz


@pytest.mark.parametrize("kind", list(FORMATS))
def test_every_format_takes_any_name(kind, run_cli, html_template):
    fuzzer(EXAMPLES)(kind, run_cli, html_template)


@pytest.mark.slow
@pytest.mark.parametrize("kind", list(FORMATS))
def test_every_format_takes_any_name_long_run(kind, run_cli, html_template):
    fuzzer(SLOW_EXAMPLES)(kind, run_cli, html_template)
