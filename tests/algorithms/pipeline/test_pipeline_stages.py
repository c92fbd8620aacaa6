"""The pipeline: clipping with exact arithmetic, clipping against no clipping, shading formulas."""
from __future__ import annotations

import math
import random
from fractions import Fraction

import pytest

from algorithms.core import registry
from algorithms.pipeline.space import clip_polygon, distance
from algorithms.core.steps import PLOT

SPEC = registry.get("pipeline")


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _inside_convex(polygon, p):
    signs = {(_cross(polygon[k], polygon[(k + 1) % len(polygon)], p) > 0) -
             (_cross(polygon[k], polygon[(k + 1) % len(polygon)], p) < 0)
             for k in range(len(polygon))}
    return not (1 in signs and -1 in signs)


@pytest.mark.parametrize("seed", range(6))
def test_near_clipping_keeps_exactly_the_part_in_front(seed):
    rng = random.Random(seed)
    corners = [[Fraction(rng.randint(-20, 20)) for _ in range(4)] for _ in range(3)]
    # Barycentric coordinates ride along as attributes: each output corner says
    # which point of the triangle it is.
    vertices = [c + [Fraction(int(k == n)) for n in range(3)] for k, c in enumerate(corners)]
    polygon, _ = clip_polygon(vertices, ("near",))
    for v in polygon:
        b = v[4:7]
        assert all(x >= 0 for x in b) and sum(b) == 1
        assert v[:4] == [sum(bk * c[n] for bk, c in zip(b, corners)) for n in range(4)]
        assert distance("near", v) >= 0
    flat = [v[4:6] for v in polygon]  # the polygon in the (b0, b1) plane
    for _ in range(300):
        b0, b1 = Fraction(rng.randint(0, 60), 60), Fraction(rng.randint(0, 60), 60)
        if b0 + b1 > 1:
            continue
        point = [b0 * corners[0][n] + b1 * corners[1][n] + (1 - b0 - b1) * corners[2][n]
                 for n in range(4)]
        front = distance("near", point) >= 0
        assert front == (len(flat) >= 3 and _inside_convex(flat, (b0, b1))) or (
            front and len(flat) < 3 and distance("near", point) == 0)


def _plotted(trace):
    for i in range(len(trace)):
        step = trace.step(i)
        if step.pixel is not None and trace.code[step.line].kind == PLOT:
            yield step


def test_clipped_equals_unclipped_where_w_is_beyond_near():
    # A floor whose front corners lie between the eye and the near plane (0 < w < near).
    points = [(10, 5), (22, 5), (16, 5)]
    options = {"z": (30, 30, -20), "eye": (16, 8, 40), "target": (16, 5, 0), "fov": 50,
               "near": 12.0, "colors": ("#ff0000", "#00ff00", "#0000ff"), "clipping": "near"}
    clipped = {s.pixel: s.values for s in _plotted(SPEC.record(points, options, (32, 24)))}
    whole = {s.pixel: s.values for s in
             _plotted(SPEC.record(points, options | {"clipping": "none"}, (32, 24)))}
    compared = 0
    for pixel, values in whole.items():
        if values["w"] > 1.2 * 12.0:
            assert pixel in clipped
            other = clipped[pixel]
            # The cut corners snap to 1/256 px like every vertex: the depth plane
            # through them moves by at most its slope times 1/512 px.
            assert other["depth"] == pytest.approx(values["depth"], abs=2e-4)
            a, b = int(values["rgb"]), int(other["rgb"])
            assert all(abs((a >> s & 255) - (b >> s & 255)) <= 1 for s in (0, 8, 16))
            compared += 1
    assert compared > 20
    assert any(v["w"] < 12.0 for v in whole.values())  # the unclipped run drew in front of near
    assert all(v["w"] >= 12.0 * (1 - 1e-9) for v in clipped.values())


def _window(x, y, grid=(32, 24), fov=40.0):
    """Default camera (16, 12, 40) looking down -z: a z = 0 point's window position."""
    f = 1 / math.tan(math.radians(fov) / 2)
    aspect = grid[0] / grid[1]
    return ((f / aspect * (x - 16) / 40 + 1) * grid[0] / 2, (f * (y - 12) / 40 + 1) * grid[1] / 2)


