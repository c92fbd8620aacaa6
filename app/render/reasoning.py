"""The reasoning of a step drawn on the grid: what the window and exported
frames show over the pixels, worked out once for both.

* A decision between two candidate pixels (Bresenham's lines, the midpoint
  circle): the midpoint M between the candidates' centres, and a short
  drop from M to the ideal primitive, which shows on which side of M it
  passes; the label at M says so in words ("line above M: NE").
* The scan-line fill: the scan line through the pixel centres at
  y + 1/2, its crossings with the edges (the AET's x values), and the pair
  of crossings a span is filled between.
* Supersampling: the samples tested so far in the current pixel, the
  step's own sample marked.

Everything is in grid units (pixel (i, j) is [i, i+1) x [j, j+1)), y up;
the window and the exporter flip it for the top-left origin themselves.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from algorithms.core.steps import Span, Table

from app.model.branches import branch_groups, candidate_offsets
from app.model.drawing import point_labels
from app.model.tools import drawing_mode
from app.render.frame import pixel_samples


@dataclass(frozen=True)
class Guides:
    """Marks of a step's reasoning.

    ``lines`` are (x0, y0, x1, y1, role), role "scan" (the scan line),
    "pair" (the run between two crossings) or "drop" (from M to the
    primitive); ``dots`` are (x, y, role), role "crossing", "midpoint",
    "hit", "miss" or "sample" (the step's own sample); ``labels`` are
    (x, y, text) placed just right of and above (x, y).
    """

    lines: tuple = ()
    dots: tuple = ()
    labels: tuple = ()

    def __bool__(self) -> bool:
        return bool(self.lines or self.dots or self.labels)


NONE = Guides()


def step_guides(trace, state, paths=(), y_down: bool = False) -> Guides:
    """The guides of ``state`` (a FrameState of ``trace``); ``paths`` is the
    ideal primitive as [(points, closed), ...] in grid units; ``y_down``:
    the scene's origin is top-left (words such as "above" follow the
    picture)."""
    if trace is None or state is None:
        return NONE
    for make in (_scan_guides, _midpoint_guides, _sample_guides):
        guides = make(trace, state, paths, y_down)
        if guides:
            return guides
    return NONE


# ------------------------------------------------------------ scan line
def _scan_guides(trace, state, paths, y_down=False) -> Guides:
    if not _is_scan_line_run(trace) or "y" not in state.variables:
        return NONE
    y = state.variables["y"]
    if not isinstance(y, (int, float)) or isinstance(y, bool):
        return NONE
    centre = float(y) + 0.5
    if not 0 < centre < trace.height:
        return NONE  # the loop's last pass: the scan line is past the grid
    lines = [(0.0, centre, float(trace.width), centre, "scan")]
    found = _latest_table(trace, "AET", state.index)
    crossings = []
    if found is not None:
        # An edge whose ymax is this row leaves the AET here: it has no crossing.
        columns = found[1].columns
        x_column, top = columns.index("x"), columns.index("ymax")
        crossings = [_x_value(row[x_column]) for row in found[1].rows if row[top] > y]
    dots = [(x, centre, "crossing") for x in crossings]
    if isinstance(state.step.record, Span) and found is not None:
        pair = _span_pair(trace, found, state.index)
        if pair is not None:
            lines.append((pair[0], centre, pair[1], centre, "pair"))
    labels = [(0.05, centre, f"y + \u00bd = {_short(centre)}")]
    return Guides(tuple(lines), tuple(dots), tuple(labels))


def _x_value(cell) -> float:
    """An AET's x as a number: the integer edge walk shows it as (whole, "e/dy")."""
    if isinstance(cell, (tuple, list)) and len(cell) == 2:
        whole, error = cell
        numerator, over = (int(part) for part in str(error).split("/"))
        return float(whole) + numerator / over
    return float(cell)


