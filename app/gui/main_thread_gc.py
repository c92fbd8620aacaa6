"""Python's cycle collector runs in the main thread only.

Automatic collection starts in whichever thread happens to allocate. When
that is a background recording and the garbage holds a Qt object, the
worker destroys the object: Qt takes its object lock and then waits for
Python's lock, while the main thread holds Python's lock and waits for
Qt's. Both wait for ever and the window freezes. So automatic collection
is off and a main-thread timer collects instead, as pyqtgraph's collector
does, with one change: the oldest generation, a walk over the whole heap
that can take a large fraction of a second, waits until no recording runs,
so that it never stalls the window while one is shown in progress.
"""
from __future__ import annotations

import gc
import weakref

from pyqtgraph.util.garbage_collector import GarbageCollector

INTERVAL_S = 0.1

_collector = None
_players: "weakref.WeakSet" = weakref.WeakSet()


class _Collector(GarbageCollector):
    def check(self) -> None:
        young, middle, old = gc.get_count()
        if young <= self.threshold[0]:
            return
        gc.collect(0)
        if middle <= self.threshold[1]:
            return
        gc.collect(1)
        if old > self.threshold[2] and not any(player.recording for player in _players):
            gc.collect(2)


def collect_in_main_thread(player) -> None:
    """Turn automatic collection over to a main-thread timer (once per
    process; call it from the main thread); ``player``'s recordings hold
    back collections of the oldest generation while they run."""
    global _collector
    _players.add(player)
    if _collector is None:
        _collector = _Collector(interval=INTERVAL_S)


def collect_now() -> None:
    """What the timer does, at once."""
    if _collector is not None:
        _collector.check()
