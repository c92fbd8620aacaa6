"""The documentation builds, its links hold, and every example it shows
prints what it shows (CONTRIBUTING.md, "Documentation", says how examples
are written).

Nothing here uses the network: links to other sites are not followed.
"""
from __future__ import annotations

import doctest
import importlib.util
import os
import re
import shlex
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
# The README, the docs and the two top-level pages the docs include.
PAGES = ([ROOT / "README.md", ROOT / "ARCHITECTURE.md", ROOT / "CONTRIBUTING.md"]
         + sorted((ROOT / "docs").rglob("*.md")))
FENCE = re.compile(r"^([ \t]*)```(\w*)[^\n]*\n(.*?)^\1```[ \t]*$", re.MULTILINE | re.DOTALL)
# Folders of a checkout a console example may name (resources/students/...).
EXAMPLE_DATA = ("scenes", "students", "templates")
HANG_GUARD = 900  # seconds; a command that has not ended by then hangs


def fences(page: Path) -> list[tuple[str, str, int]]:
    """(language, content, line number) of every fenced block of a page."""
    text = page.read_text(encoding="utf-8")
    return [(match.group(2), textwrap.dedent(match.group(3)),
             text.count("\n", 0, match.start()) + 1) for match in FENCE.finditer(text)]


def console_examples(content: str) -> list[tuple[str, str]]:
    """(command, expected output) of each `$ ` line of a console block."""
    examples = []
    for line in content.splitlines():
        if line.startswith("$ "):
            examples.append([line[2:], []])
        elif examples:
            examples[-1][1].append(line)
    return [(command, "".join(f"{line}\n" for line in output)) for command, output in examples]


def matches(expected: str, printed: str) -> bool:
    """Printed output against the shown one; `...` stands for text left out."""
    return doctest.OutputChecker().check_output(expected, printed, doctest.ELLIPSIS)


def where(page: Path, line: int) -> str:
    return f"{page.relative_to(ROOT).as_posix()}:{line}"


CONSOLE_BLOCKS = [pytest.param(content, id=where(page, line))
                  for page in PAGES for language, content, line in fences(page)
                  if language == "console"]
PYCON_PAGES = [pytest.param(page, id=page.relative_to(ROOT).as_posix())
               for page in PAGES if any(language == "pycon" for language, _, _ in fences(page))]


# ------------------------------------------------------------------- building
def test_the_site_builds_with_warnings_as_errors(tmp_path):
    done = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet",
                           "--site-dir", str(tmp_path / "site")], cwd=ROOT,
                          capture_output=True, text=True, timeout=HANG_GUARD)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "site" / "reference" / "algorithms" / "index.html").is_file()


def test_the_build_refuses_a_broken_link_or_anchor(tmp_path):
    """The validation settings of mkdocs.yml make these errors, not notes."""
    settings = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))
    docs = tmp_path / "docs"
    docs.mkdir()
    (docs / "index.md").write_text("# Home\n\n[there](other.md#no-such-part)\n", encoding="utf-8")
    (docs / "other.md").write_text("# Other\n\n[gone](missing.md)\n", encoding="utf-8")
    config = tmp_path / "mkdocs.yml"
    config.write_text(yaml.safe_dump({"site_name": "probe", "docs_dir": "docs",
                                      "validation": settings["validation"]}), encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-f", str(config),
                           "--site-dir", str(tmp_path / "site")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=HANG_GUARD)
    assert done.returncode != 0
    assert "no-such-part" in done.stderr and "missing.md" in done.stderr


def test_the_readme_links_and_pictures_point_at_files_that_exist():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    anchors = {_anchor(title) for title in re.findall(r"^#+ (.+)$", text, re.MULTILINE)}
    targets = re.findall(r"\]\(([^)\s]+)\)", text)
    assert targets
    for target in targets:
        if re.match(r"[a-z]+:", target):
            continue  # another site: not followed here
        path, _, anchor = target.partition("#")
        if path:
            assert (ROOT / path).exists(), f"README.md links to {target}, which does not exist"
        else:
            assert anchor in anchors, f"README.md links to #{anchor}, which no heading makes"