def _is_scan_line_run(trace) -> bool:
    """A run that builds an edge table first and keeps an AET (the scan-line fill)."""
    steps = trace.steps_of(Table)
    return len(steps) > 0 and trace.record_at(int(steps[0])).name == "ET"


def _latest_table(trace, name: str, index: int, hops: int = 8):
    """(step, table) of the latest table called ``name`` at or before
    ``index``, looking back over at most ``hops`` tables; else None."""
    at = index
    for _ in range(hops):
        found = trace.last_of(Table, at=at)
        if found is None:
            return None
        if found[1].name == name:
            return found
        at = found[0] - 1
    return None


def _span_pair(trace, found, index: int):
    """(x_left, x_right) of the crossings the span at ``index`` lies
    between: the k-th run of the AET ``found`` = (step, table) sorted
    before it."""
    sort_step, aet = found
    ordinal = len(trace.steps_of(Span, lo=sort_step + 1, hi=index))
    x_column = aet.columns.index("x")
    xs = [_x_value(row[x_column]) for row in aet.rows]
    if "dir" in aet.columns:
        turns = [int(row[aet.columns.index("dir")]) for row in aet.rows]
        found, winding, left = [], 0, None
        for x, turn in zip(xs, turns):
            before, winding = winding, winding + turn
            if before == 0:
                left = x
            elif winding == 0:
                found.append((left, x))
    else:
        found = [(xs[k], xs[k + 1]) for k in range(0, len(xs) - 1, 2)]
    return found[ordinal] if ordinal < len(found) else None


# ------------------------------------------------------------ midpoint
def _midpoint_guides(trace, state, paths, y_down=False) -> Guides:
    candidates = state.candidates
    if len(candidates) != 2 or getattr(trace.start, "decision", None) is None:
        return NONE
    (ax, ay), (bx, by) = candidates
    mx, my = (ax + bx) / 2 + 0.5, (ay + by) / 2 + 0.5
    lines = []
    nearest = _nearest_on_paths(paths, mx, my)
    if nearest is not None and math.dist(nearest, (mx, my)) > 1e-9:
        lines.append((mx, my, nearest[0], nearest[1], "drop"))
    label = "M"
    circle = _circle_of(trace)
    side = passing_side(paths, candidates, circle)
    if side is not None:
        noun = "circle" if circle is not None else \
            "curve" if _nearest_segment(paths, mx, my)[1] else "line"
        label = side_words(candidates, side, y_down, noun) + _branch_of(trace, state, side,
                                                                   y_down)
    return Guides(tuple(lines), ((mx, my, "midpoint"),), ((mx, my, label),))


def passing_side(paths, candidates, circle=None) -> int | None:
    """Which candidate's side of M the ideal primitive passes on: 0 (the
    first candidate's), 1 (the second's), -1 (through M, a tie), or None
    (no primitive, or one running along the candidates).

    Exact, in rationals: g(P) is the circle's F(P) = |P - C|^2 - R^2 when
    ``circle`` = (cx, cy, R) is given, else the cross product of the
    primitive's segment nearest M with P (its side of that line). Along
    the candidates' centres A, M, B, g is affine (nearly so for the
    circle, one cell away), so the primitive crosses A-B on B's side of M
    when g falls towards 0 going from M to B."""
    (ax, ay), (bx, by) = candidates
    a = (Fraction(ax) + Fraction(1, 2), Fraction(ay) + Fraction(1, 2))
    b = (Fraction(bx) + Fraction(1, 2), Fraction(by) + Fraction(1, 2))
    m = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    g = _circle_function(circle) if circle is not None else _line_function(paths, m)
    if g is None:
        return None
    at_m, towards_b = g(m), g(b) - g(a)
    if at_m == 0:
        return -1
    if towards_b == 0:
        return None
    return 1 if (at_m > 0) != (towards_b > 0) else 0


def _line_function(paths, m):
    found = _nearest_segment(paths, float(m[0]), float(m[1]))
    if found is None:
        return None
    (x0, y0), (x1, y1) = ((Fraction(x), Fraction(y)) for x, y in found[0])
    return lambda p: (x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0)


