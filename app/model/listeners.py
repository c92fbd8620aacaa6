"""Listeners of the Qt-free model: the plain-callback stand-in for signals."""


class Listeners:
    """Plain callbacks for one kind of news, called in the order connected."""

    def __init__(self):
        self._callbacks = []

    def connect(self, callback) -> None:
        self._callbacks.append(callback)

    def disconnect(self, callback) -> None:
        self._callbacks.remove(callback)

    def emit(self, *args) -> None:
        for callback in list(self._callbacks):
            callback(*args)
