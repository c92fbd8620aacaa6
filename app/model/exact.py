"""The exact values behind numbers a run records as integers or floats, for
the "exact" numbers setting (app/model/notation.py).

Each comes from exact inputs, never from a float turned into a fraction:

* ``m`` of the integer line algorithms that work in the first octant
  (Bresenham, its textbook forms, the midpoint line): dy/dx of the mapped
  segment, the slope their decision variable stands for.
* ``alpha``, ``beta``, ``gamma`` of a triangle at a pixel's sample point
  (its centre), when the vertices lie on the 1/256 grid the fixed-point
  rasterizers snap to (lattice points among them): ratios of signed areas,
  that is of integer edge values in 1/256 units, e_k / 2A. Such a
  coordinate is a float exactly (2.25 is 576/256), so it is read as it is,
  not rounded to a fraction. A run whose recorded weights are not these
  (the printed test with unsigned distances, say) keeps its floats.

An ET's 1/m and x need nothing here: the scan-line algorithms keep them as
Fractions themselves.
"""
from __future__ import annotations

from fractions import Fraction

from app.model.notation import colour, colour_names, fraction

WEIGHTS = ("alpha", "beta", "gamma")
VERTICES = ("P0", "P1", "P2")
# A recorded float weight must be this close to the exact one for the exact
# one to stand in for it (float64 arithmetic on small integers is far closer).
AGREEMENT = 1e-9
EXACT_NAMES = ("m",) + WEIGHTS  # the names exact_values can give
GRID = 256  # vertices on this subpixel grid have exact weights here


def exact_values(trace, i: int, variables: dict | None = None) -> dict[str, Fraction]:
    """{name: exact value} for step i of ``trace``: the run's own values that
    have one, and ``m`` where it is implied (see the module text)."""
    if trace is None or trace.start is None:
        return {}
    variables = trace.variables_at(i) if variables is None else variables
    found = {}
    slope = octant_slope(trace.start.constants)
    if slope is not None:
        found["m"] = slope
    found.update(lattice_weights(variables, trace.step(i).pixel))
    return found


def octant_slope(constants: dict) -> Fraction | None:
    """dy/dx of a run mapped into the first octant, or None."""
    dx, dy = constants.get("dx"), constants.get("dy")
    if "octant" not in constants or not _integer(dx) or not _integer(dy) or dx == 0:
        return None
    return Fraction(int(dy), int(dx))


def lattice_weights(variables: dict, pixel) -> dict[str, Fraction]:
    """The barycentric weights at the centre of ``pixel`` of the triangle
    P0 P1 P2, when its vertices are on the 1/256 grid and the run's recorded
    weights are these; else {}."""
    if not all(name in variables for name in WEIGHTS + VERTICES) or pixel is None:
        return {}
    vertices = [variables[name] for name in VERTICES]
    if not all(len(v) >= 2 and _on_grid(v[0]) and _on_grid(v[1]) for v in vertices) \
            or not all(_integer(c) for c in pixel):
        return {}
    a, b, c = [(Fraction(v[0]), Fraction(v[1])) for v in vertices]
    p = (Fraction(2 * int(pixel[0]) + 1, 2), Fraction(2 * int(pixel[1]) + 1, 2))
    whole = area2(a, b, c)
    if whole == 0:
        return {}
    weights = dict(zip(WEIGHTS, (area2(p, b, c) / whole, area2(a, p, c) / whole,
                                 area2(a, b, p) / whole)))
    for name, value in weights.items():
        recorded = variables[name]
        if not isinstance(recorded, (int, float)) or abs(float(value) - recorded) > AGREEMENT:
            return {}
    return weights


def area2(a, b, c):
    """Twice the signed area of the triangle a b c (an integer edge value)."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _on_grid(value) -> bool:
    """A coordinate that is a whole number of 1/256 px (and so a float exactly)."""
    return _integer(value) or (isinstance(value, float) and abs(value) < 2 ** 40
                               and (value * GRID).is_integer())


def _integer(value) -> bool:
    if isinstance(value, bool):
        return False
    if isinstance(value, int):
        return True
    return isinstance(value, float) and value.is_integer()


def shown_rows(spec, trace, i: int, numbers: str = "decimal") -> list[tuple[str, str]]:
    """The variables panel's rows at step i (``spec.panel_rows``), with
    ``numbers`` "exact": every value that has an exact form as p/q, and the
    implied ``m`` added after the run's own values. Values the run declares
    as colours (``notation.colour_names``) read as #rrggbb."""
    colours = colour_names(trace.start)
    rows = [(name, colour(text) or text if name in colours else text)
            for name, text in spec.panel_rows(trace, i)]
    if numbers != "exact":
        return rows
    exact = exact_values(trace, i)
    shown = [(name, fraction(exact[name]) if name in exact else text) for name, text in rows]
    named = {name for name, _ in rows}
    return shown + [(name, fraction(value)) for name, value in exact.items() if name not in named]
