"""Interpolation across triangles: barycentric weights, the parameter plane, perspective.

Exact references come from exact_triangles (Cramer's rule on Fractions);
the functions of algorithms/triangles/interpolate.py also run on Fractions, so
several checks are exact equalities rather than tolerances.
"""
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import triangles as X
from algorithms.triangles import interpolate as I
from algorithms.core.registry import InputError
from test_triangles_cases import run_frames, spec, subgrid_triangle

values = st.integers(-50, 50).map(float)
positive = st.integers(1, 40).map(lambda n: n / 4)


def frames_by_pixel(name, points, options, grid=(12, 10)):
    """Covered pixels -> their frame values (as a dict of column name -> value)."""
    s = spec(name)
    options = s.resolve(options)
    first = next(s.generator(points, options, grid))
    lines, frames = run_frames(name, points, options, grid)
    result = {}
    for f in frames:
        if type(f) is tuple and lines[f[0]].kind == "plot":
            result[(f[1], f[2])] = dict(zip(first.values, f[3:]))
    return result


def centre(pixel):
    return (Fraction(2 * pixel[0] + 1, 2), Fraction(2 * pixel[1] + 1, 2))


def nondegenerate(points):
    return X.twice_area([(Fraction(x), Fraction(y)) for x, y in points]) != 0


# ------------------------------------------------------- the worked example
def test_the_worked_example_affine_five_perspective_four_and_a_half():
    # Half way between s = 4 at w = 1 and s = 6 at w = 3.
    half = (Fraction(1, 2), Fraction(1, 2), Fraction(0))
    s, w = (4, 6, 0), (1, 3, 1)
    assert I.affine_value(half, s) == 5
    assert I.perspective_value(half, s, w) == Fraction(9, 2)
    assert X.perspective_correct(half, s, w) == Fraction(9, 2)
    # s/w interpolates to 3 and 1/w to 2/3; their quotient is 4.5.
    assert I.affine_value(half, [Fraction(4, 1), Fraction(6, 3), 0]) == 3
    assert I.affine_value(half, [Fraction(1, 1), Fraction(1, 3), 0]) == Fraction(2, 3)


def test_the_worked_example_in_a_trace():
    # P0 -> P1 runs through pixel centres; (4, 0) is its midpoint.
    pixels = frames_by_pixel("triangle-perspective", [(0.5, 0.5), (8.5, 0.5), (0.5, 8.5)],
                             {"s": (4, 6, 6), "w": (1, 3, 3)})
    mid = pixels[(4, 0)]
    assert mid["alpha"] == 0.5 and mid["beta"] == 0.5 and mid["gamma"] == 0.0
    assert mid["s_affine"] == 5.0
    assert mid["s/w"] == 3.0 and mid["1/w"] == pytest.approx(2 / 3)
    assert mid["s_persp"] == pytest.approx(4.5, abs=1e-12)


# ------------------------------------------------------- barycentric weights
@settings(max_examples=40)
@given(subgrid_triangle(0, 10))
def test_weights_sum_to_one_and_equal_cramers_rule(points):
    if not nondegenerate(points):
        return
    pixels = frames_by_pixel("triangle-barycentric", points, {})
    snapped = X.snap_triangle(points, 8)
    snapped = X.counter_clockwise(snapped)
    for pixel, v in pixels.items():
        exact = X.barycentric(snapped, centre(pixel))
        assert sum(exact) == 1
        for name, want in zip(("alpha", "beta", "gamma"), exact):
            assert v[name] == float(want)  # the frames round the exact ratio once
        assert v["alpha"] + v["beta"] + v["gamma"] == pytest.approx(1, abs=1e-12)


def test_weights_from_edge_functions_are_exact_on_fractions():
    tri = [(Fraction(1, 4), Fraction(0)), (Fraction(9), Fraction(1, 2)), (Fraction(3), Fraction(7))]
    for point in [(Fraction(2), Fraction(2)), tri[0], tri[1], tri[2], (Fraction(-5), Fraction(3))]:
        e = [X.cross(tri[(k + 1) % 3], tri[(k + 2) % 3], point) for k in range(3)]
        weights = I.barycentric_weights(*e, X.twice_area(tri))
        assert weights == X.barycentric(tri, point)
        assert sum(weights) == 1
    for k, vertex in enumerate(tri):
        e = [X.cross(tri[(m + 1) % 3], tri[(m + 2) % 3], vertex) for m in range(3)]
        weights = I.barycentric_weights(*e, X.twice_area(tri))
        assert weights == tuple(Fraction(int(m == k)) for m in range(3))


