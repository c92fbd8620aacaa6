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

# The stand-ins of the set-up tests are shell scripts.
needs_setup_tools = pytest.mark.skipif(
    os.name != "posix" or shutil.which("bash") is None,
    reason="the stand-ins for apt-get, dpkg and the venv's Python are shell scripts")


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
    """scripts/setup.sh, pyproject.toml and requirements/ in a folder of their
    own, with a stand-in for every command that would install something:
    ``apt-get`` and ``.venv/bin/python`` only note their arguments in
    calls.txt, and ``dpkg`` finds every system package once apt-get has
    run. Returns (folder, run)."""
    (tmp_path / "scripts").mkdir()
    shutil.copy(ROOT / "scripts" / "setup.sh", tmp_path / "scripts" / "setup.sh")
    shutil.copy(ROOT / "pyproject.toml", tmp_path / "pyproject.toml")
    shutil.copytree(ROOT / "requirements", tmp_path / "requirements")
    tools = tmp_path / "tools"
    tools.mkdir()
    # No system package is there until apt-get has run once.
    stand_in(tools / "dpkg", f'test -f "{tmp_path / "apt-done"}"')
    stand_in(tools / "id", "echo 0")
    stand_in(tools / "apt-get", f'echo "apt-get $*" >> "{tmp_path / "calls.txt"}"; '
                                f'touch "{tmp_path / "apt-done"}"')
    venv = tmp_path / ".venv" / "bin"
    venv.mkdir(parents=True)
    stand_in(venv / "python", f'echo "$*" >> "{tmp_path / "calls.txt"}"')
    stand_in(venv / "rasterlab", "exit 0")
    environment = os.environ | {"PATH": f"{tools}{os.pathsep}{os.environ['PATH']}"}

    def run(*args):
        return subprocess.run(["bash", "scripts/setup.sh", *args], cwd=tmp_path, env=environment,
                              capture_output=True, text=True, timeout=120)
    return tmp_path, run


def stand_in(path, body):
    path.write_text(f"#!/bin/sh\n{body}\n")
    path.chmod(0o755)


def calls(folder) -> list:
    path = folder / "calls.txt"
    return path.read_text().splitlines() if path.exists() else []


def installs(folder) -> list:
    return [call for call in calls(folder) if " install " in f" {call} "]


@needs_setup_tools
def test_setup_installs_the_program_from_the_lock_and_keeps_its_checksum(setup_copy):
    folder, run = setup_copy
    done = run()
    assert done.returncode == 0 and done.stderr == ""
    pip = [call for call in installs(folder) if call.startswith("-m pip")]
    assert "--require-hashes -r requirements/app.txt" in pip[0]
    assert pip[1].endswith("--no-deps -e .") and len(pip) == 2
    apt = " ".join(call for call in installs(folder) if call.startswith("apt-get"))
    assert "libegl1" in apt and "chromium" not in apt
    wanted = hashlib.sha256((folder / "requirements" / "app.txt").read_bytes()
                            + (folder / "pyproject.toml").read_bytes()).hexdigest()
    assert (folder / ".venv" / ".rasterlab-app").read_text().strip() == wanted


@needs_setup_tools
def test_setup_for_the_tests_installs_the_test_lock(setup_copy):
    folder, run = setup_copy
    assert run("--test").returncode == 0
    pip = [call for call in installs(folder) if call.startswith("-m pip")]
    assert "--require-hashes -r requirements/test.txt" in pip[0]
    assert (folder / ".venv" / ".rasterlab-test").is_file()


@needs_setup_tools
def test_setup_run_again_changes_nothing_and_says_one_line(setup_copy):
    folder, run = setup_copy
    run()
    before = installs(folder)
    done = run()
    assert done.returncode == 0 and done.stderr == ""
    assert done.stdout.count("\n") == 1 and "set up in .venv" in done.stdout
    assert installs(folder) == before, "set-up installed again with nothing changed"
    run("--test")
    after_test = installs(folder)
    assert "requirements/test.txt" in after_test[-2]
    run()  # the test install holds the program's
    assert installs(folder) == after_test


@needs_setup_tools
def test_setup_refuses_an_unknown_option_in_one_line(setup_copy):
    done = setup_copy[1]("--tests")
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "usage" in done.stderr
