"""One pixel under the sign conventions the lecture notes use, side by side.

* Edge functions (note 000): E_pq(x, y) = (q_x - p_x)(y - p_y) - (q_y - p_y)(x - p_x),
  positive to the left of p -> q, so positive inside a counter-clockwise
  triangle. The implicit line f_pq of note 003 is the same function.
* Normal form (note 004): n . x - c with n = (q_y - p_y, -(q_x - p_x)), the
  normal to the right of p -> q, and c = n . p: negative to the left of
  the edge, so negative inside a counter-clockwise triangle. It is -E_pq,
  always: the two conventions disagree in sign and in nothing else.
* Barycentric coordinates (note 003): beta = f_ac(x, y) / f_ac(b), the
  edge value at the point over its value at the opposite vertex, and so
  for alpha (edge bc, vertex a); gamma = 1 - alpha - beta. These are the
  areal (absolute) coordinates, summing to 1; the homogeneous ones are
  the same times the triangle's area A and sum to A.

Every value is an exact fraction of the vertices and the point.
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

EDGES = ("ab", "bc", "ca")


def edge_function(p, q, point) -> Fraction:
    """E_pq at point: positive to the left of p -> q (note 000; f_pq of note 003)."""
    return (q[0] - p[0]) * (point[1] - p[1]) - (q[1] - p[1]) * (point[0] - p[0])


def normal_form(p, q, point) -> Fraction:
    """n . x - c for the edge p -> q, n its right normal: negative to the left (note 004)."""
    n = (q[1] - p[1], -(q[0] - p[0]))
    return n[0] * point[0] + n[1] * point[1] - (n[0] * p[0] + n[1] * p[1])


@dataclass(frozen=True)
class Conventions:
    """A point of triangle abc under each convention."""

    counter_clockwise: bool
    edges: dict          # "ab" -> E (note 000), one per edge
    normals: dict        # "ab" -> n . x - c (note 004)
    f_bc: tuple          # (f_bc(point), f_bc(a))
    f_ac: tuple          # (f_ac(point), f_ac(b))
    areal: tuple         # (alpha, beta, gamma), summing to 1
    area: Fraction       # A, the triangle's area

    @property
    def homogeneous(self) -> tuple:
        """(alpha, beta, gamma) times A: the homogeneous coordinates, summing to A."""
        return tuple(w * self.area for w in self.areal)


def conventions(vertices, point) -> Conventions:
    """The point under each convention; vertices (a, b, c) and point exact,
    the triangle of non-zero area."""
    a, b, c = [tuple(map(Fraction, v)) for v in vertices]
    point = tuple(map(Fraction, point))
    ends = {"ab": (a, b), "bc": (b, c), "ca": (c, a)}
    twice = edge_function(a, b, c)
    f_bc = (edge_function(b, c, point), edge_function(b, c, a))
    f_ac = (edge_function(a, c, point), edge_function(a, c, b))
    alpha, beta = f_bc[0] / f_bc[1], f_ac[0] / f_ac[1]
    return Conventions(
        counter_clockwise=twice > 0,
        edges={k: edge_function(*ends[k], point) for k in EDGES},
        normals={k: normal_form(*ends[k], point) for k in EDGES},
        f_bc=f_bc, f_ac=f_ac, areal=(alpha, beta, 1 - alpha - beta), area=abs(twice) / 2)


def exact_text(value: Fraction) -> str:
    """A fraction as the notes write one: -5/2, 3."""
    return str(Fraction(value))


def _operand(value: Fraction) -> str:
    """A fraction in a quotient: a negative one in parentheses."""
    return f"({exact_text(value)})" if value < 0 else exact_text(value)


def convention_rows(vertices, point) -> list[tuple[str, str]]:
    """(label, value) rows that set the conventions side by side."""
    v = conventions(vertices, point)
    inside = "left" if v.counter_clockwise else "right"
    rows = [("winding", f"a, b, c as given: {'counter-clockwise' if v.counter_clockwise else 'clockwise'}: "
                        f"inside is to the {inside} of ab, bc, ca")]
    for k in EDGES:
        rows.append((f"edge {k}", f"E = {exact_text(v.edges[k])} (000: + on the left)  \u00b7  "
                                  f"n\u00b7x - c = {exact_text(v.normals[k])} (004: - on the left)"))
    rows.append(("alpha = f_bc(p) / f_bc(a)",
                 f"{_operand(v.f_bc[0])} / {_operand(v.f_bc[1])} = {exact_text(v.areal[0])}"))
    rows.append(("beta = f_ac(p) / f_ac(b)",
                 f"{_operand(v.f_ac[0])} / {_operand(v.f_ac[1])} = {exact_text(v.areal[1])}"))
    rows.append(("gamma = 1 - alpha - beta", exact_text(v.areal[2])))
    rows.append(("areal (sum 1)", "  ".join(exact_text(w) for w in v.areal)))
    rows.append((f"homogeneous (sum A = {exact_text(v.area)})",
                 "  ".join(exact_text(w) for w in v.homogeneous)))
    return rows