def _circle_function(circle):
    cx, cy, radius = (Fraction(value) for value in circle)
    return lambda p: (p[0] - cx) ** 2 + (p[1] - cy) ** 2 - radius ** 2


def _circle_of(trace):
    """(cx, cy, R) of a circle run, in grid units (its centre pixel's
    centre), from the run's constants; None for other runs."""
    constants = getattr(trace.start, "constants", None) or {}
    values = [constants.get(name) for name in ("xc", "yc", "R")]
    if any(not isinstance(v, (int, float, Fraction)) or isinstance(v, bool) for v in values):
        return None
    xc, yc, radius = values
    return Fraction(xc) + Fraction(1, 2), Fraction(yc) + Fraction(1, 2), Fraction(radius)


def side_words(candidates, side: int, y_down: bool, noun: str) -> str:
    """"line above M", "curve left of M", "line through M" ... as the
    picture shows it: with the origin top-left larger y is lower."""
    if side == -1:
        return f"{noun} through M (a tie)"
    (ax, ay), (bx, by) = candidates
    (px, py), (qx, qy) = (candidates[side], candidates[1 - side])
    if ay != by:
        up = (py > qy) != y_down
        return f"{noun} {'above' if up else 'below'} M"
    return f"{noun} {'right of' if px > qx else 'left of'} M"


def _branch_of(trace, state, side: int, y_down: bool = False) -> str:
    """": NE" -- the branch named for the candidate on the primitive's
    side, read from the pseudo-code's lines deciding between this step's
    candidates. A compass name is the step as it goes on the grid: the
    code is written for one octant, so a line running down and to the
    right takes the code's NE as ": SE (code: NE)"."""
    if side == -1:
        return ""
    line = trace.code[state.step.line]
    names = branch_groups(trace).get(candidate_offsets(trace, line), [])
    if len(names) != 2:
        return ""
    name = names[side]
    offsets = line.candidates or trace.start.candidates
    shown = compass(offsets[side], y_down) if name in COMPASS.values() else name
    return f": {shown}" if shown == name else f": {shown} (code: {name})"


# The unit steps on the grid by their compass names (y up).
COMPASS = {(1, 0): "E", (1, 1): "NE", (0, 1): "N", (-1, 1): "NW", (-1, 0): "W",
           (-1, -1): "SW", (0, -1): "S", (1, -1): "SE"}


def compass(offset, y_down: bool = False) -> str:
    """The compass name of a step (dx, dy) as the picture shows it: with
    the origin top-left, +y goes down the screen."""
    dx, dy = offset
    return COMPASS.get((dx, -dy if y_down else dy), f"({dx}, {dy})")


def _nearest_on_paths(paths, x: float, y: float):
    found = _nearest(paths, x, y)
    return None if found is None else found[0]


def _nearest_segment(paths, x: float, y: float):
    """(segment, closed) nearest (x, y), or None; a point is no segment."""
    found = _nearest(paths, x, y)
    if found is None or found[1][0] == found[1][1]:
        return None
    return found[1], found[2]


def _nearest(paths, x: float, y: float):
    """(nearest point, its segment, its path is closed) of the paths to
    (x, y), or None."""
    best, where = math.inf, None
    for points, closed in paths:
        points = [(float(px), float(py)) for px, py in points]
        if closed and len(points) > 2:
            points = points + points[:1]
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            dx, dy = x1 - x0, y1 - y0
            length = dx * dx + dy * dy
            t = 0.0 if length == 0 else min(1.0, max(0.0, ((x - x0) * dx + (y - y0) * dy) / length))
            px, py = x0 + t * dx, y0 + t * dy
            distance = math.hypot(px - x, py - y)
            if distance < best:
                best, where = distance, ((px, py), ((x0, y0), (x1, y1)), closed)
    return where


