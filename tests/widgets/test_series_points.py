"""Thinning a long run's value to the points worth plotting."""
import math

import numpy as np
import pytest

from widgets.series_points import plot_points


def brute_force(values, limit):
    """Per bucket of consecutive known values: its lowest and highest, in
    step order (first occurrence wins ties)."""
    known = [(i, v) for i, v in enumerate(values) if math.isfinite(v)]
    if len(known) <= limit:
        return known
    buckets = limit // 2
    size = -(-len(known) // buckets)
    out = []
    for start in range(0, len(known), size):
        part = known[start:start + size]
        low = min(range(len(part)), key=lambda k: (part[k][1], k))
        high = max(range(len(part)), key=lambda k: (part[k][1], -k))
        for k in sorted((low, high)):
            out.append(part[k])
    return out


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("length, limit", [(50, 64), (1000, 64), (999, 10), (5000, 4096)])
def test_matches_a_bucket_by_bucket_scan(seed, length, limit):
    rng = np.random.default_rng(seed)
    values = np.round(rng.normal(size=length) * 5).astype(float)
    values[rng.random(length) < 0.3] = np.nan
    steps, known = plot_points(values, limit)
    expected = brute_force(values.tolist(), limit)
    # A bucket whose lowest and highest are one step keeps it twice.
    got = list(zip(steps.astype(int).tolist(), known.tolist()))
    assert [p for k, p in enumerate(got) if k == 0 or p != got[k - 1]] == \
        [p for k, p in enumerate(expected) if k == 0 or p != expected[k - 1]]
    assert len(got) <= limit
    finite = values[np.isfinite(values)]
    assert known.min() == finite.min() and known.max() == finite.max()


def test_a_run_without_values_gives_nothing():
    steps, known = plot_points(np.full(10, np.nan))
    assert len(steps) == 0 and len(known) == 0
