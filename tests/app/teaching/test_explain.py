"""`rasterlab check` explains a first divergence with the values that decide it.

For each family a student file with one deliberate mistake is checked on
one scene; the expected deciding values are worked out here by hand (a
Bresenham loop, exact fractions, a midpoint circle), not by RasterLab.
"""
from __future__ import annotations

import csv
import io
import json
import textwrap
from fractions import Fraction

STUDENTS = {
    "tie": """
        def draw(x0, y0, x1, y1):
            dx, dy = x1 - x0, y1 - y0
            d = 2 * dy - dx
            x, y = x0, y0
            yield x, y
            while x < x1:
                if d < 0:  # the mistake: a tie (d = 0) goes NE
                    d += 2 * dy
                else:
                    d += 2 * (dy - dx)
                    y += 1
                x += 1
                yield x, y
    """,
    "dda": """
        def draw(x0, y0, x1, y1):
            steps = max(abs(x1 - x0), abs(y1 - y0))
            x, y = float(x0), float(y0)
            yield x0, y0
            for _ in range(steps):
                x += (x1 - x0) / steps
                y += (y1 - y0) / steps
                yield round(x), round(y)  # the mistake: halves to even
    """,
    "circle": """
        def draw(xc, yc, r):
            x, y, d = 0, r, 1 - r
            seen = set()
            while x <= y:
                # the mistake: the mirror (-x, y), into octant 3, is left out
                for px, py in ((x, y), (y, x), (y, -x), (x, -y), (-x, -y), (-y, -x), (-y, x)):
                    if (px, py) not in seen:
                        seen.add((px, py))
                        yield xc + px, yc + py
                if d < 0:
                    d += 2 * x + 3
                else:
                    d += 2 * (x - y) + 5
                    y -= 1
                x += 1
    """,
    "polygon": """
        def draw(contours):
            edges = [(c[k], c[(k + 1) % len(c)]) for c in contours for k in range(len(c))]
            ys = [p[1] for c in contours for p in c]
            xs = [p[0] for c in contours for p in c]
            for j in range(int(min(ys)) - 1, int(max(ys)) + 2):
                for i in range(int(min(xs)) - 1, int(max(xs)) + 2):
                    n = 0
                    for (ax, ay), (bx, by) in edges:
                        # the mistake: an edge counts at both its ends
                        if ay != by and min(ay, by) <= j + 0.5 <= max(ay, by):
                            if ax + (j + 0.5 - ay) * (bx - ax) / (by - ay) <= i + 0.5:
                                n += 1
                    if n % 2:
                        yield i, j
    """,
    "triangle": """
        from fractions import Fraction as F

        def draw(x0, y0, x1, y1, x2, y2):
            p = [(F(x0), F(y0)), (F(x1), F(y1)), (F(x2), F(y2))]
            def e(a, b, c):
                return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
            if e(*p) < 0:
                p = [p[0], p[2], p[1]]
            for j in range(0, 16):
                for i in range(0, 16):
                    c = (i + F(1, 2), j + F(1, 2))
                    # the mistake: every centre on an edge is kept (inclusive)
                    if all(e(p[k], p[(k + 1) % 3], c) >= 0 for k in range(3)):
                        yield i, j
    """,
}


def check(run_cli, tmp_path, student: str, against: str, points, options=None) -> dict:
    """The first failed case's JSON from `rasterlab check` on a one-primitive scene."""
    path = tmp_path / f"{student}.py"
    path.write_text(textwrap.dedent(STUDENTS[student]), encoding="utf-8")
    scene = tmp_path / "case.json"
    scene.write_text(json.dumps({
        "version": 1, "grid": {"width": 32, "height": 32}, "origin": "bottom-left",
        "algorithm": against, "options": options or {}, "primitives": [{"points": points}]}))
    status, out, err = run_cli("check", path, "--against", against, "--cases", scene,
                               "--time-limit", "2", "--json")
    assert status == 1, err
    case = json.loads(out)["cases"][0]
    assert not case["passed"]
    return case


def steps_table(run_cli, algorithm: str, *points) -> list[dict]:
    status, out, err = run_cli("run", algorithm, "--points", *points, "--steps", "--csv")
    assert status == 0, err
    return list(csv.DictReader(io.StringIO(out)))


def test_a_tie_broken_the_wrong_way_names_d_and_the_tie_rule(run_cli, tmp_path):
    case = check(run_cli, tmp_path, "tie", "line-bresenham", [[0, 0], [8, 2]])
    # Bresenham by hand for (0, 0) -> (8, 2): the first pixel whose d is 0.
    dx, dy, d, pixel = 8, 2, 2 * 2 - 8, 0
    while d != 0:
        d += 2 * dy if d < 0 else 2 * (dy - dx)
        pixel += 1
    pixel += 1  # a step shows the d that decided its pixel
    # the window numbers steps as `run --steps` does: find that pixel's row there
    rows = [row for row in steps_table(run_cli, "line-bresenham", "0,0", "8,2") if row["pixel"]]
    step = rows[pixel]["step"]
    divergence = case["reference_divergence"]
    assert divergence["where"] == f"step {step}"
    assert divergence["explanation"].startswith(
        "d = 0 is a tie: this algorithm goes E on a tie; you went NE")
    assert case["message"].startswith(f"differs from the reference: step {step}: ")


