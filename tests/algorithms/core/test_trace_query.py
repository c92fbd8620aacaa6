"""The Trace queries against scans of the raw frames a generator yielded.

Each expected answer is worked out here from the frames themselves (the
list the generator yields, before any recording), never from the trace's
own indexes, on runs of several families and on random synthetic runs.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from algorithms.core import trace as trace_module
from algorithms.core.raster import Raster
from algorithms.core.registry import get
from algorithms.core.steps import CALC, NO_PIXEL, PLOT, VISIT, CodeLine, Note, Span, Start, Table, Vars
from algorithms.core.trace import Trace

RICH = (Start, Vars, Table, Note, Span)

# (algorithm, points, options, grid): spans, tables, colours, depth,
# coverage, repeats and pixels outside the grid between them.
CASES = [
    ("line-bresenham", ((-3, 1), (30, 14)), {"colors": ["#ff0000", "#0000ff"]}, (24, 12)),
    ("line-parametric", ((1, 1), (20, 9)), {"dt": 0.02}, (24, 12)),
    ("circle-midpoint", ((10, 9),), {"radius": 7}, (20, 16)),
    ("polygon-scanline", ([(2, 2), (28, 3), (20, 20)], [(10, 6), (16, 6), (14, 12)]),
     {"fill_rule": "nonzero"}, (30, 22)),
    ("polygon-tessellate", ([(1, 1), (15, 2), (9, 6), (14, 11), (2, 10)],), {}, (16, 12)),
    ("flood-fill", ([(2, 2), (17, 3), (10, 14)],), {"order": "span", "seed": (10, 6)}, (20, 16)),
    ("zbuffer", ((1, 1), (14, 2), (6, 11), (2, 9), (13, 10), (12, 1)),
     {"z": [0.2, 0.5, 0.8, 0.9, 0.1, 0.4]}, (16, 12)),
    ("aa-supersample", ((1.5, 1.25), (13.5, 3.5), (6.25, 10.5)), {"n": 2}, (16, 12)),
    ("line-wu", ((1, 2), (14, 9)), {}, (16, 12)),
]


class Run:
    """A trace and the frames its generator yielded, recorded once."""

    def __init__(self, code, frames, width, height):
        self.frames = list(frames)
        self.code = tuple(code)
        self.trace = Trace.record(iter(self.frames), self.code, width, height)

    @classmethod
    def of(cls, name, points, options, grid):
        spec = get(name)
        frames = spec.frames(points, options, grid)
        code = spec.code(spec.inputs.check(points), spec.resolve(options))
        return cls(code, frames, *grid)

    # --------------------------------------------- scans of the frames
    def rich(self, types=RICH, lo=0, hi=None):
        hi = len(self.frames) if hi is None else hi
        return [(k, frame) for k, frame in enumerate(self.frames)
                if not isinstance(frame, tuple) and isinstance(frame, types) and lo <= k < hi]

    def value(self, frame, name):
        """A lean frame's value of ``name``, NaN when the run names none."""
        if name is None:
            return math.nan
        return float(frame[3 + self.frames[0].values.index(name)])

    def writes(self, lo, hi, name):
        """(step, x, y, value) of every write of steps lo..hi-1."""
        found = []
        for k in range(lo, hi):
            frame = self.frames[k]
            if isinstance(frame, tuple):
                if self.code[frame[0]].kind == PLOT and frame[1] != NO_PIXEL:
                    found.append((k, frame[1], frame[2], self.value(frame, name)))
            elif isinstance(frame, Span) and self.code[frame.line].kind == PLOT:
                value = math.nan if frame.value is None else float(frame.value)
                found += [(k, x, frame.y, value) for x in range(frame.x_start, frame.x_end)]
        return found

    def raster(self, hi):
        """The framebuffer after steps 0..hi-1, written pixel by pixel."""
        start = self.frames[0]
        colour = start.color_value or start.pixel_value
        raster = Raster(self.trace.width, self.trace.height, colour is not None,
                        start.depth_value is not None)
        for k, x, y, value in self.writes(0, hi, colour):
            frame = self.frames[k]
            depth = self.value(frame, start.depth_value) if isinstance(frame, tuple) else None
            raster.write(x, y, None if colour is None else value, depth)
        return raster


RUNS = {}


def run_of(case: int) -> Run:
    if case not in RUNS:
        RUNS[case] = Run.of(*CASES[case])
    return RUNS[case]


# ------------------------------------------------- synthetic random runs
SYNTHETIC_CODE = (CodeLine("start"), CodeLine("plot", PLOT), CodeLine("visit", VISIT),
                  CodeLine("calc", CALC))
W, H = 9, 7
coordinate = st.one_of(st.integers(-2, W + 2), st.just(NO_PIXEL))
value = st.one_of(st.integers(0, 0xFFFFFF).map(float), st.just(math.nan))
lean = st.builds(lambda line, x, y, c, z: (line, x, NO_PIXEL if x == NO_PIXEL else y, c, z),
                 st.integers(1, 3), coordinate, st.integers(-2, H + 2), value, value)
rich = st.one_of(
    st.builds(Span, line=st.integers(1, 3), y=st.integers(-1, H), x_start=st.integers(-2, W),
              x_end=st.integers(-2, W + 2), value=st.one_of(st.none(), st.integers(0, 0xFFFFFF))),
    st.builds(lambda line, a: Vars(line=line, values={"a": a}), st.integers(1, 3), st.integers(0, 9)),
    st.builds(lambda line, n: Table(line=line, name="T", columns=("k",),
                                    rows=tuple((k,) for k in range(n))),
              st.integers(1, 3), st.integers(0, 3)),
    st.builds(lambda line: Note(line=line, text="a remark"), st.integers(1, 3)))


