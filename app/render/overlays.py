"""Geometric overlays of a triangle or line run, tied to the step on show.

For the triangle being drawn and the pixel centre p the step tests:

* ``half-planes``: each edge function's positive side e_k >= 0 in one light
  tint, so that the tints add up to the darkest where all three tests
  pass (the triangle), with each edge's whole line across the grid as a
  thin line in the edge's colour (edge k joins P_(k+1) to P_(k+2));
* ``sub-triangles``: the three triangles (p, P1, P2), (P0, p, P2),
  (P0, P1, p) whose areas over the triangle's are alpha, beta, gamma: the
  one opposite P_k (p in P_k's place) carries P_k's weight, as the notes
  have it (alpha = dist(p, BC) / dist(A, BC)); each is filled translucent in
  its colour and labelled α, β or γ at its centroid;
* ``distances``: the perpendiculars from p to the three edge lines, whose
  signed lengths are e_k / |P_(k+2) - P_(k+1)|;
* ``basis``: the vectors P1 - P0 and P2 - P0 of the barycentric frame
  p = P0 + beta (P1 - P0) + gamma (P2 - P0).

And for a line run (P -> Q), whatever the step:

* ``octants``: the eight octants around P, the line's, and the mirrors that
  take it to the first (app/render/octant_overlay.py).

The shapes (``Shapes``) are strokes (polylines in grid units, one colour
each), translucent fills and labels; the window draws them as items over
the grid (widgets/overlay_layer.py) and export draws them with Pillow on
the composed frame (``draw_shapes``): both show the same geometry. Nothing
here imports Qt.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from algorithms.core.steps import Vars
from app.model import colours
from app.render import octant_overlay

OVERLAYS = ("half-planes", "sub-triangles", "distances", "basis", "octants")
# One colour per edge k (and its opposite vertex P_k), and one for the basis,
# from app/model/colours.py; each edge also carries its name as a label.
# Not blue: the ink is blue, and a blue stroke over filled pixels disappears.
EDGE_COLOURS = tuple(colours.rgb(c) for c in colours.LIGHT.edges)
BASIS_COLOUR = (30, 30, 30)
COLOURS = EDGE_COLOURS + (BASIS_COLOUR,) + octant_overlay.COLOURS
# One calm tint for every half-plane: on a projector three hatchings in
# three colours read as noise; one tint that deepens where the half-planes
# overlap shows how many edge tests a pixel passes.
HALF_PLANE_TINT, HALF_PLANE_ALPHA = (70, 90, 140), 0.12
SUB_TRIANGLE_ALPHA = 0.22
WEIGHT_NAMES = ("\u03b1", "\u03b2", "\u03b3")  # α β γ: the weights of P0, P1, P2


@dataclass(frozen=True)
class Stroke:
    points: tuple  # ((x, y), ...) in grid units
    colour: tuple  # (r, g, b)
    width: float = 2.0  # screen pixels in the window; export scales it with the cells


@dataclass(frozen=True)
class Fill:
    """A translucent polygon: ``alpha`` 0..1 of ``colour`` over the grid."""

    points: tuple  # ((x, y), ...) in grid units, not closed
    colour: tuple
    alpha: float


@dataclass(frozen=True)
class Label:
    """A short text centred on ``at`` (grid units)."""

    at: tuple
    text: str
    colour: tuple


@dataclass(frozen=True)
class Shapes:
    """Everything the overlays draw at one step, fills first, labels last."""

    strokes: tuple = ()
    fills: tuple = ()
    labels: tuple = ()

    def __add__(self, other: "Shapes") -> "Shapes":
        return Shapes(self.strokes + other.strokes, self.fills + other.fills,
                      self.labels + other.labels)

    def __bool__(self) -> bool:
        return bool(self.strokes or self.fills or self.labels)


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
    """The strokes of ``overlay_shapes`` (lines only)."""
    return list(overlay_shapes(trace, index, shown, line).strokes)


def overlay_shapes(trace, index: int, shown, line=None) -> Shapes:
    """The shapes of the overlays named in ``shown`` at step ``index``;
    ``line``: the run's segment P -> Q in grid units (octant_overlay.line_on_grid),
    None when the run draws no line."""
    shown = set(shown)
    if trace is None or not shown:
        return Shapes()
    shapes = Shapes()
    if "octants" in shown and line is not None:
        shapes += Shapes(tuple(octant_overlay.octant_strokes(line, Stroke)))
    triangle = current_triangle(trace, index)
    if triangle is None:
        return shapes
    step = trace.step(index)
    p = None if step.pixel is None else (step.pixel[0] + 0.5, step.pixel[1] + 0.5)
    grid = (trace.width, trace.height)
    if "half-planes" in shown:
        shapes += half_planes(triangle, grid)
    if "sub-triangles" in shown and p is not None:
        shapes += sub_triangles(triangle, p)
    if "distances" in shown and p is not None:
        shapes += Shapes(tuple(distance_strokes(triangle, p)))
    if "basis" in shown:
        shapes += Shapes(tuple(basis_strokes(triangle)))
    return shapes


def overlay_colours(background: str, ink: str) -> tuple:
    """Every colour the overlays draw, with their fills over the background
    and over the ink (for an export's palette)."""
    bases = [tuple(int(c[i:i + 2], 16) for i in (1, 3, 5)) for c in (background, ink)]
    tints = [blend(HALF_PLANE_TINT, base, 1 - (1 - HALF_PLANE_ALPHA) ** n)
             for base in bases for n in (1, 2, 3)]
    tints += [blend(colour, base, SUB_TRIANGLE_ALPHA) for base in bases for colour in EDGE_COLOURS]
    return COLOURS + tuple(tints)


def blend(colour, base, alpha: float) -> tuple:
    """``colour`` at ``alpha`` over ``base``, as (r, g, b) integers."""
    return tuple(round(alpha * c + (1 - alpha) * b) for c, b in zip(colour, base))


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


def _clip_polygon(polygon, f):
    """The part of a convex polygon where f >= 0 (f linear): Sutherland-Hodgman."""
    kept = []
    for a, b in zip(polygon, polygon[1:] + polygon[:1]):
        fa, fb = f(a), f(b)
        if fa >= 0:
            kept.append(a)
        if (fa >= 0) != (fb >= 0):
            t = fa / (fa - fb)
            kept.append((a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])))
    return kept


