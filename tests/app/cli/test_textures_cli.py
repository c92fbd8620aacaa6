"""triangle-texture on the command line: fragments parallel to pixels, and bad input."""
from __future__ import annotations

import json

import pytest

POINTS = ["--points", "1,1", "14,2", "3,13", "--grid", "16,16"]


def test_fragments_are_parallel_to_pixels(run_cli):
    status, out, _ = run_cli("run", "triangle-texture", *POINTS, "--set", "w=1,4,2",
                             "--set", "filter=trilinear", "--json")
    assert status == 0
    result = json.loads(out)
    assert len(result["fragments"]) == len(result["pixels"]) > 20
    for fragment, colour in zip(result["fragments"], result["values"]):
        assert fragment["color"] == colour
        assert set(fragment) >= {"u", "v", "lod", "color"}
        assert fragment["fetches"] in (4, 8)


@pytest.mark.parametrize("setting, words", [
    ("uv=0,0,1", "option uv"),
    ("texture=/no/such/file.png", "cannot read"),
    ("texture=checker:3", "power of two"),
    ("texture=hello", "not checker:N"),
    ("w=1,0,2", "greater than 0"),
    ("filter=blurry", "option filter"),
])
def test_bad_input_is_one_line_and_status_2(run_cli, setting, words):
    status, out, err = run_cli("run", "triangle-texture", *POINTS, "--set", setting)
    assert status == 2 and out == ""
    assert words in err and err.count("\n") == 1 and "Traceback" not in err


def test_a_file_that_is_not_an_image(run_cli, tmp_path):
    path = tmp_path / "fake.png"
    path.write_text("not a picture")
    status, _, err = run_cli("run", "triangle-texture", *POINTS, "--set", f"texture={path}")
    assert status == 2 and "not an image" in err and err.count("\n") == 1


@pytest.mark.parametrize("setting, words", [("alpha=0.5,2,0.5", "between 0 and 1"),
                                            ("alpha=0.5,0.5", "option alpha"),
                                            ("order=sideways", "option order")])
def test_blend_bad_input(run_cli, setting, words):
    status, _, err = run_cli("run", "blend-over", *POINTS, "--set", setting)
    assert status == 2 and words in err and err.count("\n") == 1


def test_blend_fragments(run_cli):
    status, out, _ = run_cli("run", "blend-over", *POINTS, "--set", "z=0.5,0.5,0.5", "--json")
    result = json.loads(out)
    assert status == 0 and len(result["fragments"]) == len(result["pixels"])
    first = result["fragments"][0]
    assert first["alpha"] == 0.5 and first["before"] == "#ffffff"


@pytest.mark.parametrize("setting, words", [
    ("near=0", "near"), ("fov=180", "fov"), ("far=0.5", "far"), ("eye=1,2", "eye"),
    ("normals=1,0", "normals"), ("light=0,0,0", "length 0"), ("eye=16,12,0", "length 0"),
])
def test_pipeline_bad_camera(run_cli, setting, words):
    status, _, err = run_cli("run", "pipeline", *POINTS, "--set", setting)
    assert status == 2 and words in err and err.count("\n") == 1


def test_pipeline_behind_the_eye_needs_clipping(run_cli):
    args = ("run", "pipeline", *POINTS, "--set", "z=0,0,60")
    assert run_cli(*args)[0] == 0
    status, _, err = run_cli(*args, "--set", "clipping=none")
    assert status == 2 and "w <= 0" in err and err.count("\n") == 1


def test_pipeline_final_has_clip_and_window_coordinates(run_cli):
    status, out, _ = run_cli("run", "pipeline", *POINTS, "--json")
    result = json.loads(out)
    # The left plane cuts this triangle: its window polygon has a corner more.
    assert status == 0 and len(result["final"]["clip"]) == 3 and len(result["final"]["window"]) == 4
    assert len(result["fragments"]) == len(result["pixels"])


ROOT = __import__("pathlib").Path(__file__).resolve().parents[3]
RENDERING = sorted((ROOT / "resources" / "scenes" / "rendering").glob("*.json"))


@pytest.mark.parametrize("scene", RENDERING, ids=lambda p: p.stem)
def test_shipped_rendering_scenes_run(run_cli, scene):
    status, out, err = run_cli("run", "--scene", scene, "--json")
    result = json.loads(out)
    assert status == 0 and err == "" and len(result["fragments"]) == len(result["pixels"]) > 100


def test_the_near_crossing_scene_is_refused_without_clipping(tmp_path, run_cli):
    data = json.loads((ROOT / "resources/scenes/rendering/pipeline-near-crossing.json").read_text())
    data["options"]["clipping"] = "none"
    path = tmp_path / "unclipped.json"
    path.write_text(json.dumps(data))
    status, _, err = run_cli("run", "--scene", path)
    assert status == 2 and "w <= 0" in err
