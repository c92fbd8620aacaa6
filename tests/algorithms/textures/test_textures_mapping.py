"""triangle-texture's uv, derivatives and lambda against exact rational oracles."""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest

from algorithms.core import registry
from algorithms.core.steps import PLOT

SPEC = registry.get("triangle-texture")
# Vertices on whole pixels, so snapping leaves them as they are.
CASES = [
    ([(1, 1), (14, 2), (3, 13)], (0, 0, 1, 0, 0, 1), (1, 4, 2)),
    ([(2, 12), (13, 1), (15, 14)], (0.25, 3, 2, 0.5, -1, 1.75), (0.5, 7, 3)),
    ([(0, 0), (15, 0), (7, 15)], (0, 0, 4, 0, 2, 8), (1, 1, 9)),
]


def _weights(corners, x, y):
    """Exact barycentric weights of (x, y) from signed areas."""
    (x0, y0), (x1, y1), (x2, y2) = [(Fraction(a), Fraction(b)) for a, b in corners]
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    a = ((x1 - x) * (y2 - y) - (x2 - x) * (y1 - y)) / area
    b = ((x2 - x) * (y0 - y) - (x0 - x) * (y2 - y)) / area
    return a, b, 1 - a - b


def _exact(corners, uv, w, x, y):
    """(N_u, N_v, D) at (x, y): the interpolated u/w, v/w and 1/w, exactly."""
    weights = _weights(corners, x, y)
    ws = [Fraction(wk) for wk in w]
    u = [Fraction(uv[2 * k]) for k in range(3)]
    v = [Fraction(uv[2 * k + 1]) for k in range(3)]
    nu = sum(b * uk / wk for b, uk, wk in zip(weights, u, ws))
    nv = sum(b * vk / wk for b, vk, wk in zip(weights, v, ws))
    d = sum(b / wk for b, wk in zip(weights, ws))
    return nu, nv, d


def _plotted(trace):
    lines = trace.code
    for i in range(len(trace)):
        step = trace.step(i)
        if step.pixel is not None and lines[step.line].kind == PLOT:
            yield step


@pytest.mark.parametrize("corners, uv, w", CASES)
def test_perspective_uv_and_lambda_at_centres(corners, uv, w):
    options = {"uv": uv, "w": w, "filter": "trilinear"}
    trace = SPEC.record(corners, options, grid=(16, 16))
    texture = 64  # checker:8 is 64 x 64 texels
    count = 0
    for step in _plotted(trace):
        x, y = Fraction(2 * step.pixel[0] + 1, 2), Fraction(2 * step.pixel[1] + 1, 2)
        nu, nv, d = _exact(corners, uv, w, x, y)
        u, v = nu / d, nv / d
        assert abs(step.values["u"] - u) < 1e-12 and abs(step.values["v"] - v) < 1e-12
        # The mapping is a ratio of affine functions: their exact slopes are
        # differences over one pixel, and the quotient rule gives the derivatives.
        nu1, nv1, d1 = _exact(corners, uv, w, x + 1, y)
        nu2, nv2, d2 = _exact(corners, uv, w, x, y + 1)
        dudx = ((nu1 - nu) * d - nu * (d1 - d)) / d ** 2
        dvdx = ((nv1 - nv) * d - nv * (d1 - d)) / d ** 2
        dudy = ((nu2 - nu) * d - nu * (d2 - d)) / d ** 2
        dvdy = ((nv2 - nv) * d - nv * (d2 - d)) / d ** 2
        for name, exact in (("du/dx", dudx), ("dv/dx", dvdx), ("du/dy", dudy), ("dv/dy", dvdy)):
            assert step.values[name] == pytest.approx(float(exact), rel=1e-12, abs=1e-12)
        rho = max(math.hypot(dudx * texture, dvdx * texture),
                  math.hypot(dudy * texture, dvdy * texture))
        assert step.values["lambda"] == pytest.approx(math.log2(rho), abs=1e-12)
        count += 1
    assert count > 20


def test_affine_ignores_w_and_differs_from_perspective():
    corners, uv, w = CASES[0]
    affine = SPEC.record(corners, {"uv": uv, "w": w, "perspective": False}, grid=(16, 16))
    correct = SPEC.record(corners, {"uv": uv, "w": w}, grid=(16, 16))
    differ = 0
    for a, p in zip(_plotted(affine), _plotted(correct)):
        x, y = Fraction(2 * a.pixel[0] + 1, 2), Fraction(2 * a.pixel[1] + 1, 2)
        nu, _, d = _exact(corners, uv, (1, 1, 1), x, y)
        assert abs(a.values["u"] - nu / d) < 1e-12
        differ += abs(a.values["u"] - p.values["u"]) > 1e-3
    assert differ > 10


def test_kernel_pixels_equal_the_generator():
    corners, uv, w = CASES[1]
    trace = SPEC.record(corners, {"uv": uv, "w": w}, grid=(16, 16))
    kernel = SPEC.kernel(corners, SPEC.resolve({"uv": uv, "w": w}), (16, 16))
    assert sorted(map(tuple, np.asarray(kernel).tolist())) == \
        sorted(map(tuple, trace.written_pixels().tolist()))