@st.composite
def synthetic_runs(draw):
    start = Start(line=0, values=("c", "z"), pixel_value=draw(st.sampled_from(["c", None])),
                  depth_value=draw(st.sampled_from(["z", None])))
    frames = [start] + draw(st.lists(st.one_of(lean, rich), min_size=1, max_size=60))
    return Run(SYNTHETIC_CODE, frames, W, H)


@st.composite
def runs_and_ranges(draw):
    run = draw(st.one_of(synthetic_runs(), st.integers(0, len(CASES) - 1).map(run_of)))
    n = len(run.frames)
    lo = draw(st.integers(0, n))
    hi = draw(st.integers(lo, n))
    return run, lo, hi


QUERIES = settings(max_examples=150,
                   suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


# ------------------------------------------------------------ the queries
def test_the_family_runs_are_recorded_whole():
    for case in range(len(CASES)):
        run = run_of(case)
        assert len(run.trace) == len(run.frames), CASES[case][0]


@QUERIES
@given(runs_and_ranges(), st.lists(st.sampled_from(RICH), min_size=1, max_size=3, unique=True))
def test_records_of_and_steps_of_are_a_scan_of_the_frames(found, types):
    run, lo, hi = found
    trace = run.trace
    expected = run.rich(tuple(types), lo, hi)
    assert trace.records_of(*types, lo=lo, hi=hi) == expected
    assert trace.steps_of(*types, lo=lo, hi=hi).tolist() == [k for k, _ in expected]
    assert trace.steps_of(lo=lo, hi=hi).tolist() == [k for k, _ in run.rich(RICH, lo, hi)]
    for k in range(lo, hi):
        frame = run.frames[k]
        assert trace.record_at(k) == (None if isinstance(frame, tuple) else frame)


@QUERIES
@given(runs_and_ranges(), st.lists(st.sampled_from(RICH), min_size=1, max_size=3, unique=True))
def test_last_of_is_the_latest_record_at_or_before(found, types):
    run, _, at = found
    earlier = run.rich(tuple(types), 0, at + 1)
    assert run.trace.last_of(*types, at=at) == (earlier[-1] if earlier else None)


@QUERIES
@given(runs_and_ranges())
def test_spans_are_the_span_frames_as_columns(found):
    run, lo, hi = found
    spans = run.trace.spans(lo, hi)
    expected = [(k, s.line, s.y, s.x_start, s.x_end, math.nan if s.value is None else s.value)
                for k, s in run.rich(Span, lo, hi)]
    got = [tuple(row) for row in spans.tolist()]
    assert len(got) == len(expected)
    for row, want in zip(got, expected):
        assert row[:5] == want[:5]
        assert row[5] == want[5] or (math.isnan(row[5]) and math.isnan(want[5]))


@QUERIES
@given(runs_and_ranges())
def test_written_is_every_write_in_emission_order(found):
    run, lo, hi = found
    trace = run.trace
    name = run.frames[0].pixel_value
    expected = run.writes(lo, hi, name)
    writes = trace.written(lo, hi)
    assert writes.steps.tolist() == [k for k, _, _, _ in expected]
    assert writes.pixels.reshape(-1, 2).tolist() == [[x, y] for _, x, y, _ in expected]
    if name is None:
        assert writes.values is None
    else:
        assert np.array_equal(writes.values, np.array([v for *_, v in expected]), equal_nan=True)
    everything = run.writes(0, len(run.frames), name)
    assert trace.written_pixels().reshape(-1, 2).tolist() == [[x, y] for _, x, y, _ in everything]


@QUERIES
@given(runs_and_ranges())
def test_replay_of_a_range_continues_a_raster(found):
    run, lo, hi = found
    trace = run.trace
    raster = Raster(trace.width, trace.height, run.raster(0).colors is not None,
                    run.raster(0).depth is not None)
    trace.replay(0, lo, raster)
    same_raster(raster, run.raster(lo))
    trace.replay(lo, hi, raster)
    same_raster(raster, run.raster(hi))


# ------------------------------------------------- state_at == full replay
@settings(max_examples=80,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(runs_and_ranges(), st.integers(1, 7))
def test_state_at_equals_a_replay_from_scratch(found, gap):
    run, _, hi = found
    i = max(hi - 1, 0)
    with pytest.MonkeyPatch.context() as patch:
        # Keyframes every few steps, so that state_at really starts from one.
        patch.setattr(trace_module, "MIN_KEYFRAME_GAP", gap)
        patch.setattr(trace_module, "KEYFRAME_BYTES_PER_STEP", 2 ** 40)
        trace = Trace.record(iter(run.frames), run.code, run.trace.width, run.trace.height)
        same_raster(trace.state_at(i).raster, run.raster(i + 1))
        same_raster(trace.raster_at(len(trace) - 1), run.raster(len(run.frames)))


def same_raster(a, b):
    assert np.array_equal(a.counts, b.counts)
    for got, expected in ((a.colors, b.colors), (a.depth, b.depth)):
        assert (got is None) == (expected is None)
        if got is not None:
            assert np.array_equal(got, expected, equal_nan=got.dtype.kind == "f")
