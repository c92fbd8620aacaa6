"""`rasterlab check` on the fill, visibility and antialias samples: exit
status 0 for the correct ones, 1 for the wrong ones, 2 for bad input."""
from __future__ import annotations

import json

import pytest

from app.model import scene as scenes
from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
TEMPLATES = ROOT / "resources" / "templates"
PAINTER_SCENE = ROOT / "resources" / "scenes" / "painter-intersecting.json"


@pytest.mark.parametrize("sample, against, status", [
    ("fill_correct.py", "flood-fill", 0), ("fill_truncates.py", "flood-fill", 1),
    ("zbuffer_correct.py", "zbuffer", 0), ("zbuffer_no_test.py", "zbuffer", 1),
    ("wu_correct.py", "line-wu", 0), ("wu_swapped.py", "line-wu", 1),
])
def test_samples_exit_with_their_verdict(run_cli, sample, against, status):
    code, out, err = run_cli("check", SAMPLES / sample, "--against", against,
                             "--cases", "hard", "random", "2", "--json")
    result = json.loads(out)
    assert code == status, err
    assert result["failed"] == sum(not case["passed"] for case in result["cases"])
    assert (result["failed"] == 0) == (status == 0)
    assert all(case["exact_oracle"] for case in result["cases"])


def test_a_scene_of_two_piercing_triangles_passes_the_z_buffer_not_the_painter(run_cli):
    verdicts = [run_cli("check", SAMPLES / "zbuffer_correct.py", "--against", against,
                        "--cases", PAINTER_SCENE)[0] for against in ("zbuffer", "painter")]
    assert verdicts == [0, 1]


@pytest.mark.parametrize("template, against", [
    ("fill.py", "flood-fill"), ("zbuffer.py", "zbuffer"), ("antialiased_line.py", "line-wu")])
def test_each_template_runs_and_fails_until_written(run_cli, template, against):
    code, out, err = run_cli("check", TEMPLATES / template, "--against", against)
    assert code == 1 and "Traceback" not in out + err
    assert "FAIL" in out


def test_a_scene_without_a_seed_is_refused_and_one_with_a_seed_passes(run_cli, tmp_path):
    statuses = []
    for seed in ("auto", (5, 3)):
        path = tmp_path / "fill.json"
        scenes.save(scenes.Scene("flood-fill", (((1, 1), (9, 1), (5, 8)),), {"seed": seed},
                                 16, 16), path)
        code, out, err = run_cli("check", SAMPLES / "fill_correct.py", "--against",
                                 "flood-fill", "--cases", path)
        statuses.append(code)
    assert statuses == [2, 0]
