"""What a newcomer meets first: the window without a display, `list`, the
report's promised time, set-up run a second time."""
import hashlib
import re
import subprocess

import pytest

from algorithms.core import registry
from tests.support import ROOT


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


def test_report_help_and_readme_promise_the_same_time(run_cli):
    status, out, _ = run_cli("report", "--help", child=True)
    readme = (ROOT / "README.md").read_text()
    assert status == 0
    help_text = " ".join(out.split())
    assert "about ten seconds" in help_text and "one to two minutes" in help_text
    assert re.search(r"`--quick` runs smaller sweeps in about ten seconds", readme)
    assert "one to two minutes" in " ".join(readme.split())


def test_setup_run_again_changes_nothing_and_says_one_line():
    stamp = ROOT / ".venv" / ".rasterlab-installed"
    wanted = hashlib.sha256((ROOT / "pyproject.toml").read_bytes()).hexdigest()
    assert stamp.read_text().strip() == wanted, "pyproject.toml changed: run scripts/setup.sh"
    done = subprocess.run(["bash", "scripts/setup.sh"], cwd=ROOT, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0 and done.stderr == ""
    assert done.stdout.count("\n") == 1 and "set up in .venv" in done.stdout
