"""Geometric overlays of a triangle or line run, tied to the step on show.

For the triangle being drawn and the pixel centre p the step tests:

* ``half-planes``: each edge function's positive side e_k >= 0 hatched in
  the edge's colour (edge k joins P_(k+1) to P_(k+2)), with the edge's
  whole line across the grid;
* ``sub-triangles``: the three triangles (p, P1, P2), (P0, p, P2),
  (P0, P1, p) whose areas over the triangle's are alpha, beta, gamma;
* ``distances``: the perpendiculars from p to the three edge lines, whose
  signed lengths are e_k / |P_(k+2) - P_(k+1)|;
* ``basis``: the vectors P1 - P0 and P2 - P0 of the barycentric frame
  p = P0 + beta (P1 - P0) + gamma (P2 - P0).

And for a line run (P -> Q), whatever the step:

* ``octants``: the eight octants around P, the line's, and the mirrors that
  take it to the first (app/render/octant_overlay.py).

The shapes are strokes (polylines in grid units, one colour each), so the
window draws them as line items and export draws them with Pillow on the
composed frame: both show the same geometry. Nothing here imports Qt.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from algorithms.core.steps import Vars
from app.render import octant_overlay

OVERLAYS = ("half-planes", "sub-triangles", "distances", "basis", "octants")
# One colour per edge k (and its opposite vertex P_k), and one for the basis.
# Not blue: the ink is blue, and a blue stroke over filled pixels disappears.
EDGE_COLOURS = ((214, 40, 40), (43, 138, 62), (180, 40, 180))
BASIS_COLOUR = (30, 30, 30)
COLOURS = EDGE_COLOURS + (BASIS_COLOUR,) + octant_overlay.COLOURS
HATCH_SPACING = 1.5  # px between hatch lines
HATCH_ANGLES = (math.radians(30), math.radians(90), math.radians(150))


@dataclass(frozen=True)
class Stroke:
    points: tuple  # ((x, y), ...) in grid units
    colour: tuple  # (r, g, b)


def parse_overlays(text: str) -> tuple[str, ...]:
    """Names from a comma list ("all" for every one, "none" for none); ValueError
    names a bad one."""
    names = [part.strip() for part in text.split(",") if part.strip()]
    if names == ["all"]:
        return OVERLAYS
    if names == ["none"]:
        return ()
    for name in names:
        if name not in OVERLAYS:
            raise ValueError(f"unknown overlay {name!r}; use {', '.join(OVERLAYS)} or all")
    return tuple(dict.fromkeys(names))


def scene_overlays(scene) -> tuple[str, ...]:
    """The overlays a scene's view switches on, those this program knows."""
    return tuple(name for name in scene.view.get("overlays", ()) if name in OVERLAYS)


def current_triangle(trace, index: int):
    """The vertices P0, P1, P2 of the triangle the run works on at step
    ``index``, as its latest Vars record names them; None when there is none."""
    for _, record in reversed(trace.records_of(Vars, hi=index + 1)):
        values = record.values
        if all(name in values for name in ("P0", "P1", "P2")):
            return tuple(tuple(float(c) for c in values[name]) for name in ("P0", "P1", "P2"))
    return None


def overlay_strokes(trace, index: int, shown, line=None) -> list[Stroke]:
    """The strokes of the overlays named in ``shown`` at step ``index``;
    ``line``: the run's segment P -> Q in grid units (octant_overlay.line_on_grid),
    None when the run draws no line."""
    shown = set(shown)
    if trace is None or not shown:
        return []
    strokes = []
    if "octants" in shown and line is not None:
        strokes += octant_overlay.octant_strokes(line, Stroke)
    triangle = current_triangle(trace, index)
    if triangle is None:
        return strokes
    step = trace.step(index)
    p = None if step.pixel is None else (step.pixel[0] + 0.5, step.pixel[1] + 0.5)
    grid = (trace.width, trace.height)
    if "half-planes" in shown:
        strokes += half_plane_strokes(triangle, grid)
    if "sub-triangles" in shown and p is not None:
        strokes += sub_triangle_strokes(triangle, p)
    if "distances" in shown and p is not None:
        strokes += distance_strokes(triangle, p)
    if "basis" in shown:
        strokes += basis_strokes(triangle)
    return strokes


# ------------------------------------------------------------ the shapes
def edge_function(triangle, k: int):
    """e_k as a function of a point: twice the signed area (P_(k+1), P_(k+2), point)."""
    a, b = triangle[(k + 1) % 3], triangle[(k + 2) % 3]
    return lambda q: (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])


