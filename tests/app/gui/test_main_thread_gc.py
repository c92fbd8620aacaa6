"""Cyclic garbage is collected in the main thread, never in a recording's
thread, where destroying a Qt object deadlocks against the main thread."""
import gc
import threading

from app.gui.player import Player
from tests.support.gui import WAIT_MS

SMALL = [(0, 0), (6, 0), (6, 6), (0, 6)]
SQUARE = [(0, 0), (300, 0), (300, 300), (0, 300)]


class Probe:
    """Part of a reference cycle; notes the thread that collects it."""

    def __init__(self, seen: list):
        self.seen = seen
        self.itself = self

    def __del__(self):
        self.seen.append(threading.current_thread())


def test_cycles_are_collected_in_the_main_thread_while_a_recording_runs(qtbot):
    player = Player()
    player.set_scene("flood-fill", [SMALL], {"order": "queue"}, (310, 310))
    player.sync_wait = 0.0  # edits return at once; their recording goes on in its thread
    assert not gc.isenabled()
    seen: list = []
    gc.collect()
    with qtbot.waitSignal(player.recordingFinished, timeout=60_000):
        player.set_points(SQUARE)
        for _ in range(2000):  # garbage made while the worker allocates
            Probe(seen)
    qtbot.waitUntil(lambda: len(seen) == 2000, timeout=WAIT_MS)
    assert set(seen) == {threading.main_thread()}
    player.stop_recording()


class FakePlayer:
    recording = True


def test_the_whole_heap_waits_until_no_recording_runs(monkeypatch, qtbot):
    from app.gui import main_thread_gc

    Player()  # the collector exists
    collected = []
    monkeypatch.setattr(gc, "collect", collected.append)
    monkeypatch.setattr(gc, "get_count", lambda: (701, 11, 11))
    busy = FakePlayer()
    main_thread_gc._players.add(busy)
    main_thread_gc.collect_now()
    assert collected == [0, 1]
    busy.recording = False
    main_thread_gc.collect_now()
    assert collected == [0, 1, 0, 1, 2]
    monkeypatch.setattr(gc, "get_count", lambda: (700, 11, 11))  # gen 0 under its threshold
    main_thread_gc.collect_now()
    assert collected == [0, 1, 0, 1, 2]
