"""Scene files are read only from regular files and saved without changing
the file's permissions or links."""
import json
import os
import stat
import threading

import pytest

from app.model import scene as scenes
from app.model.scene import Scene, SceneError

SCENE = Scene(algorithm="line-dda", points=[[1, 2], [20, 9]], width=40, height=30)


def _load_within(path, seconds=10.0):
    """load(path) in a thread, so that a load that blocks fails the test
    instead of hanging it: the outcome, or "still waiting"."""
    outcome = ["still waiting"]

    def load():
        try:
            outcome[0] = scenes.load(path)
        except SceneError as error:
            outcome[0] = error
    worker = threading.Thread(target=load, daemon=True)
    worker.start()
    worker.join(seconds)
    return outcome[0]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_fifo_is_refused_at_once(tmp_path):
    fifo = tmp_path / "f.json"
    os.mkfifo(fifo)
    outcome = _load_within(fifo)
    if outcome == "still waiting":
        with open(fifo, "wb"):  # let the blocked reader go
            pass
    assert isinstance(outcome, SceneError), outcome
    assert str(outcome) == "f.json: not a regular file, not a scene file"


@pytest.mark.parametrize("path", ["/dev/zero", "/dev/null"])
def test_a_device_is_refused(path):
    if not os.path.exists(path):
        pytest.skip(f"no {path}")
    outcome = _load_within(path)
    assert isinstance(outcome, SceneError) and "not a regular file" in str(outcome), outcome


def test_a_folder_is_refused(tmp_path):
    with pytest.raises(SceneError, match="a folder, not a scene file"):
        scenes.load(tmp_path)


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="no /proc")
def test_a_proc_file_is_refused():
    # stat() gives /proc files no size; their text is no scene anyway.
    with pytest.raises(SceneError, match="not a regular file"):
        scenes.load("/proc/self/status")


def test_run_of_a_fifo_scene_is_one_line(run_cli, tmp_path):
    fifo = tmp_path / "f.json"
    os.mkfifo(fifo)
    # Should the read block, a writer comes after 10 s, so the test fails instead of hanging.
    release = threading.Timer(10.0, lambda: open(fifo, "wb").close())
    release.daemon = True
    release.start()
    status, out, err = run_cli("run", "--scene", fifo)
    release.cancel()
    assert (status, out) == (2, "")
    assert err == "rasterlab: f.json: not a regular file, not a scene file\n"


def test_a_scene_with_a_utf8_bom_is_read(tmp_path):
    path = tmp_path / "bom.json"
    path.write_bytes(b"\xef\xbb\xbf" + json.dumps(SCENE.to_json()).encode("utf-8"))
    assert scenes.load(path) == SCENE


# ------------------------------------------------------------------ saving
@pytest.mark.parametrize("mode", [0o644, 0o640, 0o600])
def test_a_save_keeps_the_files_permissions(tmp_path, mode):
    path = tmp_path / "a.json"
    path.write_text("{}")
    path.chmod(mode)
    scenes.save(SCENE, path)
    assert stat.S_IMODE(path.stat().st_mode) == mode
    assert scenes.load(path) == SCENE


def test_a_new_file_gets_the_umasks_permissions(tmp_path):
    old = os.umask(0o022)
    try:
        scenes.save(SCENE, tmp_path / "new.json")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "new.json").stat().st_mode) == 0o644


def test_a_save_through_a_link_writes_its_target(tmp_path):
    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "a.json"
    target.write_text("{}")
    target.chmod(0o644)
    link = tmp_path / "link.json"
    link.symlink_to(os.path.join("real", "a.json"))  # relative, as links often are
    scenes.save(SCENE, link)
    assert link.is_symlink() and os.readlink(link) == os.path.join("real", "a.json")
    assert scenes.load(target) == SCENE
    assert stat.S_IMODE(target.stat().st_mode) == 0o644
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["a.json", "link.json", "real"]


def test_a_save_through_a_loop_of_links_is_refused(tmp_path):
    (tmp_path / "a.json").symlink_to("b.json")
    (tmp_path / "b.json").symlink_to("a.json")
    with pytest.raises(SceneError, match="a loop of symbolic links"):
        scenes.save(SCENE, tmp_path / "a.json")
    assert (tmp_path / "a.json").is_symlink() and (tmp_path / "b.json").is_symlink()
