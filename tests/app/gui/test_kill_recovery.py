"""Kill test: a program is killed (SIGKILL) right after an edit; the next
start offers the edit back."""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings

from app.gui import recovery as recovery_module
from app.model import scene as scenes
from app.gui.recovery import content, pending_recoveries
from app.gui.window import MainWindow
from tests.support import ROOT

CHILD = ROOT / "tests" / "support" / "recovery_child.py"
START_TIMEOUT = 60  # seconds; the child imports Qt and numpy on a busy machine

pytestmark = pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="needs SIGKILL")


def start_child(scene_path, points, env):
    return subprocess.Popen(
        [sys.executable, str(CHILD), str(scene_path), *(f"{x},{y}" for x, y in points)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)


def wait_ready(child) -> Path:
    """The recovery file the child reports once its edit is written."""
    deadline = time.monotonic() + START_TIMEOUT
    while time.monotonic() < deadline:
        line = child.stdout.readline()
        if line.startswith("READY "):
            return Path(line.split(" ", 1)[1].strip())
        if not line and child.poll() is not None:
            break
    child.kill()
    raise AssertionError(f"the child never got ready: {child.stderr.read()[-2000:]}")


def test_an_edit_survives_sigkill(qtbot, tmp_path, monkeypatch):
    data = tmp_path / "data"
    env = dict(os.environ, RASTERLAB_DATA_DIR=str(data), QT_QPA_PLATFORM="offscreen")
    monkeypatch.setenv("RASTERLAB_DATA_DIR", str(data))
    opened = tmp_path / "work.json"
    original = scenes.Scene(algorithm="line-dda", points=[[1, 1], [30, 7]], width=40,
                            height=30, title="Homework", options={})
    scenes.save(original, opened)
    edit = [(3, 25), (36, 2)]

    child = start_child(opened, edit, env)
    try:
        written = wait_ready(child)
        child.send_signal(signal.SIGKILL)
        child.wait(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
        child.stdout.close()
        child.stderr.close()
    assert child.returncode == -signal.SIGKILL
    assert written.parent == data / "recovery" and written.exists()

    # What the next start must offer: the file opened, with the edit.
    # (The window writes every option out, defaults included; the file
    # opened named none, so options are compared apart.)
    expected = original.to_json()
    expected["primitives"] = [{"points": [list(p) for p in edit]}]
    del expected["view"], expected["options"]

    def work(scene):
        fields = content(scene)
        fields.pop("options")
        return fields

    pending = pending_recoveries(data / "recovery")
    assert [p.path for p in pending] == [written]
    recovered = scenes.load(written)
    assert work(recovered) == expected
    assert not recovered.options["colors"]  # line-dda's default: no colours
    for item in pending:
        item.release()

    # The next start, with its question answered "Restore".
    asked = []

    def answer(parent, when):
        asked.append(when)
        return recovery_module.RESTORE
    monkeypatch.setattr(recovery_module, "ask_restore", answer)
    window = MainWindow()
    qtbot.addWidget(window)
    window.add_file_actions(QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    recovery = window.add_recovery()
    try:
        assert recovery.offer()
        assert len(asked) == 1 and asked[0].count(":") == 2  # the time of the copy
        assert work(window.file_actions.current_scene()) == expected
        assert recovery.dirty and not written.exists()
    finally:
        window.removeEventFilter(recovery)
        recovery.shutdown()
