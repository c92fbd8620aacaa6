"""`run --json`'s fragments for the triangle, visibility and pipeline families:
parallel to the pixels, and equal to exact rational interpolation at the centres."""
from __future__ import annotations

import json
from fractions import Fraction as F

import pytest

# (name, points, grid, settings): an ordinary pair (the second clockwise, so the
# run swaps P1 and P2), a sliver, and a triangle at huge coordinates (moved by
# the offset option, beyond 2 million px, where the edge values are ~1e13).
CASES = [
    ("pair", ["2,2", "20,5", "8,18", "9,3", "3,12", "14,14"], "24,24", ()),
    ("sliver", ["1,1", "30,3", "15,2.25"], "32,8", ()),
    ("huge", ["0.5,1", "15,2.75", "4.25,15.5"], "16,16", ("offset=2000000,-2000000",)),
]
TRAVERSALS = ["triangle-scan", "triangle-bbox", "triangle-incremental", "triangle-backtrack",
              "triangle-pineda", "triangle-linewise", "triangle-halfplane",
              "triangle-barycentric", "triangle-plane", "triangle-perspective",
              "triangle-texture"]


def _vertices(points):
    corners = [tuple(F(c) for c in p.split(",")) for p in points]
    return [corners[k:k + 3] for k in range(0, len(corners), 3)]


