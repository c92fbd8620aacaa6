"""A one-line progress bar for the command line."""
from __future__ import annotations

import sys


class TerminalBar:
    """Draws on ``stream`` only when it is a terminal; nothing otherwise."""

    WIDTH = 30

    def __init__(self, stream=sys.stderr):
        self.stream = stream
        try:
            self.active = stream.isatty()
        except (AttributeError, ValueError):
            self.active = False
        self.shown = False

    def draw(self, what: str, done: int, total: int, tail: str = "") -> None:
        if not self.active:
            return
        filled = done * self.WIDTH // max(1, total)
        self.stream.write(f"\r{what} [{'#' * filled}{'.' * (self.WIDTH - filled)}] "
                          f"{done}/{total} {tail}")
        self.stream.flush()
        self.shown = True

    def clear(self) -> None:
        if self.shown:
            self.stream.write("\r\033[K")
            self.stream.flush()
            self.shown = False
