"""The command-line contract of DESIGN.md: list, run --json/--ascii, bad input."""
import json
import subprocess
import sys

import pytest

from app.cli import main
from tests.support import ROOT


def test_list_names_every_line_algorithm(run_cli):
    status, out, err = run_cli("list")
    assert status == 0 and err == ""
    for name in ("line-bresenham", "line-dda"):
        assert name in out


def test_list_json_schema(run_cli):
    status, out, _ = run_cli("list", "--json")
    assert status == 0
    specs = json.loads(out)
    names = [spec["name"] for spec in specs]
    assert len(names) == len(set(names))
    for spec in specs:
        assert set(spec) >= {"name", "family", "inputs", "options"}
        for option in spec["options"]:
            assert set(option) >= {"name", "type", "default"}


def test_run_json_schema_and_pixels(run_cli):
    status, out, err = run_cli("run", "line-bresenham", "--points", "0,0", "6,3", "--json")
    assert status == 0 and err == ""
    result = json.loads(out)
    assert set(result) >= {"algorithm", "grid", "pixels", "steps", "final", "options"}
    assert result["algorithm"] == "line-bresenham"
    assert result["grid"] == [32, 24]
    # By hand: d = 0 (tie, E), 6 (NE), 0 (E), 6 (NE), 0 (E), 6 (NE).
    assert result["pixels"] == [[0, 0], [1, 0], [2, 1], [3, 1], [4, 2], [5, 2], [6, 3]]
    assert result["steps"] >= len(result["pixels"])
    assert result["options"] == {"symmetric": False, "colors": []}
    assert result["final"]["dx"] == 6 and result["final"]["dy"] == 3


def test_run_json_values_are_colours(run_cli):
    status, out, _ = run_cli("run", "line-dda", "--points", "0,0", "4,0",
                             "--set", "colors=#ff0000,#0000ff", "--json")
    assert status == 0
    result = json.loads(out)
    assert result["values"][0] == "#ff0000"
    assert result["values"][-1] == "#0000ff"
    assert len(result["values"]) == len(result["pixels"]) == 5


def test_run_ascii_draws_the_grid_top_row_first(run_cli):
    status, out, _ = run_cli("run", "line-bresenham", "--points", "0,0", "3,1",
                             "--grid", "4,2", "--ascii")
    assert status == 0
    assert out.splitlines() == ["..##", "##.."]


def test_run_options_are_applied(run_cli):
    _, out, _ = run_cli("run", "line-dda", "--points", "0,0", "5,2",
                        "--set", "dtype=float32", "--json")
    assert json.loads(out)["options"]["dtype"] == "float32"


def test_step_cap_stops_with_a_message(run_cli):
    status, out, err = run_cli("run", "line-bresenham", "--points", "0,0", "100,3",
                               "--step-cap", "10", "--json")
    result = json.loads(out)
    assert status == 0
    assert result["steps"] == 10 and result["truncated"] is True
    assert "step cap" in err


@pytest.mark.parametrize("argv, words", [
    (["run", "line-nope", "--points", "0,0", "1,1"], "unknown algorithm"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--set", "nope=1"], "no option"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--set", "dtype=float16"], "dtype"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--set", "dtype"], "KEY=VALUE"),
    (["run", "line-bresenham", "--points", "0,0", "1,1", "--set", "symmetric=maybe"], "true or false"),
    (["run", "line-dda", "--points", "0,0", "1,x"], "not a number"),
    (["run", "line-dda", "--points", "0,0", "1,nan"], "finite"),
    (["run", "line-dda", "--points", "0,0", "inf,1"], "finite"),
    (["run", "line-dda", "--points", "0,0", "1"], "X,Y"),
    (["run", "line-dda", "--points", "0,0", "1,2,3"], "X,Y"),
    (["run", "line-dda", "--points", "0,0"], "expected 2 points"),
    (["run", "line-dda", "--points", "0,0", "1,1", "2,2"], "expected 2 points"),
    (["run", "line-dda", "--points", "0.5,0", "1,1"], "whole"),
    (["run", "line-dda", "--points", "-1,0", "1,1"], "outside"),
    (["run", "line-dda", "--points", "0,0", "40,1", "--grid", "32,24"], "outside"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--grid", "4097,10"], "4096"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--grid", "0,10"], "outside"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--grid", "10"], "W,H"),
    (["run", "line-dda", "--points", "0,0", "5000,1"], "4096"),
    (["run", "line-dda", "--points", "0,0", "1e300,1"], "4096"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--step-cap", "0"], "step-cap"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--json", "--ascii"], "not allowed"),
    (["run", "line-dda"], "--points"),
    (["frobnicate"], "invalid choice"),
])
def test_bad_input_exits_2_with_one_line(run_cli, argv, words):
    status, out, err = run_cli(*argv)
    assert status == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("rasterlab: ")
    assert words in lines[0]
    assert "Traceback" not in err


def test_entry_point_in_a_subprocess():
    """`python -m rasterlab` really exits 2 with one line, and 0 with JSON."""
    bad = subprocess.run([sys.executable, "-m", "rasterlab", "run", "line-dda", "--points", "0,0"],
                         cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2
    assert len(bad.stderr.strip().splitlines()) == 1 and "Traceback" not in bad.stderr
    good = subprocess.run([sys.executable, "-m", "rasterlab", "run", "line-bresenham", "--points",
                           "2,3", "-0,0", "--json"], cwd=ROOT, capture_output=True, text=True,
                          timeout=60)
    assert good.returncode == 0, good.stderr
    assert json.loads(good.stdout)["pixels"][0] == [2, 3]


def test_ctrl_c_during_a_report_or_export_ends_with_130_and_one_line(capsys, monkeypatch, tmp_path):
    from app.render import export
    from app.analysis import report

    def interrupted(*_args, **_kwargs):
        raise KeyboardInterrupt
    monkeypatch.setattr(report, "write_report", interrupted)
    assert main(["report", "--quick", "--out", str(tmp_path / "out")]) == 130
    assert capsys.readouterr().err.strip() == "rasterlab: report interrupted"
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"version": 1, "grid": {"width": 8, "height": 8},
                                 "algorithm": "line-bresenham",
                                 "primitives": [{"points": [[0, 0], [5, 2]]}]}))
    monkeypatch.setattr(export, "export", interrupted)
    assert main(["export", str(scene), "--gif", str(tmp_path / "a.gif")]) == 130
    assert "export interrupted; nothing was written" in capsys.readouterr().err
    assert not (tmp_path / "a.gif").exists()