def exact_weights(triangle, x, y):
    """The barycentric weights of (x + 1/2, y + 1/2): sub-triangle areas over the area."""
    def area(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
    p = (F(x) + F(1, 2), F(y) + F(1, 2))
    p0, p1, p2 = triangle
    whole = area(p0, p1, p2)
    return [area(p, p1, p2) / whole, area(p0, p, p2) / whole, area(p0, p1, p) / whole]


def run_json(run_cli, name, points, grid, *settings):
    extra = [word for s in settings for word in ("--set", s)]
    status, out, err = run_cli("run", name, "--points", *points, "--grid", grid, *extra,
                               "--json")
    assert status == 0, err
    result = json.loads(out)
    assert len(result["fragments"]) == len(result["pixels"]) > 0
    return result


@pytest.mark.parametrize("name", TRAVERSALS)
@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_weights_at_each_pixel_centre(run_cli, name, case):
    _, points, grid, settings = case
    result = run_json(run_cli, name, points, grid, *settings)
    triangles = _vertices(points)
    for (x, y), fragment in zip(result["pixels"], result["fragments"]):
        exact = exact_weights(triangles[fragment["triangle"] - 1], x, y)
        assert all(w >= 0 for w in exact)  # a pixel the triangle covers
        assert fragment["weights"] == pytest.approx([float(w) for w in exact], abs=1e-12)


def _interpolated(weights, values):
    return sum(w * F(v) for w, v in zip(weights, values))


@pytest.mark.parametrize("case", CASES[:2], ids=[c[0] for c in CASES[:2]])
def test_plane_z_and_perspective_attributes(run_cli, case):
    _, points, grid, _ = case
    z = ["0.25", "0.5", "0.875"]
    w, s = ["1", "4", "2"], ["4", "6", "10"]
    plane = run_json(run_cli, "triangle-plane", points, grid, "z=" + ",".join(z))
    persp = run_json(run_cli, "triangle-perspective", points, grid, "z=" + ",".join(z),
                     "w=" + ",".join(w), "s=" + ",".join(s))
    triangles = _vertices(points)
    for result in (plane, persp):
        for (x, y), fragment in zip(result["pixels"], result["fragments"]):
            exact = exact_weights(triangles[fragment["triangle"] - 1], x, y)
            assert fragment["z"] == pytest.approx(float(_interpolated(exact, z)), abs=1e-12)
    for (x, y), fragment in zip(persp["pixels"], persp["fragments"]):
        exact = exact_weights(triangles[fragment["triangle"] - 1], x, y)
        over_w = _interpolated(exact, [1 / F(v) for v in w])
        correct = [b / F(v) / over_w for b, v in zip(exact, w)]
        assert fragment["1/w"] == pytest.approx(float(over_w), abs=1e-12)
        assert fragment["weights_p"] == pytest.approx([float(c) for c in correct], abs=1e-12)
        assert fragment["s_persp"] == pytest.approx(float(_interpolated(correct, s)), abs=1e-12)


def test_keys_follow_the_options_given(run_cli):
    points, grid = CASES[0][1], CASES[0][2]
    bare = run_json(run_cli, "triangle-bbox", points, grid)
    assert set(bare["fragments"][0]) == {"triangle", "weights"}
    coloured = run_json(run_cli, "triangle-bbox", points, grid, "colors=#ff0000,#00ff00,#0000ff")
    assert [f["color"] for f in coloured["fragments"]] == coloured["values"]


@pytest.mark.parametrize("name", ["zbuffer", "painter"])
def test_depth_family_reports_the_fragment_written(run_cli, name):
    # Two overlapping triangles at different depths: each fragment's z is its own
    # triangle's interpolation and its colour the one written at that pixel.
    points = ["1,1", "14,2", "4,13", "3,3", "15,12", "2,14"]
    z = ["0.1", "0.9", "0.5", "0.7", "0.2", "0.3"]
    result = run_json(run_cli, name, points, "16,16", "z=" + ",".join(z),
                      "colors=#ff0000,#ff0000,#ff0000,#0000ff,#0000ff,#0000ff")
    triangles = _vertices(points)
    for (x, y), fragment in zip(result["pixels"], result["fragments"]):
        n = fragment["triangle"] - 1
        exact = exact_weights(triangles[n], x, y)
        assert fragment["z"] == pytest.approx(float(_interpolated(exact, z[3 * n:3 * n + 3])),
                                              abs=1e-12)
        assert fragment["color"] == ("#ff0000", "#0000ff")[n]
    assert [f["color"] for f in result["fragments"]] == result["values"]


def test_blend_over_reports_alpha_and_the_composite(run_cli):
    points = ["1,1", "14,2", "4,13", "3,3", "15,12", "2,14"]
    alpha = ["0.2", "0.6", "1", "0.5", "0.5", "0.5"]
    result = run_json(run_cli, "blend-over", points, "16,16", "alpha=" + ",".join(alpha),
                      "colors=#ff0000,#ff0000,#ff0000,#0040ff,#0040ff,#0040ff")
    triangles = _vertices(points)
    for (x, y), fragment in zip(result["pixels"], result["fragments"]):
        n = fragment["triangle"] - 1
        a = _interpolated(exact_weights(triangles[n], x, y), alpha[3 * n:3 * n + 3])
        assert fragment["alpha"] == pytest.approx(float(a), abs=1e-12)
        src, dst, out = (_rgb(fragment[k]) for k in ("source", "before", "color"))
        for s, d, o in zip(src, dst, out):
            assert abs(o - float(a * s + (1 - a) * d)) <= 0.5 + 1e-9


def _rgb(text):
    return [int(text[k:k + 2], 16) for k in (1, 3, 5)]


def test_pipeline_final_holds_clip_and_window_coordinates(run_cli):
    # The default camera looks down -z from (16, 12, 40) at the z = 0 plane: a
    # world point (x, y, 0) is 40 in front, so clip w = 40, and the viewport maps
    # NDC (clip / w) to the grid: x_win = (x_ndc + 1) W / 2.
    points = ["2,2", "20,5", "8,18"]
    result = run_json(run_cli, "pipeline", points, "32,24")
    final = result["final"]
    assert len(final["clip"]) == len(final["window"]) == 3
    for clip, window in zip(final["clip"], final["window"]):
        assert clip[3] == pytest.approx(40.0)
        assert window[0] == pytest.approx((clip[0] / clip[3] + 1) * 32 / 2)
        assert window[1] == pytest.approx((clip[1] / clip[3] + 1) * 24 / 2)
    assert all(f["triangle"] == 1 and 0 <= f["depth"] <= 1 for f in result["fragments"])


def test_fragments_printed_in_parts_equal_one_part(run_cli, monkeypatch):
    from app import cli
    points, grid = CASES[0][1], CASES[0][2]
    whole = run_json(run_cli, "triangle-perspective", points, grid)
    monkeypatch.setattr(cli.Rows, "PART", 7)  # many parts, one cut inside each triangle
    parts = run_json(run_cli, "triangle-perspective", points, grid)
    assert parts == whole and len(whole["fragments"]) > 7 * 10
