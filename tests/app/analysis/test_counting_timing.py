"""median_seconds: how many calls a timing makes, and what it returns."""
from __future__ import annotations

import pytest

from app.analysis import counting


class FakeClock:
    """perf_counter that moves only when the timed call runs: each call takes ``step`` s."""

    def __init__(self, step):
        self.now, self.step, self.calls = 0.0, step, 0

    def __call__(self):
        return self.now

    def call(self):
        self.calls += 1
        self.now += self.step


@pytest.mark.parametrize("once", [None, 0.01])
def test_samples_and_warm_up(monkeypatch, once):
    clock = FakeClock(0.01)  # longer than ``least``: one call a sample
    monkeypatch.setattr(counting.time, "perf_counter", clock)
    seconds = counting.median_seconds(clock.call, repeats=5, least=0.002, once=once)
    assert seconds == pytest.approx(0.01)
    # A given ``once`` stands for the warm-up call, which is then not made.
    assert clock.calls == 5 + (1 if once is None else 0)


def test_short_calls_repeat_within_a_sample(monkeypatch):
    clock = FakeClock(0.0005)
    monkeypatch.setattr(counting.time, "perf_counter", clock)
    seconds = counting.median_seconds(clock.call, repeats=3, least=0.002, once=0.0005)
    assert seconds == pytest.approx(0.0005)
    assert clock.calls == 3 * 4  # 0.002 / 0.0005 calls in each of 3 samples


def test_timed_returns_the_result_and_its_time(monkeypatch):
    clock = FakeClock(0.25)
    monkeypatch.setattr(counting.time, "perf_counter", clock)
    result, seconds = counting.timed(lambda: clock.call() or "done")
    assert result == "done" and seconds == pytest.approx(0.25)