# ------------------------------------------------------------ samples
def _sample_guides(trace, state, paths, y_down=False) -> Guides:
    samples = pixel_samples(trace, state.index)
    if samples is None:
        return NONE
    dots = [(float(x), float(y), "hit" if hit else "miss")
            for x, y, hit in zip(samples.xs, samples.ys, samples.hits)]
    if samples.current >= 0:
        x, y = float(samples.xs[samples.current]), float(samples.ys[samples.current])
        dots.append((x, y, "sample"))
    return Guides((), tuple(dots), ())


def vertex_labels(spec, scene) -> list[tuple[float, float, str]]:
    """(x, y, name) of the scene's points in grid units, named as the
    window names them (P1, P2, ...; C2.P1 for a second contour). Integer
    inputs (lines, circles) stand for pixels: their label sits at the
    pixel's centre."""
    flat = [tuple(point) for point in scene.flat]
    mode = drawing_mode(spec)
    names = point_labels(mode, spec.inputs.count or 0, len(flat), scene.breaks,
                         getattr(spec.inputs, "names", ()) or ())
    half = 0.5 if getattr(spec.inputs, "integer", False) else 0.0
    return [(float(x) + half, float(y) + half, name) for (x, y), name in zip(flat, names)]


def _short(value: float) -> str:
    return f"{value:g}"


# ------------------------------------------------------------ drawing
def draw_guides(indices: np.ndarray, guides: Guides, scale: int, colour: int,
                current: int) -> None:
    """Draw ``guides`` into a grid image of palette indices (row 0 at y = 0,
    ``scale`` image pixels a cell) in place: lines and dots in ``colour``,
    the step's own sample in ``current``. Labels are text, drawn by the
    exporter with its fonts."""
    width = max(1, round(scale / 10))
    for x0, y0, x1, y1, role in guides.lines:
        _segment(indices, x0 * scale, y0 * scale, x1 * scale, y1 * scale,
                 width * (3 if role == "pair" else 1), colour)
    for x, y, role in guides.dots:
        radius = max(1.5, scale / {"crossing": 4, "midpoint": 5}.get(role, 8))
        if role == "sample":
            _disc(indices, x * scale, y * scale, radius * 1.6, current)
        elif role == "miss":
            _disc(indices, x * scale, y * scale, radius, colour, hollow=True)
        else:
            _disc(indices, x * scale, y * scale, radius, colour)


def _segment(image, x0, y0, x1, y1, width, value) -> None:
    rows, cols = image.shape
    length = math.hypot(x1 - x0, y1 - y0)
    t = np.linspace(0.0, 1.0, max(2, int(length * 2) + 1))
    xs, ys = x0 + (x1 - x0) * t, y0 + (y1 - y0) * t
    half = (width - 1) / 2
    for offset in np.arange(-half, half + 0.5, 1.0):
        # Thickness across the segment's main direction.
        if abs(x1 - x0) >= abs(y1 - y0):
            c, r = np.floor(xs), np.floor(ys + offset)
        else:
            c, r = np.floor(xs + offset), np.floor(ys)
        c, r = c.astype(np.int64), r.astype(np.int64)
        keep = (c >= 0) & (c < cols) & (r >= 0) & (r < rows)
        image[r[keep], c[keep]] = value


def _disc(image, cx, cy, radius, value, hollow: bool = False) -> None:
    rows, cols = image.shape
    r = int(math.ceil(radius))
    y0, y1 = max(0, int(cy) - r - 1), min(rows, int(cy) + r + 2)
    x0, x1 = max(0, int(cx) - r - 1), min(cols, int(cx) + r + 2)
    if y0 >= y1 or x0 >= x1:
        return
    yy, xx = np.mgrid[y0:y1, x0:x1]
    distance = np.hypot(xx + 0.5 - cx, yy + 0.5 - cy)
    inside = distance <= radius
    if hollow:
        inside &= distance >= radius - max(1.0, radius / 3)
    image[y0:y1, x0:x1][inside] = value
