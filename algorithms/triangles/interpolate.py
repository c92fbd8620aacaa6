"""Interpolating vertex attributes across a triangle.

Three views of the same linear function, each exact where the inputs are:

* barycentric weights from the edge functions: alpha = e0 / 2A,
  beta = e1 / 2A, gamma = e2 / 2A (e_k is twice the area of the triangle
  the pixel makes with edge k, so the weights sum to 1);
* the parameter plane q(x, y) = c_x x + c_y y + c_k through the three
  vertex values, solved by Cramer's rule relative to P0 and walked with
  q += c_x along a row and q_row += c_y between rows;
* perspective-correct interpolation: with the clip-space w of every vertex,
  interpolate s / w and 1 / w with the screen-space weights and divide per
  pixel. Screen-space (affine) interpolation of s itself is what a renderer
  without correction does; the two agree when all w are equal.

The functions take any numbers that support + - * / (ints, floats,
fractions.Fraction), so tests can run them exactly. ``VertexAttributes``
turns the triangle options (colors, z, w, s, perspective) into the extra
values a traversal frame carries.
"""
from __future__ import annotations

import math

from algorithms.core.registry import InputError, Option

NAN = math.nan

COLORS = Option("colors", "colors", (), "a colour #rrggbb per vertex (or three, shared by every "
                "triangle); pixels are shaded by interpolation (Gouraud)")
Z = Option("z", "numbers", (), "a depth per vertex (or three, shared), interpolated "
           "linearly in screen space")
W = Option("w", "numbers", (), "a clip-space w per vertex (or three, shared), all > 0; "
           "needed for perspective-correct values")
S = Option("s", "numbers", (), "a scalar attribute per vertex (or three, shared), such as "
           "a texture coordinate; shown affine and, with w, perspective-correct")
PERSPECTIVE = Option("perspective", "bool", False, "shade colours with perspective-correct "
                     "weights (needs w) instead of screen-space ones")
ATTRIBUTE_OPTIONS = (COLORS, Z, W, S, PERSPECTIVE)


# ---------------------------------------------------------- the maths
def barycentric_weights(e0, e1, e2, twice_area):
    """(alpha, beta, gamma) = (e0, e1, e2) / 2A."""
    return e0 / twice_area, e1 / twice_area, e2 / twice_area


def affine_value(weights, values):
    """alpha v0 + beta v1 + gamma v2."""
    return weights[0] * values[0] + weights[1] * values[1] + weights[2] * values[2]


def perspective_weights(weights, w):
    """Weights of the point in space: (alpha / w0, beta / w1, gamma / w2) / their sum.

    Raises InputError when a w is not positive or the sum is not (the
    pixel would otherwise get an infinite or NaN value).
    """
    if any(not wk > 0 for wk in w):
        raise InputError("option w: every w must be greater than 0")
    f = [a / wk for a, wk in zip(weights, w)]
    total = f[0] + f[1] + f[2]
    if not total > 0 or (isinstance(total, float) and not math.isfinite(total)):
        raise InputError("perspective interpolation: the interpolated 1/w is not positive "
                         "(w too large or too unequal to represent); use smaller w values")
    return f[0] / total, f[1] / total, f[2] / total


def perspective_value(weights, values, w):
    """(interpolated s / w) / (interpolated 1 / w)."""
    return affine_value(perspective_weights(weights, w), values)


def plane_coefficients(points, values):
    """(c_x, c_y) of the plane through (x_k, y_k, q_k), by Cramer's rule.

    Relative to P0 the plane is q = q0 + c_x (x - x0) + c_y (y - y0); the
    two other vertices give a 2 x 2 system whose determinant is 2A.
    """
    (x0, y0), (x1, y1), (x2, y2) = points
    q0, q1, q2 = values
    dx1, dy1, dx2, dy2 = x1 - x0, y1 - y0, x2 - x0, y2 - y0
    det = dx1 * dy2 - dx2 * dy1
    if det == 0:
        raise InputError("a degenerate triangle has no parameter plane")
    cx = ((q1 - q0) * dy2 - (q2 - q0) * dy1) / det
    cy = ((q2 - q0) * dx1 - (q1 - q0) * dx2) / det
    if isinstance(cx, float) and not (math.isfinite(cx) and math.isfinite(cy)):
        # Products of huge values and coordinates leave the float range.
        raise InputError("the parameter plane overflows floating point: use smaller attribute "
                         "values or coordinates")
    return cx, cy


