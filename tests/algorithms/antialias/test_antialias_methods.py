"""Adaptive supersampling, post-filtering and temporal antialiasing; the command line."""
import json

import numpy as np
import pytest

from algorithms import antialias as aa
from algorithms.exact import coverage as ec
from algorithms import triangles
from algorithms.core.registry import get
from app.cli import main

TRI = [(1.5, 2.0), (20.0, 3.25), (8.0, 17.0)]
GRID = (24, 20)


# ------------------------------------------------------------- adaptive
def test_adaptive_spends_five_samples_on_whole_pixels_and_more_on_edges():
    coverage, spent = aa.adaptive_image(TRI, {"max_depth": 3}, GRID)
    exact = ec.triangle_coverage(TRI, GRID)
    inside = exact == 1
    assert np.all(spent[inside & (coverage == 1)] == 5)
    edge = (exact > 0) & (exact < 1)
    assert spent[edge].mean() > 10
    assert spent.max() <= (2 ** 3 + 1) ** 2 + 4 ** 3  # corners and centres of the finest squares
    trace = get("aa-adaptive").record(TRI, {"max_depth": 3}, grid=GRID)
    assert trace.final_variables()["samples"] == spent.sum()


def test_adaptive_error_falls_with_depth():
    exact = ec.triangle_coverage(TRI, GRID)
    edge = (exact > 0) & (exact < 1)
    errors = []
    for depth in (0, 2, 4):
        coverage, _ = aa.adaptive_image(TRI, {"max_depth": depth}, GRID)
        errors.append(np.sqrt(np.mean((coverage - exact)[edge] ** 2)))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 0.05


def test_adaptive_depth_zero_is_five_samples():
    coverage, spent = aa.adaptive_image(TRI, {"max_depth": 0}, GRID)
    assert set(np.unique(spent)) <= {0, 5}
    assert set(np.round(np.unique(coverage) * 5, 9)) <= {0, 1, 2, 3, 4, 5}


def test_adaptive_frames_test_each_point_once_per_pixel():
    trace = get("aa-adaptive").record([(1.25, 1.5), (6.5, 2.0), (2.0, 6.75)],
                                      {"max_depth": 2}, grid=(8, 8))
    seen = {}
    for i in np.flatnonzero(~np.isnan(trace.series("sx"))):
        step = trace.step(i)
        key = (step.pixel, step.values["sx"], step.values["sy"])
        assert key not in seen
        seen[key] = step.values["hit"]
        assert step.branch in ("hit", "miss")


# ---------------------------------------------------------- post-filter
def test_kernels():
    seed = aa.filter_kernel("seed")
    assert seed.sum() == 36 and seed[1, 1] == 16 and seed[0, 0] == 1 and seed[0, 1] == 4
    assert aa.filter_kernel("box3").sum() == 9
    g = aa.filter_kernel("gaussian", 1.0)
    assert g.shape == (7, 7) and np.array_equal(g, g.T) and np.array_equal(g, g[::-1])
    assert g[3, 3] == g.max() == 65536


@pytest.mark.parametrize("kernel", aa.KERNELS)
def test_filter_generator_equals_the_vectorised_filter(kernel):
    options = {"kernel": kernel, "sigma": 0.7}
    image = aa.filter_image(TRI, options, GRID)
    trace = get("aa-filter").record(TRI, options, grid=GRID)
    raster = trace.raster_at(len(trace) - 1)
    pixels, values = trace.written_pixels(), trace.pixel_values()
    last = {}
    for (x, y), v in zip(pixels.tolist(), values):
        last[(x, y)] = v
    got = np.zeros_like(image)
    for (x, y), v in last.items():
        got[y, x] = v
    assert np.array_equal(got, image)
    assert np.array_equal(raster.counts > 0, image > 0)
    # the aliased fill first: every covered centre written with 1
    aliased = triangles.fill(TRI, GRID) > 0
    first = pixels[:int(aliased.sum())]
    assert np.all(aliased[first[:, 1], first[:, 0]]) and np.all(values[:len(first)] == 1)


@pytest.mark.parametrize("kernel", aa.KERNELS)
def test_filtering_keeps_the_total_and_smooths(kernel):
    inner = [(5.5, 4.0), (20.0, 5.25), (10.0, 16.0)]  # the kernel stays within the grid
    image = aa.filter_image(inner, {"kernel": kernel}, GRID)
    aliased = aa.aliased_image(inner, {}, GRID)
    assert image.sum() == pytest.approx(aliased.sum(), rel=1e-12)  # nothing reaches the border
    assert image.max() == 1.0  # deep inside, the weights add up to 1
    assert ((image > 0) & (image < 1)).sum() > ((aliased > 0) & (aliased < 1)).sum()


def test_filtered_error_against_exact_coverage():
    exact = ec.triangle_coverage(TRI, GRID)
    aliased = aa.aliased_image(TRI, {}, GRID).astype(float)
    filtered = aa.filter_image(TRI, {"kernel": "seed"}, GRID)
    edge = (exact > 0) & (exact < 1)
    rms = lambda a: np.sqrt(np.mean((a - exact)[edge] ** 2))  # noqa: E731
    assert rms(filtered) < rms(aliased)


# ------------------------------------------------------------- temporal
WHEEL = [(12.0, 12.0)]


