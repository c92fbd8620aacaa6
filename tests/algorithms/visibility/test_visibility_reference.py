"""The visibility family against exact references, on the hard-case catalogue's
triangles (tests/algorithms/test_stability.py) and on random scenes.

* zbuffer: at each pixel the triangle kept is the one whose depth, exact
  barycentric interpolation at the centre rounded once to float64, passes
  the depth test against every fragment before it: the nearest, ties to the
  first drawn with ``less`` and to the last with ``less-equal``; nothing
  where no depth passes the clear depth (tests/support/visibility_oracles.py).
* painter: each pixel shows the last triangle, in the order sorted by the
  key (mean, min or max vertex depth, farthest first, ties in input order),
  whose coverage holds it.
* painter-split: its picture is the z-buffer's wherever the nearest
  triangle is clear of the others in depth and of every edge by more than a
  snap step (``check_split``).
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import triangles as exact_triangles
from algorithms.triangles.interpolate import unpack
from tests.support.catalogue import cases_of, recorded, TRIANGLES
from tests.support import record
from tests.support.raster_reference import triangle_pixels
from tests.support.visibility_oracles import (check_split, fragments, nearest_oracle,
                                              palette_colors, snapped)


def per_point(values, count):
    values = list(values)
    return values if len(values) == count else [values[k % 3] for k in range(count)]


def final_colors(trace):
    return trace.raster_at(len(trace) - 1).colors


# ------------------------------------------------------- the coverage reference
@pytest.mark.parametrize("rule, bits", [("top-left", 8), ("top-left", 0), ("inclusive", 8),
                                        ("strict", 4)])
def test_the_whole_number_coverage_is_the_exact_oracles(rule, bits):
    """tests/support/raster_reference.py against algorithms/exact/triangles.py."""
    for name, points in TRIANGLES.items():
        if name in ("beyond the limit", "huge coordinates"):
            continue
        for k in range(0, len(points), 3):
            tri = points[k:k + 3]
            want = exact_triangles.coverage(tri, bits, rule, (0, 0, 40, 32))
            assert triangle_pixels(tri, (40, 32), rule, bits) == set(want), (name, k)


# ------------------------------------------------------------------ z-buffer
def check_zbuffer(points, options, grid, trace):
    z = per_point(options.get("z") or (0.5,), len(points)) if options.get("z") else \
        [0.5] * len(points)
    clear = Fraction(options.get("clear_depth", 1.0))
    owner, depth = nearest_oracle(points, z, grid, options.get("depth_test", "less"), clear)
    raster = trace.raster_at(len(trace) - 1)
    assert np.array_equal(raster.colors, palette_colors(owner))
    kept = owner >= 0
    assert np.array_equal(raster.depth[kept], np.array([float(d) for d in depth[kept]]))
    assert trace.final_variables()["visible"] == kept.sum()


@pytest.mark.parametrize("case", cases_of("zbuffer"), ids=str)
def test_zbuffer_keeps_the_nearest_fragment_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_zbuffer(case.points, case.options, case.grid, trace)


# Vertices on the 1/8 px grid and depths in eighths: centres fall on edges
# and depths tie, where the fill rule and the depth test decide.
COORD = st.integers(0, 8 * 16).map(lambda v: v / 8)
EIGHTHS = st.integers(0, 8).map(lambda v: v / 8)
SCENE = st.integers(1, 4).flatmap(lambda k: st.tuples(
    st.lists(st.tuples(COORD, COORD), min_size=3 * k, max_size=3 * k),
    st.lists(EIGHTHS, min_size=3 * k, max_size=3 * k)))
SMALL = (16, 12)


@settings(max_examples=30, deadline=None)
@given(SCENE, st.sampled_from(["less", "less-equal"]), st.sampled_from([1.0, 0.5]))
def test_zbuffer_random_scenes_with_ties(scene, test, clear):
    points, z = scene
    options = {"z": tuple(z), "depth_test": test, "clear_depth": clear}
    check_zbuffer(points, options, SMALL, record("zbuffer", points, options, SMALL))


# ------------------------------------------------------------------- painter
KEYS = {"mean": lambda zs: sum(zs) / 3, "min": min, "max": max}


def painter_reference(points, z, grid, key):
    """The triangle each pixel shows: the last one drawn over it, back to front."""
    zs = [[Fraction(v) for v in z[3 * k:3 * k + 3]] for k in range(len(points) // 3)]
    order = sorted(range(len(zs)), key=lambda k: -KEYS[key](zs[k]))  # stable: ties in input order
    covered = fragments(points, z, grid)
    owner = np.full((grid[1], grid[0]), -1)
    for k in order:
        for i, j in covered[k]:
            owner[j, i] = k
    return owner


def gouraud(points, colors, owner):
    """Per pixel, the owner's vertex colours mixed by its exact barycentric weights
    (channels unrounded), None where no triangle shows."""
    colors = [unpack(c) for c in per_point(colors, len(points))]
    result = {}
    for (j, i), k in np.ndenumerate(owner):
        if k >= 0:
            tri = [snapped(p) for p in points[3 * k:3 * k + 3]]
            weights = exact_triangles.barycentric(tri, exact_triangles.centre(i, j))
            result[(i, j)] = [sum(w * c[n] for w, c in zip(weights, colors[3 * k:3 * k + 3]))
                              for n in range(3)]
    return result


def check_painter(points, options, grid, trace):
    z = per_point(options["z"], len(points)) if options.get("z") else [0.5] * len(points)
    owner = painter_reference(points, z, grid, options.get("sort", "mean"))
    got = final_colors(trace)
    if not options.get("colors"):
        assert np.array_equal(got, palette_colors(owner))
        return
    assert np.array_equal(got >= 0, owner >= 0)
    for (i, j), channels in gouraud(points, options["colors"], owner).items():
        # rounded to whole channels: within 1/2 of the exact mix, plus float rounding
        assert all(abs((int(got[j, i]) >> shift & 255) - float(c)) <= 0.5 + 1e-9
                   for shift, c in zip((16, 8, 0), channels)), (i, j)


@pytest.mark.parametrize("case", cases_of("painter"), ids=str)
def test_painter_shows_the_last_triangle_drawn_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_painter(case.points, case.options, case.grid, trace)


@settings(max_examples=30, deadline=None)
@given(SCENE, st.sampled_from(sorted(KEYS)))
def test_painter_random_scenes(scene, key):
    points, z = scene
    options = {"z": tuple(z), "sort": key}
    check_painter(points, options, SMALL, record("painter", points, options, SMALL))


# ------------------------------------------------------------- painter-split
@pytest.mark.parametrize("case", cases_of("painter-split"), ids=str)
def test_painter_split_equals_the_nearest_triangle_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        z = per_point(case.options["z"], len(case.points)) if case.options.get("z") else \
            [0.5] * len(case.points)
        check_split(case.points, z, case.grid, trace)
