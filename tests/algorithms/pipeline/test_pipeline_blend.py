"""blend-over against `over` composited directly, per pixel, in the test."""
from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from algorithms.core import registry
from algorithms.pipeline.blend import final_colors

SPEC = registry.get("blend-over")
GRID = (26, 20)
RED, BLUE, GREEN = (255, 0, 0), (0, 0, 255), (0, 160, 0)


def _hex(c):
    return "#%02x%02x%02x" % c


def _weights(tri, x, y):
    (x0, y0), (x1, y1), (x2, y2) = [(Fraction(a), Fraction(b)) for a, b in tri]
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    a = ((x1 - x) * (y2 - y) - (x2 - x) * (y1 - y)) / area
    b = ((x2 - x) * (y0 - y) - (x0 - x) * (y2 - y)) / area
    return a, b, 1 - a - b


def _oracle(tris, order):
    """The colour buffer from `over` per pixel: the fragments of the triangles in
    ``order`` (a list of indices, or "depth": per pixel, farthest first)."""
    image = np.full((GRID[1], GRID[0], 3), 255.0)
    for y in range(GRID[1]):
        for x in range(GRID[0]):
            cx, cy = Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2)
            frags = []
            for n, (points, zs, colour, alpha) in enumerate(tris):
                weights = _weights(points, cx, cy)
                assert all(w != 0 for w in weights), "no centre on an edge in these scenes"
                if all(w > 0 for w in weights):
                    z = sum(w * Fraction(zk) for w, zk in zip(weights, zs))
                    frags.append((n, z, colour, alpha))
            if order == "depth":
                frags.sort(key=lambda f: -f[1])
            else:
                frags.sort(key=lambda f: order.index(f[0]))
            for _, _, colour, alpha in frags:
                image[y, x] = [alpha * s + (1 - alpha) * d for s, d in zip(colour, image[y, x])]
    return image


def _run(tris, order):
    points = [p for t in tris for p in t[0]]
    options = {"z": tuple(z for t in tris for z in t[1]),
               "colors": tuple(_hex(t[2]) for t in tris for _ in range(3)),
               "alpha": tuple(t[3] for t in tris for _ in range(3)), "order": order}
    return final_colors(points, SPEC.resolve(options), GRID)


def _off(*points):
    """Points moved by (27/256, 61/256): on the sub-pixel grid, and no edge meets a centre."""
    return [(x + 27 / 256, y + 61 / 256) for x, y in points]


# Three overlapping transparent triangles, each at one depth (the nearest given first).
STACKED = [(_off((2, 2), (20, 3), (8, 16)), (0.2, 0.2, 0.2), RED, 0.5),
           (_off((6, 4), (24, 8), (14, 18)), (0.5, 0.5, 0.5), BLUE, 0.6),
           (_off((4, 9), (22, 1), (18, 15)), (0.8, 0.8, 0.8), GREEN, 0.4)]
# Two that pierce each other: each is nearer over part of the other.
PIERCING = [(_off((2, 3), (23, 3), (12, 17)), (0.2, 0.8, 0.5), RED, 0.5),
            (_off((3, 15), (12, 1), (23, 15)), (0.7, 0.3, 0.5), BLUE, 0.5)]


def test_input_order_composites_like_the_formula():
    got = _run(STACKED, "input")
    assert np.all(np.abs(got - _oracle(STACKED, [0, 1, 2])) <= 0.5 + 1e-9)


def test_the_result_depends_on_the_order_and_back_to_front_fixes_it():
    correct = _oracle(STACKED, "depth")
    in_input_order = _run(STACKED, "input")
    sorted_run = _run(STACKED, "back-to-front")
    assert np.max(np.abs(in_input_order - correct)) > 20
    assert np.all(np.abs(sorted_run - correct) <= 0.5 + 1e-9)


def test_back_to_front_cannot_fix_piercing_triangles():
    correct = _oracle(PIERCING, "depth")
    sorted_run = _run(PIERCING, "back-to-front")
    wrong = np.any(np.abs(sorted_run - correct) > 1, axis=2)
    assert 5 < wrong.sum()
    points = [p for t in PIERCING for p in t[0]]
    options = {"z": tuple(z for t in PIERCING for z in t[1]), "alpha": (0.5,) * 6,
               "colors": tuple(_hex(t[2]) for t in PIERCING for _ in range(3)),
               "order": "back-to-front"}
    trace = SPEC.record(points, options, grid=GRID)
    assert trace.final_variables()["misordered"] == int(wrong.sum())


def test_an_opaque_surface_hides_what_is_drawn_behind_it_later():
    opaque = [(STACKED[0][0], (0.2,) * 3, RED, 1.0), (STACKED[1][0], (0.5,) * 3, BLUE, 0.6)]
    got = _run(opaque, "input")
    # Behind the opaque red triangle the blue one fails the depth test.
    expected = _oracle([opaque[0]], [0])
    red = np.all(expected == RED, axis=2)
    assert red.sum() > 20 and np.all(got[red] == RED)


def test_alpha_out_of_range_is_refused():
    with pytest.raises(ValueError, match="alpha"):
        SPEC.record(STACKED[0][0], {"alpha": (0.5, 1.5, 0.5)}, grid=GRID)
