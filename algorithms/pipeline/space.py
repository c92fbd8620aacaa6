"""The geometry of the pipeline: camera, projection, clipping, divide and viewport.

Conventions (OpenGL's). The camera looks from ``eye`` at ``target`` with
+y up; eye space has the camera at the origin looking down -z. The
projection with vertical field of view ``fov`` and planes ``near`` and
``far`` maps eye (x, y, z) to clip (x', y', z', w) with w = -z, so a point
is in the view volume when -w <= x', y', z' <= w; z' = -w at the near plane
and z' = w at the far one.

Clipping (Sutherland-Hodgman) cuts the polygon by one plane at a time in
clip space, where the planes are linear: the signed distance of a vertex
to the plane is d = w + x' (left), w - x' (right), w + y' (bottom),
w - y' (top), w + z' (near), w - z' (far), inside where d >= 0. An edge
from a (d_a) to b (d_b) whose ends lie on opposite sides gains the point
a + t (b - a) with t = d_a / (d_a - d_b); every attribute is cut with the
same t (they are linear in clip space). The functions take any numbers
with + - * /, so tests run them with fractions.Fraction.

Divide and viewport: NDC = (x', y', z') / w; window x = (x_ndc + 1) W / 2,
y = (y_ndc + 1) H / 2 (y up, as the grid), depth = (z_ndc + 1) / 2.
"""
from __future__ import annotations

import math

from algorithms.core.errors import InputError

PLANES = ("near", "far", "left", "right", "bottom", "top")


def _sub(a, b):
    return [p - q for p, q in zip(a, b)]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def normalized(v):
    length = math.sqrt(_dot(v, v))
    if length == 0:
        raise InputError("a direction of length 0 (a camera looking at itself, a normal or "
                         "light of 0, 0, 0)")
    return [p / length for p in v]


class Camera:
    """The view and projection of one run, checked when made."""

    def __init__(self, eye, target, fov: float, near: float, far: float, aspect: float):
        if not near > 0:
            raise InputError(f"option near: {near} must be greater than 0")
        if not far > near:
            raise InputError(f"option far: {far} must be greater than near ({near})")
        if not 0 < fov < 180:
            raise InputError(f"option fov: {fov} degrees is outside 0 .. 180")
        if len(eye) != 3 or len(target) != 3:
            raise InputError("options eye and target: give x,y,z (three numbers) each")
        self.eye, self.target = list(eye), list(target)
        forward = normalized(_sub(self.target, self.eye))
        side = _cross(forward, [0.0, 1.0, 0.0])
        if _dot(side, side) < 1e-24:  # looking straight up or down: +z is "up" on screen
            side = _cross(forward, [0.0, 0.0, -1.0])
        self.side = normalized(side)
        self.up = _cross(self.side, forward)
        self.forward = forward
        self.near, self.far, self.fov = near, far, fov
        self.f = 1 / math.tan(math.radians(fov) / 2)
        self.aspect = aspect

    def to_eye(self, p):
        d = _sub(p, self.eye)
        return [_dot(d, self.side), _dot(d, self.up), -_dot(d, self.forward)]

    def to_clip(self, e):
        """Eye (x, y, z) to clip (x', y', z', w)."""
        n, f = self.near, self.far
        x, y, z = e
        return [self.f / self.aspect * x, self.f * y,
                (f + n) / (n - f) * z + 2 * f * n / (n - f), -z]


def distance(plane: str, c):
    """Signed distance (up to a positive factor) of clip point c to a plane; inside >= 0."""
    x, y, z, w = c[:4]
    return {"near": w + z, "far": w - z, "left": w + x, "right": w - x, "bottom": w + y,
            "top": w - y}[plane]


def clip_polygon(vertices, planes=PLANES):
    """Sutherland-Hodgman: the polygon (lists whose first four entries are clip
    x', y', z', w and the rest attributes) cut by each plane in turn; returns
    (the polygon left, [(plane, vertices in, vertices out)])."""
    report = []
    for plane in planes:
        if not vertices:
            break
        out = []
        for k, a in enumerate(vertices):
            b = vertices[(k + 1) % len(vertices)]
            da, db = distance(plane, a), distance(plane, b)
            if da >= 0:
                out.append(a)
            if (da >= 0) != (db >= 0):
                t = da / (da - db)
                out.append([p + t * (q - p) for p, q in zip(a, b)])
        report.append((plane, len(vertices), len(out)))
        vertices = out
    return vertices, report


def to_window(c, width: int, height: int):
    """Clip (x', y', z', w) to window (x, y, depth) and the w kept for perspective."""
    x, y, z, w = c[:4]
    return ((x / w + 1) * width / 2, (y / w + 1) * height / 2, (z / w + 1) / 2)
