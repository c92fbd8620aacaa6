"""Shared segments and helpers for the line tests (not a test module)."""
from __future__ import annotations

from hypothesis import strategies as st

from algorithms.core.cases import OCTANT_CASES, SPECIAL_CASES
from algorithms.core.registry import get

LINE_ALGORITHMS = ("line-bresenham", "line-dda", "line-incremental",
                   "line-explicit", "line-implicit", "line-parametric")

# The hard-case catalogue (algorithms/core/cases.py) is shared with `rasterlab check`.
NAMED_CASES = OCTANT_CASES + SPECIAL_CASES


def points(span: int = 40):
    return st.tuples(st.integers(-span, span), st.integers(-span, span))


@st.composite
def tie_segments(draw, span: int = 30):
    """Segments with at least one column where the ideal line is half-way.

    A major extent 2a and an odd minor extent b make 2a / gcd(2a, b) even.
    """
    a = draw(st.integers(1, span // 2))
    b = draw(st.integers(0, a - 1)) * 2 + 1
    major, minor = 2 * a, b
    sx, sy = draw(st.sampled_from([1, -1])), draw(st.sampled_from([1, -1]))
    ddx, ddy = (major, minor) if draw(st.booleans()) else (minor, major)
    p = draw(points(span))
    return p, (p[0] + sx * ddx, p[1] + sy * ddy)


def segments(span: int = 40):
    """Random segments of every direction, with ties and axis cases made likely."""
    general = st.tuples(points(span), points(span))
    axis = st.builds(lambda p, n, horizontal: (p, (p[0] + n, p[1]) if horizontal else (p[0], p[1] + n)),
                     points(span), st.integers(-span, span), st.booleans())
    diagonal = st.builds(lambda p, n, s: (p, (p[0] + n, p[1] + s * n)),
                         points(span), st.integers(-span, span), st.sampled_from([1, -1]))
    return st.one_of(general, general, tie_segments(span), axis, diagonal)


def trace_of(name, p, q, options=None, grid=(64, 64)):
    return get(name).record((p, q), options or {}, grid=grid)


def pixels_of(name, p, q, options=None):
    """Written pixels, in order, as a list of (x, y) tuples."""
    return [tuple(map(int, pixel)) for pixel in trace_of(name, p, q, options).written_pixels()]


def pack(color: str) -> int:
    return int(color[1:], 16)


def channels(packed: int) -> tuple[int, int, int]:
    return (packed >> 16) & 255, (packed >> 8) & 255, packed & 255