def plane_value(points, values, x, y):
    """q at (x, y) from the plane's coefficients (not incrementally)."""
    cx, cy = plane_coefficients(points, values)
    (x0, y0) = points[0]
    return values[0] + cx * (x - x0) + cy * (y - y0)


# ---------------------------------------------------------- colours
def unpack(text: str) -> tuple[int, int, int]:
    value = int(text[1:], 16)
    return (value >> 16) & 255, (value >> 8) & 255, value & 255


def pack(channels) -> int:
    r, g, b = (min(255, max(0, math.floor(c + 0.5))) for c in channels)
    return (r << 16) | (g << 8) | b


def mix(weights, colors) -> int:
    """The packed colour alpha c0 + beta c1 + gamma c2, per channel, rounded."""
    return pack([affine_value(weights, [c[n] for c in colors]) for n in range(3)])


# ------------------------------------------------ options to values
def check_w(w) -> None:
    """Every w > 0, and 1/w small enough that sums of weights over w stay finite.

    With these, every covered pixel gets a positive, finite interpolated
    1/w (its weights are >= 0 and sum to 1), so no pixel can become NaN.
    """
    if any(not wk > 0 for wk in w):
        raise InputError("option w: every w must be greater than 0")
    if not math.isfinite(3.0 / min(w)):
        raise InputError(f"option w: w = {min(w)} is too close to 0 (1/w overflows)")


def per_vertex(options: dict, name: str, count: int):
    """The option's list stretched to one entry per point, or None when not given.

    A list of three is shared by every triangle.
    """
    values = options.get(name) or ()
    if not values:
        return None
    if len(values) == count:
        return list(values)
    if len(values) == 3:
        return [values[k % 3] for k in range(count)]
    raise InputError(f"option {name}: give one value per point ({count}) or three "
                     f"shared by every triangle, not {len(values)}")


class VertexAttributes:
    """The attribute options of a run, checked, and the frame values they add."""

    def __init__(self, options: dict, count: int, weights_always: bool = False):
        colors = per_vertex(options, "colors", count)
        self.colors = [unpack(c) for c in colors] if colors else None
        self.z = per_vertex(options, "z", count)
        self.w = per_vertex(options, "w", count)
        self.s = per_vertex(options, "s", count)
        self.perspective = bool(options.get("perspective"))
        if self.w is not None:
            check_w(self.w)
        if self.perspective and self.w is None:
            raise InputError("option perspective: give w, one per vertex (or three)")
        self.active = weights_always or any(v is not None for v in
                                            (self.colors, self.z, self.w, self.s))
        names = []
        if self.active:
            names += ["alpha", "beta", "gamma"]
        if self.w is not None:
            names += ["alpha_p", "beta_p", "gamma_p", "1/w"]
        if self.z is not None:
            names.append("z")
        if self.s is not None:
            names.append("s_affine")
            if self.w is not None:
                names.append("s_persp")
        if self.colors is not None:
            names.append("rgb")
        self.names = tuple(names)
        self.nothing = (NAN,) * len(names)

    @property
    def pixel_value(self):
        return "rgb" if self.colors is not None else None

    def for_triangle(self, order) -> "TriangleAttributes":
        """The vertex values of one triangle; ``order`` lists its input point indices."""
        return TriangleAttributes(self, order)


class TriangleAttributes:
    def __init__(self, attributes: VertexAttributes, order):
        self.a = attributes
        pick = (lambda values: None if values is None else [values[k] for k in order])
        self.colors, self.z, self.w, self.s = (pick(attributes.colors), pick(attributes.z),
                                               pick(attributes.w), pick(attributes.s))

    def values(self, weights) -> tuple:
        """Frame values at a covered pixel with these screen-space weights."""
        if not self.a.active:
            return ()
        result = list(weights)
        corrected = None
        if self.w is not None:
            corrected = perspective_weights(weights, self.w)
            result += list(corrected)
            result.append(affine_value(weights, [1 / wk for wk in self.w]))
        if self.z is not None:
            result.append(affine_value(weights, self.z))
        if self.s is not None:
            result.append(affine_value(weights, self.s))
            if corrected is not None:
                result.append(affine_value(corrected, self.s))
        if self.colors is not None:
            shade = corrected if self.a.perspective else weights
            result.append(float(mix(shade, self.colors)))
        return tuple(float(v) for v in result)
