"""Steps in words: each family's description holds the values worked out
here by hand from the lecture notes' formulas, not read from the run."""
from fractions import Fraction

import pytest

from algorithms.core import registry

from app.model import runs
from app.model.step_words import describe, describe_steps


def record(algorithm, points, options=None, grid=(12, 10)):
    spec = registry.get(algorithm)
    return runs.record(spec, spec.inputs.check(points), spec.resolve(options or {}), grid, 100_000)


def test_bresenham_0_0_to_5_2_step_by_step():
    """The textbook's d: d = 2dy - dx, then + 2dy after E, + 2(dy - dx) after NE."""
    trace = record("line-bresenham", [(0, 0), (5, 2)])
    dx, dy = 5, 2
    d, x, y = 2 * dy - dx, 0, 0
    expected = []
    while x < 5:
        if d <= 0:
            x, branch, words = x + 1, "E", "at most"
            shown, d = d, d + 2 * dy
        else:
            x, y, branch, words = x + 1, y + 1, "NE", "above"
            shown, d = d, d + 2 * (dy - dx)
        expected.append(f"d = {shown}, {words} 0, so {branch}: plot ({x}, {y})")
    last = len(trace) - 1
    found = [text for text in describe_steps(trace) if ", so " in text]
    assert found == [f"step {i} of {last}: {text}" for i, text in enumerate(expected, 2)]
    assert expected[0] == "d = -1, at most 0, so E: plot (1, 0)"


def test_midpoint_circle_decision_compares_with_its_own_test():
    """d = 1 - R; below 0: E, d += 2x + 3; else SE (the notes' integer form)."""
    trace = record("circle-midpoint", [(10, 10)], {"radius": 4}, (20, 20))
    decisions = [text.split(": ", 1)[1] for text in describe_steps(trace) if ", so " in text]
    d, x, y = 1 - 4, 0, 4
    expected = []
    while y > x:
        if d < 0:
            expected.append(f"d = {d}, below 0, so E: now at ({10 + x + 1}, {10 + y})")
            d, x = d + 2 * x + 3, x + 1
        else:
            expected.append(f"d = {d}, at least 0, so SE: now at ({10 + x + 1}, {10 + y - 1})")
            d, x, y = d + 2 * (x - y) + 5, x + 1, y - 1
    assert decisions == expected


def _crossing(p, q, centre):
    (x0, y0), (x1, y1) = p, q
    return Fraction(x0) + (Fraction(centre) - y0) * Fraction(x1 - x0, y1 - y0)


def test_scan_line_span_names_the_scan_line_crossings_and_pixels():
    vertices = [(1, 1), (8, 2), (5, 7)]
    trace = record("polygon-scanline", [vertices])
    centre = Fraction(3, 2)  # row 1's scan line
    left = _crossing(vertices[2], vertices[0], centre)   # 4/3
    right = _crossing(vertices[0], vertices[1], centre)  # 9/2
    filled = [i for i in range(12) if left <= i + Fraction(1, 2) < right]
    exact = [text for text in describe_steps(trace, "exact") if "row 1" in text]
    assert exact == [f"step 7 of {len(trace) - 1}: scan line y = 1 + 1/2 crosses the edges at "
                     f"x = {left}, {right}; fill pixels {filled[0]} to {filled[-1]} of row 1"]
    decimal = describe(trace, 7)
    assert f"x = {left} ({float(left):.4f}), {right} ({float(right):g})" in decimal


def test_triangle_pixels_inside_outside_and_why():
    p = [(1, 1), (6, 2), (3, 6)]
    trace = record("triangle-bbox", p, grid=(8, 8))

    def edge(k, x, y):  # edge k joins the two other vertices, Pi -> Pj
        (xi, yi), (xj, yj) = p[(k + 1) % 3], p[(k + 2) % 3]
        return (yi - yj) * x + (xj - xi) * y + (xi * yj - yi * xj)

    texts = {text.split(": ", 1)[1].split(":")[0]: text for text in describe_steps(trace)}
    for pixel, verdict in (((2, 2), "inside"), ((4, 1), "outside"), ((1, 2), "outside")):
        e = [edge(k, pixel[0] + 0.5, pixel[1] + 0.5) for k in range(3)]
        text = texts[f"pixel {pixel}"]
        assert f"e0 = {e[0]:g}, e1 = {e[1]:g}, e2 = {e[2]:g}" in text
        assert verdict + ":" in text
        negative = [f"e{k}" for k in range(3) if e[k] < 0]
        if negative:
            assert f"outside: {', '.join(negative)} is negative" in text
        else:
            assert text.endswith("so plot it")
    # (3, 1)'s centre lies on edge 2: the top-left rule leaves out a bottom edge.
    assert edge(2, 3.5, 1.5) == 0
    assert "on edge e2, and the fill rule leaves it out" in texts["pixel (3, 1)"]


def test_antialiased_line_says_the_coverage():
    """Wu: the near pixel gets 1 - e/dx, the far one e/dx, e growing by dy."""
    trace = record("line-wu", [(0, 0), (6, 2)], grid=(8, 8))
    texts = describe_steps(trace)
    assert any(text.endswith(f"near pixel (1, 0) gets coverage intensity = {1 - 2 / 6:.5f}")
               for text in texts)
    assert any(text.endswith(f"far pixel (1, 1) gets coverage intensity = {2 / 6:.5f}")
               for text in texts)


def test_depth_test_passes_on_an_empty_buffer():
    trace = record("zbuffer", [(1, 1), (8, 2), (4, 7)], {"z": (0.5, 0.5, 0.5)}, (10, 8))
    texts = [text for text in describe_steps(trace) if "fragment at" in text]
    assert texts and all("z = 0.5 against ZB = 1, the depth test passes" in text
                         for text in texts)


def test_flood_fill_steps_say_the_pixel_taken_and_filled():
    trace = record("flood-fill", [[(1, 1), (7, 1), (7, 6), (1, 6)]], grid=(9, 8))
    texts = describe_steps(trace)
    assert len(texts) == len(trace)
    assert any("p = pop(); visit (" in text for text in texts)
    assert any(text.startswith("step ") and "fill p;" in text and "plot (" in text
               for text in texts)


def test_bad_numbers_setting_is_refused():
    trace = record("line-bresenham", [(0, 0), (5, 2)])
    with pytest.raises(ValueError, match="numbers must be"):
        describe(trace, 1, "roman")
