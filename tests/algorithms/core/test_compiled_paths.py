"""Both paths of every compiled kernel: the plain Python loop (what runs without
numba, the ``fast`` extra) against a reference that uses no compiled code,
and, where numba is installed, the compiled loop against the plain one on
the same inputs, arrays written in place included (the test extra installs
numba, so the suite compares both)."""
import copy
import importlib.util

import numpy as np
import pytest
from skimage.segmentation import flood

from algorithms import triangles
from algorithms.antialias.wu_kernel import _draw_wu, wu_lines
from algorithms.fill.flood import outline_pixels
from algorithms.fill.kernel import _segment_params, mark_segments, span_fill
from algorithms.polygons import scanline_pixels
from algorithms.polygons.many import RULES as POLYGON_RULES, _edge_setup, _fill_polygons, \
    _vertices_of
from algorithms.polygons.scanline import sample_of
from algorithms.triangles.canvas import RULES as TRIANGLE_RULES, _fill_rows, _largest_int64_reach
from algorithms.triangles.kernels import snap_array

HAS_NUMBA = importlib.util.find_spec("numba") is not None
SEEDS = range(6)


def both(kernel, *args):
    """(result, args after) of the plain loop; with numba the compiled loop's
    are asserted equal to them. Each loop gets its own copy of ``args``."""
    plain_args = copy.deepcopy(args)
    plain = kernel.python(*plain_args)
    if HAS_NUMBA:
        compiled_args = copy.deepcopy(args)
        assert_same(kernel(*compiled_args), plain)
        assert_same(compiled_args, plain_args)
    return plain, plain_args


def assert_same(got, want):
    if isinstance(want, (tuple, list)):
        assert type(got) is type(want) and len(got) == len(want)
        for a, b in zip(got, want):
            assert_same(a, b)
    elif isinstance(want, np.ndarray):
        assert got.dtype == want.dtype and np.array_equal(got, want)
    else:
        assert got == want


@pytest.mark.parametrize("gap", [False, True])
@pytest.mark.parametrize("dtype", [np.float64, np.uint8])
@pytest.mark.parametrize("seed", SEEDS)
def test_wu_lines_into_a_canvas(seed, dtype, gap):
    rng = np.random.default_rng(seed)
    starts, ends = rng.integers(-8, 50, (2, 30, 2))
    ends[:3] = starts[:3]  # points
    canvas = np.zeros((40, 44), dtype)
    _, (drawn, *_) = both(_draw_wu, canvas, starts, ends, gap, 255.0)
    # The numpy kernel's pixels, written in its order where they lie on the canvas.
    pixels, intensity, _ = wu_lines(starts, ends, "gap" if gap else "full")
    want = np.zeros_like(canvas)
    for (x, y), value in zip(pixels.tolist(), intensity.tolist()):
        if 0 <= x < 44 and 0 <= y < 40:
            want[y, x] = value * 255.0
    assert np.array_equal(drawn, want)


@pytest.mark.parametrize("eight", [False, True])
@pytest.mark.parametrize("four", [False, True])
@pytest.mark.parametrize("seed", SEEDS)
def test_outline_and_span_fill(seed, four, eight):
    rng = np.random.default_rng(seed)
    width, height = 36, 28
    contours = [[tuple(p) for p in rng.integers(-6, 40, (rng.integers(3, 8), 2)).tolist()]
                for _ in range(2)]
    params = np.array([found for contour in contours for k, p in enumerate(contour)
                       if (found := _segment_params(p, contour[(k + 1) % len(contour)],
                                                    width, height))], np.int64)
    cells = np.zeros((height, width), np.uint8)
    _, (outlined, *_) = both(mark_segments, cells, params, four)
    want = np.zeros_like(cells)
    for x, y in outline_pixels(contours, four):
        if 0 <= x < width and 0 <= y < height:
            want[y, x] = 1
    assert np.array_equal(outlined, want)

    free = np.argwhere(outlined == 0)
    y, x = (int(v) for v in free[rng.integers(len(free))])
    filled, (cells_after, *_) = both(span_fill, outlined, x, y, 0, 2, eight)
    region = flood(outlined, (y, x), connectivity=2 if eight else 1)
    assert np.array_equal(cells_after, np.where(region, 2, outlined))
    assert filled is not None and np.array_equal(filled, cells_after)


@pytest.mark.parametrize("add", [True, False])
@pytest.mark.parametrize("rule", list(POLYGON_RULES))
@pytest.mark.parametrize("seed", SEEDS)
def test_many_polygons(seed, rule, add):
    rng = np.random.default_rng(seed)
    width, height = 40, 30
    polygons = rng.uniform(-5, 45, (12, 1, 2)) + rng.uniform(-9, 9, (12, 6, 2))
    polygons[0] = 7.5  # a point: no edge meets a scan line
    options = {"edge_x": "x-low"} if seed % 2 else {}
    edges, _ = both(_edge_setup, *_vertices_of(polygons), sample_of(options))
    canvas = np.zeros((height, width), np.int32)
    _, after = both(_fill_polygons, *edges, POLYGON_RULES[rule], canvas, np.int32(1 if add else 5),
                    add)
    want = np.zeros_like(canvas)
    for polygon in polygons:  # the per-polygon numpy kernel
        pixels = scanline_pixels([[tuple(p) for p in polygon]], {**options, "fill_rule": rule})
        on = (pixels[:, 0] >= 0) & (pixels[:, 0] < width) & (pixels[:, 1] >= 0) \
            & (pixels[:, 1] < height)
        if add:
            want[pixels[on, 1], pixels[on, 0]] += 1
        else:
            want[pixels[on, 1], pixels[on, 0]] = 5
    assert np.array_equal(after[-3], want)


@pytest.mark.parametrize("add", [True, False])
@pytest.mark.parametrize("rule", list(TRIANGLE_RULES))
@pytest.mark.parametrize("seed", SEEDS)
def test_triangle_rows(seed, rule, add):
    rng = np.random.default_rng(seed)
    width, height = 40, 30
    points = np.round(rng.uniform(-5, 45, (30, 2)) * 256) / 256
    far = [(0.0, 0.0), (1e7, 0.0), (0.0, 1e7)]  # edge terms beyond int64: left to Python integers
    snapped = snap_array(np.concatenate([points, far]), 256).reshape(-1, 3, 2)
    canvas = np.zeros((height, width), np.int32)
    beyond = np.zeros(len(snapped), np.bool_)
    _, after = both(_fill_rows, snapped, 256, TRIANGLE_RULES[rule], False,
                    _largest_int64_reach(256), canvas, np.int32(1 if add else 5), add, beyond)
    counts = triangles.fill(points, (width, height), rule)  # the span kernel, numpy
    assert np.array_equal(after[5], counts if add else np.where(counts > 0, 5, 0))
    assert after[-1].tolist() == [False] * 10 + [True]
