"""The triangle family through the command line contract of DESIGN.md."""
import json

import pytest

from algorithms.exact import triangles as exact_triangles

POINTS = ["1.5,2", "20,3.25", "8,17"]


def test_run_triangle_bbox_inclusive_json(run_cli):
    status, out, err = run_cli("run", "triangle-bbox", "--points", *POINTS,
                               "--set", "fill_rule=inclusive", "--json")
    assert status == 0 and err == ""
    result = json.loads(out)
    assert result["algorithm"] == "triangle-bbox"
    assert result["grid"] == [32, 24]
    assert result["options"]["fill_rule"] == "inclusive"
    points = [(1.5, 2), (20, 3.25), (8, 17)]
    want = exact_triangles.coverage(points, 8, "inclusive", (0, 0, 32, 24))
    assert sorted(map(tuple, result["pixels"])) == sorted(want)
    # emission order: rows bottom to top, left to right
    assert result["pixels"] == sorted(result["pixels"], key=lambda p: (p[1], p[0]))
    final = result["final"]
    assert final["filled"] == len(want) and final["overlaps"] == 0 and final["cracks"] == 0
    assert final["tested"] > final["filled"]


@pytest.mark.parametrize("name", ["triangle-scan", "triangle-incremental", "triangle-backtrack",
                                  "triangle-pineda", "triangle-linewise", "triangle-halfplane",
                                  "triangle-barycentric", "triangle-plane",
                                  "triangle-perspective"])
def test_every_traversal_runs_from_the_command_line(run_cli, name):
    status, out, err = run_cli("run", name, "--points", *POINTS, "--json")
    assert status == 0, err
    want = exact_triangles.coverage([(1.5, 2), (20, 3.25), (8, 17)], 8, "top-left", (0, 0, 32, 24))
    assert sorted(map(tuple, json.loads(out)["pixels"])) == sorted(want)


def test_colours_per_vertex_give_pixel_values(run_cli):
    status, out, _ = run_cli("run", "triangle-barycentric", "--points", "0.5,0.5",
                             "8.5,0.5", "0.5,8.5", "--set", "colors=#ff0000,#00ff00,#0000ff",
                             "--set", "fill_rule=inclusive", "--json")
    assert status == 0
    result = json.loads(out)
    assert len(result["values"]) == len(result["pixels"])
    by_pixel = dict(zip(map(tuple, result["pixels"]), result["values"]))
    assert by_pixel[(0, 0)] == "#ff0000" and by_pixel[(8, 0)] == "#00ff00"


def test_two_triangles_and_numbers_options(run_cli):
    status, out, err = run_cli("run", "triangle-bbox", "--points", "1,1", "9,1", "9,9",
                               "1,1", "9,9", "1,9", "--set", "z=0,1,2", "--set", "w=1,2,4",
                               "--set", "s=0,10,20", "--set", "perspective=true", "--json")
    assert status == 0, err
    result = json.loads(out)
    assert result["options"]["z"] == [0.0, 1.0, 2.0]
    assert result["final"]["drawn"] == 2 and result["final"]["overlaps"] == 0
    assert len(result["pixels"]) == 64


def test_list_shows_the_family(run_cli):
    status, out, _ = run_cli("list", "--json")
    specs = {s["name"]: s for s in json.loads(out)}
    bbox = specs["triangle-bbox"]
    assert bbox["family"] == "triangles" and bbox["inputs"]["multiple"]
    types = {o["name"]: o["type"] for o in bbox["options"]}
    assert types["z"] == "numbers" and types["colors"] == "colors"
    assert types["fill_rule"] == "choice" and types["precision"] == "choice"


@pytest.mark.parametrize("argv, words", [
    (["run", "triangle-bbox", "--points", "1,1", "5,1", "1,5", "2,2"], "multiple of 3"),
    (["run", "triangle-bbox", "--points", *POINTS, "--set", "fill_rule=sideways"], "fill_rule"),
    (["run", "triangle-bbox", "--points", *POINTS, "--set", "precision=float16"], "precision"),
    (["run", "triangle-bbox", "--points", *POINTS, "--set", "w=0,1,1"], "w"),
    (["run", "triangle-bbox", "--points", *POINTS, "--set", "z=1,2"], "z"),
    (["run", "triangle-bbox", "--points", *POINTS, "--set", "z=1,nan,2"], "z"),
    (["run", "triangle-bbox", "--points", *POINTS, "--set", "perspective=true"], "w"),
    (["run", "triangle-perspective", "--points", *POINTS, "--set", "w=1e-320,1,1"], "too close to 0"),
    (["run", "triangle-bbox", "--points", *POINTS, "--set", "subpixel_bits=12"], "subpixel_bits"),
    (["run", "triangle-bbox", "--points", "1,1", "50,1", "1,5", "--grid", "32,24"], "outside"),
])
def test_bad_input_exits_2_with_one_line(run_cli, argv, words):
    status, out, err = run_cli(*argv)
    assert status == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("rasterlab: ") and words in lines[0], err
