"""What clicks, keys and drags on the grid do to the points being drawn.

The grid view only displays the points it is given and reports what the
person did as a gesture (``Place``, ``Move``, ``Remove``, ``Close``). The
rules that turn a gesture into new points live here, apart from Qt, as
pure functions of (sketch, gesture) -> sketch; the session applies them
(``Session.draw``) and the grid shows the result.

Modes
-----
``fixed``     exactly ``count`` points (a segment's two ends); once they
              are all placed, the next click starts a new set.
``circle``    one point, the centre; the radius is dragged out (the view
              reports the drag, the options hold the radius).
``contours``  polygons: clicks add vertices to the contour being drawn;
              closing it (double-click, Enter, or a click on its first
              vertex) finishes it; a click after that starts a new polygon,
              and a click with ``new_contour`` (Shift) starts another
              contour of the same polygon, a hole or a second part.
``groups``    k primitives of ``count`` points (triangles): every click
              adds a point; a click on an existing vertex adds a point at
              that very vertex, which is how a mesh shares its corners.

Points are one flat tuple; ``breaks`` holds the indices where contours 2,
3, ... start, as the session keeps them; ``open`` says whether the last
contour is still being drawn.

Two questions about "complete" have two names: ``all_placed`` here (does
nothing on the grid wait for more points?) and ``app.model.inputs.complete``
(is there enough for the algorithm to run?).
"""
from __future__ import annotations

from dataclasses import dataclass, replace

FIXED, CIRCLE, CONTOURS, GROUPS = "fixed", "circle", "contours", "groups"
MODES = (FIXED, CIRCLE, CONTOURS, GROUPS)


@dataclass(frozen=True)
class Tool:
    """The drawing tool: its mode and how many points a primitive takes."""
    mode: str = FIXED
    count: int = 2

    def __post_init__(self):
        if self.mode not in MODES:
            raise ValueError(f"unknown drawing mode {self.mode!r}")
        object.__setattr__(self, "count", max(1, int(self.count)))


@dataclass(frozen=True)
class Sketch:
    """The points on the grid, where contours start, and whether the last
    contour is still being drawn."""
    points: tuple = ()
    breaks: tuple[int, ...] = ()
    open: bool = False

    @classmethod
    def of(cls, points, breaks=(), open_: bool = False) -> "Sketch":
        points = tuple(tuple(p) for p in points)
        breaks = tuple(b for b in breaks if 0 < b < len(points))
        return cls(points, breaks, bool(open_ and points))


# ------------------------------------------------------------ gestures
@dataclass(frozen=True)
class Place:
    """A click at ``point`` (already snapped), possibly on the handle of
    point ``on_handle``; ``new_contour``: Shift was held."""
    point: tuple
    on_handle: int | None = None
    new_contour: bool = False


@dataclass(frozen=True)
class Move:
    """Point ``index`` dragged to ``point``."""
    index: int
    point: tuple


@dataclass(frozen=True)
class Remove:
    """Point ``index`` taken away (Backspace takes the last one)."""
    index: int


@dataclass(frozen=True)
class Close:
    """Finish the contour being drawn (Enter, double-click)."""


# ------------------------------------------------------------- queries
def contours(sketch: Sketch) -> list[range]:
    """Index ranges of the contours (one range without breaks)."""
    edges = [0, *sketch.breaks, len(sketch.points)]
    return [range(a, b) for a, b in zip(edges, edges[1:])]


def all_placed(tool: Tool, sketch: Sketch) -> bool:
    """Does nothing wait for more points (no segment, triangle or contour
    half drawn)?"""
    n = len(sketch.points)
    if tool.mode in (FIXED, CIRCLE):
        return n >= tool.count
    if tool.mode == GROUPS:
        return n > 0 and n % tool.count == 0
    return n > 0 and not sketch.open


def pending(tool: Tool, sketch: Sketch) -> list[int]:
    """Indices of the points of a primitive still being drawn, in order:
    the open contour, the last triangle's first one or two points, the
    first end of a segment."""
    n = len(sketch.points)
    if tool.mode == CONTOURS:
        return list(contours(sketch)[-1]) if sketch.open and n else []
    if tool.mode == GROUPS:
        return list(range(n - n % tool.count, n))
    return list(range(n)) if 0 < n < tool.count else []


def closes_at(tool: Tool, sketch: Sketch, index: int | None) -> bool:
    """Would a click on handle ``index`` close the open contour?"""
    if tool.mode != CONTOURS or not sketch.open or index is None:
        return False
    last = contours(sketch)[-1]
    return index == last.start and len(last) >= tool.count


