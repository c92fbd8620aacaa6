"""`rasterlab run ... --save SCENE.json`: the scene written runs to the same
pixels as the command; an existing file is kept unless --force; a run that
fails, or a folder that is missing, leaves no file."""
import json

from tests.support.bresenham import bresenham_pixels

ARGS = ("run", "line-bresenham", "--points", "1,2", "20,9", "--grid", "24,12",
        "--set", "symmetric=true")


def test_a_saved_scene_runs_to_the_same_pixels(run_cli, tmp_path):
    scene = tmp_path / "line.json"
    status, out, err = run_cli(*ARGS, "--save", scene)
    assert (status, err) == (0, "")
    direct = json.loads(run_cli(*ARGS, "--json")[1])
    assert out == (f"{scene}: a scene of line-bresenham on a 24x12 grid "
                   f"({len(direct['pixels'])} pixels written in {direct['steps']} steps)\n")
    data = json.loads(scene.read_text())
    assert (data["algorithm"], data["grid"], data["options"], data["primitives"]) == \
        ("line-bresenham", {"width": 24, "height": 12}, {"symmetric": True},
         [{"points": [[1, 2], [20, 9]]}])
    status, out, _ = run_cli("run", "--scene", scene, "--json")
    assert status == 0 and json.loads(out) == direct


def test_an_output_asked_for_is_printed_as_without_save(run_cli, tmp_path):
    for output in ("--json", "--ascii", "--steps"):
        saved = run_cli(*ARGS, output, "--save", tmp_path / f"s{output}.json")
        assert saved == run_cli(*ARGS, output)


def test_a_shipped_scene_is_copied(run_cli, tmp_path):
    copy = tmp_path / "copy.json"
    status, out, _ = run_cli("run", "--scene", "demo-bresenham", "--save", copy)
    assert status == 0 and out.startswith(f"{copy}: a scene of line-bresenham on a 32x24 grid")
    data = json.loads(copy.read_text())
    assert data["title"] == "Bresenham's line"
    pixels = json.loads(run_cli("run", "--scene", copy, "--json")[1])["pixels"]
    assert [tuple(p) for p in pixels] == bresenham_pixels((3, 4), (27, 15))


def test_an_existing_file_is_kept_unless_force(run_cli, tmp_path):
    scene = tmp_path / "mine.json"
    scene.write_text("my notes")
    status, out, err = run_cli(*ARGS, "--save", scene)
    assert (status, out) == (2, "") and err == f"rasterlab: {scene}: the file exists; give " \
                                               "--force to replace it\n"
    assert scene.read_text() == "my notes"
    status, _, _ = run_cli(*ARGS, "--save", scene, "--force")
    assert status == 0 and json.loads(scene.read_text())["algorithm"] == "line-bresenham"


def test_a_failing_run_or_a_missing_folder_leaves_no_file(run_cli, tmp_path):
    status, _, err = run_cli("run", "line-bresenham", "--points", "1,2", "40,9", "--grid", "24,12",
                             "--save", tmp_path / "s.json")
    assert status == 2 and "outside the 24x12 grid" in err
    status, _, err = run_cli(*ARGS, "--save", tmp_path / "no" / "s.json")
    assert status == 2 and err.count("\n") == 1 and "does not exist" in err
    assert list(tmp_path.iterdir()) == []


def test_force_without_save_is_refused(run_cli):
    status, out, err = run_cli(*ARGS, "--force")
    assert (status, out) == (2, "") and "--force replaces the file of --save" in err
