"""The circle, curve and triangle variants on the command line: listed with
their options, run as JSON and ASCII, bad options refused with one line."""
import json

import pytest

from tests.support.curve_oracles import printed_c

NEW = {"circle-bresenham": ["--points", "10,10", "--set", "radius=6"],
       "circle-polar": ["--points", "10,10", "--set", "radius=6", "--set", "dt=0.4"],
       "circle-midpoint-printed": ["--points", "10,10", "--set", "radius=6"],
       "circle-distance": ["--points", "10.3,9.8", "--set", "radius=4.5", "--set",
                           "shape=outline"],
       "circle-wu": ["--points", "10,10", "--set", "radius=6"],
       "curve-bezier": ["--points", "1,1", "4,20", "25,20", "30,2", "--set", "segments=5"],
       "triangle-cramer": ["--points", "2.5,2", "30,6.25", "12,22"],
       "line-subpixels": ["--points", "1,1", "14,6", "--set", "n=4"],
       "triangle-columns": ["--points", "2.5,2", "30,6.25", "12,22"],
       "triangle-span-interpolate": ["--points", "2.5,2", "30,6.25", "12,22", "--set",
                                     "s=0,2,1"],
       "painter-split": ["--points", "2,3", "29,11", "3,21", "30,3", "29,21", "2,12", "--set",
                         "z=0.1,0.9,0.1,0.1,0.1,0.9"],
       "triangle-trilinear": ["--points", "2.5,2", "30,6.25", "12,22"],
       "triangle-wireframe": ["--points", "2.5,2", "30,6.25", "12,22"]}


def test_list_shows_each_with_its_options(run_cli):
    status, out, _ = run_cli("list", "--json")
    listed = {entry["name"]: entry for entry in json.loads(out)}
    assert status == 0 and set(NEW) <= set(listed)
    assert [o["name"] for o in listed["circle-polar"]["options"]] == ["radius", "dt"]
    assert listed["circle-distance"]["inputs"]["integer"] is False
    assert listed["curve-bezier"]["inputs"]["points"] == 4


@pytest.mark.parametrize("name", sorted(NEW))
def test_run_json_and_ascii(run_cli, name):
    status, out, err = run_cli("run", name, *NEW[name], "--json")
    assert status == 0, err
    result = json.loads(out)
    assert result["algorithm"] == name and result["pixels"] and result["steps"] > 0
    status, out, _ = run_cli("run", name, *NEW[name], "--ascii")
    assert status == 0 and "#" in out


def test_printed_circle_json_is_the_printed_code(run_cli):
    status, out, _ = run_cli("run", "circle-midpoint-printed", "--points", "0,0", "--set",
                             "radius=9", "--json")
    assert [tuple(p) for p in json.loads(out)["pixels"]] == printed_c(9)


@pytest.mark.parametrize("argv", [
    ["run", "circle-polar", "--points", "5,5", "--set", "dt=0"],
    ["run", "circle-polar", "--points", "5,5", "--set", "dt=fast"],
    ["run", "circle-distance", "--points", "5.5,5", "--set", "shape=square"],
    ["run", "circle-distance", "--points", "5.5,5", "--set", "radius=-1"],
    ["run", "curve-bezier", "--points", "1,1", "4,20", "25,20", "--set", "segments=4"],
    ["run", "curve-bezier", "--points", "1,1", "4,20", "25,20", "30,2", "--set", "segments=0"],
    ["run", "triangle-cramer", "--points", "1e300,0", "0,1", "1,0"],
    ["run", "circle-wu", "--points", "5.5,5"],
    ["run", "triangle-columns", "--points", "1,1", "5,1", "3,4", "--set", "swap=reversed"],
    ["run", "line-subpixels", "--points", "1,1", "5,5", "--set", "n=0"],
])
def test_bad_input_is_one_line_and_status_2(run_cli, argv):
    status, out, err = run_cli(*argv)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err


def test_export_refuses_an_unknown_overlay(run_cli, tmp_path):
    scene = tmp_path / "t.json"
    scene.write_text(json.dumps({"version": 1, "algorithm": "triangle-bbox",
                                 "grid": {"width": 32, "height": 24},
                                 "primitives": [{"points": [[2, 2], [30, 6], [12, 22]]}]}))
    status, _, err = run_cli("export", scene, "--frames-dir", tmp_path / "f", "--overlays",
                             "planes", "--to", "2")
    assert status == 2 and "unknown overlay" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "f").exists()
    status, _, err = run_cli("export", scene, "--frames-dir", tmp_path / "g", "--overlays",
                             "all", "--to", "2")
    assert status == 0, err
    assert len(list((tmp_path / "g").glob("*.png"))) == 3
