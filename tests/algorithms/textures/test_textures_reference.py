"""triangle-texture against an exact reference, on the hard-case catalogue's
triangles and options (tests/algorithms/test_stability.py) and on random
triangles.

The reference, per covered pixel, from the definitions in
algorithms/textures/: the pixels are those whose centres the snapped
triangle covers under the fill rule (tests/support/raster_reference.py);
u and v at the centre are the perspective-correct interpolation of the
vertices' uv, sum b_k u_k / w_k / sum b_k / w_k with the exact barycentric
weights b_k of the snapped triangle (w = 1 with perspective off), in
fractions; the colour of ``nearest`` is the texel holding (u W, v H) and
that of ``bilinear`` the four texels around (u W - 1/2, v H - 1/2) weighted
by the exact fractions, wrapped as the option says, rounded to whole
channels. The texels are the texture's own (checked in
tests/algorithms/test_textures_filters.py).

The mip-mapped and anisotropic filters have no exact reference here: their
colour is a blend the level of detail picks from floats (lambda = log2 rho),
held to bounds against the reference average in test_textures_filters.py;
for them this module checks the pixels and u, v only.
"""
from __future__ import annotations

import math
from collections import Counter
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import triangles as exact_triangles
from algorithms.textures import texels
from tests.support.catalogue import cases_of, recorded
from tests.support import record
from tests.support.raster_reference import triangle_pixels

DEFAULTS = {"uv": (0.0, 0.0, 1.0, 0.0, 0.0, 1.0), "w": (), "texture": "checker:8",
            "perspective": True, "filter": "bilinear", "wrap": "repeat",
            "fill_rule": "top-left", "subpixel_bits": 8, "cull": False, "precision": "fixed"}


def per_point(values, count, size=1):
    values = list(values)
    if len(values) == size * count:
        return [tuple(values[size * k:size * k + size]) for k in range(count)]
    return [tuple(values[size * (k % 3):size * (k % 3) + size]) for k in range(count)]


def reference(points, options, grid):
    """{pixel: [(u, v) exact, per triangle covering it]}."""
    bits = options["subpixel_bits"]
    uv = per_point(options["uv"], len(points), 2)
    w = [wk for (wk,) in per_point(options["w"], len(points))] if options["w"] else \
        [1.0] * len(points)
    found = {}
    for k in range(len(points) // 3):
        tri = exact_triangles.snap_triangle(points[3 * k:3 * k + 3], bits)
        area = exact_triangles.twice_area(tri)
        if area == 0 or (options["cull"] and area < 0):
            continue
        ws = [Fraction(w[3 * k + n]) if options["perspective"] else Fraction(1) for n in range(3)]
        for pixel in triangle_pixels(points[3 * k:3 * k + 3], grid, options["fill_rule"], bits):
            b = exact_triangles.barycentric(tri, exact_triangles.centre(*pixel))
            q = [bk / wk for bk, wk in zip(b, ws)]
            total = sum(q)
            u = sum(qk * Fraction(uv[3 * k + n][0]) for n, qk in enumerate(q)) / total
            v = sum(qk * Fraction(uv[3 * k + n][1]) for n, qk in enumerate(q)) / total
            found.setdefault(pixel, []).append((u, v))
    return found


def texel(texture, i, j, wrap):
    height, width = texture.levels[0].shape[:2]
    if wrap == "repeat":
        i, j = i % width, j % height
    else:
        i, j = min(max(i, 0), width - 1), min(max(j, 0), height - 1)
    return [Fraction(c) for c in texture.levels[0][j, i]]


def lookup(texture, u, v, filter_name, wrap):
    """The exact colour at (u, v); None where a float u or v may fall either way."""
    width, height = texture.width, texture.height
    if filter_name == "nearest":
        s, t = u * width, v * height
        if min(abs(s - round(s)), abs(t - round(t))) < Fraction(1, 10 ** 9):
            return None  # on a texel border: rounding decides the texel
        return texel(texture, math.floor(s), math.floor(t), wrap)
    s, t = u * width - Fraction(1, 2), v * height - Fraction(1, 2)
    i, j = math.floor(s), math.floor(t)
    a, b = s - i, t - j
    corners = [(0, 0, (1 - a) * (1 - b)), (1, 0, a * (1 - b)), (0, 1, (1 - a) * b), (1, 1, a * b)]
    return [sum(f * texel(texture, i + di, j + dj, wrap)[n] for di, dj, f in corners)
            for n in range(3)]


def check(points, options, grid, trace):
    options = {**DEFAULTS, **options}
    want = reference(points, options, grid)
    plotted = trace.writes()
    pixels = [tuple(p) for p in trace.written_pixels().tolist()]
    if options["precision"] == "fixed" and not options.get("offset"):
        assert Counter(pixels) == Counter({p: len(uvs) for p, uvs in want.items()})
    texture = texels.load(options["texture"])
    values = zip(pixels, trace.series("u")[plotted], trace.series("v")[plotted],
                 trace.series("rgb")[plotted])
    checked = 0
    for pixel, u, v, rgb in values:
        if pixel not in want:
            continue
        # u and v come from float planes: within 1e-9 of the exact values, relative.
        close = [(eu, ev) for eu, ev in want[pixel]
                 if abs(u - eu) <= 1e-9 * max(1, abs(eu)) and abs(v - ev) <= 1e-9 * max(1, abs(ev))]
        assert close, (pixel, u, v, [tuple(map(float, e)) for e in want[pixel]])
        if options["filter"] not in ("nearest", "bilinear") or len(want[pixel]) > 1:
            continue
        colour = lookup(texture, *close[0], options["filter"], options["wrap"])
        if colour is None:
            continue
        got = [(int(rgb) >> shift) & 255 for shift in (16, 8, 0)]
        # Whole channels, rounded: within 1/2 of the exact colour, and a hair
        # for the float uv.
        assert all(abs(g - float(c)) <= 0.5 + 1e-6 for g, c in zip(got, colour)), \
            (pixel, got, [float(c) for c in colour])
        checked += 1
    return checked


@pytest.mark.parametrize("case", cases_of("triangle-texture"), ids=str)
def test_textured_pixels_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check(case.points, case.options, case.grid, trace)


COORD = st.integers(0, 8 * 14).map(lambda v: v / 8)
UV = st.integers(-8, 16).map(lambda v: v / 8)
GRID = (14, 12)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(COORD, COORD), min_size=3, max_size=3),
       st.lists(UV, min_size=6, max_size=6),
       st.lists(st.sampled_from([0.5, 1.0, 2.0, 7.0]), min_size=3, max_size=3),
       st.sampled_from(["nearest", "bilinear"]), st.sampled_from(["repeat", "clamp"]),
       st.booleans(), st.sampled_from(["checker:4", "checker:16", "zoneplate"]))
def test_random_triangles(points, uv, w, filter_name, wrap, perspective, texture):
    options = {"uv": tuple(uv), "w": tuple(w), "filter": filter_name, "wrap": wrap,
               "perspective": perspective, "texture": texture}
    trace = record("triangle-texture", points, options, GRID)
    check(points, options, GRID, trace)


def test_the_catalogue_checks_colours():
    """The default options (bilinear) check a colour at most covered pixels."""
    case = next(c for c in cases_of("triangle-texture") if c.name == "plain")
    trace = record(case.algorithm, case.points, case.options, case.grid)
    assert check(case.points, case.options, case.grid, trace) > 200
