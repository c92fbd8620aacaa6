"""The pipeline family against references written here, on the hard-case
catalogue's triangles and options (tests/algorithms/test_stability.py) and
on random scenes.

* blend-over: per pixel, the fragments of the triangles in the documented
  drawing order (input, or by exact mean depth, stable), each with z, alpha
  and colour interpolated exactly at the centre and rounded once, tested
  z < ZB and composited CB = alpha src + (1 - alpha) CB over white; depth
  written by the depth_write rule. The fragments are the pixel centres the
  snapped triangle covers (tests/support/raster_reference.py).
* pipeline: the camera of OpenGL's lookAt and perspective written again
  here; a triangle whose corners all lie strictly inside the clipped volume
  (no plane cuts it) must give exactly the fragments of its projected,
  snapped triangle, with depth the window z interpolated linearly on the
  screen (to 1e-9); one that a plane cuts must give the projected
  triangle's pixels within the grid, but for centres within 1/128 px of an
  edge (the cut corners snap to 1/256 px). Shading is held to its formulas
  in tests/algorithms/test_pipeline_stages.py.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.core.steps import Vars
from algorithms.exact import triangles as exact_triangles
from algorithms.triangles.interpolate import unpack
from algorithms.visibility.zbuffer_painter import PALETTE
from tests.support.catalogue import cases_of, recorded
from tests.support import record
from tests.support.raster_reference import triangle_pixels


def per_point(values, count):
    values = list(values)
    return values if len(values) == count else [values[k % 3] for k in range(count)]


def snapped(points):
    return [tuple(exact_triangles.snap(v, 8) for v in p) for p in points]


# ============================================================== blend-over
def blend_reference(points, options, grid):
    """The final colour buffer, (H, W, 3) floats, white where nothing is drawn."""
    count = len(points)
    z = per_point(options.get("z") or (0.5,) * 3, count)
    alpha = per_point(options.get("alpha", (0.5, 0.5, 0.5)), count)
    colors = [unpack(c) for c in per_point(options["colors"], count)] if options.get("colors") \
        else [unpack(PALETTE[(k // 3) % len(PALETTE)]) for k in range(count)]
    triangles = [k for k in range(count // 3)
                 if exact_triangles.twice_area(snapped(points[3 * k:3 * k + 3]))]
    means = {k: sum(Fraction(v) for v in z[3 * k:3 * k + 3]) / 3 for k in triangles}
    order = options.get("order", "input")
    if order != "input":
        triangles.sort(key=lambda k: -means[k] if order == "back-to-front" else means[k])
    image = np.full((grid[1], grid[0], 3), 255.0)
    depth = np.full((grid[1], grid[0]), math.inf)
    write = options.get("depth_write", "opaque")
    for k in triangles:
        tri = snapped(points[3 * k:3 * k + 3])
        for i, j in sorted(triangle_pixels(points[3 * k:3 * k + 3], grid), key=lambda p: p[::-1]):
            b = exact_triangles.barycentric(tri, exact_triangles.centre(i, j))

            def mixed(values):
                return float(sum(bk * Fraction(v) for bk, v in zip(b, values)))
            fz, fa = mixed(z[3 * k:3 * k + 3]), mixed(alpha[3 * k:3 * k + 3])
            if not fz < depth[j, i]:
                continue
            src = [mixed([c[n] for c in colors[3 * k:3 * k + 3]]) for n in range(3)]
            image[j, i] = [fa * s + (1 - fa) * d for s, d in zip(src, image[j, i])]
            if write == "all" or (write == "opaque" and fa == 1):
                depth[j, i] = fz
    return image


def check_blend(points, options, grid, trace):
    want = blend_reference(points, options, grid)
    got = trace.raster_at(len(trace) - 1).colors
    drawn = got >= 0
    channels = np.stack([(got >> 16) & 255, (got >> 8) & 255, got & 255], axis=2)
    # Whole channels, rounded: within 1/2 of the composite.
    assert np.all(np.abs(channels[drawn] - want[drawn]) <= 0.5 + 1e-9)
    assert np.all(want[~drawn] == 255.0)


@pytest.mark.parametrize("case", cases_of("blend-over"), ids=str)
def test_blend_over_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_blend(case.points, case.options, case.grid, trace)


COORD = st.integers(0, 8 * 14).map(lambda v: v / 8)
EIGHTHS = st.integers(0, 8).map(lambda v: v / 8)
SMALL = (14, 12)


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 3).flatmap(lambda k: st.tuples(
           st.lists(st.tuples(COORD, COORD), min_size=3 * k, max_size=3 * k),
           st.lists(EIGHTHS, min_size=3 * k, max_size=3 * k),
           st.lists(st.sampled_from([0.0, 0.25, 0.5, 1.0]), min_size=3 * k, max_size=3 * k))),
       st.sampled_from(["input", "back-to-front", "front-to-back"]),
       st.sampled_from(["opaque", "all", "none"]), st.booleans())
def test_blend_over_random_scenes(scene, order, write, colored):
    points, z, alpha = scene
    options = {"z": tuple(z), "alpha": tuple(alpha), "order": order, "depth_write": write}
    if colored:
        options["colors"] = ("#ff0000", "#00ff80", "#2040c0")
    check_blend(points, options, SMALL, record("blend-over", points, options, SMALL))


# ================================================================ pipeline
CAMERA = {"eye": (16.0, 12.0, 40.0), "target": (16.0, 12.0, 0.0), "fov": 40.0, "near": 1.0,
          "far": 100.0, "clipping": "all"}


def unit(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def project(point, options, grid):
    """World (x, y, z) to clip (x, y, z, w): lookAt, then the perspective matrix."""
    eye, target = options["eye"], options["target"]
    forward = unit([t - e for t, e in zip(target, eye)])
    side = unit(cross(forward, [0.0, 1.0, 0.0]))
    up = cross(side, forward)
    d = [p - e for p, e in zip(point, eye)]
    x, y, z = (sum(a * b for a, b in zip(d, side)), sum(a * b for a, b in zip(d, up)),
               -sum(a * b for a, b in zip(d, forward)))
    f = 1 / math.tan(math.radians(options["fov"]) / 2)
    n, far = options["near"], options["far"]
    return [f / (grid[0] / grid[1]) * x, f * y, (far + n) / (n - far) * z + 2 * far * n / (n - far),
            -z]


def fragments_by_triangle(trace):
    """{triangle number (from 0): [(pixel, depth)]} of every fragment, passing or not."""
    starts = [(i, r.values["triangle"] - 1) for i, r in trace.records_of(Vars)
              if "triangle" in r.values]
    bounds = [i for i, _ in starts[1:]] + [len(trace)]
    depth = trace.series("depth")
    found = {}
    for (lo, k), hi in zip(starts, bounds):
        steps = np.flatnonzero(~np.isnan(depth[lo:hi])) + lo
        found[k] = [((int(trace.x[i]), int(trace.y[i])), float(depth[i])) for i in steps]
    return found


def near_an_edge(tri, point, margin=Fraction(1, 128)) -> bool:
    for k in range(3):
        (ax, ay), (bx, by) = tri[k], tri[(k + 1) % 3]
        side = (bx - ax) * (point[1] - ay) - (by - ay) * (point[0] - ax)
        if side * side <= margin * margin * ((bx - ax) ** 2 + (by - ay) ** 2):
            return True
    return False


def outside(clip, planes) -> bool:
    """Is some corner on or beyond one of the planes (names as in space.PLANES)?"""
    distance = {"near": lambda c: c[3] + c[2], "far": lambda c: c[3] - c[2],
                "left": lambda c: c[3] + c[0], "right": lambda c: c[3] - c[0],
                "bottom": lambda c: c[3] + c[1], "top": lambda c: c[3] - c[1]}
    return any(distance[plane](c) <= 0 for plane in planes for c in clip)


def check_pipeline(points, options, grid, trace):
    options = {**CAMERA, **options}
    z = per_point(options.get("z") or (0.0,) * 3, len(points))
    clipping = options["clipping"]
    depth_planes = {"all": ("near", "far"), "near": ("near",), "none": ()}[clipping]
    screen_planes = ("left", "right", "bottom", "top") if clipping == "all" else ()
    got = fragments_by_triangle(trace)
    checked = 0
    for k in range(len(points) // 3):
        clip = [project((*points[3 * k + n], z[3 * k + n]), options, grid) for n in range(3)]
        if any(c[3] <= 0 for c in clip):
            continue  # behind the eye: no triangle on the screen to compare with
        window = [((c[0] / c[3] + 1) * grid[0] / 2, (c[1] / c[3] + 1) * grid[1] / 2,
                   (c[2] / c[3] + 1) / 2) for c in clip]
        tri = snapped([p[:2] for p in window])
        want = triangle_pixels([p[:2] for p in window], grid)
        fragments = got.get(k, [])
        pixels = {p for p, _ in fragments}
        clear = {p for p in want | pixels if not near_an_edge(tri, exact_triangles.centre(*p))}
        if outside(clip, depth_planes):
            # Cut in depth: part of the screen triangle goes, nothing is added.
            assert pixels & clear <= want, k
        elif outside(clip, screen_planes):
            # Cut by the sides of the view: the grid's border, where no centre lies.
            assert want & clear == pixels & clear, k
        else:
            assert sorted(pixels) == sorted(want) and len(fragments) == len(want), k
            for (i, j), depth in fragments:
                b = exact_triangles.barycentric(tri, exact_triangles.centre(i, j))
                exact = sum(bk * Fraction(corner[2]) for bk, corner in zip(b, window))
                assert depth == pytest.approx(float(exact), abs=1e-9), (k, i, j)
        checked += len(clear)
    return checked


@pytest.mark.parametrize("case", cases_of("pipeline"), ids=str)
def test_pipeline_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_pipeline(case.points, case.options, case.grid, trace)


WORLD = st.integers(-40, 72).map(lambda v: v / 2)


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(WORLD, WORLD), min_size=3, max_size=6).filter(lambda p: len(p) % 3 == 0),
       st.lists(st.integers(-70, 45).map(float), min_size=3, max_size=3),
       st.sampled_from(["all", "near"]))
def test_pipeline_random_triangles(points, z, clipping):
    options = {"z": tuple(z), "clipping": clipping}
    grid = (32, 24)
    check_pipeline(points, options, grid, record("pipeline", points, options, grid))