@settings(max_examples=40)
@given(subgrid_triangle(0, 10), st.tuples(values, values, values))
def test_vertex_values_are_reproduced_at_the_vertices(points, q):
    if not nondegenerate(points):
        return
    snapped = X.snap_triangle(points, 8)
    for k, vertex in enumerate(snapped):
        assert I.affine_value(X.barycentric(snapped, vertex), q) == q[k]
        assert I.plane_value(snapped, [Fraction(v) for v in q], *vertex) == q[k]
        w = (Fraction(1), Fraction(2), Fraction(5))
        assert I.perspective_value(X.barycentric(snapped, vertex), q, w) == q[k]


def test_vertex_colours_land_on_vertex_pixels():
    colors = ("#ff0000", "#00ff00", "#0000ff")
    pixels = frames_by_pixel("triangle-bbox", [(0.5, 0.5), (8.5, 0.5), (0.5, 8.5)],
                             {"colors": colors, "fill_rule": "inclusive"})
    for pixel, color in zip([(0, 0), (8, 0), (0, 8)], colors):
        assert pixels[pixel]["rgb"] == int(color[1:], 16)


# ---------------------------------------------- the parameter plane (Cramer)
@settings(max_examples=40)
@given(subgrid_triangle(0, 10), st.tuples(values, values, values))
def test_the_parameter_plane_equals_barycentric_interpolation_exactly(points, q):
    if not nondegenerate(points):
        return
    snapped = X.snap_triangle(points, 8)
    q = [Fraction(v) for v in q]
    cx, cy = I.plane_coefficients(snapped, q)
    (x0, y0) = snapped[0]
    # the incremental walk of triangle-plane (q += c_x, q_row += c_y), exactly, on a 12 x 10 box
    q_row = q[0] + cx * (Fraction(1, 2) - x0) + cy * (Fraction(1, 2) - y0)
    for j in range(10):
        value = q_row
        for i in range(12):
            assert value == I.affine_value(X.barycentric(snapped, centre((i, j))), q)
            value += cx
        q_row += cy


@settings(max_examples=25)
@given(subgrid_triangle(0, 10), st.tuples(values, values, values))
def test_the_plane_trace_agrees_with_the_barycentric_trace(points, z):
    if not nondegenerate(points):
        return
    plane = frames_by_pixel("triangle-plane", points, {"z": z, "colors": ()})
    bary = frames_by_pixel("triangle-barycentric", points, {"z": z})
    assert plane.keys() == bary.keys()
    for pixel in plane:
        assert plane[pixel]["z"] == pytest.approx(bary[pixel]["z"], abs=1e-9)


def test_plane_colours_match_gouraud_shading():
    colors = ("#ff0000", "#00ff00", "#0000ff")
    points = [(0.3, 0.2), (11.1, 1.7), (4.4, 9.6)]
    plane = frames_by_pixel("triangle-plane", points, {"colors": colors})
    gouraud = frames_by_pixel("triangle-bbox", points, {"colors": colors})
    for pixel in plane:
        a, b = int(plane[pixel]["rgb"]), int(gouraud[pixel]["rgb"])
        for shift in (16, 8, 0):  # the plane walk accumulates rounding: within one step
            assert abs(((a >> shift) & 255) - ((b >> shift) & 255)) <= 1


# -------------------------------------------------- perspective correction
@settings(max_examples=40)
@given(subgrid_triangle(0, 10), st.tuples(values, values, values),
       st.tuples(positive, positive, positive))
def test_affine_and_perspective_values_match_exact_formulas(points, s, w):
    if not nondegenerate(points):
        return
    pixels = frames_by_pixel("triangle-bbox", points, {"s": s, "w": w, "z": s})
    snapped = X.snap_triangle(points, 8)
    swapped = X.twice_area(snapped) < 0
    if swapped:  # attributes travel with their vertices
        snapped, s, w = X.counter_clockwise(snapped), (s[0], s[2], s[1]), (w[0], w[2], w[1])
    for pixel, v in pixels.items():
        weights = X.barycentric(snapped, centre(pixel))
        assert v["s_affine"] == pytest.approx(float(X.affine(weights, s)), abs=1e-9)
        assert v["z"] == pytest.approx(float(X.affine(weights, s)), abs=1e-9)
        assert v["s_persp"] == pytest.approx(float(X.perspective_correct(weights, s, w)), abs=1e-9)
        assert v["1/w"] == pytest.approx(float(X.affine(weights, [Fraction(1) / Fraction(x) for x in w])))
        assert v["alpha_p"] + v["beta_p"] + v["gamma_p"] == pytest.approx(1, abs=1e-12)


