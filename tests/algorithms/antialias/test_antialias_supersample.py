"""Supersampling: error against the exact coverage, patterns, filters, generator == kernel."""
import json
from fractions import Fraction

import numpy as np
import pytest

from algorithms import antialias as aa
from algorithms.exact import coverage as ec
from algorithms import triangles
from algorithms.core.registry import get
from app.cli import main
from tests.support.trace_oracle import slow_replay

GRID = (40, 32)


def lattice_triangles(seed, count, grid=GRID, margin=2):
    """Random triangles with vertices on the 1/256 px grid (no snapping error)."""
    rng = np.random.default_rng(seed)
    result = []
    for _ in range(count):
        pts = np.round(rng.uniform(margin, min(grid) - margin, (3, 2)) * 256) / 256
        result.append([tuple(map(float, p)) for p in pts])
    return result


TRIANGLES = lattice_triangles(5, 8)


def edge_rms(pattern, n, tris=TRIANGLES, name="box"):
    errors = []
    for tri in tris:
        cov, _ = aa.supersample_image(tri, {"pattern": pattern, "n": n, "filter": name, "seed": 3},
                                      GRID, colors=False)
        exact = ec.triangle_coverage(tri, GRID)
        edge = (exact > 0) & (exact < 1)
        errors.append((cov - exact)[edge])
    errors = np.concatenate(errors)
    return float(np.sqrt(np.mean(errors ** 2)))


# Measured RMS at n = 4 on these triangles: grid 0.026, rotated-grid 0.033,
# jitter 0.045, random 0.088. The bounds leave room, not slack.
BOUNDS_AT_4 = {"grid": 0.04, "rotated-grid": 0.05, "jitter": 0.065, "random": 0.12}


@pytest.mark.parametrize("pattern", aa.PATTERNS)
def test_error_falls_with_the_sample_count(pattern):
    rms = [edge_rms(pattern, n) for n in (1, 2, 4, 8)]
    assert rms[0] > rms[1] > rms[2] > rms[3], rms
    assert rms[2] < BOUNDS_AT_4[pattern], rms
    assert rms[3] < rms[0] / 4


def test_one_centre_sample_is_the_aliased_fill():
    tris = lattice_triangles(11, 6) + [[(1.5, 2.0), (20.0, 3.25), (8.0, 17.0)]]
    for tri in tris:
        cov, _ = aa.supersample_image(tri, {"pattern": "grid", "n": 1, "filter": "box"}, GRID)
        fill = triangles.fill(tri, GRID) > 0
        assert np.array_equal(cov, fill.astype(float))
    # several triangles at once, shared edges included: the union of the fills
    mesh = [(2, 2), (12, 2), (12, 12), (2, 2), (12, 12), (2, 12), (12, 2), (20.5, 7.25), (12, 12)]
    cov, _ = aa.supersample_image(mesh, {"n": 1}, GRID)
    assert np.array_equal(cov, (triangles.fill(mesh, GRID) > 0).astype(float))
    # real vertices snap like the triangle family's
    odd = [(3.1234, 2.9876), (30.777, 5.5001), (9.3333, 27.6666)]
    cov, _ = aa.supersample_image(odd, {"n": 1}, GRID)
    assert np.array_equal(cov, (triangles.fill(odd, GRID) > 0).astype(float))


@pytest.mark.parametrize("pattern", aa.PATTERNS)
@pytest.mark.parametrize("name", aa.FILTERS)
@pytest.mark.parametrize("n", [1, 3, 4])
def test_filter_weights_add_up_to_one(pattern, name, n):
    for x, y in [(0, 0), (5, 7), (70, 3)]:
        weights = aa.normalised_weights(pattern, n, name, sigma=0.4, seed=9, x=x, y=y)
        assert len(weights) == n * n
        assert sum(weights) == 1
        assert all(w > 0 for w in weights)


def test_weighted_filter_on_the_4x4_grid_is_the_classic_kernel():
    kx, ky, big = aa.sample_strata("grid", 4, 0, 0, np.array([0]))
    w = aa.sample_weights(kx[0], ky[0], big, "weighted").reshape(4, 4)
    classic = np.array([[1, 2, 2, 1], [2, 3, 3, 2], [2, 3, 3, 2], [1, 2, 2, 1]])
    assert np.array_equal(w, 2 * classic)
    # and in general 1 + d_i + d_j
    kx, ky, big = aa.sample_strata("grid", 5, 0, 0, np.array([0]))
    w = aa.sample_weights(kx[0], ky[0], big, "weighted").reshape(5, 5)
    d = np.minimum(np.arange(5), 4 - np.arange(5))
    assert np.array_equal(w, 2 * (1 + d[:, None] + d[None, :]))


