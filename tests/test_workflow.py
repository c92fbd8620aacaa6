"""The CI workflow, which cannot run here: valid against GitHub's workflow
schema, and running what this repository proves locally (the set-up from the
lock, the smoke test of the installed wheel, the suite) on every system and
supported Python. What the schema cannot see (an action's inputs, a runner's
tools) is only proved by a run on GitHub."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from ruamel.yaml import YAML

ROOT = Path(__file__).resolve().parents[1]
WORKFLOWS = sorted((ROOT / ".github" / "workflows").glob("*.yml"))
CI = YAML(typ="safe").load((ROOT / ".github" / "workflows" / "ci.yml").read_text(encoding="utf-8"))


def commands(job: str) -> str:
    return "\n".join(step.get("run", "") for step in CI["jobs"][job]["steps"])


def test_every_workflow_is_valid_against_githubs_schema():
    assert WORKFLOWS
    done = subprocess.run([sys.executable, "-m", "check_jsonschema", "--builtin-schema",
                           "vendor.github-workflows", *map(str, WORKFLOWS)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_suite_runs_on_three_systems_and_every_supported_python():
    matrix = CI["jobs"]["test"]["strategy"]["matrix"]
    assert set(matrix["os"]) == {"ubuntu-latest", "windows-latest", "macos-latest"}
    assert matrix["python"] == ["3.10", "3.11", "3.12", "3.13"]
    assert CI["env"]["QT_QPA_PLATFORM"] == "offscreen"


def test_ci_and_ci_run_take_the_same_steps():
    """Set-up from the lock, the suite, then the smoke test of the wheel:
    in the workflow's job and in .ci/run, which proves the Linux job here."""
    local = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    steps = ("scripts/setup.sh --test", "-m pytest -q", "scripts/smoke.py")
    for text in (commands("test"), local):
        places = [text.find(step) for step in steps]
        assert -1 not in places and places == sorted(places), text


def test_newest_releases_are_tried_on_a_schedule_without_the_lock():
    triggers = CI["on"]
    assert "schedule" in triggers and "workflow_dispatch" in triggers
    newest = CI["jobs"]["newest"]
    assert "schedule" in newest["if"]
    assert "--upgrade-strategy eager -e" in commands("newest")
