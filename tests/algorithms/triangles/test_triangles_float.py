"""Floating-point edge functions against exact integers: where do they part ways?

precision=float32/float64 evaluate the implicit form a*x + b*y + c, with
c = x_i*y_j - y_i*x_j, in that type. For coordinates in [0, 2^m) on the
1/256 grid every product and sum is a multiple of 2^-16 below 2^(2m+2),
so the result is exact while 2m + 18 bits fit the significand: float32
(24 bits) is exact below 8 px, float64 (53 bits) below 2^17 px. Beyond,
the sweep below finds the first magnitude where a pixel flips, and
reports it (run pytest with -s to see the table).
"""
import math

import numpy as np
import pytest

from algorithms import triangles
from test_triangles_cases import RULES, SUB, counts_of, oracle, plotted, spec

EXACT = {"precision": "fixed", "subpixel_bits": 8, "fill_rule": "top-left", "cull": False}
FLOAT_SPECS = ("triangle-scan", "triangle-bbox", "triangle-incremental", "triangle-backtrack",
               "triangle-pineda", "triangle-linewise", "triangle-halfplane",
               "triangle-barycentric")


def random_case(rng, magnitude):
    """Vertices on the 1/256 grid in [M, 2M); a 12 x 12 window on edge P0 -> P1."""
    lo, hi = magnitude * SUB, 2 * magnitude * SUB
    points = [(rng.integers(lo, hi) / SUB, rng.integers(lo, hi) / SUB) for _ in range(3)]
    t = rng.uniform(0.2, 0.8)
    x = math.floor(points[0][0] + t * (points[1][0] - points[0][0]))
    y = math.floor(points[0][1] + t * (points[1][1] - points[0][1]))
    return points, (x - 6, y - 6, x + 6, y + 6)


def tie_case(rng, magnitude):
    """An edge through a pixel centre C near (M, M), vertices with all 8 fractional bits used."""
    cx, cy = magnitude + int(rng.integers(0, 4)), magnitude + int(rng.integers(0, 4))
    c = (cx * SUB + SUB // 2, cy * SUB + SUB // 2)
    d = (int(rng.integers(1, SUB)) | 1, int(rng.integers(1, SUB)) | 1)
    s1 = max(1, magnitude // 4 + int(rng.integers(0, 8)))
    s2 = max(1, magnitude // 4 + int(rng.integers(0, 8)))
    p0 = (c[0] + s1 * d[0], c[1] - s1 * d[1])
    p1 = (c[0] - s2 * d[0], c[1] + s2 * d[1])
    p2 = (c[0] + int(rng.integers(1, 8 * SUB)) * (1 if rng.random() < 0.5 else -1) + 1,
          c[1] + int(rng.integers(1, 8 * SUB)) + 1)
    points = [(x / SUB, y / SUB) for x, y in (p0, p1, p2)]
    return points, (cx - 6, cy - 6, cx + 6, cy + 6)


def mismatches(precision, magnitude, rng, trials=12):
    bad = 0
    for make in (random_case, tie_case):
        for _ in range(trials):
            points, window = make(rng, magnitude)
            exact = triangles.kernel_pixels(points, EXACT, window)
            floats = triangles._float_box_pixels(points, {**EXACT, "precision": precision},
                                                 window, whole=False)
            bad += len(set(map(tuple, exact.tolist())) ^ set(map(tuple, floats.tolist())))
    return bad


def sweep(precision):
    rng = np.random.default_rng(2024)
    return [(2 ** k, mismatches(precision, 2 ** k, rng)) for k in range(0, 22)]


def first_bad(rows):
    return next((m for m, bad in rows if bad), None)


def test_float32_sweep_finds_where_it_disagrees_with_exact(record_property):
    rows = sweep("float32")
    first = first_bad(rows)
    print("\nfloat32 vs exact (coordinates in [M, 2M) px, 1/256 grid): "
          + ", ".join(f"M={m}: {bad}" for m, bad in rows))
    print(f"float32 first disagrees at M = {first} px")
    record_property("float32_first_disagreement_px", first)
    assert all(bad == 0 for m, bad in rows if 2 * m <= 8)  # provably exact below 8 px
    assert first is not None and first <= 2 ** 12


def test_float64_sweep_finds_where_it_disagrees_with_exact(record_property):
    rows = sweep("float64")
    first = first_bad(rows)
    print("\nfloat64 vs exact: " + ", ".join(f"M={m}: {bad}" for m, bad in rows))
    print(f"float64 first disagrees at M = {first} px")
    record_property("float64_first_disagreement_px", first)
    assert all(bad == 0 for m, bad in rows if 2 * m <= 2 ** 17)  # provably exact below 2^17 px


@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_small_coordinates_agree_in_every_traversal(precision):
    rng = np.random.default_rng(5)
    for _ in range(10):
        points = [(rng.integers(0, 7 * SUB) / SUB, rng.integers(0, 7 * SUB) / SUB)
                  for _ in range(3)]
        for rule in RULES:
            want = oracle(points, rule, (0, 0, 8, 8))
            for name in FLOAT_SPECS:
                got = plotted(name, points, {"precision": precision, "fill_rule": rule}, (8, 8))
                assert counts_of(got) == want, (name, precision, rule, points)


@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_float_kernels_equal_their_generators(precision):
    rng = np.random.default_rng(9)
    for _ in range(6):
        base = 3000.0
        points = [(base + rng.integers(0, 12 * SUB) / SUB, base + rng.integers(0, 12 * SUB) / SUB)
                  for _ in range(6)]
        window = (3000, 3000, 3012, 3012)
        for name in FLOAT_SPECS:
            s = spec(name)
            if s.kernel is None:
                continue
            options = s.resolve({"precision": precision})
            want = plotted(name, points, options, window)
            assert [tuple(p) for p in s.kernel(points, options, window).tolist()] == want, name
