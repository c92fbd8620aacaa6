"""Random access: compact keyframes and the variables restore what a slow replay gives."""
import random

import numpy as np
import pytest

from algorithms.core import keyframes as keyframes_module
from algorithms.core import trace as trace_module
from algorithms.core.registry import get
from tests.support.trace_oracle import slow_replay


def same_values(raster, oracle):
    assert np.array_equal(raster.counts.astype(np.int64), oracle.counts.astype(np.int64))
    for name in ("colors", "depth"):
        a, b = getattr(raster, name), getattr(oracle, name)
        assert (a is None) == (b is None)
        if a is not None:
            assert np.array_equal(a, b, equal_nan=True)


@pytest.fixture
def tiny_keyframes(small_keyframes, monkeypatch):
    """Keyframes every 37 steps, a dense copy after every few hundred changed pixels."""
    small_keyframes(37)
    monkeypatch.setattr(keyframes_module, "CHAIN_PIXELS", 300)


@pytest.mark.parametrize("name, points, options, grid", [
    ("line-parametric", ((0, 0), (300, 200)), {"dt": 2e-4, "colors": ["#000000", "#ffffff"]},
     (320, 240)),
    ("flood-fill", [[(3, 2), (37, 3), (30, 21), (38, 30), (12, 25), (4, 31)]], {"order": "span"},
     (40, 34)),
    ("zbuffer", [(2, 2), (28, 6), (10, 20), (4, 18), (26, 20), (18, 3)], {}, (32, 24)),
])
def test_restored_rasters_equal_a_slow_replay(tiny_keyframes, name, points, options, grid):
    trace = get(name).record(points, options, grid)
    n = len(trace)
    trace.raster_at(n - 1)
    slots = trace._keyframes.slots
    kinds = {type(slot).__name__ for slot in slots[1:]}
    assert len(slots) > 3 and ("Dense" in kinds or n < 2000) and "Delta" in kinds
    rng = random.Random(5)
    for i in sorted({0, 36, 37, 38, n - 1} | {rng.randrange(n) for _ in range(12)}):
        oracle = slow_replay(trace, i)
        plain = trace.raster_at(i)
        assert plain.counts.dtype == np.int32
        same_values(plain, oracle)
        compact = trace.raster_at(i, compact=True)
        same_values(compact, oracle)
        assert trace.state_at(i, compact=True).raster.counts.dtype == compact.counts.dtype


def test_compact_rasters_take_the_smallest_dtypes():
    trace = get("line-parametric").record(((0, 0), (60, 40)), {"dt": 1e-3,
                                          "colors": ["#000000", "#ffffff"]}, grid=(64, 48))
    final = slow_replay(trace, len(trace) - 1)
    most = int(final.counts.max())
    assert 1 < most < 256  # repeats, but fewer than 256 to a pixel
    compact = trace.raster_at(len(trace) - 1, compact=True)
    assert compact.counts.dtype == np.uint8 and compact.colors.dtype == np.int32
    same_values(compact, final)


def test_dense_copies_stay_inside_the_budget(monkeypatch):
    monkeypatch.setattr(trace_module, "MIN_KEYFRAME_GAP", 50)
    monkeypatch.setattr(trace_module, "KEYFRAME_BYTES_PER_STEP", 0)
    monkeypatch.setattr(keyframes_module, "CHAIN_PIXELS", 10)
    probe = get("line-bresenham").record(((0, 0), (999, 700)), grid=(1000, 800))
    one = probe.raster_at(0).counts.size  # a dense uint8 copy: one byte a pixel
    monkeypatch.setattr(trace_module, "KEYFRAME_BUDGET", 2 * one)
    trace = get("line-bresenham").record(((0, 0), (999, 700)), grid=(1000, 800))
    trace.raster_at(len(trace) - 1)
    dense = [slot for slot in trace._keyframes.slots if type(slot).__name__ == "Dense"]
    assert len(dense) == 2
    assert sum(slot.nbytes() for slot in dense) <= 2 * one
    for i in (0, 420, 777, len(trace) - 1):
        same_values(trace.raster_at(i, compact=True), slow_replay(trace, i))


def folded_variables(trace, i):
    """The variables at step i by applying every Vars record up to it in turn."""
    from algorithms.core.steps import Vars

    result = dict(trace.start.constants)
    for step in range(i + 1):
        record = trace.record_at(step)
        if isinstance(record, Vars):
            result.update(record.values)
    result.update(trace.step(i).values)
    branch = trace.code[int(trace.line[i])].branch
    if branch:
        result["choice"] = branch
    return result


@pytest.mark.parametrize("name, points, options", [
    ("flood-fill", [[(3, 2), (27, 3), (20, 11), (28, 20), (12, 15), (4, 21)]], {"order": "queue"}),
    ("polygon-scanline", [[(2.5, 2.25), (29.25, 3.5), (21.5, 11.75), (12.0, 15.25)]], {}),
    ("line-bresenham", [(1, 2), (27, 13)], {}),
])
def test_variables_equal_the_fold_of_every_update(name, points, options):
    trace = get(name).record(points, options, (32, 24))
    rng = random.Random(9)
    for i in sorted({0, 1, len(trace) - 1} | {rng.randrange(len(trace)) for _ in range(25)}):
        expected = folded_variables(trace, i)
        got = trace.variables_at(i)
        assert list(got.items()) == list(expected.items())  # the order shows in the panel


@pytest.mark.parametrize("spread", [50, 10_000_000])  # close writes (counted) and far ones
@pytest.mark.parametrize("dtype", [np.uint8, np.int32])
def test_write_many_counts_every_repeat(spread, dtype):
    from algorithms.core.raster import Raster

    rng = np.random.default_rng(spread)
    raster = Raster(4096, 4096)
    raster.counts = raster.counts.astype(dtype)
    flat = rng.integers(1000, 1000 + spread, 400)
    flat[::7] = -1  # outside the grid: skipped
    raster.write_many(flat)
    expected = {}
    for index in flat.tolist():
        if index >= 0:
            expected[index] = expected.get(index, 0) + 1
    counts = raster.counts.reshape(-1)
    assert int(counts.sum()) == sum(expected.values())
    assert all(int(counts[index]) == n for index, n in expected.items())
    assert raster.counts.dtype == dtype
