"""What clicks, keys and drags on the grid do to the points being drawn.

The rules of the drawing tools live here, apart from Qt, so that they read
(and are tested) as plain Python; the grid view turns mouse events into
calls on a ``Drawing`` and draws what it holds.

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

Points are one flat list; ``breaks`` holds the indices where contours 2,
3, ... start, as the session keeps them.
"""
from __future__ import annotations

FIXED, CIRCLE, CONTOURS, GROUPS = "fixed", "circle", "contours", "groups"
MODES = (FIXED, CIRCLE, CONTOURS, GROUPS)


class Drawing:
    """The points on the grid and the state of the drawing tool."""

    def __init__(self, mode: str = FIXED, count: int = 2):
        self.mode, self.count = FIXED, 2
        self.points: list[tuple] = []
        self.breaks: tuple[int, ...] = ()
        # Contours: is the last contour still being drawn?
        self.open = False
        self.set_mode(mode, count)

    def set_mode(self, mode: str, count: int) -> None:
        if mode not in MODES:
            raise ValueError(f"unknown drawing mode {mode!r}")
        self.mode, self.count = mode, max(1, int(count))
        if mode != CONTOURS:
            self.breaks, self.open = (), False

    def reset(self, points, breaks=(), keep_open: bool = False) -> None:
        """Points set from outside (an editor, undo, another algorithm):
        every contour counts as finished, unless ``keep_open`` (the same
        drawing, put back after the algorithm refused an edit)."""
        self.points = [tuple(p) for p in points]
        n = len(self.points)
        self.breaks = tuple(b for b in breaks if 0 < b < n) if self.mode == CONTOURS else ()
        self.open = keep_open and self.open and n > 0

    # ------------------------------------------------------------ queries
    def contours(self) -> list[range]:
        """Index ranges of the contours (one range outside contour mode)."""
        edges = [0, *self.breaks, len(self.points)]
        return [range(a, b) for a, b in zip(edges, edges[1:])]

    def complete(self) -> bool:
        """Is everything placed (nothing waits for more points)?"""
        n = len(self.points)
        if self.mode in (FIXED, CIRCLE):
            return n >= self.count
        if self.mode == GROUPS:
            return n > 0 and n % self.count == 0
        return n > 0 and not self.open

    def pending(self) -> list[int]:
        """Indices of the points of a primitive still being drawn, in order:
        the open contour, the last triangle's first one or two points, the
        first end of a segment."""
        n = len(self.points)
        if self.mode == CONTOURS:
            return list(self.contours()[-1]) if self.open and n else []
        if self.mode == GROUPS:
            return list(range(n - n % self.count, n))
        return list(range(n)) if 0 < n < self.count else []

    def closes_at(self, index: int | None) -> bool:
        """Would a click on handle ``index`` close the open contour?"""
        if self.mode != CONTOURS or not self.open or index is None:
            return False
        last = self.contours()[-1]
        return index == last.start and len(last) >= self.count

    def labels(self, names=()) -> list[str]:
        """A short name for every point (see ``point_labels``)."""
        return point_labels(self.mode, self.count, len(self.points), self.breaks, names)

    # ------------------------------------------------------------ edits
    def click(self, point, on_handle: int | None = None, new_contour: bool = False) -> bool:
        """A click at ``point`` (already snapped), possibly on the handle of
        point ``on_handle``. Returns whether the points changed."""
        point = tuple(point)
        if self.mode == CONTOURS:
            return self._click_contour(point, on_handle, new_contour)
        if self.mode == GROUPS:
            # On a vertex: share it exactly (a mesh's common corner).
            self.points.append(self.points[on_handle] if on_handle is not None else point)
            return True
        if on_handle is not None and self.complete():
            return False  # a press on a handle that did not become a drag
        if len(self.points) >= self.count:
            self.points = [point]
        else:
            self.points.append(point)
        return True

    def _click_contour(self, point, on_handle, new_contour) -> bool:
        if self.closes_at(on_handle):
            self.open = False
            return False
        if on_handle is not None and not new_contour:
            return False  # a press on a vertex that did not become a drag
        if new_contour and self.points:
            self.breaks = self.breaks + (len(self.points),)
        elif not self.open:
            self.points, self.breaks = [], ()  # a finished polygon: start a new one
        self.points.append(point)
        self.open = True
        return True

    def close(self) -> bool:
        """Finish the contour being drawn, if it has enough vertices."""
        if self.mode != CONTOURS or not self.open:
            return False
        if len(self.contours()[-1]) < self.count:
            return False
        self.open = False
        return True

    def remove_last(self) -> bool:
        """Take the last point away; in contour mode its contour is open
        again, to go on drawing it."""
        if not self.points:
            return False
        self.points.pop()
        n = len(self.points)
        if self.breaks and self.breaks[-1] >= n:
            self.breaks = self.breaks[:-1]
        self.open = self.mode == CONTOURS and n > 0
        return True

    def move(self, index: int, point) -> bool:
        point = tuple(point)
        if not 0 <= index < len(self.points) or self.points[index] == point:
            return False
        self.points[index] = point
        return True

    def clear(self) -> bool:
        changed = bool(self.points)
        self.points, self.breaks, self.open = [], (), False
        return changed


def point_labels(mode: str, count: int, n: int, breaks=(), names=()) -> list[str]:
    """A short name for each of n points: the algorithm's names for a fixed
    set (P, Q); P1, P2 ... for one contour and C2.P1 ... (contour 2, vertex
    1) when there are several, as a scan-line fill names its edges; the
    algorithm's P0 P1 P2 for one triangle and T2.P0 ... for more."""
    if mode == CONTOURS:
        edges = [0, *(b for b in breaks if 0 < b < n), n]
        several = len(edges) > 2
        result = []
        for c, (a, b) in enumerate(zip(edges, edges[1:])):
            result += [f"C{c + 1}.P{k + 1}" if several else f"P{k + 1}" for k in range(b - a)]
        return result
    if mode == GROUPS and n > count:
        return [f"T{k // count + 1}.{_name(names, k % count)}" for k in range(n)]
    return [_name(names, k) for k in range(n)]


def _name(names, k: int) -> str:
    return names[k] if k < len(names) else f"P{k + 1}"
