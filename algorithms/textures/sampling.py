"""Looking a texture up at a pixel: the uv mapping, its derivatives, the level of detail and filters.

The mapping. Across a triangle u/w, v/w and 1/w are linear functions of
the screen position (planes through the vertex values); u = (u/w) / (1/w).
With perspective off, u and v themselves are the planes (the affine
mapping a renderer without correction uses). Writing U, V, Q for the planes
of u/w, v/w and 1/w, the quotient rule gives the exact derivatives

    du/dx = (U_x - u Q_x) / Q,   du/dy = (U_y - u Q_y) / Q   (and so for v),

at the pixel centre, which is what the level of detail uses.

Level of detail, as OpenGL defines it (4.6, 8.14.1): with the derivatives
in texels (du/dx W, dv/dx H, ...), rho is the larger of the lengths of the
x and y derivative vectors and lambda = log2(rho). Filters:

* nearest: the texel containing (u W, v H) at level 0;
* bilinear: the four texels around (u W - 1/2, v H - 1/2), weighted by the
  fractions, at level 0;
* mip-nearest: bilinear at the level nearest lambda (OpenGL's
  LINEAR_MIPMAP_NEAREST: level ceil(lambda + 1/2) - 1, level 0 when
  lambda <= 1/2);
* trilinear: bilinear at levels floor(lambda) and floor(lambda) + 1,
  mixed by the fraction of lambda (LINEAR_MIPMAP_LINEAR);
* anisotropic: N trilinear probes spaced along the longer derivative
  vector, N = min(ceil(major / minor), max_aniso), each at
  lambda = log2(major / N), averaged (as EXT_texture_filter_anisotropic
  describes it);
* reference: the average of the texture (level 0 texels, each a constant
  square) over the pixel's pre-image, estimated by mapping an n x n grid of
  sub-pixel points (n = ``samples``) through the exact mapping and
  averaging their texels. The estimate's error falls as 1/n for a
  piecewise-constant texture (only sub-squares straddling a texel edge are
  wrong); with n = 8 a pixel is within 1/8 of the texture's range of the
  32 x 32 estimate (tests/algorithms/textures/test_textures_filters.py checks it).

Bounds the tests hold the filters to, on a checkerboard floor receding to
w = 12 (RMS over pixels, against the reference): trilinear within 25% of
the texture's range and anisotropic within 15%, each below point
sampling's error (about 17%, 10% and 92% of the 200-level range measured).

A lookup returns its fetches: (level, i, j, weight) per texel read, the
weights summing to 1, so steps can show them and the report can count them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from algorithms.core.errors import InputError
from algorithms.triangles.interpolate import plane_coefficients

from .texels import Texture

WRAPS = ("repeat", "clamp")
FILTERS = ("nearest", "bilinear", "mip-nearest", "trilinear", "anisotropic", "reference")
MIPMAPPED = ("mip-nearest", "trilinear", "anisotropic")
# Texel indices stay exact and finite below this (|u| W, rho W within 2^53).
LIMIT = 1e9


class Mapping:
    """uv across one triangle, from its screen corners, uv and w per vertex."""

    def __init__(self, corners, uv, w, perspective: bool = True):
        if any(not wk > 0 for wk in w):
            raise InputError("option w: every w must be greater than 0")
        if not perspective:
            w = (1.0, 1.0, 1.0)
        # u is the same for w scaled by any constant: scaling the least w to 1
        # keeps 1/w and u/w within the float range for any positive w.
        least = min(w)
        w = [wk / least for wk in w]
        self.corners = corners
        (x0, y0), (x1, y1), (x2, y2) = corners
        self.area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        self.values = ([uk / wk for (uk, _), wk in zip(uv, w)],
                       [vk / wk for (_, vk), wk in zip(uv, w)], [1 / wk for wk in w])
        self.slopes = [plane_coefficients(corners, values) for values in self.values]

    def weights(self, x, y):
        """Barycentric weights of (x, y): values as weighted sums of the vertices' (no
        cancellation against a far vertex, so 1/w stays positive inside)."""
        c = self.corners
        return [((c[(k + 2) % 3][0] - c[(k + 1) % 3][0]) * (y - c[(k + 1) % 3][1])
                 - (c[(k + 2) % 3][1] - c[(k + 1) % 3][1]) * (x - c[(k + 1) % 3][0]))
                / self.area2 for k in range(3)]

    def _at(self, x, y, inside):
        weights = self.weights(x, y)
        if inside:  # the pixel is covered: its true weights are >= 0
            weights = [max(b, 0.0) for b in weights]
        U, V, Q = (sum(b * q for b, q in zip(weights, values)) for values in self.values)
        return U, V, Q

    def uv(self, x, y):
        """(u, v) at (x, y), or None where 1/w is not positive (beyond the horizon)."""
        U, V, Q = self._at(x, y, False)
        if not (Q > 0 and math.isfinite(Q)):
            return None
        return U / Q, V / Q

    def derivatives(self, x, y):
        """(u, v, du/dx, dv/dx, du/dy, dv/dy) at (x, y) in the triangle, by the quotient rule."""
        U, V, Q = self._at(x, y, True)
        if not (Q > 0 and math.isfinite(Q)):
            raise InputError(f"texture mapping at ({x:g}, {y:g}): the interpolated 1/w is not "
                             "a positive finite number (w too large or too unequal)")
        (Ux, Uy), (Vx, Vy), (Qx, Qy) = self.slopes
        u, v = U / Q, V / Q
        return u, v, (Ux - u * Qx) / Q, (Vx - v * Qx) / Q, (Uy - u * Qy) / Q, (Vy - v * Qy) / Q


def rho_lambda(texture: Texture, d):
    """(rho, lambda) from the derivatives (du/dx, dv/dx, du/dy, dv/dy) in uv units."""
    dudx, dvdx, dudy, dvdy = d
    w, h = texture.width, texture.height
    rho = max(math.hypot(dudx * w, dvdx * h), math.hypot(dudy * w, dvdy * h))
    if math.isnan(rho) or rho > LIMIT:  # next to a vertex with w near 0: capped
        return LIMIT, math.log2(LIMIT)
    return rho, (math.log2(rho) if rho > 0 else -math.inf)


def wrap(i: int, n: int, mode: str) -> int:
    return i % n if mode == "repeat" else min(max(i, 0), n - 1)


def nearest(texture: Texture, level: int, u, v, mode: str, weight=1.0):
    h, w = texture.levels[level].shape[:2]
    return [(level, wrap(math.floor(u * w), w, mode), wrap(math.floor(v * h), h, mode), weight)]


def bilinear(texture: Texture, level: int, u, v, mode: str, weight=1.0):
    h, w = texture.levels[level].shape[:2]
    s, t = u * w - 0.5, v * h - 0.5
    i, j = math.floor(s), math.floor(t)
    a, b = s - i, t - j
    return [(level, wrap(i + di, w, mode), wrap(j + dj, h, mode), weight * fa * fb)
            for dj, fb in ((0, 1 - b), (1, b)) for di, fa in ((0, 1 - a), (1, a))]


def levels_of(lam: float, top: int, filter_name: str):
    """The levels a mip-mapped filter reads at lambda, with their weights."""
    if filter_name == "mip-nearest":
        level = 0 if lam <= 0.5 else math.ceil(lam + 0.5) - 1
        return [(min(level, top), 1.0)]
    if lam <= 0:
        return [(0, 1.0)]
    if lam >= top:
        return [(top, 1.0)]
    low = math.floor(lam)
    frac = lam - low
    return [(low, 1 - frac), (low + 1, frac)] if frac > 0 else [(low, 1.0)]


@dataclass
class Sample:
    """One lookup: the colour, what was read and why."""

    color: tuple
    fetches: list
    rho: float
    lam: float
    levels: list  # (level, weight) of the mip-mapped filters; [(0, 1.0)] otherwise
    uv: tuple  # (u, v) at the pixel centre
    d: tuple  # (du/dx, dv/dx, du/dy, dv/dy) there
    probes: int = 1


class Sampler:
    """A texture with a filter and an address mode, looked up per pixel."""

    def __init__(self, texture: Texture, filter_name: str, mode: str, max_aniso: int = 8,
                 samples: int = 8):
        if filter_name not in FILTERS:
            raise InputError(f"option filter: expected one of {', '.join(FILTERS)}")
        self.texture, self.filter, self.mode = texture, filter_name, mode
        self.max_aniso, self.samples = max_aniso, samples

    def sample(self, mapping: Mapping, x: int, y: int) -> Sample:
        """The lookup for pixel (x, y), its centre (x + 1/2, y + 1/2)."""
        u, v, *d = mapping.derivatives(x + 0.5, y + 0.5)
        rho, lam = rho_lambda(self.texture, d)
        if not all(abs(value) <= LIMIT for value in (u, v)):
            raise InputError(f"texture lookup at pixel ({x}, {y}): u or v is beyond "
                             f"+-{LIMIT:g}; use smaller texture coordinates")
        levels, probes = [(0, 1.0)], 1
        if self.filter == "nearest":
            fetches = nearest(self.texture, 0, u, v, self.mode)
        elif self.filter == "bilinear":
            fetches = bilinear(self.texture, 0, u, v, self.mode)
        elif self.filter == "reference":
            fetches = self._reference(mapping, x, y)
        elif self.filter == "anisotropic":
            fetches, levels, probes = self._anisotropic(u, v, d)
        else:
            levels = levels_of(lam, self.texture.top, self.filter)
            fetches = self._mip(u, v, levels)
        return Sample(self.color(fetches), fetches, rho, lam, levels, (u, v), tuple(d), probes)

    def color(self, fetches) -> tuple:
        total = [0.0, 0.0, 0.0]
        for level, i, j, weight in fetches:
            texel = self.texture.levels[level][j, i]
            for n in range(3):
                total[n] += weight * texel[n]
        return tuple(total)

    def _mip(self, u, v, levels, weight=1.0):
        return [f for level, w in levels
                for f in bilinear(self.texture, level, u, v, self.mode, weight * w)]

    def _anisotropic(self, u, v, d):
        dudx, dvdx, dudy, dvdy = d
        tw, th = self.texture.width, self.texture.height
        px, py = math.hypot(dudx * tw, dvdx * th), math.hypot(dudy * tw, dvdy * th)
        major, minor = max(px, py), min(px, py)
        if math.isnan(major) or major > LIMIT:
            return self._mip(u, v, [(self.texture.top, 1.0)]), [(self.texture.top, 1.0)], 1
        count = self.max_aniso if minor == 0 else min(math.ceil(major / minor), self.max_aniso)
        count = max(count, 1)
        lam = math.log2(major / count) if major > 0 else -math.inf
        levels = levels_of(lam, self.texture.top, "trilinear")
        du, dv = (dudx, dvdx) if px >= py else (dudy, dvdy)
        fetches = []
        for k in range(count):
            t = (k + 0.5) / count - 0.5
            fetches += self._mip(u + t * du, v + t * dv, levels, 1 / count)
        return fetches, levels, count

    def _reference(self, mapping: Mapping, x: int, y: int):
        n = self.samples
        fetches = []
        points = [mapping.uv(x + (a + 0.5) / n, y + (b + 0.5) / n)
                  for b in range(n) for a in range(n)]
        # Sub-pixel points beyond the horizon (1/w <= 0) see no texture.
        points = [p for p in points if p is not None and abs(p[0]) <= LIMIT
                  and abs(p[1]) <= LIMIT] or [(0.0, 0.0)]
        weight = 1 / len(points)
        for u, v in points:
            fetches += nearest(self.texture, 0, u, v, self.mode, weight)
        return fetches
