"""Python's cycle collector runs in the main thread only.

Automatic collection starts in whichever thread happens to allocate. When
that is a background recording and the garbage holds a Qt object, the
worker destroys the object: Qt takes its object lock and then waits for
Python's lock, while the main thread holds Python's lock and waits for
Qt's. Both wait for ever and the window freezes. pyqtgraph's collector
turns automatic collection off and collects from a main-thread timer.
"""
from __future__ import annotations

_collector = None


def collect_in_main_thread():
    """Turn automatic collection off and collect on a timer of the main
    thread, once per process (call it from the main thread)."""
    global _collector
    if _collector is None:
        from pyqtgraph.util.garbage_collector import GarbageCollector

        _collector = GarbageCollector(interval=0.25)
    return _collector


def collect_now() -> None:
    """What the timer does, at once: collect the generations over their thresholds."""
    if _collector is not None:
        _collector.check()