def test_sample_positions():
    kx, ky, big = aa.sample_strata("grid", 1, 0, 0, np.array([0]))
    assert aa.lattice(kx, big)[0, 0] == 256 and aa.lattice(ky, big)[0, 0] == 256  # the centre
    kx, ky, big = aa.sample_strata("rotated-grid", 2, 0, 0, np.array([0]))
    positions = sorted(zip(aa.lattice(kx, big)[0] / 512, aa.lattice(ky, big)[0] / 512))
    assert positions == [(0.125, 0.375), (0.375, 0.875), (0.625, 0.125), (0.875, 0.625)]
    for n in range(1, 9):  # n-rooks: one sample in every row and column of n^2 strata
        kx, ky, big = aa.sample_strata("rotated-grid", n, 0, 0, np.array([0]))
        assert sorted(kx[0]) == list(range(n * n)) == sorted(ky[0])
        kx, ky, big = aa.sample_strata("jitter", n, 4, 2, np.arange(3))
        cells = set(zip((kx * n // big).ravel().tolist(), (ky * n // big).ravel().tolist()))
        assert len(cells) == n * n  # stratified: one sample per cell (in each pixel)


def test_jitter_and_random_are_reproducible_with_a_seed():
    tri = TRIANGLES[0]
    for pattern in ("jitter", "random"):
        a, _ = aa.supersample_image(tri, {"pattern": pattern, "n": 3, "seed": 42}, GRID)
        b, _ = aa.supersample_image(tri, {"pattern": pattern, "n": 3, "seed": 42}, GRID)
        c, _ = aa.supersample_image(tri, {"pattern": pattern, "n": 3, "seed": 43}, GRID)
        assert np.array_equal(a, b) and not np.array_equal(a, c)
        # a pixel's samples do not depend on the grid around it
        big, _ = aa.supersample_image(tri, {"pattern": pattern, "n": 3, "seed": 42}, (200, 90))
        assert np.array_equal(big[:GRID[1], :GRID[0]], a)


KERNEL_CASES = [
    ("triangles", [(1.5, 2.0), (20.0, 3.25), (8.0, 17.0), (6, 5), (25, 14), (3, 19)],
     {"colors": ("#ff0000", "#0000ff")}),
    ("polygon", [(3, 3), (30, 5), (8, 25), (20, 27), (28, 2.5)], {"fill_rule": "evenodd"}),
    ("polygon", [(3, 3), (30, 5), (8, 25), (20, 27), (28, 2.5)], {"fill_rule": "nonzero"}),
    ("thick-line", [(2.5, 3), (30, 20.5), (4, 25), (26, 4)], {"width": 2.5, "caps": "square",
                                                              "colors": ("#00ff00", "#ff00ff")}),
]


@pytest.mark.parametrize("pattern", aa.PATTERNS)
@pytest.mark.parametrize("case", range(len(KERNEL_CASES)))
def test_generator_equals_kernel(pattern, case):
    shape, points, extra = KERNEL_CASES[case]
    options = {"shape": shape, "pattern": pattern, "n": 3, "seed": 5,
               "filter": aa.FILTERS[case % 4], **extra}
    coverage, rgb = aa.supersample_image(points, options, (32, 30))
    trace = get("aa-supersample").record(points, options, grid=(32, 30))
    pixels = trace.written_pixels()
    values = trace.pixel_values()
    got = np.zeros_like(coverage)
    got[pixels[:, 1], pixels[:, 0]] = values
    assert np.array_equal(got, coverage)
    raster = trace.raster_at(len(trace) - 1)
    written = raster.counts > 0
    assert np.array_equal(written, coverage > 0)
    assert np.array_equal(raster.colors[written], rgb[written])
    assert trace.final_variables()["area"] == pytest.approx(coverage.sum(), rel=1e-12)


def test_frames_show_every_sample_with_its_position_and_verdict():
    options = {"pattern": "jitter", "n": 2, "seed": 1}
    tri = [(1.5, 1.5), (6.5, 1.5), (1.5, 6.5)]
    trace = get("aa-supersample").record(tri, options, grid=(8, 8))
    sx, sy, hit = trace.series("sx"), trace.series("sy"), trace.series("hit")
    samples = ~np.isnan(sx)
    pixel_frames = np.isin(trace.line, [5, 6])  # write, or nothing to write
    assert samples.sum() == 4 * pixel_frames.sum() > 0
    for i in np.flatnonzero(samples):
        step = trace.step(i)
        x, y = step.pixel
        assert x <= sx[i] < x + 1 and y <= sy[i] < y + 1
        assert step.branch == ("hit" if hit[i] == 1 else "miss")
        inside = aa.Shapes(tri, {"shape": "triangles"}).owner(int(sx[i] * 512), int(sy[i] * 512))
        assert (inside >= 0) == (hit[i] == 1)


def test_state_at_equals_slow_replay_on_a_supersample_trace(small_keyframes):
    small_keyframes(5)
    trace = get("aa-supersample").record([(1.5, 2.0), (12.0, 3.25), (5.0, 10.0)],
                                         {"n": 2, "pattern": "random", "colors": ("#3366cc",)},
                                         grid=(14, 12))
    assert len(trace._ensure_keyframes()) > 3
    for i in range(0, len(trace), 3):
        fast, slow = trace.state_at(i).raster, slow_replay(trace, i)
        assert np.array_equal(fast.counts, slow.counts)
        assert np.array_equal(fast.colors, slow.colors)
        assert fast.depth is None and slow.depth is None


def test_polygon_and_thick_line_estimates_approach_the_exact_coverage():
    for shape, points, extra in KERNEL_CASES[1:]:
        options = {"shape": shape, **extra}
        exact = aa.reference_coverage(points, options, (32, 30))
        errors = []
        for n in (2, 8):
            cov, _ = aa.supersample_image(points, {**options, "n": n}, (32, 30), colors=False)
            errors.append(np.abs(cov - exact).max())
        assert errors[1] < errors[0] and errors[1] <= 1 / 8 + 1e-12, (shape, errors)


def test_grey_is_the_coverage_and_colours_blend_with_white():
    tri = [(1.5, 1.5), (9.25, 2.0), (3.0, 9.5)]
    cov, rgb = aa.supersample_image(tri, {"n": 4}, (12, 12))
    grey = rgb & 0xFF
    assert np.array_equal(grey, np.floor(255 * (1 - cov) + 0.5).astype(int))
    assert np.all((rgb >> 16) == grey) and np.all(((rgb >> 8) & 0xFF) == grey)
    _, red = aa.supersample_image(tri, {"n": 4, "colors": ("#ff0000",)}, (12, 12))
    assert np.all((red >> 16) == 255)
    assert np.array_equal(red & 0xFF, grey)


def test_command_line_values_are_coverages(capsys):
    status = main(["run", "aa-supersample", "--points", "1.5,2", "20,3.25", "8,17",
                   "--set", "pattern=jitter", "--set", "n=4", "--set", "seed=7", "--json"])
    out, err = capsys.readouterr()
    assert status == 0, err
    result = json.loads(out)
    values = result["values"]
    assert len(values) == len(result["pixels"]) and all(0 < v <= 1 for v in values)
    cov, _ = aa.supersample_image([(1.5, 2), (20, 3.25), (8, 17)],
                                  {"pattern": "jitter", "n": 4, "seed": 7}, tuple(result["grid"]))
    for (x, y), v in zip(result["pixels"], values):
        assert v == cov[y, x]
    assert all(Fraction(v).limit_denominator(16) == Fraction(v) for v in values)  # k / 16


@pytest.mark.parametrize("argv, words", [
    (["--points", "1,1", "5,1", "1,5", "2,2"], "multiple of 3"),
    (["--points", "1,1", "5,1", "--set", "shape=polygon"], "at least 3"),
    (["--points", "1,1", "5,1", "1,5", "--set", "shape=thick-line"], "2 points per segment"),
    (["--points", "1,1", "5,1", "1,5", "--set", "n=9"], "above the maximum"),
    (["--points", "1,1", "5,1", "1,5", "--set", "pattern=poisson"], "expected one of"),
])
def test_bad_input_exits_with_one_line(capsys, argv, words):
    status = main(["run", "aa-supersample", *argv])
    out, err = capsys.readouterr()
    assert status == 2 and words in err and err.count("\n") == 1
