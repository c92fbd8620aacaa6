"""The step cap and a cancel bound the work a run does, not only the steps it keeps."""
import pytest

import importlib

from algorithms.registry import get
from algorithms.trace import Cancelled, RecordMonitor

temporal_module = importlib.import_module("algorithms.antialias.temporal")
WHEEL = [(10.0, 10.0)]


def _count_instants(monkeypatch) -> list:
    """Count the instants at which aa-temporal places its primitive."""
    calls = []
    real = temporal_module._temporal_shapes

    def counted(points, options, t):
        calls.append(t)
        return real(points, options, t)

    monkeypatch.setattr(temporal_module, "_temporal_shapes", counted)
    return calls


def test_temporal_frames_are_computed_only_as_far_as_the_step_cap(monkeypatch):
    calls = _count_instants(monkeypatch)
    trace = get("aa-temporal").record(WHEEL, {"frames": 240, "n": 1}, grid=(20, 20),
                                      step_cap=50)
    assert trace.truncated
    # frame 0 is reached (and perhaps frame 1 is made before the cap is noticed);
    # before, all 240 frames were made before the first step
    assert len(calls) <= 3


def test_temporal_motion_blur_stops_at_the_cap_after_a_frame_or_two(monkeypatch):
    calls = _count_instants(monkeypatch)
    get("aa-temporal").record(WHEEL, {"frames": 240, "mode": "motion-blur",
                                      "time_samples": 64, "n": 1}, grid=(20, 20), step_cap=20)
    assert len(calls) <= 3 * 64


def test_temporal_cancel_stops_between_frames(monkeypatch):
    calls = _count_instants(monkeypatch)
    monitor = RecordMonitor(every=1)
    monitor.cancel()
    with pytest.raises(Cancelled):
        get("aa-temporal").record(WHEEL, {"frames": 240, "n": 1}, grid=(20, 20),
                                  monitor=monitor)
    assert len(calls) < 240


def test_a_slow_motion_blur_frame_stops_at_the_cap_within_the_frame(monkeypatch):
    from algorithms.antialias.shapes import Shapes
    tested = []
    real = Shapes.owners

    def counted(self, sx, sy):
        tested.append(sx.size)
        return real(self, sx, sy)

    monkeypatch.setattr(Shapes, "owners", counted)
    options = {"frames": 2, "mode": "motion-blur", "time_samples": 64, "n": 8,
               "radius": 50.0}
    get("aa-temporal").record([(64.0, 64.0)], options, grid=(128, 128), step_cap=30)
    whole_frame = 101 * 101 * 64 * 64  # the wheel's window, its samples, its instants
    # the image is made band by band as the steps need it; before, the whole
    # frame (and every other frame) was made before its first step
    assert 0 < sum(tested) < whole_frame // 10


def test_the_simplicity_check_tests_pairs_as_the_exact_segment_test_does():
    import numpy as np
    from algorithms.polygons import tessellate as tess
    rng = np.random.default_rng(7)
    for _ in range(200):
        p, q = (tuple(int(v) for v in rng.integers(0, 6, 2)) for _ in range(2))
        others = [tuple(int(v) for v in rng.integers(0, 6, 2)) for _ in range(40)]
        r, s = np.array(others[:20]), np.array(others[20:])
        expected = [tess._segments_meet(p, q, tuple(a), tuple(b)) for a, b in zip(r, s)]
        assert list(tess._meets(np.array(p), np.array(q), r, s)) == expected


def test_a_many_vertex_polygon_is_checked_for_simplicity_quickly():
    import math
    import time
    n = 6000
    ring = [(2000 + 1900 * math.cos(2 * math.pi * k / n),
             2000 + 1900 * math.sin(2 * math.pi * k / n)) for k in range(n)]
    started = time.perf_counter()
    get("polygon-tessellate").record([ring], {}, grid=(4096, 4096), step_cap=50)
    # about 19 s when every pair of edges was tested one by one (100,000
    # vertices: hours), about 1.5 s now; a generous bound
    assert time.perf_counter() - started < 10
