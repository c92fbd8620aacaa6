"""Shared inputs and helpers for the polygon tests (this file holds no tests).

Coordinates are drawn so that the hard cases come up often: vertices on
whole numbers (pixel corners and edges), on halves (pixel centres, so edges
through centres and vertices on scan lines), anywhere on the 1/256 grid, and
arbitrary reals that the algorithms snap.
"""
from __future__ import annotations

import math

from hypothesis import assume
from hypothesis import strategies as st

from algorithms.core.steps import PLOT, Span

SIZE = 24  # polygons lie in [0, SIZE] x [0, SIZE] unless a test says otherwise


def coordinate(size: int = SIZE):
    return st.one_of(
        st.integers(0, 2 * size).map(lambda k: k / 2),
        st.integers(0, 256 * size).map(lambda k: k / 256),
        st.floats(0, size, allow_nan=False, allow_infinity=False),
    )


def point(size: int = SIZE):
    return st.tuples(coordinate(size), coordinate(size))


def contour(size: int = SIZE, most: int = 9):
    return st.lists(point(size), min_size=3, max_size=most)


def polygon(size: int = SIZE, contours: int = 3, most: int = 9):
    """One or more contours: concave, self-intersecting, overlapping, holes."""
    return st.lists(contour(size, most), min_size=1, max_size=contours)


@st.composite
def star_shaped(draw, size: int = SIZE, most: int = 12):
    """A simple polygon: vertices around a centre by increasing angle.

    Coordinates are halves, so edges often run through pixel centres.
    """
    n = draw(st.integers(3, most))
    cx = draw(st.integers(2 * 8, 2 * (size - 8))) / 2
    cy = draw(st.integers(2 * 8, 2 * (size - 8))) / 2
    turns = sorted(set(draw(st.lists(st.integers(0, 359), min_size=n, max_size=n, unique=True))))
    radii = draw(st.lists(st.integers(2, 14), min_size=len(turns), max_size=len(turns)))
    points = [(round(2 * (cx + r / 2 * math.cos(math.radians(a)))) / 2,
               round(2 * (cy + r / 2 * math.sin(math.radians(a)))) / 2)
              for a, r in zip(turns, radii)]
    # Rounding to halves may break the order around the centre: keep only
    # polygons that every ray from the centre meets once (so simple ones).
    c = (round(256 * cx), round(256 * cy))
    snapped = [(round(256 * x), round(256 * y)) for x, y in points]
    turns = [(a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
             for a, b in zip(snapped, snapped[1:] + snapped[:1])]
    assume(all(t > 0 for t in turns))
    assume(sum(math.atan2(t, (a[0] - c[0]) * (b[0] - c[0]) + (a[1] - c[1]) * (b[1] - c[1]))
               for t, a, b in zip(turns, snapped, snapped[1:] + snapped[:1])) < 3 * math.pi)
    if draw(st.booleans()):
        points.reverse()
    return points


def generator_pixels(spec, contours, options=None) -> list[tuple[int, int]]:
    """The pixels a run writes, in order, read straight from its frames (no grid)."""
    options = spec.resolve(options)
    points = spec.inputs.check(contours)
    code = spec.code(points, options)
    pixels = []
    for frame in spec.generator(points, options):
        if isinstance(frame, Span) and code[frame.line].kind == PLOT:
            pixels.extend((x, frame.y) for x in range(frame.x_start, frame.x_end))
        elif isinstance(frame, tuple) and code[frame[0]].kind == PLOT:
            pixels.append((frame[1], frame[2]))
    return pixels


def kernel_pixels(spec, contours, options=None) -> list[tuple[int, int]]:
    return [tuple(p) for p in spec.kernel(spec.inputs.check(contours), spec.resolve(options)).tolist()]