def can_close(tool: Tool, sketch: Sketch) -> bool:
    """Is there an open contour with enough vertices to close?"""
    return (tool.mode == CONTOURS and sketch.open
            and len(contours(sketch)[-1]) >= tool.count)


# --------------------------------------------------------------- rules
def apply(tool: Tool, sketch: Sketch, gesture) -> Sketch:
    """The sketch after ``gesture``; the same sketch when it changes nothing."""
    if isinstance(gesture, Place):
        return _place(tool, sketch, tuple(gesture.point), gesture.on_handle,
                      gesture.new_contour)
    if isinstance(gesture, Move):
        return _move(sketch, gesture.index, tuple(gesture.point))
    if isinstance(gesture, Remove):
        return _remove(tool, sketch, gesture.index)
    if isinstance(gesture, Close):
        return replace(sketch, open=False) if can_close(tool, sketch) else sketch
    raise TypeError(f"not a drawing gesture: {gesture!r}")


def _place(tool: Tool, sketch: Sketch, point, on_handle, new_contour) -> Sketch:
    points = sketch.points
    if tool.mode == CONTOURS:
        return _place_on_contour(tool, sketch, point, on_handle, new_contour)
    if tool.mode == GROUPS:
        # On a vertex: share it exactly (a mesh's common corner).
        return replace(sketch, points=points + (points[on_handle] if on_handle is not None
                                                else point,))
    if on_handle is not None and all_placed(tool, sketch):
        return sketch  # a press on a handle that did not become a drag
    if len(points) >= tool.count:
        return replace(sketch, points=(point,))
    return replace(sketch, points=points + (point,))


def _place_on_contour(tool: Tool, sketch: Sketch, point, on_handle, new_contour) -> Sketch:
    if closes_at(tool, sketch, on_handle):
        return replace(sketch, open=False)
    if on_handle is not None and not new_contour:
        return sketch  # a press on a vertex that did not become a drag
    points, breaks = sketch.points, sketch.breaks
    if new_contour and points:
        breaks = breaks + (len(points),)
    elif not sketch.open:
        points, breaks = (), ()  # a finished polygon: start a new one
    return Sketch(points + (point,), breaks, True)


def _move(sketch: Sketch, index: int, point) -> Sketch:
    points = sketch.points
    if not 0 <= index < len(points) or points[index] == point:
        return sketch
    return replace(sketch, points=points[:index] + (point,) + points[index + 1:])


def _remove(tool: Tool, sketch: Sketch, index: int) -> Sketch:
    """Take a point away; in contour mode the contour is open again, to
    go on drawing it, and a contour left empty disappears."""
    points = sketch.points
    if not 0 <= index < len(points):
        return sketch
    points = points[:index] + points[index + 1:]
    n = len(points)
    breaks = sorted({b - 1 if b > index else b for b in sketch.breaks})
    breaks = tuple(b for b in breaks if 0 < b < n)
    return Sketch(points, breaks if tool.mode == CONTOURS else (), tool.mode == CONTOURS and n > 0)


def labels(tool: Tool, n: int, breaks=(), names=()) -> list[str]:
    """A short name for every point (see ``point_labels``)."""
    return point_labels(tool.mode, tool.count, n, breaks, names)


def point_labels(mode: str, count: int, n: int, breaks=(), names=()) -> list[str]:
    """A short name for each of n points: the algorithm's names for a fixed
    set (P, Q); P1, P2 ... for one contour and C2.P1 ... (contour 2, vertex
    1) when there are several, as a scan-line fill names its edges; the
    algorithm's P0 P1 P2 for one triangle and T2.P0 ... for more; unnamed
    points of k triangles T1.P1 ... T2.P1 ... (S1.P1 ... for segments)."""
    if mode == CONTOURS:
        edges = [0, *(b for b in breaks if 0 < b < n), n]
        several = len(edges) > 2
        result = []
        for c, (a, b) in enumerate(zip(edges, edges[1:])):
            result += [f"C{c + 1}.P{k + 1}" if several else f"P{k + 1}" for k in range(b - a)]
        return result
    if mode == GROUPS and count > 1 and (n > count or not names):
        # Unnamed points are numbered within their triangle (or segment)
        # even while there is one, since a second may follow.
        prefix = "S" if count == 2 else "T"
        return [f"{prefix}{k // count + 1}.{_name(names, k % count)}" for k in range(n)]
    return [_name(names, k) for k in range(n)]


def _name(names, k: int) -> str:
    return names[k] if k < len(names) else f"P{k + 1}"