def test_a_wheel_turning_by_its_symmetry_looks_still():
    frames = aa.temporal_frames(WHEEL, {"speed": 90, "spokes": 4, "frames": 5}, GRID)
    assert len(frames) == 5 and frames[0].shape == (GRID[1], GRID[0])
    assert all(np.array_equal(f, frames[0]) for f in frames)
    assert aa.apparent_speed(WHEEL, {**_temporal(), "speed": 90}) == 0


def test_wagon_wheel_seems_to_turn_backwards():
    forward = aa.temporal_frames(WHEEL, {"speed": 80, "frames": 4}, GRID)
    backward = aa.temporal_frames(WHEEL, {"speed": -10, "frames": 4}, GRID)
    for a, b in zip(forward, backward):
        assert np.abs(a - b).max() <= 0.25  # the same picture (spoke angles equal mod 90)
        assert np.abs(a - b).sum() < 0.5
    assert aa.apparent_speed(WHEEL, {**_temporal(), "speed": 80}) == -10
    assert not np.array_equal(forward[0], forward[1])


def test_motion_blur_smears_the_spokes():
    sharp = aa.temporal_frames(WHEEL, {"speed": 30, "frames": 2}, GRID)[1]
    blurred = aa.temporal_frames(WHEEL, {"speed": 30, "frames": 2, "mode": "motion-blur",
                                         "time_samples": 16}, GRID)[1]
    assert (blurred > 0).sum() > (sharp > 0).sum()
    assert blurred.max() <= sharp.max()
    assert blurred.sum() == pytest.approx(sharp.sum(), rel=0.2)


def test_a_moving_triangle_moves_whole_pixels():
    tri = [(1.5, 2.0), (7.0, 3.0), (3.0, 8.5)]
    frames = aa.temporal_frames(tri, {"motion": "move", "speed": 2, "frames": 3}, GRID)
    assert np.array_equal(frames[2][:, 4:], frames[0][:, :-4])
    assert np.all(frames[2][:, :4] == 0)


def test_temporal_generator_rows_are_the_frames():
    options = {"speed": 80, "frames": 3, "mode": "motion-blur", "time_samples": 4}
    frames = aa.temporal_frames(WHEEL, options, GRID)
    trace = get("aa-temporal").record(WHEEL, options, grid=GRID)
    frame_column = trace.series("frame")
    coverage = trace.series("coverage")
    images = [np.zeros(frames[0].shape) for _ in frames]
    for i in np.flatnonzero(~np.isnan(frame_column)):
        x, y = trace.step(i).pixel
        images[int(frame_column[i])][y, x] = coverage[i]
    for got, want in zip(images, frames):
        assert np.array_equal(got, want)
    # the grid at the end of frame k shows image k
    frame_line = aa.temporal_code(WHEEL, options).at["frames"]
    ends = [i for i in range(len(trace)) if trace.step(i).record is not None
            and trace.step(i).line == frame_line][1:] + [len(trace) - 1]
    for k, end in enumerate(ends):
        raster = trace.raster_at(end - 1 if k < len(ends) - 1 else end)
        grey = raster.colors & 0xFF
        shown = raster.colors >= 0
        want = np.floor(255 * (1 - frames[k]) + 0.5)
        assert np.array_equal(grey[shown], want[shown])
        assert np.all(frames[k][~shown] == 0)


def _temporal():
    return {o.name: o.default for o in aa.TEMPORAL_OPTIONS}


# --------------------------------------------------------- command line
@pytest.mark.parametrize("argv", [
    ["aa-adaptive", "--points", "1.5,2", "20,3.25", "8,17", "--set", "max_depth=2"],
    ["aa-filter", "--points", "1.5,2", "20,3.25", "8,17", "--set", "kernel=gaussian",
     "--set", "sigma=1"],
    ["line-wu", "--points", "2,3", "17,9"],
    ["line-area", "--points", "2,3", "7,19", "--set", "width=2"],
    ["aa-temporal", "--points", "12,12", "--set", "frames=3", "--set", "mode=motion-blur"],
    ["aa-supersample", "--points", "3,3", "20,5", "8,17", "15,18", "--set", "shape=polygon"],
    ["aa-supersample", "--points", "3,3", "20,15", "--set", "shape=thick-line",
     "--set", "width=3"],
])
def test_every_antialiasing_run_prints_coverages(capsys, argv):
    status = main(["run", *argv, "--json"])
    out, err = capsys.readouterr()
    assert status == 0, err
    result = json.loads(out)
    assert len(result["values"]) == len(result["pixels"]) > 0
    assert all(isinstance(v, float) and 0 <= v <= 1 for v in result["values"])


@pytest.mark.parametrize("argv, words", [
    (["aa-temporal", "--points", "1,1", "5,5"], "expected 1 point (a wheel's centre) or 3"),
    (["aa-temporal", "--points", "1,1", "--set", "primitive=triangle"], "expected 3 points"),
    (["line-wu", "--points", "1.5,1", "5,5"], "whole pixel"),
    (["aa-filter", "--points", "1,1", "5,5"], "multiple of 3"),
    (["aa-adaptive", "--points", "1,1", "5,1", "1,5", "--set", "max_depth=9"], "maximum"),
])
def test_bad_input_exits_with_one_line(capsys, argv, words):
    status = main(["run", *argv])
    out, err = capsys.readouterr()
    assert status == 2 and words in err and err.count("\n") == 1
