"""Fixtures shared by the tests of the algorithms."""
import pytest

from algorithms.core import trace as trace_module


@pytest.fixture
def small_keyframes(monkeypatch):
    """``small_keyframes(gap, budget=KEYFRAME_BUDGET)``: keyframes every
    ``gap`` steps, so that random access really starts from them."""
    def use(gap, budget=trace_module.KEYFRAME_BUDGET):
        monkeypatch.setattr(trace_module, "MIN_KEYFRAME_GAP", gap)
        monkeypatch.setattr(trace_module, "KEYFRAME_BUDGET", budget)
        # Short traces would otherwise get no keyframes at all.
        monkeypatch.setattr(trace_module, "KEYFRAME_BYTES_PER_STEP", 2 ** 40)
    return use
