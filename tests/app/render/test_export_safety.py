"""Exports never delete a file they did not write, leave nothing behind when
refused, and what a killed export leaves is cleaned up by the next one.

The kill tests run the real command in a child process whose writer is
slowed down by a hook (the child's own patch, below), kill it with SIGKILL
or SIGTERM mid-export, and look at the folder.
"""
import json
import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest
from PIL import Image

from app.model.scene import Scene, save
from app.model.staging import StagedFolder
from app.render import export as ex
from tests.support import ROOT

GRID = (14, 8)


def line_scene(last=(12, 6)):
    return Scene(algorithm="line-bresenham", points=[[1, 1], list(last)], width=GRID[0],
                 height=GRID[1])


def frames_in(folder):
    return sorted(p.name for p in folder.glob("frame_*.png"))


def old_export(folder, count):
    """A folder as an earlier export left it: ``count`` frames in it."""
    ex.export(line_scene(), ex.ExportSettings(scale=2, first=0, last=count - 1),
              frames_dir=folder)


# -------------------------------------------------------- the user's files
def test_frames_the_program_did_not_write_are_kept(tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    theirs = {f"frame_{k:04d}.png": b"user %d" % k for k in range(20, 40)}
    theirs["frame_12345.png"] = b"user"
    theirs["notes.txt"] = b"notes"
    for name, data in theirs.items():
        (folder / name).write_bytes(data)
    ex.export(line_scene(), ex.ExportSettings(scale=2, first=0, last=8), frames_dir=folder)
    for name, data in theirs.items():
        assert (folder / name).read_bytes() == data, name
    assert len(frames_in(folder)) == 9 + 21


def test_only_the_frames_of_the_last_export_are_replaced(tmp_path):
    folder = tmp_path / "frames"
    old_export(folder, 12)
    (folder / "frame_0040.png").write_bytes(b"user")
    ex.export(line_scene(), ex.ExportSettings(scale=2, first=0, last=4), frames_dir=folder)
    assert frames_in(folder) == [f"frame_{k:04d}.png" for k in range(5)] + ["frame_0040.png"]
    manifest = json.loads((folder / ex.MANIFEST).read_text())
    assert manifest["frames"] == [f"frame_{k:04d}.png" for k in range(5)]


def test_a_manifest_cannot_make_an_export_delete_other_files(tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    (folder / "notes.txt").write_text("keep")
    (folder / ex.MANIFEST).write_text(json.dumps({"frames": ["notes.txt", "../x.png"]}))
    ex.export(line_scene(), ex.ExportSettings(scale=2, first=0, last=1), frames_dir=folder)
    assert (folder / "notes.txt").read_text() == "keep"


# -------------------------------------------------------------- size limit
def test_an_oversized_frames_export_is_refused_and_leaves_nothing(tmp_path):
    folder = tmp_path / "frames"
    with pytest.raises(ex.ExportError) as caught:
        ex.export(line_scene(), ex.ExportSettings(scale=2), frames_dir=folder,
                  gif=tmp_path / "a.gif", frames_limit=10 * 4096)
    message = str(caught.value)
    assert "MiB" in message and "limit" in message and "\n" not in message
    assert list(tmp_path.iterdir()) == []


def test_the_default_limit_refuses_millions_of_frames():
    class Steps(list):
        def __len__(self):
            return 2_100_000
    renderer = ex.FrameRenderer(line_scene(), ex.ExportSettings(scale=2))
    with pytest.raises(ex.ExportError, match="2,100,000 PNG frames"):
        ex.check_frames_size(renderer, Steps([0, 1]), ex.MAX_FRAMES_BYTES)


def test_a_frames_export_under_the_limit_is_made(tmp_path):
    result = ex.export(line_scene(), ex.ExportSettings(scale=2), frames_dir=tmp_path / "f",
                       frames_limit=200 * 4096)
    assert len(frames_in(tmp_path / "f")) == result.frames


def test_a_failed_frames_write_names_the_frames_folder(tmp_path, monkeypatch):
    save_image = Image.Image.save

    def full(self, target, *args, **kwargs):
        if isinstance(target, os.PathLike):  # a frame file; the estimate's buffer is not
            raise OSError(28, "No space left on device")
        return save_image(self, target, *args, **kwargs)
    monkeypatch.setattr(Image.Image, "save", full)
    folder = tmp_path / "frames"
    with pytest.raises(ex.ExportError) as caught:
        ex.export(line_scene(), ex.ExportSettings(scale=2), gif=tmp_path / "a.gif",
                  frames_dir=folder, frames_limit=2 ** 40)
    assert str(folder) in str(caught.value) and "No space left" in str(caught.value)
    assert list(tmp_path.iterdir()) == []


# ------------------------------------------------------------------- kills
CHILD = textwrap.dedent("""
    import pathlib, sys, time
    from app import cli
    from app.model import staging
    from app.render import writers
    marker = pathlib.Path(sys.argv[1])
    where = sys.argv[2]
    grab = writers.PngFolderWriter.grab_frame
    def slow_grab(self, image):
        grab(self, image)
        if where == "frames" and len(self.names) == 3:
            marker.touch()
            time.sleep(60)
    move = staging.StagedFolder._move
    def slow_move(self, stage, names, remove):
        if where != "commit":
            return move(self, stage, names, remove)
        move(self, stage, names[:2], [])
        marker.touch()
        time.sleep(60)
    writers.PngFolderWriter.grab_frame = slow_grab
    staging.StagedFolder._move = slow_move
    sys.exit(cli.main(sys.argv[3:]))
""")


def killed_export(tmp_path, where, how, scene_path, folder, gif):
    """Start an export in a child process and kill it with ``how`` once the
    hook at ``where`` is reached."""
    marker = tmp_path / "reached"
    child = subprocess.Popen(
        [sys.executable, "-c", CHILD, str(marker), where, "export", str(scene_path),
         "--scale", "2", "--gif", str(gif), "--frames-dir", str(folder)],
        cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        deadline = time.monotonic() + 120  # a child starting on a busy machine
        while not marker.exists():
            assert child.poll() is None, child.stderr.read()
            assert time.monotonic() < deadline, "the child never reached the hook"
            time.sleep(0.02)
        child.send_signal(how)
        child.wait(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
        child.stderr.close()
    return child.returncode


@pytest.fixture
def old_folder(tmp_path):
    """A frames folder with an earlier 5-frame export, a user's file and a
    GIF; the new scene's export has more frames."""
    folder = tmp_path / "frames"
    old_export(folder, 5)
    (folder / "notes.txt").write_text("keep")
    gif = tmp_path / "out.gif"
    gif.write_bytes(b"GIF89a old")  # a GIF an earlier export wrote
    scene_path = tmp_path / "scene.json"
    save(line_scene(), scene_path)
    before = {name: (folder / name).read_bytes() for name in frames_in(folder)}
    return folder, gif, scene_path, before


@pytest.mark.parametrize("how", [signal.SIGKILL, signal.SIGTERM])
def test_a_kill_while_drawing_keeps_the_old_export_and_the_next_run_cleans_up(
        tmp_path, old_folder, how):
    folder, gif, scene_path, before = old_folder
    assert killed_export(tmp_path, "frames", how, scene_path, folder, gif) == -how
    # The old frames are untouched; the debris is there until the next run.
    assert {name: (folder / name).read_bytes() for name in frames_in(folder)} == before
    assert gif.read_bytes() == b"GIF89a old"
    assert list(folder.glob(".rasterlab-frames-*"))
    assert list(tmp_path.glob(".out.gif.*.tmp"))
    result = ex.export(line_scene(), ex.ExportSettings(scale=2), gif=gif, frames_dir=folder)
    assert not list(folder.glob(".rasterlab-frames-*"))
    assert not list(tmp_path.glob(".out.gif.*.tmp"))
    assert frames_in(folder) == [f"frame_{k:04d}.png" for k in range(result.frames)]
    assert (folder / "notes.txt").read_text() == "keep"


@pytest.mark.parametrize("how", [signal.SIGKILL, signal.SIGTERM])
def test_a_kill_while_committing_is_finished_by_the_next_run(tmp_path, old_folder, how):
    folder, gif, scene_path, before = old_folder
    assert killed_export(tmp_path, "commit", how, scene_path, folder, gif) == -how
    count = len(ex.record(line_scene()))
    # Cleaning up finishes the committed export: all its frames, no mix.
    assert StagedFolder(folder, "frames").recover()
    assert frames_in(folder) == [f"frame_{k:04d}.png" for k in range(count)]
    assert json.loads((folder / ex.MANIFEST).read_text())["frames"] == frames_in(folder)
    assert not list(folder.glob(".rasterlab-frames-*"))
    assert (folder / "notes.txt").read_text() == "keep"


def test_a_live_exports_staging_folder_is_not_taken_for_debris(tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    live = folder / f".rasterlab-frames-{os.getppid()}-abc"
    live.mkdir()
    ex.export(line_scene(), ex.ExportSettings(scale=2, first=0, last=1), frames_dir=folder)
    assert live.is_dir()


def test_cleaning_up_follows_no_link_and_a_folder_in_the_way_stops_before_moving(tmp_path):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "precious.txt").write_text("keep")
    (elsewhere / ".commit.json").write_text('{"names": ["precious.txt"], "remove": []}')
    folder = tmp_path / "frames"
    folder.mkdir()
    (folder / ".rasterlab-frames-999999999-x").symlink_to(elsewhere)
    (folder / "frame_0001.png").mkdir()
    with pytest.raises(ex.ExportError, match="frame_0001.png: is a link or not a regular file"):
        ex.export(line_scene(), ex.ExportSettings(scale=2, first=0, last=2), frames_dir=folder)
    assert (elsewhere / "precious.txt").read_text() == "keep"
    assert not (folder / "precious.txt").exists()
    assert sorted(p.name for p in folder.iterdir()) == [".rasterlab-frames-999999999-x",
                                                        "frame_0001.png"]


def test_the_estimate_is_not_below_what_the_frames_take(tmp_path):
    # A fill's frames grow and shrink as it goes: the first and the last
    # frame alone are smaller than frames in the middle.
    scene = Scene(algorithm="flood-fill-circle", points=[[10, 10]], options={"radius": 8},
                  width=21, height=21)
    settings = ex.ExportSettings(scale=8, fps=50, hold=0)
    result = ex.export(scene, settings, frames_dir=tmp_path / "f", frames_limit=2 ** 40)
    on_disk = sum(-(-p.stat().st_size // ex.BLOCK) * ex.BLOCK
                  for p in (tmp_path / "f").glob("frame_*.png"))
    renderer = ex.FrameRenderer(scene, settings)
    steps = ex.frame_steps(scene, renderer.trace, renderer.settings)
    assert len(steps) == result.frames > 100
    with pytest.raises(ex.ExportError, match="more than the limit"):
        ex.check_frames_size(renderer, steps, on_disk - 1)