def test_python_round_shows_y_before_rounding_and_the_rule(run_cli, tmp_path):
    case = check(run_cli, tmp_path, "dda", "line-dda", [[0, 0], [6, 3]])
    # y after i steps is i * 3/6: the first half-way y is at i = 1
    i = next(i for i in range(7) if Fraction(3 * i, 6).denominator == 2)
    y = Fraction(3 * i, 6)
    up = int(y + Fraction(1, 2))
    explanation = case["reference_divergence"]["explanation"]
    assert f"y = {float(y)!r} before rounding" in explanation
    assert f"round means floor(y + 1/2) = {up}, you gave {up - 1}" in explanation
    assert f"round({float(y)!r}) = {up - 1}" in explanation


def test_a_missing_octant_is_named_with_its_pixels(run_cli, tmp_path):
    centre, r = (16, 16), 5
    case = check(run_cli, tmp_path, "circle", "circle-midpoint", [list(centre)], {"radius": r})
    # the midpoint circle's first octant by hand; its mirrors (-x, y) off the axis
    # and the diagonal lie strictly in octant 3 (x < 0, |y| > |x|), and no other
    # mirror the student yields reaches them
    first, x, y, d = [], 0, r, 1 - r
    while x <= y:
        first.append((x, y))
        d, x, y = (d + 2 * x + 3, x + 1, y) if d < 0 else (d + 2 * (x - y) + 5, x + 1, y - 1)
    octant3 = sorted((centre[0] - a, centre[1] + b) for a, b in first if 0 < a < b)
    assert octant3
    explanation = case["reference_divergence"]["explanation"]
    listed = ", ".join(f"({px}, {py})" for px, py in octant3)
    assert explanation.startswith(f"centre ({centre[0]}, {centre[1]}), radius {r}")
    assert f"missing: {len(octant3)} in octant 3 ({listed})" in explanation
    assert "extra" not in explanation


def test_a_wrong_crossing_rule_shows_the_scan_line_and_its_crossings(run_cli, tmp_path):
    square = [[1.5, 1.5], [8.5, 1.5], [8.5, 8.5], [1.5, 8.5]]
    case = check(run_cli, tmp_path, "polygon", "polygon-scanline", square)
    explanation = case["reference_divergence"]["explanation"]
    # the student fills (1, 8): its centre's scan line y = 8.5 runs through the top
    # corners, the upper ends of both upright edges, so no edge counts there
    assert case["reference_divergence"]["got"] == "pixel (1, 8)"
    assert explanation.startswith("(1, 8): vertices (1.5, 1.5) (8.5, 1.5) (8.5, 8.5) (1.5, 8.5)")
    assert "the scan line y = 8.5 crosses the edges at x = none" in explanation
    assert "an edge whose upper end lies on it, at x = 1.5, 8.5, does not" in explanation
    assert explanation.endswith("0 at or left of the centre: outside by the even-odd rule")


def test_an_inclusive_fill_rule_names_the_edge_value_and_the_top_left_rule(run_cli, tmp_path):
    corners = [(2, 2), (12, 3), (5, 10)]
    case = check(run_cli, tmp_path, "triangle", "triangle-bbox", [list(p) for p in corners])
    divergence = case["reference_divergence"]
    pixel = tuple(int(v) for v in divergence["got"][len("pixel ("):-1].split(", "))
    centre = (Fraction(2 * pixel[0] + 1, 2), Fraction(2 * pixel[1] + 1, 2))
    (ax, ay), (bx, by) = corners[1], corners[2]  # the edge (12, 3) -> (5, 10), going up
    on_edge = (bx - ax) * (centre[1] - ay) - (by - ay) * (centre[0] - ax)
    assert on_edge == 0 and by > ay  # going up on a counter-clockwise triangle: a right edge
    assert divergence["expected"] == f"no pixel ({pixel[0]}, {pixel[1]})"
    assert divergence["explanation"].startswith(
        f"({pixel[0]}, {pixel[1]}): at its centre ({float(centre[0])}, {float(centre[1])}) e0 = 0")
    assert divergence["explanation"].endswith(
        "its centre lies on a right edge (e0, from (12, 3) to (5, 10)); "
        "the top-left rule leaves it out")
    # the student yields row by row from (0, 0): the pixel's yield, counted from 1
    yields = [(i, j) for j in range(16) for i in range(16) if inside_or_on(corners, (i, j))]
    assert divergence["where"] == f"yield {yields.index(pixel) + 1}"


def inside_or_on(corners, pixel) -> bool:
    """The student's (inclusive) test, on a counter-clockwise triangle."""
    centre = (Fraction(2 * pixel[0] + 1, 2), Fraction(2 * pixel[1] + 1, 2))
    return all((b[0] - a[0]) * (centre[1] - a[1]) - (b[1] - a[1]) * (centre[0] - a[0]) >= 0
               for a, b in zip(corners, corners[1:] + corners[:1]))
