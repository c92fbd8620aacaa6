"""Shared helpers for the triangle tests: strategies, running a spec, the oracle."""
from __future__ import annotations

from fractions import Fraction
from math import gcd

from hypothesis import strategies as st

from algorithms.exact import triangles as exact_triangles
from algorithms.core import registry
from algorithms.core.steps import PLOT, VISIT

SUB = 256  # 8 sub-pixel bits, the default
RULES = ("top-left", "inclusive", "strict")
TRAVERSALS = ("triangle-scan", "triangle-bbox", "triangle-incremental", "triangle-backtrack",
              "triangle-pineda", "triangle-linewise", "triangle-halfplane",
              "triangle-barycentric", "triangle-plane", "triangle-perspective")


def spec(name):
    return registry.get(name)


def run_frames(name, points, options=None, grid=(16, 12)):
    """(code lines, frames after the Start record) of a spec's generator on a grid or window."""
    s = spec(name)
    options = s.resolve(options or {})
    points = s.inputs.check(points)
    lines = s.code(points, options)
    frames = list(s.generator(points, options, grid))
    return lines, frames


def plotted(name, points, options=None, grid=(16, 12)):
    lines, frames = run_frames(name, points, options, grid)
    return [(f[1], f[2]) for f in frames if type(f) is tuple and lines[f[0]].kind == PLOT]


def visited(name, points, options=None, grid=(16, 12)):
    """Every pixel a traversal looks at (tests and plots), in order."""
    lines, frames = run_frames(name, points, options, grid)
    return [(f[1], f[2]) for f in frames
            if type(f) is tuple and lines[f[0]].kind in (PLOT, VISIT)]


def counts_of(pixels) -> dict:
    counts = {}
    for p in pixels:
        counts[p] = counts.get(p, 0) + 1
    return counts


def oracle(points, rule, window, cull=False, bits=8) -> dict:
    return exact_triangles.coverage(points, bits, rule, window, cull)


def as_window(grid):
    return (0, 0, *grid) if len(grid) == 2 else tuple(grid)


# --------------------------------------------------------- strategies
def sub(n: int) -> float:
    """n sub-pixel units as a float (exact)."""
    return n / SUB


@st.composite
def subgrid_triangle(draw, lo=-2, hi=18):
    """Three vertices anywhere on the 1/256 grid, either winding."""
    return [(sub(draw(st.integers(lo * SUB, hi * SUB))), sub(draw(st.integers(lo * SUB, hi * SUB))))
            for _ in range(3)]


@st.composite
def centre_triangle(draw, width=16, height=12):
    """Vertices exactly on pixel centres (so edges run through many centres)."""
    return [(draw(st.integers(-1, width)) + 0.5, draw(st.integers(-1, height)) + 0.5)
            for _ in range(3)]


@st.composite
def sliver(draw):
    """A long thin triangle: twice its area is k L <= 80 sub-pixel units^2 (< 1e-3 px^2)."""
    px, py = draw(st.integers(0, 14 * SUB)), draw(st.integers(0, 10 * SUB))
    u, v = draw(st.integers(-12 * SUB, 12 * SUB)), draw(st.integers(-12 * SUB, 12 * SUB))
    g = gcd(u, v)
    u, v = (u // g, v // g) if g else (1, 0)
    s, t = _bezout(u, v)  # u t - v s = 1
    length = draw(st.integers(1, 8))
    k = draw(st.integers(1, 10)) * draw(st.sampled_from([1, -1]))
    m = draw(st.integers(0, length))
    # Q - P = L (u, v) and R - P = k (s, t) + m (u, v): twice the area is k L.
    points = [(px, py), (px + length * u, py + length * v), (px + k * s + m * u, py + k * t + m * v)]
    return [(sub(x), sub(y)) for x, y in points]


def _bezout(a: int, b: int):
    """(s, t) with a t - b s = 1 for coprime a, b."""
    old_r, r, old_s, s_, old_t, t_ = a, b, 1, 0, 0, 1
    while r:
        q = old_r // r
        old_r, r = r, old_r - q * r
        old_s, s_ = s_, old_s - q * s_
        old_t, t_ = t_, old_t - q * t_
    # a * old_s + b * old_t = old_r = +-1
    sign = old_r
    return (-old_t * sign, old_s * sign)


@st.composite
def far_triangle(draw):
    """A triangle with coordinates up to 1e6 px whose edge passes through a small window.

    Returns (points, window). A point C of the window (on the sub-pixel grid,
    often a pixel centre) lies exactly on the edge P0 -> P1, so ties happen
    at large magnitudes.
    """
    wx = draw(st.integers(-999_000, 999_000))
    wy = draw(st.integers(-999_000, 999_000))
    window = (wx, wy, wx + 10, wy + 10)
    if draw(st.booleans()):
        cx, cy = (wx + draw(st.integers(0, 9))) * SUB + SUB // 2, (wy + draw(st.integers(0, 9))) * SUB + SUB // 2
    else:
        cx, cy = draw(st.integers(wx * SUB, (wx + 10) * SUB)), draw(st.integers(wy * SUB, (wy + 10) * SUB))
    span = 1_000_000 * SUB

    def clamp_vector(dx, dy, scale_max):
        limit = span - max(abs(cx), abs(cy))
        steps = max(1, min(scale_max, limit // max(1, abs(dx), abs(dy))))
        return steps

    dx, dy = draw(st.integers(-4000, 4000)), draw(st.integers(-4000, 4000))
    if dx == 0 and dy == 0:
        dx = 1
    s1 = draw(st.integers(1, clamp_vector(dx, dy, 200_000)))
    s2 = draw(st.integers(1, clamp_vector(dx, dy, 200_000)))
    p0 = (cx + dx * s1, cy + dy * s1)
    p1 = (cx - dx * s2, cy - dy * s2)
    ex, ey = draw(st.integers(-999_000 * SUB, 999_000 * SUB)), draw(st.integers(-999_000 * SUB, 999_000 * SUB))
    points = [p0, p1, (ex, ey)]
    points = [(max(-span, min(span, x)), max(-span, min(span, y))) for x, y in points]
    return [(sub(x), sub(y)) for x, y in points], window


def exact_twice_area(points) -> Fraction:
    (x0, y0), (x1, y1), (x2, y2) = [(Fraction(x), Fraction(y)) for x, y in points]
    return (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
