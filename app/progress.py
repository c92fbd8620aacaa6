"""One-line progress bars for the command line."""
from __future__ import annotations

import sys
import time
from contextlib import contextmanager

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


class DelayedBar(TerminalBar):
    """A bar drawn only once its work has taken ``AFTER`` seconds, so that
    quick work prints nothing; ``show`` draws ``done`` of ``total`` with the
    time left at the rate so far."""

    AFTER = 2.0

    def __init__(self, stream=sys.stderr, clock=time.monotonic):
        super().__init__(stream)
        self.clock = clock
        self.started = clock()

    def due(self) -> bool:
        return self.clock() - self.started >= self.AFTER

    def show(self, what: str, done: int, total: int, label: str) -> None:
        left = (self.clock() - self.started) * (total - done) / max(1, done)
        self.draw(what, done, total, f"{label} {left:.0f} s left ")


class CountBar(DelayedBar):
    """Things done so far, ``(done, total)``: "WHAT [###...] LABEL n s left"."""

    def __init__(self, what: str, label: str, stream=sys.stderr, clock=time.monotonic):
        super().__init__(stream, clock)
        self.what, self.label = what, label

    def __call__(self, done: int, total: int) -> None:
        if self.due():
            self.show(self.what, done, total, self.label)


class CasesBar(CountBar):
    """The cases of a check done so far."""

    def __init__(self, stream=sys.stderr, clock=time.monotonic):
        super().__init__("checking", "cases, about", stream, clock)


class GradingBar(DelayedBar):
    """A class's grading: the cases done of every submission's, with the
    submissions finished, and the time left at the rate so far."""

    def __init__(self, submissions: int, cases: int, stream=sys.stderr, clock=time.monotonic):
        super().__init__(stream, clock)
        self.submissions, self.cases = submissions, cases
        self.finished = self.done = 0

    def case_done(self) -> None:
        self.done += 1
        self._draw()

    def submission_done(self) -> None:
        self.finished += 1
        self._draw()

    def _draw(self) -> None:
        if self.due():
            self.show("grading", self.done, self.submissions * self.cases,
                      f"cases, {self.finished} of {self.submissions} submissions, about")


class RecordingBar(DelayedBar):
    """A recording's progress, as ``RecordMonitor`` reports it (the steps so
    far), against ``bound()``, the most steps the budget expects, so the
    time left is an upper estimate. The bound is asked for at the first
    drawing, when the run's inputs have been checked."""

    def __init__(self, bound, stream=sys.stderr, clock=time.monotonic):
        super().__init__(stream, clock)
        self.bound = bound

    def __call__(self, steps: int) -> None:
        if not self.due():
            return
        if callable(self.bound):
            self.bound = max(1, int(self.bound()))
        self.show("recording", min(int(steps), self.bound), self.bound, "steps, at most")


def recording_bar(spec, points, options, grid, step_cap: int = DEFAULT_STEP_CAP) -> RecordingBar:
    """A terminal bar for a recording that takes more than two seconds (nothing otherwise)."""
    return RecordingBar(lambda: budget.step_bound(spec, points, options, grid, step_cap),
                        sys.stderr)


@contextmanager
def drawn(bar: TerminalBar):
    """``bar`` as the work's progress callback while the block runs (None
    when stderr is not a terminal, so the work skips the calls), wiped from
    the terminal at the end however the block ends."""
    try:
        yield bar if bar.active else None
    finally:
        bar.clear()
