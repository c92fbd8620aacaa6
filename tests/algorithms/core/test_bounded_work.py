"""The step cap and a cancel bound the work a run does, not only the steps it keeps."""
import importlib

import numpy as np
import pytest

from algorithms.core.registry import get
from algorithms.core.steps import PLOT, CodeLine, Start
from algorithms.core.trace import Cancelled, RecordMonitor, Trace

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


def test_the_simplicity_check_tests_each_edge_against_all_later_ones_at_once(monkeypatch):
    import math
    from algorithms.polygons import tessellate as tess
    batches, pairs = [], []
    real_meets, real_meet = tess._meets, tess._segments_meet
    monkeypatch.setattr(tess, "_meets", lambda p, q, r, s: batches.append(len(r)) or
                        real_meets(p, q, r, s))
    monkeypatch.setattr(tess, "_segments_meet", lambda *a: pairs.append(a) or real_meet(*a))
    n = 600
    ring = [(2000 + 1900 * math.cos(2 * math.pi * k / n),
             2000 + 1900 * math.sin(2 * math.pi * k / n)) for k in range(n)]
    get("polygon-tessellate").record([ring], {}, grid=(4096, 4096), step_cap=50)
    # Testing every pair of edges one by one took about 19 s at 6,000
    # vertices (100,000: hours): n - 2 batches of numpy work instead.
    assert pairs == [] and len(batches) <= n


fill_module = importlib.import_module("algorithms.fill.flood")


