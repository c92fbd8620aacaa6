"""The accumulation buffer of supersampling and motion blur, step by step,
against sample counts worked out here in exact arithmetic."""
from __future__ import annotations

from fractions import Fraction

import numpy as np
from hypothesis import assume, given, settings, strategies as st

from algorithms.core import registry
from algorithms.core.steps import Vars
from app.model.buffers import side_buffer
from tests.support.triangle_variant_oracles import edge, strictly_inside

GRID = (12, 10)


def area2(tri) -> Fraction:
    return abs(edge(tri[0], tri[1], tri[2]))


# vertices in 1/256 px, so that snapping them changes nothing
coordinate = st.integers(0, 256 * GRID[1] - 1).map(lambda v: Fraction(v, 256))
triangle = st.lists(st.tuples(coordinate, coordinate), min_size=3, max_size=3)


def grid_samples(n: int):
    """The n x n grid of a pixel, in the order the run tests it: s = i + n j."""
    return [(Fraction(2 * (s % n) + 1, 2 * n), Fraction(2 * (s // n) + 1, 2 * n))
            for s in range(n * n)]


@settings(max_examples=25)
@given(triangle)
def test_supersampling_accumulates_each_pixels_samples_one_at_a_time(tri):
    assume(area2(tri) > 4)
    n = 4
    trace = registry.get("aa-supersample").record(
        [tuple(map(float, p)) for p in tri], {"shape": "triangles", "n": n, "filter": "box"},
        GRID)
    samples = grid_samples(n)
    inside_at = {}  # pixel -> its samples inside, in test order (None: a tie)
    tested = {}     # pixel -> samples tested so far
    rng = np.random.default_rng(len(trace))
    checked = set(rng.integers(0, len(trace), 40).tolist()) | {len(trace) - 1}
    for i in range(len(trace)):
        step = trace.step(i)
        if step.record is None and step.pixel is not None and step.kind == "visit" \
                and step.branch in ("hit", "miss"):
            tested[step.pixel] = tested.get(step.pixel, 0) + 1
        if i not in checked:
            continue
        buffer = side_buffer(trace, i)
        assert buffer.name == "accumulation buffer"
        for (x, y), count in tested.items():
            if (x, y) not in inside_at:
                inside_at[(x, y)] = [strictly_inside(tri, (x + u, y + v)) for u, v in samples]
            first = inside_at[(x, y)][:count]
            if None in first:
                continue
            assert Fraction(buffer.at(x, y)) == Fraction(sum(first), n * n)
        untouched = np.ones(buffer.values.shape, bool)
        for x, y in tested:
            untouched[y, x] = False
        assert np.isnan(buffer.values[untouched]).all()


def moved(tri, shift):
    return [(x + shift, y) for x, y in tri]


@settings(max_examples=15)
@given(triangle, st.sampled_from([1, 2, 3]))
def test_motion_blur_adds_each_instants_samples_into_the_buffer(tri, speed):
    assume(area2(tri) > 4)
    n, count, frames = 2, 4, 2
    options = {"primitive": "triangle", "motion": "move", "mode": "motion-blur",
               "frames": frames, "speed": float(speed), "time_samples": count, "n": n}
    grid = (GRID[0] + 8, GRID[1])
    trace = registry.get("aa-temporal").record([tuple(map(float, p)) for p in tri], options,
                                               grid)
    samples = grid_samples(n)
    clears = [step for step, record in trace.records_of(Vars)
              if record.values.get("cleared") == "accumulation buffer"]
    assert len(clears) == frames
    ends = clears[1:] + [len(trace)]
    for k, (lo, hi) in enumerate(zip(clears, ends)):
        # the frame's instants: the middle of each quarter of the frame
        shifts = [speed * (k + Fraction(2 * s + 1, 2 * count)) for s in range(count)]
        expected = {}  # pixel -> running totals, one per instant that reaches it
        for shift in shifts:
            shape = moved(tri, shift)
            for y in range(grid[1]):
                for x in range(grid[0]):
                    hits = [strictly_inside(shape, (x + u, y + v)) for u, v in samples]
                    assume(None not in hits)
                    if sum(hits):
                        totals = expected.setdefault((x, y), [])
                        totals.append((totals[-1] if totals else 0) + sum(hits))
        seen = {}
        for i in range(lo, hi):
            step = trace.step(i)
            if step.record is None and step.kind == "visit":
                seen.setdefault(step.pixel, []).append(
                    Fraction(step.values["accum"]) * count * n * n)
            elif step.kind == "plot":
                total = expected.get(step.pixel, [0])[-1]
                assert Fraction(step.values["coverage"]) == Fraction(total, count * n * n)
        assert seen == expected
        buffer = side_buffer(trace, hi - 1)
        for (x, y), totals in expected.items():
            assert buffer.at(x, y) * count * n * n == totals[-1]
        assert np.isnan(buffer.values).sum() == grid[0] * grid[1] - len(expected)


def test_the_buffer_is_cleared_at_each_frame_and_kept_only_with_motion_blur():
    spec = registry.get("aa-temporal")
    tri = [(2.25, 1.5), (9.5, 3.25), (4.0, 9.0)]
    blur = spec.record(tri, {"mode": "motion-blur", "motion": "move", "frames": 2,
                             "speed": 3.0, "time_samples": 4}, (24, 12))
    clears = [step for step, record in blur.records_of(Vars)
              if record.values.get("cleared") == "accumulation buffer"]
    assert np.isnan(side_buffer(blur, clears[1]).values).all()
    assert not np.isnan(side_buffer(blur, clears[1] - 1).values).all()
    instant = spec.record(tri, {"mode": "instant", "motion": "move", "frames": 2}, (24, 12))
    assert side_buffer(instant, len(instant) - 1) is None
    assert np.nanmax(side_buffer(blur, len(blur) - 1).values) > 0