def _weights(tri, x, y):
    (x0, y0), (x1, y1), (x2, y2) = tri
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    a = ((x1 - x) * (y2 - y) - (x2 - x) * (y1 - y)) / area
    b = ((x2 - x) * (y0 - y) - (x0 - x) * (y2 - y)) / area
    return a, b, 1 - a - b


def _lit(colour, normal, light):
    length = math.sqrt(sum(v * v for v in normal))
    llen = math.sqrt(sum(v * v for v in light))
    dot = sum(-p / llen * q / length for p, q in zip(light, normal))
    return [c * (0.2 + 0.8 * max(0.0, dot)) for c in colour]


POINTS = [(4, 3), (28, 5), (15, 21)]
NORMALS = (0, 0, 1, 1, 0, 1, -1, 1, 1)
LIGHT = (-1.0, -1.0, -2.0)


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_shading_matches_the_formula(shading):
    colours = [(255, 0, 0), (0, 255, 0), (0, 0, 255)]
    options = {"colors": ("#ff0000", "#00ff00", "#0000ff"), "normals": NORMALS,
               "shading": shading}
    tri = [_window(x, y) for x, y in POINTS]
    normals = [NORMALS[3 * k:3 * k + 3] for k in range(3)]
    count = 0
    for step in _plotted(SPEC.record(POINTS, options, (32, 24))):
        b = _weights(tri, step.pixel[0] + 0.5, step.pixel[1] + 0.5)
        if shading == "flat":
            mean = [sum(c[n] for c in colours) / 3 for n in range(3)]
            expected = _lit(mean, (0, 0, 1), LIGHT)  # the face normal of a z = 0 triangle
        elif shading == "gouraud":
            lit = [_lit(c, nk, LIGHT) for c, nk in zip(colours, normals)]
            expected = [sum(bk * c[n] for bk, c in zip(b, lit)) for n in range(3)]
        else:
            base = [sum(bk * c[n] for bk, c in zip(b, colours)) for n in range(3)]
            unit = [[v / math.sqrt(sum(x * x for x in nk)) for v in nk] for nk in normals]
            normal = [sum(bk * nk[n] for bk, nk in zip(b, unit)) for n in range(3)]
            expected = _lit(base, normal, LIGHT)
        got = int(step.values["rgb"])
        got = [(got >> 16) & 255, (got >> 8) & 255, got & 255]
        # Snapping the window vertices to 1/256 px moves the weights by < 0.002.
        assert all(abs(g - e) <= 1.5 for g, e in zip(got, expected)), (step.pixel, got, expected)
        count += 1
    assert count > 100


def test_a_fragments_panel_retraces_it_to_its_own_pixel_centre():
    points = [(10, 5), (22, 5), (16, 5)]
    options = {"z": (30, 30, -20), "eye": (16, 8, 40), "target": (16, 5, 0), "fov": 50}
    trace = SPEC.record(points, options, (32, 24))
    for step in list(_plotted(trace))[::25]:
        rows = dict(SPEC.explain(trace, step.index))
        x, y, depth = (float(v) for v in rows["window"].strip("()").split(", "))
        # Back through clip space and the divide: the pixel centre and the fragment's depth.
        assert (x, y) == pytest.approx((step.pixel[0] + 0.5, step.pixel[1] + 0.5), abs=0.01)
        assert depth == pytest.approx(step.values["depth"], abs=1e-3)


@pytest.mark.parametrize("options, has_uv", [
    ({}, False), ({"uv": (0.0, 0.0, 1.0, 0.0, 0.0, 1.0)}, True), ({"texture": "checker:4"}, True)])
def test_uv_columns_only_when_the_scene_has_them(options, has_uv):
    """Model only what a scene needs: no u, v per step without uv or a texture."""
    trace = SPEC.record([(3, 3), (28, 4), (15, 20)], options, grid=(32, 24))
    assert ({"u", "v"} <= set(trace.value_names)) == has_uv
    assert "depth" in trace.value_names and len(trace.written().steps) > 50
