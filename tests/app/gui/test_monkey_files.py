"""GUI monkey test of the File menu: open, cancel, fail, finish and save at
random, every open recording in the background. No file may ever be written
with a scene it did not hold: the only saves here are of scenes opened from
a file (no edits), so each save must write the file's own scene back.

Every recording is held until the monkey lets it finish, fail (a
MemoryError) or cancels it (Esc), so the order of events is the monkey's
and the run is the same every time.
"""
import json
import os
import random
import threading

import pytest
from PySide6.QtWidgets import QMessageBox

from app.gui.recovery import content
from app.model import scene as scenes
from app.model.scene import Scene

SEEDS = tuple(int(s) for s in os.environ.get("RASTERLAB_MONKEY_SEEDS", "1,2").split(","))
EVENTS = int(os.environ.get("RASTERLAB_MONKEY_FILE_EVENTS", "100"))  # per seed

SCENES = {
    "line.json": Scene(algorithm="line-bresenham", points=[[1, 2], [20, 9]], width=24,
                       height=16, title="line"),
    "circle.json": Scene(algorithm="circle-midpoint", points=[[12, 10]], options={"radius": 6},
                         width=26, height=22, origin="top-left", title="circle",
                         view={"compare": True, "speed": 7}),
    "fill.json": Scene(algorithm="flood-fill", points=[[[0, 0], [9, 0], [9, 9], [0, 9]]],
                       width=14, height=12, title="fill", bookmarks=[{"step": 2, "name": "b"}]),
}


class Held:
    """Holds each background recording until released: ``finish`` runs it,
    ``fail`` makes it raise MemoryError."""

    def __init__(self, session):
        self.record = session.outcome
        self.waiting: list = []

    def outcome(self, *args, **kwargs):
        gate = {"event": threading.Event(), "fail": False}
        self.waiting.append(gate)
        gate["event"].wait(30)
        if gate["fail"]:
            raise MemoryError()
        return self.record(*args, **kwargs)

    def release(self, fail: bool) -> None:
        for gate in self.waiting:
            gate["fail"] = fail
            gate["event"].set()
        self.waiting = []


class FileMonkey:
    def __init__(self, window, qtbot, folder, rng, held: Held, known: dict, said: list):
        self.window, self.qtbot, self.rng, self.held_session = window, qtbot, rng, held
        self.files = window.file_actions
        self.paths = {name: folder / name for name in SCENES}
        # What each file (of every seed: another seed's may be on show)
        # holds, its work without the view: what it may be written with.
        self.held, self.said = known, said
        self.counts: dict = {}

    def act(self) -> None:
        action = self.rng.choice(["open", "open", "cancel", "finish", "fail", "save", "save"])
        self.counts[action] = self.counts.get(action, 0) + 1
        getattr(self, action)()

    def open(self) -> None:
        self.files.open_path(self.paths[self.rng.choice(sorted(self.paths))])

    def cancel(self) -> None:
        self.window.recording_status.shortcut.activated.emit()  # Esc
        self.held_session.release(fail=False)  # the worker ends (cancelled)

    def finish(self, fail: bool = False) -> None:
        player = self.window.player
        if not player.recording:
            return
        with self.qtbot.waitSignal(player.recordingFinished, timeout=30_000):
            self.held_session.release(fail)

    def fail(self) -> None:
        self.finish(fail=True)

    def save(self) -> None:
        path = self.files.path
        if path is None or self.window.player.trace is None:
            return
        shown = content(self.files.current_scene())
        if self.files.opening:
            # The name is still the previous file's: the save is refused.
            assert not self.files.save() and self.said.pop() == "information"
            return
        assert self.files.save()
        assert content(scenes.load(path)) == shown
        # The scene on show was never edited: it is the one some file held.
        assert shown == self.held[path], (path.name, shown, self.held[path])

    def check_files(self) -> None:
        for path, held in self.held.items():
            assert content(scenes.load(path)) == held, path.name


def write_scenes(window, folder):
    """The scenes as the window saves them (with its option defaults), so a
    save of one opened unchanged writes the same work back."""
    folder.mkdir()
    for name, scene in SCENES.items():
        scenes.save(scene, folder / name)
        assert window.file_actions.open_path(folder / name)
        assert window.file_actions.save()


@pytest.mark.window(shown=False, recovery=True)
def test_monkey_opens_cancels_and_saves(window, qtbot, tmp_path, monkeypatch, capsys):
    shown = []
    for name in ("warning", "information", "critical", "question"):
        monkeypatch.setattr(QMessageBox, name,
                            lambda *a, _n=name, **k: shown.append(_n) or
                            QMessageBox.StandardButton.Discard)
    for seed in SEEDS:
        write_scenes(window, tmp_path / f"seed-{seed}")
    held = Held(window.player.session)
    monkeypatch.setattr(window.player.session, "outcome", held.outcome)
    window.player.sync_wait = 0.0
    total, counts = 0, {}
    known = {path: content(scenes.load(path)) for path in tmp_path.glob("seed-*/*.json")}
    try:
        for seed in SEEDS:
            monkey = FileMonkey(window, qtbot, tmp_path / f"seed-{seed}", random.Random(seed),
                                held, known, shown)
            for _ in range(EVENTS):
                monkey.act()
                monkey.check_files()
                if not window.player.recording:
                    window.recovery.check()
                    # Only opened scenes, never edited: nothing is unsaved.
                    assert not window.recovery.dirty, monkey.counts
            monkey.finish()
            total += EVENTS
            for key, value in monkey.counts.items():
                counts[key] = counts.get(key, 0) + value
    finally:
        held.release(fail=False)
        window.player.stop_recording()
    assert shown == []
    with capsys.disabled():
        print(f"\nfile monkey: {total} events, seeds {SEEDS}: {json.dumps(counts)}")
    assert counts.get("save", 0) > 0 and counts.get("cancel", 0) > 0
