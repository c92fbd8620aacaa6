"""What a newcomer meets first: the window without a display, `list`, the
report's promised time, set-up run a first and a second time (in a copy of
its own, so no test needs the checkout's .venv)."""
import hashlib
import os
import re
import shutil
import subprocess

import pytest

from algorithms.core import registry
from tests.support import ROOT

# scripts/setup.sh is for Debian and Ubuntu: bash and coreutils' sha256sum.
needs_setup_tools = pytest.mark.skipif(
    shutil.which("bash") is None or shutil.which("sha256sum") is None,
    reason="scripts/setup.sh runs where bash and sha256sum are (Debian, Ubuntu)")


@pytest.mark.parametrize("platform", [None, "xcb"])
def test_the_window_without_a_display_is_refused_in_one_line(run_cli, monkeypatch, platform):
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    if platform is None:
        monkeypatch.delenv("QT_QPA_PLATFORM", raising=False)
    else:
        monkeypatch.setenv("QT_QPA_PLATFORM", platform)
    status, out, err = run_cli()
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and "needs a display" in err and "rasterlab run" not in err
    assert "`run`" in err and "Xvfb" in err


def test_list_shows_the_choices_of_every_choice_option(run_cli):
    status, out, _ = run_cli("list")
    assert status == 0
    lines = {line.split()[0]: line for line in out.splitlines()}
    for spec in registry.all_specs():
        for option in spec.options:
            if option.kind == "choice" and len(option.choices) > 1:
                shown = "|".join(map(str, option.choices))
                assert f"{option.name}=" in lines[spec.name] and f"({shown})" in lines[spec.name]


def test_report_help_and_the_guide_promise_the_same_time(run_cli):
    status, out, _ = run_cli("report", "--help", child=True)
    guide = (ROOT / "docs" / "guides" / "lecturers.md").read_text(encoding="utf-8")
    assert status == 0
    help_text = " ".join(out.split())
    assert "about a tenth of the full report's work" in help_text
    assert re.search(r"`--quick` runs smaller sweeps, about a tenth of the full report's work",
                     " ".join(guide.split()))


@pytest.fixture
def setup_copy(tmp_path):
    """scripts/setup.sh and pyproject.toml in a folder of their own, with a
    stand-in for every command that would install something: ``dpkg``
    finds each system package, and ``.venv/bin/python`` only notes its
    arguments in calls.txt. Returns (folder, run)."""
    (tmp_path / "scripts").mkdir()
    shutil.copy(ROOT / "scripts" / "setup.sh", tmp_path / "scripts" / "setup.sh")
    shutil.copy(ROOT / "pyproject.toml", tmp_path / "pyproject.toml")
    tools = tmp_path / "tools"
    tools.mkdir()
    stand_in(tools / "dpkg", "exit 0")
    venv = tmp_path / ".venv" / "bin"
    venv.mkdir(parents=True)
    stand_in(venv / "python", f'echo "$*" >> "{tmp_path / "calls.txt"}"')
    stand_in(venv / "rasterlab", "exit 0")
    environment = os.environ | {"PATH": f"{tools}{os.pathsep}{os.environ['PATH']}"}

    def run():
        return subprocess.run(["bash", "scripts/setup.sh"], cwd=tmp_path, env=environment,
                              capture_output=True, text=True, timeout=120)
    return tmp_path, run


def stand_in(path, body):
    path.write_text(f"#!/bin/sh\n{body}\n")
    path.chmod(0o755)


def calls(folder) -> list:
    path = folder / "calls.txt"
    return path.read_text().splitlines() if path.exists() else []


@needs_setup_tools
def test_setup_installs_when_pyproject_changed_and_keeps_its_checksum(setup_copy):
    folder, run = setup_copy
    done = run()
    assert done.returncode == 0 and done.stderr == ""
    assert any('install --quiet -e .[test]' in call for call in calls(folder))
    wanted = hashlib.sha256((folder / "pyproject.toml").read_bytes()).hexdigest()
    assert (folder / ".venv" / ".rasterlab-installed").read_text().strip() == wanted


@needs_setup_tools
def test_setup_run_again_changes_nothing_and_says_one_line(setup_copy):
    folder, run = setup_copy
    run()
    before = calls(folder)
    done = run()
    assert done.returncode == 0 and done.stderr == ""
    assert done.stdout.count("\n") == 1 and "set up in .venv" in done.stdout
    assert calls(folder) == before, "set-up installed again with pyproject.toml unchanged"
