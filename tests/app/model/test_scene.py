"""Scene files: round trips, every malformed case named, atomic saves."""
import json
import os

import pytest

from app.model import scene as scenes
from app.cli import main
from app.model.scene import Scene, SceneError


def good() -> dict:
    return Scene(algorithm="line-dda", points=[[1, 2], [20, 9]], options={"dtype": "float32"},
                 width=40, height=30, origin="top-left", title="t", description="d",
                 view={"step": 3, "speed": 12.5, "show_grid": True},
                 bookmarks=[{"name": "start", "step": 0}]).to_json()


def test_round_trip(tmp_path):
    path = tmp_path / "a.json"
    scenes.save(scenes.from_json(good()), path)
    loaded = scenes.load(path)
    assert loaded.to_json() == good()
    assert loaded.points == ((1, 2), (20, 9)) and loaded.options == {"dtype": "float32"}


def test_every_shipped_scene_round_trips(tmp_path):
    shipped = sorted((scenes.RESOURCES / "scenes").glob("*.json"))
    for path in shipped:
        scene = scenes.load(path)
        copy = tmp_path / path.name
        scenes.save(scene, copy)
        assert scenes.load(copy).to_json() == scene.to_json()


def broken(change):
    data = good()
    change(data)
    return json.dumps(data)


@pytest.mark.parametrize("text, field", [
    (broken(lambda d: d.pop("version")), "version: missing"),
    (broken(lambda d: d.update(version=2)), "version"),
    (broken(lambda d: d.update(version="1")), "version"),
    (broken(lambda d: d.pop("grid")), "grid: missing"),
    (broken(lambda d: d["grid"].update(width=5000)), "grid.width"),
    (broken(lambda d: d["grid"].update(height=-3)), "grid.height"),
    (broken(lambda d: d["grid"].update(width=1e300)), "grid.width"),
    (broken(lambda d: d["grid"].update(width=True)), "grid.width"),
    (broken(lambda d: d.update(origin="middle")), "origin"),
    (broken(lambda d: d.update(algorithm="line-nope")), "algorithm"),
    (broken(lambda d: d.update(algorithm=3)), "algorithm"),
    (broken(lambda d: d.update(options={"dtype": "float16"})), "options.dtype"),
    (broken(lambda d: d.update(options={"nope": 1})), "options.nope"),
    (broken(lambda d: d.update(options=[])), "options"),
    (broken(lambda d: d.update(primitives=[{"points": [[1, 2]]}])), "primitives"),
    (broken(lambda d: d.update(primitives=[{"points": [[1, 2], [99, 2]]}])), "outside"),
    (broken(lambda d: d.update(primitives=[{"points": [[1, 2], [3.5, 2]]}])), "primitives"),
    (broken(lambda d: d.update(primitives=[{"points": [[1, 2], ["a", 2]]}])), "primitives"),
    (broken(lambda d: d.update(primitives=[{"points": [[1, 2], [3]]}])), "primitives"),
    (broken(lambda d: d.update(primitives=[7])), "primitives[0]"),
    (broken(lambda d: d.update(primitives={})), "primitives"),
    (broken(lambda d: d.update(view={"step": "x"})), "view.step"),
    (broken(lambda d: d.update(view={"speed": -1})), "view.speed"),
    (broken(lambda d: d.update(bookmarks=[{"name": "a"}])), "bookmarks[0]"),
    (broken(lambda d: d.update(title=5)), "title"),
    ('{"version": 1, "grid": {"width": NaN, "height": 3}}', "NaN"),
    ('{"version": 1, "grid": {"width": Infinity, "height": 3}}', "Infinity"),
    (json.dumps(good())[:57], "not valid JSON"),
    ("[1, 2, 3]", "JSON object"),
    ("", "not valid JSON"),
])
def test_malformed_scene_is_rejected_naming_the_field(tmp_path, text, field):
    path = tmp_path / "bad.json"
    path.write_text(text)
    with pytest.raises(SceneError) as error:
        scenes.load(path)
    assert field in str(error.value)
    assert str(error.value).startswith("bad.json: ")


def test_binary_and_missing_files(tmp_path):
    binary = tmp_path / "b.json"
    binary.write_bytes(b"\x89PNG\r\n\x1a\n\xff\xfe\x00")
    with pytest.raises(SceneError, match="not a text file"):
        scenes.load(binary)
    with pytest.raises(SceneError, match="cannot read"):
        scenes.load(tmp_path / "missing.json")


def test_failed_save_leaves_the_old_file(tmp_path, monkeypatch):
    path = tmp_path / "keep.json"
    scenes.save(scenes.from_json(good()), path)
    before = path.read_bytes()

    def explode(*args):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(os, "replace", explode)
    changed = scenes.from_json(good()).replace(title="changed")
    with pytest.raises(SceneError, match="No space left"):
        scenes.save(changed, path)
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["keep.json"]


def test_save_into_a_missing_folder_is_refused(tmp_path):
    with pytest.raises(SceneError, match="does not exist"):
        scenes.save(scenes.from_json(good()), tmp_path / "nope" / "a.json")


def test_cli_runs_a_scene(tmp_path, capsys):
    path = tmp_path / "s.json"
    scenes.save(scenes.from_json(good()), path)
    assert main(["run", "--scene", str(path), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["algorithm"] == "line-dda" and result["grid"] == [40, 30]
    assert result["pixels"][0] == [1, 2] and result["pixels"][-1] == [20, 9]
    path.write_text("{")
    assert main(["run", "--scene", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "not valid JSON" in err[0]


def test_a_scene_is_frozen_and_replace_checks_again():
    scene = scenes.from_json(good())
    with pytest.raises(AttributeError):
        scene.title = "changed"
    with pytest.raises(TypeError):
        scene.options["dtype"] = "float64"
    with pytest.raises(TypeError):
        scene.bookmarks[0]["step"] = 9
    moved = scene.replace(points=[[2, 3], [21, 9]])
    assert moved.points == ((2, 3), (21, 9)) and scene.points == ((1, 2), (20, 9))
    assert moved == scene.replace(points=((2, 3), (21, 9)))
    with pytest.raises(SceneError, match="grid.width"):
        scene.replace(width=0)
    with pytest.raises(SceneError, match="origin"):
        scene.replace(origin="middle")
    with pytest.raises(SceneError, match="options.dtype"):
        scene.replace(options={"dtype": "int3"})
    with pytest.raises(SceneError, match="primitives"):
        scene.replace(points=[[1, float("nan")], [2, 2]])
    with pytest.raises(SceneError, match="algorithm"):
        scene.replace(algorithm="no-such-thing")


def test_flat_points_and_breaks_round_trip_for_contours():
    scene = Scene.of_flat("polygon-scanline", [(1, 1), (9, 1), (5, 8), (3, 3), (4, 3)], (3,))
    assert scene.points == (((1, 1), (9, 1), (5, 8)), ((3, 3), (4, 3)))
    assert scene.flat == ((1, 1), (9, 1), (5, 8), (3, 3), (4, 3)) and scene.breaks == (3,)
    assert scene.complete and scene.runnable() == [[(1, 1), (9, 1), (5, 8)]]
    assert not Scene.of_flat("line-dda", [(1, 1)]).complete
    assert Scene.of_flat("polygon-scanline", []).points == ()
