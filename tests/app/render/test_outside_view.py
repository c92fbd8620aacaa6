"""The pipeline's outside view: the frustum's corners from the camera's own formula."""
from __future__ import annotations

import math

import pytest

from algorithms.core import registry
from app.render.outside_view import outside_view


def test_near_rectangle_of_the_default_camera():
    spec = registry.get("pipeline")
    options = spec.resolve({"near": 2.0})
    view = outside_view([(3, 3), (28, 4), (15, 20)], options, (32, 24))
    half_w = 2.0 * math.tan(math.radians(40) / 2) * 32 / 24
    near_xs = sorted({round(x, 9) for segment in view.frustum[:4] for x, _ in segment})
    near_zs = {round(z, 9) for segment in view.frustum[:4] for _, z in segment}
    assert near_xs == pytest.approx([16 - half_w, 16 + half_w])
    assert near_zs == {38.0}  # the eye at z = 40 looks down -z
    assert view.eye == (16.0, 40.0)
    assert len(view.triangles) == 3 and len(view.frustum) == 12


def test_a_bad_camera_gives_no_view():
    spec = registry.get("pipeline")
    assert outside_view([(3, 3), (28, 4), (15, 20)], spec.resolve({"near": 0.0}), (32, 24)) is None


def test_projected_outline_is_the_clipped_polygon_in_the_window():
    from app.model.geometry import projected_paths
    spec = registry.get("pipeline")
    trace = spec.record([(3, 3), (28, 4), (15, 20)], {}, grid=(32, 24))
    (corners, closed), = projected_paths(trace)
    # The default camera looks straight at z = 0: window = centre + (p - centre) f / (40 a) W / 2.
    f = 1 / math.tan(math.radians(40) / 2)
    expected = [(16 + (x - 16) * f / (40 * 32 / 24) * 16, 12 + (y - 12) * f / 40 * 12)
                for x, y in [(3, 3), (28, 4), (15, 20)]]
    assert closed and len(corners) == 3
    for got, want in zip(corners, expected):
        assert got == pytest.approx(want, abs=1e-5)
