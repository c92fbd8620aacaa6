"""Work a run does before its first frame, or between two frames, stays small or
hears a cancel: big buffers are not filled up front, long passes check in."""
import os

import numpy as np

import pytest

from algorithms.core.registry import get
from algorithms.core.trace import Cancelled, RecordMonitor, watching

BIG = (4096, 4096)  # 16M pixels: a filled float64 buffer is 128 MiB
TRIANGLE = [(10.0, 10.0), (30.0, 12.0), (20.0, 28.0)]


def _resident_bytes() -> int:
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _growth_until_first_pixel(name, points, options, grid) -> int:
    """Resident memory the run's generator gains up to its first pixel frame."""
    spec = get(name)
    frames = spec.generator(points, spec.resolve(options), grid)
    before = _resident_bytes()
    for frame in frames:
        if type(frame) is tuple:
            break
    grown = _resident_bytes() - before
    frames.close()
    return grown


@pytest.mark.parametrize("name", ["zbuffer", "painter", "blend-over"])
def test_the_big_buffers_are_not_filled_before_the_first_frame(name):
    # Filling one 16M-pixel buffer touches 128 MiB; a zeroed one touches
    # only the pages a fragment writes.
    assert _growth_until_first_pixel(name, TRIANGLE, {}, BIG) < 32 * 2 ** 20


def test_the_painters_final_comparison_hears_a_cancel():
    from algorithms.visibility import zbuffer_painter as visibility
    monitor = RecordMonitor()
    monitor.cancel()
    with watching(monitor), pytest.raises(Cancelled):
        visibility.zbuffer_image(TRIANGLE, {}, BIG)


def _count_tested_samples(monkeypatch) -> list:
    from algorithms.antialias.shapes import Shapes
    tested = []
    real = Shapes.owners

    def counted(self, sx, sy):
        tested.append(sx.size)
        return real(self, sx, sy)

    monkeypatch.setattr(Shapes, "owners", counted)
    return tested


def test_a_temporal_band_is_tested_in_pieces_that_each_hear_a_cancel(monkeypatch):
    from algorithms.antialias.temporal import frame_bands
    tested = _count_tested_samples(monkeypatch)
    options = {"n": 8, "radius": 100.0}
    top, rows = next(frame_bands([(128.0, 128.0)], options, (256, 256), 0))
    band = rows.size * 64  # the band's pixels, 64 samples each
    assert len(tested) > 1 and sum(tested) <= band and max(tested) < band
    # a cancel is heard before the first piece is tested
    tested.clear()
    monitor = RecordMonitor()
    monitor.cancel()
    with watching(monitor), pytest.raises(Cancelled):
        next(frame_bands([(128.0, 128.0)], options, (256, 256), 0))
    assert tested == []


def test_the_post_filters_aliased_image_is_made_block_by_block_as_the_frames_need_it(
        monkeypatch):
    from algorithms.antialias import filters
    blocks = []
    real = filters.span_arrays

    def counted(tris, scale, rule, window=None, top_down=False):
        blocks.append(window)
        return real(tris, scale, rule, window, top_down)

    monkeypatch.setattr(filters, "span_arrays", counted)
    # a triangle over the whole grid: 4096 rows, the first frame in row 0
    trace = get("aa-filter").record([(-10.0, -10.0), (9000.0, -10.0), (-10.0, 9000.0)], {},
                                    grid=BIG, step_cap=100)
    assert trace.truncated
    assert 1 <= len(blocks) <= 2 and all(w[3] - w[1] < BIG[1] // 8 for w in blocks)


@pytest.mark.parametrize("seed", range(3))
def test_the_aliased_blocks_make_the_centre_sampled_image(seed):
    # oracle: a pixel centre is covered when it lies strictly inside a
    # triangle (three signed areas > 0, exact); a centre on an edge depends
    # on the fill rule and is left out of the comparison
    import random
    from fractions import Fraction
    from algorithms.antialias.filters import aliased_blocks
    rng = random.Random(seed)
    grid = (23, 37)
    points = [(rng.randrange(-20, 120) / 4 + 0.125, rng.randrange(-20, 160) / 4 + 0.0625)
              for _ in range(9)]
    made = np.zeros((grid[1], grid[0]), bool)
    for top, rows in aliased_blocks(points, grid, "top-left"):
        made[top:top + len(rows)] = rows
    expected = np.zeros_like(made)
    on_edge = np.zeros_like(made)
    for k in range(0, 9, 3):
        a, b, c = (tuple(map(Fraction, p)) for p in points[k:k + 3])
        area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if area < 0:
            b, c = c, b
        for y in range(grid[1]):
            for x in range(grid[0]):
                p = (Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2))
                sides = [(e[0] - s[0]) * (p[1] - s[1]) - (e[1] - s[1]) * (p[0] - s[0])
                         for s, e in ((a, b), (b, c), (c, a))]
                if all(side > 0 for side in sides):
                    expected[y, x] = True
                elif all(side >= 0 for side in sides):
                    on_edge[y, x] = True
    assert expected.any()
    assert (made[~on_edge] == expected[~on_edge]).all()