def _zigzag(vertices: int) -> list:
    """A polygon whose edges each run the height of a 4096 grid."""
    return [(4000 * k // vertices, 4000 * (k % 2)) for k in range(vertices)] + [(4000, 4050),
                                                                               (0, 4050)]


def _count_outline_pixels(monkeypatch) -> list:
    made = [0]
    real = fill_module._segment_walk

    def counted(p, q, four):
        for pixel in real(p, q, four):
            made[0] += 1
            yield pixel
    monkeypatch.setattr(fill_module, "_segment_walk", counted)
    return made


def test_a_flood_fill_outline_is_drawn_only_as_far_as_the_step_cap(monkeypatch):
    made = _count_outline_pixels(monkeypatch)
    trace = get("flood-fill").record([_zigzag(400)], {"seed": (1, 4049)}, grid=(4096, 4096),
                                     step_cap=1000)
    assert trace.truncated
    # about 1.6 million outline pixels; before, all were drawn before the first step
    assert made[0] <= 1000 + 64


def test_a_flood_fill_outline_is_the_same_drawn_lazily():
    # the frames' outline pixels are outline_pixels (made at once, deduplicated)
    contours = [[(2, 2), (30, 5), (12, 20), (2, 2), (30, 5)], [(8, 8), (14, 9), (9, 14)]]
    for outline in ("4", "8"):
        trace = get("flood-fill").record(contours, {"seed": (0, 0), "outline": outline},
                                         grid=(24, 16))
        at = [k for k, line in enumerate(trace.code) if line.text.startswith("draw")][0]
        steps = np.flatnonzero(trace.line == at)[1:]  # step 0 is the Start record
        drawn = list(zip(trace.x[steps].tolist(), trace.y[steps].tolist()))
        assert drawn == fill_module.outline_pixels(contours, outline == "4")


@pytest.mark.parametrize("four", [False, True])
def test_outline_row_is_the_row_of_the_drawn_outline(four):
    rng = np.random.default_rng(11)
    for _ in range(300):
        contours = [[tuple(int(v) for v in rng.integers(-12, 13, 2))
                     for _ in range(int(rng.integers(1, 6)))] for _ in range(2)]
        pixels = fill_module.outline_pixels(contours, four)
        for y in range(-14, 15):
            assert fill_module.outline_row(contours, y, four) == {x for x, r in pixels if r == y}


def test_the_seed_search_hears_a_cancel_between_rows(monkeypatch):
    rows = []
    real = fill_module.outline_row
    monkeypatch.setattr(fill_module, "outline_row",
                        lambda *args: rows.append(args[1]) or real(*args))
    monitor = RecordMonitor()
    monitor.cancel()
    # no pixel inside this outline is free: the search would try all 4,050 rows
    with pytest.raises(Cancelled):
        get("flood-fill").record([_zigzag(4000)[:-2]], {}, grid=(4096, 4096), monitor=monitor)
    assert len(rows) <= 1


def test_slow_frames_are_recorded_in_small_chunks_so_a_cancel_is_heard_soon():
    import time
    monitor = RecordMonitor(every=4096)
    pulled = [0]

    def frames():
        yield Start(line=0, values=())
        for k in range(4096):
            pulled[0] += 1
            if k == 200:
                monitor.cancel()
            time.sleep(0.001)  # a slow frame
            yield (0, 0, 0)
    with pytest.raises(Cancelled):
        Trace.record(frames(), [CodeLine("a", PLOT)], 4, 4, monitor=monitor)
    # before, the whole chunk of 4,096 frames was made before the cancel was heard
    assert pulled[0] < 300


def test_a_polygon_of_many_edges_tests_samples_through_crossing_tables():
    from algorithms.antialias.shapes import TABLE_EDGES, Shape
    rng = np.random.default_rng(5)
    for _ in range(40):
        count = int(rng.integers(TABLE_EDGES + 1, 90))
        contour = [tuple(int(v) for v in rng.integers(-600, 3000, 2)) for _ in range(count)]
        for rule in ("evenodd", "nonzero"):
            shape = Shape([contour], rule, (0, 0, 0), False)
            sx = rng.integers(-700, 3100, 200)
            sy = np.concatenate([rng.integers(-700, 3100, 100),
                                 rng.choice([p[1] for p in contour], 100)])
            expected = shape.hits(sx, sy)  # numpy, one edge at a time
            assert [shape.hit(int(a), int(b)) for a, b in zip(sx, sy)] == expected.tolist()


def test_the_mask_of_many_boxes_is_the_union_of_the_boxes():
    from algorithms.antialias.shapes import UNIT, Shapes
    rng = np.random.default_rng(9)
    for _ in range(30):
        count = int(rng.integers(1, 80))
        points = [tuple(float(v) for v in rng.uniform(-5, 40, 2)) for _ in range(3 * count)]
        shapes = Shapes(points, {"shape": "triangles"})
        window = shapes.window((int(rng.integers(1, 40)), int(rng.integers(1, 30))))
        x0, y0, x1, y1 = window
        expected = np.zeros((y1 - y0, x1 - x0), bool)
        for shape in shapes.items:  # each box painted in turn
            box = shape.box
            expected[max(box[1] // UNIT, y0) - y0:max(min(box[3] // UNIT + 1, y1) - y0, 0),
                     max(box[0] // UNIT, x0) - x0:max(min(box[2] // UNIT + 1, x1) - x0, 0)] = True
        assert np.array_equal(shapes.mask(window), expected)


@pytest.mark.parametrize("grid", [(1, 1), (2, 5), (7, 3), (24, 18)])
@pytest.mark.parametrize("kernel", ["box3", "seed", "gaussian"])
def test_the_post_filter_made_row_by_row_writes_what_the_whole_image_filter_does(grid, kernel):
    # the frames look at the aliased image a row at a time (small grids: a
    # kernel wider than the grid)
    from algorithms.antialias.filters import filter_image
    points = [(0.3, 0.2), (20.5, 3.7), (6.1, 16.9), (3.0, 1.0), (5.5, 1.5), (2.0, 4.0)]
    options = {"kernel": kernel}
    expected = filter_image(points, options, grid)  # the whole image at once, in numpy
    trace = get("aa-filter").record(points, options, grid=grid)
    last = {}
    for (x, y), value in zip(trace.written_pixels().tolist(), trace.pixel_values()):
        last[(x, y)] = value
    got = np.zeros_like(expected)
    for (x, y), value in last.items():
        got[y, x] = value
    assert np.array_equal(got, expected)