def half_planes(triangle, grid) -> Shapes:
    """Each edge's line across the grid, thin, and its positive side in the tint."""
    box = (0.0, 0.0, float(grid[0]), float(grid[1]))
    corners = [(box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])]
    if edge_function(triangle, 0)(triangle[0]) == 0:
        return Shapes()  # a degenerate triangle has no inside
    strokes, fills = [], []
    for k in range(3):
        a, b = triangle[(k + 1) % 3], triangle[(k + 2) % 3]
        line = _clip_to_box(a, (b[0] - a[0], b[1] - a[1]), box)
        if line is not None:
            strokes.append(Stroke(tuple(line), EDGE_COLOURS[k], 1.0))
        inside = _clip_polygon(corners, edge_function(triangle, k))
        if len(inside) >= 3:
            fills.append(Fill(tuple(inside), HALF_PLANE_TINT, HALF_PLANE_ALPHA))
    return Shapes(tuple(strokes), tuple(fills))


def sub_triangles(triangle, p) -> Shapes:
    """The sub-triangle opposite each P_k (p in its place): outlined and filled
    in P_k's colour, labelled with P_k's weight at its centroid."""
    strokes, fills, labels = [], [], []
    for k in range(3):
        corners = list(triangle)
        corners[k] = p
        strokes.append(Stroke(tuple(corners + [corners[0]]), EDGE_COLOURS[k], 1.5))
        fills.append(Fill(tuple(corners), EDGE_COLOURS[k], SUB_TRIANGLE_ALPHA))
        centroid = (sum(c[0] for c in corners) / 3, sum(c[1] for c in corners) / 3)
        labels.append(Label(centroid, WEIGHT_NAMES[k], EDGE_COLOURS[k]))
    return Shapes(tuple(strokes), tuple(fills), tuple(labels))


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
def draw_shapes(rgb: np.ndarray, shapes: Shapes, scale: int, y_down: bool,
                halo: tuple = (255, 255, 255)) -> np.ndarray:
    """The shapes drawn over an (H * scale, W * scale, 3) uint8 image whose
    row 0 is y = 0 (as compose makes it): a new array. Labels are written
    upright in the frame (``y_down`` false: the image is flipped after),
    in the shipped font, with a ``halo`` so they read over any cell."""
    from PIL import Image, ImageDraw  # for exported frames: the window does not load it
    image = Image.fromarray(np.ascontiguousarray(rgb), "RGB").convert("RGBA")
    for fill in shapes.fills:
        layer = Image.new("RGBA", image.size, (0, 0, 0, 0))
        ImageDraw.Draw(layer).polygon([(x * scale, y * scale) for x, y in fill.points],
                                      fill=tuple(fill.colour) + (round(fill.alpha * 255),))
        image = Image.alpha_composite(image, layer)
    draw = ImageDraw.Draw(image)
    for stroke in shapes.strokes:
        width = max(1, round(scale / 8 * stroke.width / 2))
        draw.line([(x * scale, y * scale) for x, y in stroke.points], fill=stroke.colour,
                  width=width)
    if shapes.labels:
        image = _write_labels(image, shapes.labels, scale, y_down, halo)
    return np.asarray(image.convert("RGB"))


def _write_labels(image, labels, scale: int, y_down: bool, halo):
    from PIL import ImageDraw
    from app.render.text import font
    face = font("sans_bold", max(12, min(48, round(scale * 1.2))))
    upright = image if y_down else image.transpose(1)  # FLIP_TOP_BOTTOM
    draw = ImageDraw.Draw(upright)
    height = upright.height
    for label in labels:
        x, y = label.at[0] * scale, label.at[1] * scale
        draw.text((x, y if y_down else height - y), label.text, font=face, fill=label.colour,
                  anchor="mm", stroke_width=max(1, face.size // 10), stroke_fill=halo)
    return upright if y_down else upright.transpose(1)