def test_line_area_computes_its_window_a_block_of_columns_at_a_time(monkeypatch):
    from algorithms.antialias import lines
    computed = []
    real = lines.exact_coverage.segment_coverage

    def counted(*args, columns=None, **kwargs):
        computed.append(columns)
        return real(*args, columns=columns, **kwargs)

    monkeypatch.setattr(lines.exact_coverage, "segment_coverage", counted)
    trace = get("line-area").record([(4000, 10), (5, 3000)], {}, grid=BIG, step_cap=50)
    assert trace.truncated
    # the window is about 4000 columns wide; before, all were computed at once
    assert computed and sum(end - first for first, end in computed) <= 64


def test_line_area_written_values_are_the_exact_coverage_of_the_whole_window():
    # oracle: the exact (rational) coverage of the rectangle over its window
    from algorithms.antialias.lines import area_image
    for points in ([(1, 2), (30, 9)], [(30, 9), (1, 2)], [(3, 1), (9, 40)], [(9, 40), (3, 1)]):
        options = {"width": 1.5}
        trace = get("line-area").record(points, options, grid=(48, 48))
        (x0, y0, _, _), exact = area_image(points, options, exact=True)
        plotted = {}
        for i in range(len(trace)):
            step = trace.step(i)
            if step.kind == "plot" and step.pixel is not None:
                plotted[step.pixel] = step.values["intensity"]
        expected = {(x0 + x, y0 + y): float(a) for (y, x), a in np.ndenumerate(exact) if a > 0}
        assert plotted.keys() == expected.keys()
        assert all(abs(plotted[k] - expected[k]) < 1e-9 for k in expected)


def _count_calls(monkeypatch, module, name) -> list:
    made = [0]
    real = getattr(module, name)

    def counted(*args):
        for item in real(*args):
            made[0] += 1
            yield item
    monkeypatch.setattr(module, name, counted)
    return made


def test_a_seed_search_that_finds_nothing_stops_at_the_step_caps_work(monkeypatch):
    from algorithms.fill import flood as fill
    from algorithms.core.errors import InputError
    rows = [0]
    real_row = fill.outline_row

    def counted_row(*args):
        rows[0] += 1
        return real_row(*args)
    monkeypatch.setattr(fill, "outline_row", counted_row)
    # 1,000 edges across the grid, 10 to a row: every pixel inside is on the outline
    zigzag = [(0 if k % 2 else 99, k * 99 // 1000) for k in range(1000)]
    with pytest.raises(InputError, match="seed=X,Y"):
        get("flood-fill").record([zigzag], {}, grid=(100, 100), step_cap=1000)
    # 1,000 steps allow 2,000 edge tests: 2 rows of 1,000 edges; before, all 100 rows
    assert 1 <= rows[0] <= 2


def test_outline_pixels_walked_again_count_against_the_step_cap(monkeypatch):
    from algorithms.fill import flood as fill
    from algorithms.core.errors import InputError
    walked = _count_calls(monkeypatch, fill, "_segment_walk")
    # segments back and forth over one row, each a pixel shorter: no two are
    # the same segment, and all but the first walk pixels drawn before
    points = [(k // 2 if k % 2 == 0 else 3999 - k // 2, 0) for k in range(200)] + [(50, 60)]
    with pytest.raises(InputError, match="overlap"):
        get("flood-fill").record([points], {"seed": (60, 30)}, grid=(100, 100),
                                 step_cap=5000)
    # 5,000 steps allow 10,000 pixels passed over; before, all ~800,000 were walked
    assert walked[0] <= 5000 + 10_000 + 4000


def test_a_temporal_frame_does_not_fill_its_image_before_its_first_pixel():
    spec = get("aa-temporal")
    frames = spec.generator([(2048.0, 12.0)], spec.resolve({"frames": 2}), BIG)
    vars_seen = 0
    for frame in frames:  # to the start of the second animation frame
        if type(frame).__name__ == "Vars":
            vars_seen += 1
            if vars_seen == 2:
                break
    before = _resident_bytes()
    for frame in frames:  # the wheel is in the top band: its first pixel comes at once
        if type(frame) is tuple:
            break
    grown = _resident_bytes() - before
    frames.close()
    assert grown < 32 * 2 ** 20  # a filled 4096^2 image is 128 MiB


def test_line_subpixels_walks_its_cells_as_the_frames_go(monkeypatch):
    import importlib
    module = importlib.import_module("algorithms.antialias.subpixel_line")
    walked = _count_calls(monkeypatch, module, "walk_cells")
    trace = get("line-subpixels").record([(0, 0), (4095, 3000)], {"n": 8}, grid=BIG,
                                         step_cap=20)
    assert trace.truncated
    # about 57,000 cells along the line; before, all were found before the first frame
    assert walked[0] <= 20 * 2 * 8
