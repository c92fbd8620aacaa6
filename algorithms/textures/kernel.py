"""triangle-texture's fast kernel: the same lookups as the generator, for every covered pixel
at once with numpy (for the report's timings and large grids).

Coverage is the triangle family's kernel; the mapping, lambda and the
filters follow sampling.py step for step, so tests can hold kernel and
generator to the same colours.
"""
from __future__ import annotations

import numpy as np

from algorithms.triangles.interpolate import plane_coefficients
from algorithms.triangles.edges import OPTIONS as TRIANGLE_OPTIONS, prepare
from algorithms.triangles.kernels import kernel_pixels

from .sampling import LIMIT
from .triangle import TextureColumns


def texture_image(points, options, grid):
    """(pixels (n, 2), colours (n, 3) floats 0..255) of every covered pixel, triangle by
    triangle in input order (pixels of one triangle in the kernel's order)."""
    full = {**{o.name: o.default for o in TRIANGLE_OPTIONS}, **options}
    cols = TextureColumns(full, len(points))
    texture = cols.sampler.texture
    all_pixels, all_colours = [], []
    for n, setup in enumerate(prepare(points, full)):
        if setup.tri is None:
            continue
        pixels = kernel_pixels(points[3 * n:3 * n + 3], full, grid)
        if not len(pixels):
            continue
        tri = setup.tri
        corners = [tri.px(k) for k in range(3)]
        uv = [cols.uv[k] for k in tri.order]
        w = [cols.w[k] for k in tri.order] if cols.perspective else [1.0, 1.0, 1.0]
        mapping = _mapping(corners, uv, w, pixels[:, 0] + 0.5, pixels[:, 1] + 0.5, True)
        colours = _filter(texture, full, mapping, corners, uv, w, pixels)
        all_pixels.append(pixels)
        all_colours.append(colours)
    if not all_pixels:
        return np.zeros((0, 2), np.int64), np.zeros((0, 3))
    return np.concatenate(all_pixels), np.concatenate(all_colours)


def _mapping(corners, uv, w, x, y, inside):
    """u, v, du/dx, dv/dx, du/dy, dv/dy at the points (x, y), as Mapping computes them."""
    least = min(w)
    w = [wk / least for wk in w]
    values = ([uk / wk for (uk, _), wk in zip(uv, w)], [vk / wk for (_, vk), wk in zip(uv, w)],
              [1 / wk for wk in w])
    (x0, y0), (x1, y1), (x2, y2) = corners
    area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    c = corners
    weights = [((c[(k + 2) % 3][0] - c[(k + 1) % 3][0]) * (y - c[(k + 1) % 3][1])
                - (c[(k + 2) % 3][1] - c[(k + 1) % 3][1]) * (x - c[(k + 1) % 3][0])) / area2
               for k in range(3)]
    if inside:
        weights = [np.maximum(b, 0.0) for b in weights]
    U, V, Q = (sum(b * q for b, q in zip(weights, vals)) for vals in values)
    with np.errstate(divide="ignore", invalid="ignore"):
        u, v = U / Q, V / Q
        (Ux, Uy), (Vx, Vy), (Qx, Qy) = (plane_coefficients(corners, vals) for vals in values)
        d = ((Ux - u * Qx) / Q, (Vx - v * Qx) / Q, (Uy - u * Qy) / Q, (Vy - v * Qy) / Q)
    return u, v, d, Q


def _wrap(i, n, mode):
    return np.mod(i, n) if mode == "repeat" else np.clip(i, 0, n - 1)


def nearest(level, u, v, mode):
    h, w = level.shape[:2]
    return level[_wrap(np.floor(v * h).astype(np.int64), h, mode),
                 _wrap(np.floor(u * w).astype(np.int64), w, mode)]


def bilinear(level, u, v, mode):
    h, w = level.shape[:2]
    s, t = u * w - 0.5, v * h - 0.5
    i, j = np.floor(s).astype(np.int64), np.floor(t).astype(np.int64)
    a, b = (s - i)[:, None], (t - j)[:, None]
    i0, i1 = _wrap(i, w, mode), _wrap(i + 1, w, mode)
    j0, j1 = _wrap(j, h, mode), _wrap(j + 1, h, mode)
    return ((1 - a) * (1 - b) * level[j0, i0] + a * (1 - b) * level[j0, i1]
            + (1 - a) * b * level[j1, i0] + a * b * level[j1, i1])


