"""The inspector's sign conventions: the values shown at random pixels
equal exact fractions worked out here from the notes' own formulas, and
the two edge conventions differ in sign only."""
from __future__ import annotations

import re
from fractions import Fraction

from hypothesis import assume, given, settings, strategies as st

from algorithms.core import registry
from app.model.inspector import inspect

GRID = (24, 18)
coordinate = st.integers(0, 256 * GRID[1]).map(lambda v: Fraction(v, 256))
vertex = st.tuples(coordinate, coordinate)


def implicit(p, q, point):
    """Note 003's line through p and q: (y_p - y_q) x + (x_q - x_p) y + x_p y_q - x_q y_p."""
    (xp, yp), (xq, yq), (x, y) = p, q, point
    return (yp - yq) * x + (xq - xp) * y + xp * yq - xq * yp


def determinant(p, q, point):
    """Note 000's E: the determinant | q - p, point - p |."""
    return (q[0] - p[0]) * (point[1] - p[1]) - (q[1] - p[1]) * (point[0] - p[0])


def shown(rows) -> dict[str, str]:
    return {row.label: row.value for row in rows if row.section == "Sign conventions"}


def fractions(text: str) -> list[Fraction]:
    return [Fraction(t) for t in re.findall(r"-?\d+(?:/\d+)?", text)]


@settings(max_examples=40)
@given(st.lists(vertex, min_size=3, max_size=3), st.integers(0, GRID[0] - 1),
       st.integers(0, GRID[1] - 1), st.sampled_from(["triangle-halfplane", "triangle-bbox"]))
def test_the_values_shown_are_the_exact_ones_and_differ_in_sign_only(tri, x, y, algorithm):
    a, b, c = tri
    assume(determinant(a, b, c) != 0)
    spec = registry.get(algorithm)
    points = [tuple(map(float, v)) for v in tri]
    trace = spec.record(points, {}, GRID)
    rows = shown(inspect(trace, len(trace) - 1, (x, y), spec, points, {}, GRID))
    p = (x + Fraction(1, 2), y + Fraction(1, 2))
    ccw = determinant(a, b, c) > 0
    assert rows["winding"].startswith("a, b, c as given: "
                                      + ("counter-clockwise" if ccw else "clockwise"))
    signs = []
    for name, (u, v) in {"ab": (a, b), "bc": (b, c), "ca": (c, a)}.items():
        e, n = fractions(rows[f"edge {name}"].split("(000")[0])[0], \
            fractions(rows[f"edge {name}"].split("c =")[1])[0]
        assert e == determinant(u, v, p) == implicit(u, v, p)
        assert n == -e  # note 004: the normal form is negative where note 000's E is positive
        signs.append(e)
    alpha = implicit(b, c, p) / implicit(b, c, a)
    beta = implicit(a, c, p) / implicit(a, c, b)
    assert fractions(rows["alpha = f_bc(p) / f_bc(a)"]) == [implicit(b, c, p), implicit(b, c, a),
                                                           alpha]
    assert fractions(rows["beta = f_ac(p) / f_ac(b)"]) == [implicit(a, c, p), implicit(a, c, b),
                                                          beta]
    gamma = 1 - alpha - beta
    assert fractions(rows["areal (sum 1)"]) == [alpha, beta, gamma]
    area = abs(determinant(a, b, c)) / 2
    [label] = [k for k in rows if k.startswith("homogeneous")]
    assert fractions(label) == [area]
    assert fractions(rows[label]) == [alpha * area, beta * area, gamma * area]
    # inside is all three E positive (counter-clockwise) or all negative
    # (clockwise), which is every weight positive either way
    inside = all(s > 0 for s in signs) if ccw else all(s < 0 for s in signs)
    assert inside == (alpha > 0 and beta > 0 and gamma > 0)


def test_the_shipped_scene_shows_a_clockwise_triangle():
    from app.model.scene import load
    from app.model.shipped import scene_path
    scene = load(scene_path("triangle-sign-conventions"))
    spec = registry.get(scene.algorithm)
    trace = spec.record(scene.points, dict(scene.options), (scene.width, scene.height))
    rows = shown(inspect(trace, len(trace) - 1, (14, 10), spec, scene.points,
                         dict(scene.options), (scene.width, scene.height)))
    assert rows["winding"] == "a, b, c as given: clockwise: inside is to the right of ab, bc, ca"
    assert all(fractions(rows[f"edge {k}"])[0] < 0 for k in ("ab", "bc", "ca"))