def test_equal_w_makes_perspective_and_affine_agree():
    pixels = frames_by_pixel("triangle-bbox", [(0.3, 0.2), (11.1, 1.7), (4.4, 9.6)],
                             {"s": (1, 5, -3), "w": (2, 2, 2)})
    for v in pixels.values():
        assert v["s_persp"] == pytest.approx(v["s_affine"], abs=1e-12)


def test_perspective_colours_differ_from_affine_when_w_differs():
    points = [(0.3, 0.2), (11.1, 1.7), (4.4, 9.6)]
    base = {"colors": ("#ff0000", "#00ff00", "#0000ff"), "w": (1, 4, 9)}
    affine = frames_by_pixel("triangle-bbox", points, base)
    corrected = frames_by_pixel("triangle-bbox", points, {**base, "perspective": True})
    assert any(affine[p]["rgb"] != corrected[p]["rgb"] for p in affine)
    for v in corrected.values():
        assert not math.isnan(v["rgb"])


# ------------------------------------------------------------ bad input
@pytest.mark.parametrize("w", [(0, 1, 1), (1, -2, 1), (1, 1, -0.5)])
def test_w_not_positive_is_an_input_error(w):
    for name in ("triangle-bbox", "triangle-perspective"):
        with pytest.raises(InputError, match="w"):
            spec(name).record([(0, 0), (5, 0), (0, 5)], {"s": (1, 2, 3), "w": w})


def test_a_zero_or_infinite_one_over_w_sum_is_an_input_error_not_nan():
    with pytest.raises(InputError):
        I.perspective_weights((0.5, -0.5, 0.0), (1.0, 1.0, 1.0))
    with pytest.raises(InputError):
        I.perspective_weights((0.5, 0.5, 0.0), (1e-320, 1.0, 1.0))  # 1/w overflows
    with pytest.raises(InputError):
        spec("triangle-perspective").record([(0, 0), (5, 0), (0, 5)],
                                            {"s": (1, 2, 3), "w": (1e-320, 1, 1)})


def test_huge_and_tiny_w_still_give_finite_values():
    pixels = frames_by_pixel("triangle-perspective", [(0, 0), (9, 0), (0, 9)],
                             {"s": (1, 2, 3), "w": (1e-300, 1e300, 1.0),
                              "colors": ("#ff0000", "#00ff00", "#0000ff")})
    for v in pixels.values():
        assert all(not math.isnan(x) for x in v.values())


def test_attribute_lists_need_one_value_per_point_or_three():
    points = [(0, 0), (5, 0), (0, 5), (5, 0), (5, 5), (0, 5)]
    trace = spec("triangle-bbox").record(points, {"z": (1, 2, 3)})  # three, shared
    assert "z" in trace.value_names
    trace = spec("triangle-bbox").record(points, {"z": (1, 2, 3, 4, 5, 6)})
    assert "z" in trace.value_names
    with pytest.raises(InputError, match="one value per point"):
        spec("triangle-bbox").record(points, {"z": (1, 2)})
    with pytest.raises(InputError, match="one value per point"):
        spec("triangle-bbox").record(points, {"colors": ("#ffffff",) * 4})
    with pytest.raises(InputError, match="needs w|give w"):
        spec("triangle-bbox").record(points, {"perspective": True})


def test_the_numbers_option_kind():
    option = spec("triangle-bbox").option("z")
    assert option.parse("1,2.5,-3") == (1.0, 2.5, -3.0)
    assert option.parse("") == ()
    for bad in ("1,x", "nan,1,2", "1,inf,2"):
        with pytest.raises(InputError):
            option.parse(bad)
    with pytest.raises(InputError):
        option.check("1,2,3")
    assert option.describe()["type"] == "numbers"


def test_pack_and_mix_round_half_up_and_clamp():
    assert I.pack((255.4, 0.5, -3)) == 0xFF0100
    assert I.mix((Fraction(1, 2), Fraction(1, 2), 0), [(255, 0, 0), (0, 0, 255), (0, 0, 0)]) == 0x800080
    assert np.isclose(I.plane_coefficients([(0, 0), (1, 0), (0, 1)], [1, 3, 5]), (2, 4)).all()
