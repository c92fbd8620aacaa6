"""One-line progress bars for the command line."""
from __future__ import annotations

import sys
import time

from algorithms.core.trace import DEFAULT_STEP_CAP
from app.model import budget


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
        # \033[K clears what a longer line drawn before left at the end.
        self.stream.write(f"\r{what} [{'#' * filled}{'.' * (self.WIDTH - filled)}] "
                          f"{done}/{total} {tail}\033[K")
        self.stream.flush()
        self.shown = True

    def clear(self) -> None:
        if self.shown:
            self.stream.write("\r\033[K")
            self.stream.flush()
            self.shown = False


class CasesBar(TerminalBar):
    """The cases of a check done so far, ``(done, total)``: drawn only once
    the check has taken ``AFTER`` seconds, so a quick check prints nothing."""

    AFTER = 2.0

    def __init__(self, stream=sys.stderr, clock=time.monotonic):
        super().__init__(stream)
        self.clock = clock
        self.started = clock()

    def __call__(self, done: int, total: int) -> None:
        elapsed = self.clock() - self.started
        if elapsed >= self.AFTER:
            left = elapsed * (total - done) / max(1, done)
            self.draw("checking", done, total, f"cases, about {left:.0f} s left ")


class RecordingBar(TerminalBar):
    """A recording's progress, as ``RecordMonitor`` reports it (the steps so
    far): drawn only once the run has taken ``AFTER`` seconds, so a quick
    run prints nothing, against ``bound()``, the most steps the budget
    expects, with the time left at the rate so far (an upper estimate, as the
    bound is). The bound is asked for at the first drawing, when the run's
    inputs have been checked."""

    AFTER = 2.0

    def __init__(self, bound, stream=sys.stderr, clock=time.monotonic):
        super().__init__(stream)
        self.bound = bound
        self.clock = clock
        self.started = clock()

    def __call__(self, steps: int) -> None:
        elapsed = self.clock() - self.started
        if elapsed < self.AFTER:
            return
        if callable(self.bound):
            self.bound = max(1, int(self.bound()))
        done = min(int(steps), self.bound)
        left = elapsed * (self.bound - done) / max(1, done)
        self.draw("recording", done, self.bound, f"steps, at most {left:.0f} s left ")


def recording_bar(spec, points, options, grid, step_cap: int = DEFAULT_STEP_CAP) -> RecordingBar:
    """A terminal bar for a recording that takes more than two seconds (nothing otherwise)."""
    return RecordingBar(lambda: budget.step_bound(spec, points, options, grid, step_cap),
                        sys.stderr)