def _rho(texture, d):
    dudx, dvdx, dudy, dvdy = d
    px = np.hypot(dudx * texture.width, dvdx * texture.height)
    py = np.hypot(dudy * texture.width, dvdy * texture.height)
    return px, py


def _lambda(rho):
    rho = np.where(np.isnan(rho) | (rho > LIMIT), LIMIT, rho)
    with np.errstate(divide="ignore"):
        return np.log2(rho)


def trilinear(texture, u, v, lam, mode, nearest_level=False):
    """Bilinear in the level(s) sampling.levels_of picks, per pixel."""
    top = texture.top
    if nearest_level:
        low = np.where(lam <= 0.5, 0, np.ceil(lam + 0.5) - 1)
        low, frac = np.clip(low, 0, top).astype(np.int64), np.zeros_like(lam)
    else:
        clamped = np.clip(lam, 0, top)
        low = np.floor(clamped).astype(np.int64)
        frac = np.where((lam <= 0) | (lam >= top), 0.0, clamped - low)
        low = np.where(lam >= top, top, np.where(lam <= 0, 0, low))
    out = np.zeros((len(u), 3))
    for level in np.unique(low):
        mask = low == level
        out[mask] += (1 - frac[mask])[:, None] * bilinear(texture.levels[level], u[mask],
                                                          v[mask], mode)
        upper = mask & (frac > 0)
        if upper.any():
            out[upper] += frac[upper][:, None] * bilinear(texture.levels[level + 1], u[upper],
                                                          v[upper], mode)
    return out


def _filter(texture, options, mapping, corners, uv, w, pixels):
    u, v, d, _ = mapping
    mode, name = options["wrap"], options["filter"]
    if name == "nearest":
        return nearest(texture.levels[0], u, v, mode)
    if name == "bilinear":
        return bilinear(texture.levels[0], u, v, mode)
    px, py = _rho(texture, d)
    if name in ("mip-nearest", "trilinear"):
        return trilinear(texture, u, v, _lambda(np.maximum(px, py)), mode,
                         nearest_level=name == "mip-nearest")
    if name == "anisotropic":
        return _anisotropic(texture, options, u, v, d, px, py)
    return _reference(texture, options, corners, uv, w, pixels)


def _anisotropic(texture, options, u, v, d, px, py):
    major, minor = np.maximum(px, py), np.minimum(px, py)
    cap = options["max_aniso"]
    with np.errstate(divide="ignore", invalid="ignore"):
        count = np.where(minor == 0, cap, np.minimum(np.ceil(major / minor), cap))
    count = np.maximum(np.nan_to_num(count, nan=1), 1).astype(np.int64)
    bad = np.isnan(major) | (major > LIMIT)
    count[bad] = 1
    lam = _lambda(np.where(bad, LIMIT, major / count))
    lam[bad] = np.inf
    du = np.where(px >= py, d[0], d[2])
    dv = np.where(px >= py, d[1], d[3])
    out = np.zeros((len(u), 3))
    for k in range(int(count.max())):
        mask = count > k
        t = (k + 0.5) / count[mask] - 0.5
        probe_u = u[mask] + np.where(bad[mask], 0.0, t * du[mask])
        probe_v = v[mask] + np.where(bad[mask], 0.0, t * dv[mask])
        out[mask] += trilinear(texture, probe_u, probe_v, lam[mask], options["wrap"]) \
            / count[mask][:, None]
    return out


def _reference(texture, options, corners, uv, w, pixels):
    n = options["samples"]
    total = np.zeros((len(pixels), 3))
    count = np.zeros(len(pixels))
    for b in range(n):
        for a in range(n):
            x = pixels[:, 0] + (a + 0.5) / n
            y = pixels[:, 1] + (b + 0.5) / n
            u, v, _, q = _mapping(corners, uv, w, x, y, False)
            ok = (q > 0) & np.isfinite(q) & (np.abs(u) <= LIMIT) & (np.abs(v) <= LIMIT)
            total[ok] += nearest(texture.levels[0], u[ok], v[ok], options["wrap"])
            count += ok
    empty = count == 0
    if empty.any():
        total[empty] = nearest(texture.levels[0], np.zeros(empty.sum()), np.zeros(empty.sum()),
                               options["wrap"])
        count[empty] = 1
    return total / count[:, None]
