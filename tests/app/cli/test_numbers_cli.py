"""--numbers exact|decimal on run --steps, export and worksheet."""
import csv
import json

import pytest


def test_run_steps_shows_1_over_m_as_fractions(run_cli):
    status, decimal, _ = run_cli("run", "--scene", "polygon-xlow-half-pixel", "--steps")
    assert status == 0 and "1/m=6.25" in decimal and "1/m=25/4" not in decimal
    status, exact, _ = run_cli("run", "--scene", "polygon-xlow-half-pixel", "--steps",
                               "--numbers", "exact")
    # P1P2 of (3, 2) -> (28, 6): 25/4; P2P3: -14/15; P3P1: 11/19.
    assert status == 0
    assert all(f"1/m={m}" in exact for m in ("25/4", "-14/15", "11/19"))
    assert "6.25" not in exact


def test_run_steps_json_adds_exact_fields(run_cli):
    args = ("run", "triangle-cramer", "--points", "0,0", "4,0", "0,4", "--steps", "--json")
    _, plain, _ = run_cli(*args)
    status, more, _ = run_cli(*args, "--numbers", "exact")
    plain, more = json.loads(plain), json.loads(more)
    assert status == 0
    assert more["columns"][:len(plain["columns"])] == plain["columns"]
    keys = [c["key"] for c in more["columns"]]
    rows = [dict(zip(keys, row)) for row in more["rows"]]
    # Pixel (1, 0), centre (3/2, 1/2), in the triangle of 2A = 16: alpha 1/2, beta 3/8, gamma 1/8.
    row = [r for r in rows if r["pixel"] == [1, 0] and r["alpha_exact"]][-1]
    assert (row["alpha_exact"], row["beta_exact"], row["gamma_exact"]) == ("1/2", "3/8", "1/8")
    assert row["beta"] == 0.375


def test_worksheet_follows_the_setting(run_cli, tmp_path):
    for numbers in ("decimal", "exact"):
        status, _, err = run_cli("worksheet", "demo-bresenham", "--out", tmp_path / numbers,
                                 "--format", "md", "--numbers", numbers)
        assert status == 0, err
    decimal = (tmp_path / "decimal" / "answers.md").read_text(encoding="utf-8")
    exact = (tmp_path / "exact" / "answers.md").read_text(encoding="utf-8")
    # demo-bresenham runs over dx = 24, dy = 11: m = 11/24.
    assert "11/24" in exact and "11/24" not in decimal


def test_worksheet_weights_as_fractions(run_cli, tmp_path):
    from app.model import scene as scenes
    scene = tmp_path / "tri.json"
    status, _, err = run_cli("run", "triangle-cramer", "--points", "0,0", "4,0", "0,4",
                             "--grid", "6,6", "--save", scene)
    assert status == 0, err
    assert scenes.load(scene).algorithm == "triangle-cramer"
    status, _, err = run_cli("worksheet", scene, "--out", tmp_path / "sheet", "--format", "csv",
                             "--blank", "pixel", "--numbers", "exact")
    assert status == 0, err
    with open(tmp_path / "sheet" / "answers.csv", encoding="utf-8", newline="") as stream:
        rows = list(csv.DictReader(stream))
    assert {"1/2", "3/8", "1/8"} <= {row[name] for row in rows for name in ("alpha", "beta",
                                                                             "gamma")}


@pytest.mark.parametrize("args", [
    ("run", "--scene", "demo-bresenham", "--steps", "--numbers", "fractions"),
    ("worksheet", "demo-bresenham", "--out", "x", "--numbers", "Exact"),
    ("export", "demo-bresenham", "--gif", "x.gif", "--numbers", ""),
    ("run", "--scene", "demo-bresenham", "--numbers", "exact"),
])
def test_bad_values_get_exit_2_and_one_line(run_cli, args, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, out, err = run_cli(*args)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "--numbers" in err
    assert not (tmp_path / "x").exists() and not (tmp_path / "x.gif").exists()