def _clip_to_box(origin, direction, box):
    """The part of the line origin + t direction inside box (x0, y0, x1, y1), or None."""
    lo, hi = -math.inf, math.inf
    for axis, (low, high) in enumerate(((box[0], box[2]), (box[1], box[3]))):
        d, o = direction[axis], origin[axis]
        if abs(d) < 1e-12:
            if not low <= o <= high:
                return None
            continue
        t0, t1 = sorted(((low - o) / d, (high - o) / d))
        lo, hi = max(lo, t0), min(hi, t1)
    if lo >= hi:
        return None
    return [(origin[0] + t * direction[0], origin[1] + t * direction[1]) for t in (lo, hi)]


def _keep_positive(segment, f):
    """The part of the segment where f >= 0 (f linear), or None."""
    (a, b), fa, fb = segment, f(segment[0]), f(segment[1])
    if fa < 0 and fb < 0:
        return None
    if fa >= 0 and fb >= 0:
        return segment
    t = fa / (fa - fb)
    cut = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
    return [a, cut] if fa >= 0 else [cut, b]


def half_plane_strokes(triangle, grid) -> list[Stroke]:
    box = (0.0, 0.0, float(grid[0]), float(grid[1]))
    strokes = []
    area = edge_function(triangle, 0)(triangle[0])
    for k in range(3):
        f = edge_function(triangle, k)
        a, b = triangle[(k + 1) % 3], triangle[(k + 2) % 3]
        line = _clip_to_box(a, (b[0] - a[0], b[1] - a[1]), box)
        if line is None or area == 0:
            continue
        strokes.append(Stroke(tuple(line), EDGE_COLOURS[k]))
        angle = HATCH_ANGLES[k]
        d = (math.cos(angle), math.sin(angle))
        n = (-d[1], d[0])
        corners = [(x, y) for x in box[0::2] for y in box[1::2]]
        offsets = [c[0] * n[0] + c[1] * n[1] for c in corners]
        s = math.floor(min(offsets) / HATCH_SPACING) * HATCH_SPACING
        while s <= max(offsets):
            hatch = _clip_to_box((s * n[0], s * n[1]), d, box)
            kept = hatch and _keep_positive(hatch, f)
            if kept:
                strokes.append(Stroke(tuple(kept), EDGE_COLOURS[k]))
            s += HATCH_SPACING
    return strokes


def sub_triangle_strokes(triangle, p) -> list[Stroke]:
    strokes = []
    for k in range(3):
        corners = list(triangle)
        corners[k] = p  # the sub-triangle opposite P_k has p in its place
        strokes.append(Stroke(tuple(corners + [corners[0]]), EDGE_COLOURS[k]))
    return strokes


def foot_on_line(a, b, p):
    """The foot of the perpendicular from p to the line through a and b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    if length2 == 0:
        return a
    t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2
    return (a[0] + t * dx, a[1] + t * dy)


def distance_strokes(triangle, p) -> list[Stroke]:
    return [Stroke((p, foot_on_line(triangle[(k + 1) % 3], triangle[(k + 2) % 3], p)),
                   EDGE_COLOURS[k]) for k in range(3)]


def basis_strokes(triangle) -> list[Stroke]:
    origin = triangle[0]
    strokes = []
    for tip in triangle[1:]:
        strokes.append(Stroke((origin, tip), BASIS_COLOUR))
        dx, dy = tip[0] - origin[0], tip[1] - origin[1]
        length = math.hypot(dx, dy)
        if length == 0:
            continue
        ux, uy = dx / length, dy / length
        size = min(1.0, length / 3)
        for side in (1, -1):  # the arrow head's two barbs
            barb = (tip[0] - size * (ux - side * 0.5 * uy), tip[1] - size * (uy + side * 0.5 * ux))
            strokes.append(Stroke((tip, barb), BASIS_COLOUR))
    return strokes


# ------------------------------------------------------------ drawing
def draw_strokes(rgb: np.ndarray, strokes, scale: int) -> np.ndarray:
    """The strokes drawn over an (H * scale, W * scale, 3) uint8 image whose
    row 0 is y = 0 (as compose makes it): a new array."""
    from PIL import Image, ImageDraw  # for exported frames: the window does not load it
    image = Image.fromarray(np.ascontiguousarray(rgb), "RGB")
    draw = ImageDraw.Draw(image)
    width = max(1, scale // 8)
    for stroke in strokes:
        draw.line([(x * scale, y * scale) for x, y in stroke.points], fill=stroke.colour,
                  width=width)
    return np.asarray(image)
