"""Declared events of the Qt-free model, the plain-callback stand-in for Qt's signals.

A class declares each thing that can change about it once, in its body::

    class Session:
        step_changed = Event(int)   # the step on show (its index)

and each of its objects then has its own callbacks for it:
``session.step_changed.connect(f)``, ``.disconnect(f)`` and ``.emit(i)``, as
with a Qt signal. Callbacks are held strongly and called in the thread that
emits, in the order they were connected.
"""
from __future__ import annotations


class Event:
    """One event of a class; ``types`` document what ``emit`` passes."""

    def __init__(self, *types: type):
        self.types = types
        self.name = ""

    def __set_name__(self, owner, name: str) -> None:
        self.name = name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        # The object's own callbacks, stored under the event's name: Python
        # finds them there before this descriptor from now on.
        callbacks = obj.__dict__[self.name] = Callbacks()
        return callbacks


class Callbacks:
    """The callbacks one object's event calls, in the order connected."""

    def __init__(self):
        self._callbacks = []

    def connect(self, callback) -> None:
        self._callbacks.append(callback)

    def disconnect(self, callback) -> None:
        self._callbacks.remove(callback)

    def emit(self, *args) -> None:
        for callback in list(self._callbacks):
            callback(*args)