def _anchor(title: str) -> str:
    """A heading's anchor, as GitHub makes it."""
    return re.sub(r"[^\w\- ]", "", title.strip().lower()).replace(" ", "-")


def test_the_generated_reference_pages_are_current():
    script = ROOT / "scripts" / "docs_reference.py"
    spec = importlib.util.spec_from_file_location("docs_reference", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for path, text in module.pages().items():
        committed = (ROOT / path).read_text(encoding="utf-8")
        assert committed == text, f"{path} is out of date: run python scripts/docs_reference.py"


# ------------------------------------------------------------------- examples
@pytest.mark.parametrize("content", CONSOLE_BLOCKS)
def test_every_console_example_prints_what_it_shows(content, tmp_path):
    examples = console_examples(content)
    assert examples, "a console block shows no `$ ` command"
    for name in EXAMPLE_DATA:
        shutil.copytree(ROOT / "resources" / name, tmp_path / "resources" / name)
    for command, expected in examples:
        printed = _run(command, tmp_path)
        assert matches(expected, printed), (
            f"$ {command}\nshown:\n{expected}\nprinted:\n{printed}")


def _run(command: str, folder: Path) -> str:
    words = shlex.split(command)
    assert words[0] == "rasterlab", f"a console example runs rasterlab, not {words[0]}"
    env = dict(os.environ, PYTHONPATH=str(ROOT), PYTHONIOENCODING="utf-8")
    done = subprocess.run([sys.executable, "-m", "rasterlab", *words[1:]], cwd=folder, env=env,
                          capture_output=True, timeout=HANG_GUARD)
    assert b"Traceback" not in done.stderr, done.stderr.decode("utf-8", "replace")
    return done.stdout.decode("utf-8").replace("\r\n", "\n")


@pytest.mark.parametrize("page", PYCON_PAGES)
def test_every_python_example_prints_what_it_shows(page, tmp_path, monkeypatch):
    """A page's pycon blocks are one doctest, run in order in an empty folder."""
    monkeypatch.chdir(tmp_path)
    blocks = [(content, line) for language, content, line in fences(page) if language == "pycon"]
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    globs: dict = {}
    report: list[str] = []
    for content, line in blocks:
        test = parser.get_doctest(content, globs, where(page, line), str(page), line)
        runner.run(test, out=report.append, clear_globs=False)
        globs = test.globs  # a DocTest runs in a copy: the next block goes on from this one
    assert runner.failures == 0, "".join(report)


def test_commands_are_shown_only_where_they_are_run():
    """A `rasterlab ...` line outside a console block would go unchecked."""
    shown = re.compile(r"^(\$ )?rasterlab\s+[\w-]")
    for page in PAGES:
        for language, content, line in fences(page):
            if language == "console":
                continue
            for text in content.splitlines():
                assert not shown.match(text), (
                    f"{where(page, line)}: {text!r} belongs in a console block with its output")


# ------------------------------------------------------------- the harness
def test_an_omission_stands_for_lines_and_a_wrong_line_is_found():
    shown = "first\n...\nlast\n"
    assert matches(shown, "first\nsecond\nthird\nlast\n")
    assert not matches(shown, "first\nsecond\nlost\n")
    assert not matches("only\n", "only\nmore\n")


def test_console_blocks_split_into_commands_and_their_output():
    block = "$ rasterlab list --scenes\na  A\n...\n$ rasterlab --version\nrasterlab 0.1.0\n"
    assert console_examples(block) == [("rasterlab list --scenes", "a  A\n...\n"),
                                       ("rasterlab --version", "rasterlab 0.1.0\n")]


def test_the_algorithm_counts_the_docs_give_are_current():
    from algorithms.core import registry
    count = len(registry.all_specs())
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    changelog = (ROOT / "docs" / "developers" / "changelog.md").read_text(encoding="utf-8")
    assert f"It covers {count} algorithms" in readme
    assert f"**Algorithms** ({count}, in" in changelog
