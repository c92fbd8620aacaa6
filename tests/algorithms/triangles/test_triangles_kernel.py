"""The vectorised span kernel: same pixels as the generators, exact at any size."""
import numpy as np
import pytest

from algorithms import triangles
from test_triangles_cases import RULES, SUB, counts_of, oracle, plotted, spec

OPTIONS = {"subpixel_bits": 8, "fill_rule": "top-left", "cull": False}


def naive_counts(y, s, e, width, height):
    counts = np.zeros((height, width), np.int32)
    for row, start, end in zip(y, s, e):
        if 0 <= row < height:
            counts[row, max(0, start):max(0, min(width, end))] += 1
    return counts


@pytest.mark.parametrize("count, size", [(30, 20), (3000, 40), (400, 200)])
def test_counts_from_spans_every_path_agrees_with_slices(count, size):
    rng = np.random.default_rng(count)
    points = rng.integers(-SUB, (size + 1) * SUB, (3 * count, 2)) / SUB
    tris, _ = triangles.oriented(points, OPTIONS)
    _, y, s, e = triangles.span_arrays(tris, SUB, "top-left")
    got = triangles.counts_from_spans(y, s, e, size, size)
    assert np.array_equal(got, naive_counts(y, s, e, size, size))
    assert np.array_equal(triangles.fill(points, (size, size)), got)


@pytest.mark.parametrize("rule", RULES)
def test_triangles_beyond_int64_take_the_python_path_and_stay_exact(rule):
    # ~1e9 px: too large for the int64 edge bounds; ~3e13 px: its areas need Python integers too.
    window = (5, 5, 17, 15)
    for far in (1e9, 3e13):
        points = [(-far, -far / 3), (far / 2, 10.3), (11.25, far)]
        assert not triangles._fits_int64(triangles.prepare(points, {**OPTIONS, "fill_rule": rule})[0].tri.v, SUB)
        want = oracle(points, rule, window)
        got = triangles.kernel_pixels(points, {**OPTIONS, "fill_rule": rule}, window)
        assert counts_of(map(tuple, got.tolist())) == want
        assert counts_of(plotted("triangle-bbox", points, {"fill_rule": rule}, window)) == want
    assert want  # the window is inside the triangle's reach


def test_two_to_the_twenty_px_stays_on_the_int64_path():
    m = 2.0 ** 20
    tris = np.array([[[-m * SUB, -m * SUB], [m * SUB, -m * SUB + 7], [-m * SUB + 3, m * SUB]]],
                    dtype=np.int64)
    assert triangles._fits_int64_array(tris, SUB).all()
    points = [(-m, -m), (m, -m + 7 / SUB), (-m + 3 / SUB, m)]
    window = (-3, -3, 9, 9)
    for rule in RULES:
        got = triangles.kernel_pixels(points, {**OPTIONS, "fill_rule": rule}, window)
        assert counts_of(map(tuple, got.tolist())) == oracle(points, rule, window)


def test_the_kernel_without_a_grid_gives_the_whole_triangle():
    points = [(-3.3, -2.1), (9.7, 1.2), (2.5, 12.9)]
    whole = triangles.kernel_pixels(points, OPTIONS)
    assert counts_of(map(tuple, whole.tolist())) == oracle(points, "top-left", (-5, -5, 12, 14))


def test_coordinates_beyond_the_limit_are_input_errors():
    from algorithms.core.registry import InputError

    with pytest.raises(InputError):
        triangles.kernel_pixels([(0, 0), (2e15, 0), (0, 1)], OPTIONS, (8, 8))
    with pytest.raises(InputError):
        spec("triangle-bbox").record([(0, 0), (2e15, 0), (0, 1)], {})


def test_cull_and_degenerate_in_the_kernel():
    cw = [(1, 1), (1, 6), (6, 1)]
    flat = [(1, 1), (3, 3), (5, 5)]
    assert len(triangles.kernel_pixels(cw, {**OPTIONS, "cull": True}, (8, 8))) == 0
    assert len(triangles.kernel_pixels(cw, OPTIONS, (8, 8))) > 0
    assert len(triangles.kernel_pixels(flat, OPTIONS, (8, 8))) == 0


def test_backtrack_kernel_runs_top_down_in_the_walks_order():
    points = [(0.7, 0.2), (9.1, 3.3), (4.2, 8.8)]
    s = spec("triangle-backtrack")
    fast = [tuple(p) for p in s.kernel(points, s.resolve({}), (12, 10)).tolist()]
    assert fast == plotted("triangle-backtrack", points, {}, (12, 10))
    assert fast[0][1] > fast[-1][1]


def test_the_pineda_walk_has_no_kernel_but_the_same_pixels():
    points = [(0.7, 0.2), (9.1, 3.3), (4.2, 8.8)]
    assert spec("triangle-pineda").kernel is None
    assert sorted(plotted("triangle-pineda", points)) == sorted(plotted("triangle-bbox", points))
