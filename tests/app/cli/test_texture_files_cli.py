"""Texture files a scene names: a regular file only, its size checked from the
header before decoding, found beside the scene (or among the shipped
textures) and nowhere else; every refusal one line and exit status 2."""
from __future__ import annotations

import json
import os

import pytest
from PIL import Image

from app.model import scene as scenes
from tests.support import ROOT
from tests.support.textures import huge_png

FLOOR = ROOT / "resources" / "scenes" / "rendering" / "textured-floor.json"


def textured_scene(folder, texture, name="scene.json"):
    """The shipped textured floor, with ``texture`` as its texture."""
    data = json.loads(FLOOR.read_text(encoding="utf-8"))
    data["options"]["texture"] = texture
    path = folder / name
    path.write_text(json.dumps(data), encoding="utf-8")
    return path


def refused(status, out, err, *words):
    assert status == 2 and "Traceback" not in err, err
    assert err.count("\n") == 1 and all(word in err for word in words), err


@pytest.fixture(scope="module")
def huge_scene(tmp_path_factory):
    folder = tmp_path_factory.mktemp("huge")
    huge_png(folder / "huge.png")
    return textured_scene(folder, "huge.png")


@pytest.mark.parametrize("command", [["run", "--scene"], ["export", "--html", "a.html"],
                                     ["export", "--pdf", "a.pdf"]], ids=lambda c: c[-1])
def test_a_50000_square_png_is_refused_before_decoding(huge_scene, command, run_cli, tmp_path):
    if command[0] == "export":
        command = ["export", huge_scene, command[1], tmp_path / command[2]]
    else:
        command = [*command, huge_scene]
    refused(*run_cli(*command), "huge.png", "larger than 1024 x 1024")
    assert list(tmp_path.iterdir()) == []


def test_a_texture_over_the_bound_is_refused_from_its_header(tmp_path, run_cli):
    # 2048 x 2048: under Pillow's own limit, over ours.
    huge_png(tmp_path / "big.png", 2048)
    refused(*run_cli("run", "--scene", textured_scene(tmp_path, "big.png")),
            "2048 x 2048", "up to 1024")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")
def test_a_fifo_as_texture_is_refused_at_once(tmp_path, run_cli):
    os.mkfifo(tmp_path / "pipe.png")  # no writer: reading it would wait for ever
    scene = textured_scene(tmp_path, "pipe.png")
    # A child process, so that the fixture's timeout guards against a hang.
    refused(*run_cli("run", "--scene", scene, child=True), "not a regular file")
    refused(*run_cli("export", scene, "--gif", tmp_path / "a.gif", child=True),
            "not a regular file")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")
def test_a_fifo_named_on_the_command_line_is_refused(tmp_path, run_cli):
    os.mkfifo(tmp_path / "pipe.png")
    refused(*run_cli("run", "triangle-texture", "--points", "1,1", "14,2", "3,13",
                     "--set", f"texture={tmp_path / 'pipe.png'}", child=True),
            "not a regular file")


def test_a_folder_as_texture_is_refused(tmp_path, run_cli):
    (tmp_path / "dir.png").mkdir()
    refused(*run_cli("run", "--scene", textured_scene(tmp_path, "dir.png")), "a folder")


def test_a_jpeg_named_png_is_refused(tmp_path, run_cli):
    Image.new("RGB", (8, 8), (0, 0, 255)).save(tmp_path / "photo.png", format="JPEG")
    refused(*run_cli("run", "--scene", textured_scene(tmp_path, "photo.png")), "PNG")


@pytest.fixture
def outside(tmp_path):
    """A picture beside the folder of the scene, and that folder."""
    Image.new("RGB", (8, 8), (255, 0, 0)).save(tmp_path / "outside.png")
    folder = tmp_path / "scenes"
    folder.mkdir()
    return tmp_path / "outside.png", folder


def test_a_path_out_of_the_scenes_folder_is_refused(outside, run_cli):
    picture, folder = outside
    refused(*run_cli("run", "--scene", textured_scene(folder, "../outside.png")),
            "outside the scene's folder")
    refused(*run_cli("run", "--scene", textured_scene(folder, str(picture))),
            "absolute path")


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="needs symbolic links")
def test_a_link_out_of_the_scenes_folder_is_refused(outside, run_cli):
    picture, folder = outside
    (folder / "link.png").symlink_to(picture)
    refused(*run_cli("run", "--scene", textured_scene(folder, "link.png")),
            "outside the scene's folder")


def test_a_texture_beside_the_scene_is_found_from_another_folder(tmp_path, run_cli,
                                                                 monkeypatch):
    folder = tmp_path / "scenes"
    folder.mkdir()
    Image.new("RGB", (4, 4), (255, 0, 0)).save(folder / "red.png")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    Image.new("RGB", (4, 4), (0, 255, 0)).save(elsewhere / "red.png")  # the wrong one
    monkeypatch.chdir(elsewhere)
    status, out, err = run_cli("run", "--scene", textured_scene(folder, "red.png"), "--json")
    assert status == 0, err
    assert set(json.loads(out)["values"]) == {"#ff0000"}


def test_a_shipped_texture_is_found_by_its_name(tmp_path, run_cli):
    status, out, err = run_cli("run", "--scene", textured_scene(tmp_path, "bricks.png"),
                               "--json")
    assert status == 0, err
    assert json.loads(out)["final"]["texture"] == "bricks.png"


def test_saving_writes_the_texture_as_found_again(tmp_path):
    Image.new("RGB", (4, 4), (255, 0, 0)).save(tmp_path / "red.png")
    scene = scenes.load(textured_scene(tmp_path, "red.png"))
    assert os.path.isabs(scene.options["texture"])
    copy = tmp_path / "copy.json"
    scenes.save(scene, copy)
    assert json.loads(copy.read_text())["options"]["texture"] == "red.png"
    assert scenes.load(copy) == scene
    scenes.save(scenes.load(textured_scene(tmp_path, "bricks.png")), copy)
    assert json.loads(copy.read_text())["options"]["texture"] == "bricks.png"


def test_a_recovery_copy_keeps_a_texture_chosen_anywhere(outside, tmp_path):
    picture, folder = outside
    scene = scenes.load(textured_scene(tmp_path, "outside.png"))
    copy = folder / "recovery.json"
    scenes.save(scene, copy)
    with pytest.raises(scenes.SceneError, match="absolute path"):
        scenes.load(copy)
    assert scenes.load(copy, confine=False).options["texture"] == str(picture.resolve())
