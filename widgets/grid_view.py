"""The magnified pixel grid: image of the raster, grid lines, outlines,
the ideal primitive and draggable vertex handles.

Coordinates in the view are grid units: pixel (i, j) is the square
[i, i+1) x [j, j+1) and its centre is (i + 1/2, j + 1/2). With the origin at
the bottom-left (the default) y grows upwards; with the origin at the top-left
the view's y axis is inverted, so the same numbers are drawn top-down and a
click reads its coordinates in that frame.

The view only displays: it is handed an RGBA image of the grid (row 0 at
y = 0), the cells to outline, and the points; it reports what the person
did as gestures (``app.model.drawing``: a point placed, moved or removed, a
contour closed), radii dragged out, a marker (a seed) placed, and the pixel
under the cursor. What a gesture does to the points is decided by the
model; the view is given the result.

Mouse and keys (the window's Help lists them too):

* click: place a point (the tool's rule); drag a handle: move its point;
* Ctrl with a click or drag: real coordinates to 1/256 px instead of 1/8;
* Shift+click: start a new contour (a hole, a second part);
* double-click, Enter, or a click on the first vertex: close the contour;
* Backspace: remove the last point;
* circles: drag from an empty cell: centre and radius; drag the square
  rim handle: radius; Shift keeps an ellipse's radii equal;
* drag the seed marker, or use the marker tool, to move a fill's seed;
* drag elsewhere, or with the middle button: pan; wheel: zoom;
* by keyboard, a cell cursor does all of the above (widgets/grid_cursor.py).
"""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QColor, QCursor
from PySide6.QtWidgets import QGraphicsView, QMenu, QSizePolicy

from app.model.drawing import (CIRCLE, CONTOURS, FIXED, GROUPS, Close, Move, Place, Remove,
                               Sketch, Tool, all_placed, can_close, closes_at, pending)
from app.model.drawing import labels as point_names
from app.model.inputs import clamp

from .grid_box import GridViewBox
from .axes_frame import axes_frame
from .grid_items import (CellOutlines, GridLinesItem, PixelAxis, handle_items, number_text,
                         path_xy, place_labels, point_label, primitive_curves, translucent)


HANDLE_HIT = 12   # screen pixels from a handle's centre that grab it
MAX_LABELS = 40   # more points than this go unlabelled on the grid
# Real coordinates snap to 1/COARSE_SNAP px on a plain click, 1/FINE_SNAP
# px (the algorithms' own sub-pixel grid) with FINE held.
COARSE_SNAP = 8
FINE_SNAP = 256
FINE = Qt.KeyboardModifier.ControlModifier
NEW_CONTOUR = Qt.KeyboardModifier.ShiftModifier
EQUAL_RADII = Qt.KeyboardModifier.ShiftModifier
INSPECT = Qt.KeyboardModifier.AltModifier  # Alt+click asks to inspect a pixel
DRAW, MARKER = "draw", "marker"  # the tools


class PixelGridView(pg.GraphicsView):
    """The grid of pixels, with everything drawn over it, and the drawing
    tools (see ``app.model.drawing``)."""

    #: What a click, a drag or a key did to the points: a gesture of
    #: ``app.model.drawing`` (Place, Move, Remove, Close).
    gestured = Signal(object)
    #: The pixel under the cursor, (x, y) in the current frame, or None.
    hoverChanged = Signal(object)
    pointerMoved = Signal(object)  #: the pointer's real (x, y), or None off the grid
    #: The person asked to clear the points (context menu).
    clearRequested = Signal()
    #: A radius was dragged out: (rx, ry) in pixels, not yet rounded. Equal
    #: for a circle, or for an ellipse dragged with Shift.
    radiusDragged = Signal(float, float)
    #: The marker (a fill's seed) was placed or dragged onto pixel (x, y).
    markerPlaced = Signal(object)
    #: A click, drag or key is about to edit the points, the radius or the
    #: marker: one gesture, one step to undo.
    editStarted = Signal()
    #: The person asked to inspect pixel (x, y) (Alt+click, or the menu).
    inspectRequested = Signal(object)

    def __init__(self, palette, outline_styles, parent=None):
        super().__init__(parent)
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
        self._box = GridViewBox(self)
        #: The grid's coordinates, "bottom" and "left".
        self.axes = {"bottom": PixelAxis("bottom"), "left": PixelAxis("left")}
        self.setCentralItem(axes_frame(self._box, self.axes))
        self.palette = palette
        self._style_plot(palette)
        self._add_items(palette, outline_styles)
        self._init_state()
        # The view keeps the whole grid in sight as the widget resizes until
        # the person pans or zooms.
        self._auto_fit = True
        self._box.sigRangeChangedManually.connect(self._manual_range)
        self._box.sigTransformChanged.connect(self._place_labels)  # labels keep pixel gaps
        # A step repaints a few small areas: one rectangle around them, so
        # that Qt scales the image by the same rule as in a whole repaint
        # (under a clip of several rectangles it samples differently, and
        # a cell's edge would move by a screen pixel).
        self.setViewportUpdateMode(QGraphicsView.ViewportUpdateMode.BoundingRectViewportUpdate)

        self.scene().sigMouseMoved.connect(self._mouse_moved)
        self.viewport().setMouseTracking(True)
        self.setCursor(QCursor(Qt.CursorShape.CrossCursor))
        self.set_grid(32, 24)

    def close(self):
        # As PlotWidget.close: the axes and the view box leave the scene
        # before the scene is cleared, which would otherwise crash PySide.
        if not self.closed:
            for axis in self.axes.values():
                axis.unlinkFromView()
                axis.close()
            self.scene().removeItem(self._box)
            self.setParent(None)
        return super().close()

    def _style_plot(self, palette) -> None:
        self.setBackground(palette.outside)
        for axis in self.axes.values():
            axis.setPen(pg.mkPen("#6b7785"))
            axis.setTextPen(pg.mkPen("#3d4754"))
        self._box.setBackgroundColor(palette.outside)
        self._box.setDefaultPadding(0.02)

    def _add_items(self, palette, outline_styles) -> None:
        """The image and everything drawn over it, bottom to top."""
        self.image = pg.ImageItem(axisOrder="row-major")
        self.image.setZValue(0)
        self.grid_lines = GridLinesItem(palette.grid)
        self.grid_lines.setZValue(1)
        self.outlines = CellOutlines(palette, outline_styles)
        self.outlines.setZValue(2)
        self.primitive, self.preview = primitive_curves(palette)
        self.handles, self.rim, self.marker = handle_items(palette)
        # The samples tested in the current pixel: hit filled, miss hollow,
        # sized in grid units so that they stay inside the magnified cell.
        self.samples = pg.ScatterPlotItem(pxMode=False, symbol="o")
        self.samples.setZValue(3.5)
        self._sample_data = None
        for item in (self.image, self.grid_lines, self.outlines, self.primitive,
                     self.preview, self.handles, self.rim, self.marker, self.samples):
            self._box.addItem(item)
        for empty in (self.rim, self.marker, self.samples):
            empty.setVisible(False)  # shown when they have something to show
        self._labels: list[pg.TextItem] = []
        self._marker_label = self._make_label(palette.seed)

    def _init_state(self) -> None:
        self._size = (0, 0)
        self._shown = None  # the array the image item shows
        self._rules = Tool()
        self._sketch = Sketch()  # the points on show, as last given
        self._places = None  # where the handles sit when not at the points
        self._integer = True
        self._names: tuple[str, ...] = ()
        self._closed = False
        self._y_down = False
        self._hover = None
        self._show_primitive = True
        self._shape = None
        self._circle: str | None = None  # "radius", "radii" or None
        self._radii = (0.0, 0.0)
        self._marker_point = None
        self._marker_name = ""
        self._marker_automatic = False
        self._tool = DRAW
        self._cursor_at = None  # where the pointer is, in grid units

    # --------------------------------------------------------- set-up
    @property
    def view_box(self) -> pg.ViewBox:
        return self._box

    @property
    def grid_size(self) -> tuple[int, int]:
        return self._size

    def set_grid(self, width: int, height: int, fit: bool = True) -> None:
        if (width, height) == self._size:
            return
        self._size = (width, height)
        self.axes["bottom"].set_cells(width, max(width, height))
        self.axes["left"].set_cells(height, max(width, height))
        self.grid_lines.set_size(width, height)
        self.outlines.set_size(width, height)
        margin = max(width, height) * 0.5 + 2
        self._box.setLimits(xMin=-margin, xMax=width + margin, yMin=-margin, yMax=height + margin,
                            minXRange=2, minYRange=2)
        if fit:
            self.fit()

    def fit(self) -> None:
        """Show the whole grid (and keep it in sight while the widget resizes)."""
        width, height = self._size
        self._auto_fit = True
        self._box.setRange(QRectF(0, 0, width, height), padding=0.02)

    def set_auto_fit(self, on: bool) -> None:
        """Fit the whole grid again whenever the widget resizes (or not)."""
        self._auto_fit = on

    def resizeEvent(self, event):  # noqa: N802
        super().resizeEvent(event)
        if getattr(self, "_auto_fit", False) and self._size[0] > 0:
            self.fit()

    def _manual_range(self, *_args) -> None:
        self._auto_fit = False

    def set_y_down(self, y_down: bool) -> None:
        """Origin top-left with y growing downwards (True) or bottom-left, y up."""
        self._y_down = bool(y_down)
        self._box.invertY(self._y_down)
        self._place_labels()

    @property
    def y_down(self) -> bool:
        return self._y_down

    def set_input(self, count: int, integer: bool, names=(), closed: bool | None = None,
                  open_ended: bool = False, mode: str | None = None) -> None:
        """How many points the algorithm takes, whether they are whole
        pixels, and which drawing tool places them (``app.model.drawing``).

        Without a ``mode``: ``open_ended`` inputs are contours when
        ``closed`` and groups of ``count`` otherwise; the rest a fixed set.
        """
        self._integer, self._names = integer, tuple(names)
        self._closed = count >= 3 if closed is None else closed
        if mode is None:
            mode = (CONTOURS if self._closed else GROUPS) if open_ended else FIXED
        self._rules = Tool(mode, count)
        if mode != CONTOURS:
            self._sketch = Sketch(self._sketch.points)
        if mode != CIRCLE:
            self._circle = None
        self._refresh_points()

    @property
    def mode(self) -> str:
        return self._rules.mode

    def set_circle(self, kind: str | None, rx: float = 0.0, ry: float = 0.0) -> None:
        """The radius the centre's rim handle shows: ``"radius"`` (one, a
        circle), ``"radii"`` (rx and ry, an ellipse) or None (no handle)."""
        self._circle, self._radii = kind, (float(rx), float(ry))
        self._refresh_rim()

    def set_marker_name(self, name: str) -> None:
        """The name of what the marker tool places (a fill's "seed"), or ""
        when the algorithm has no such point: then there is no marker."""
        self._marker_name = name
        if not name:
            self.set_marker(None)

    def set_marker(self, pixel, automatic: bool = False) -> None:
        """Show the marker at a pixel, or none. An automatic one (chosen by
        the algorithm, not the person) is drawn faint."""
        self._marker_point = None if pixel is None else (int(pixel[0]), int(pixel[1]))
        self._marker_automatic = automatic
        self._refresh_marker()

    @property
    def marker_point(self):
        return self._marker_point

    def set_tool(self, tool: str) -> None:
        """``"draw"`` (clicks place points) or ``"marker"`` (a click places
        the marker, a fill's seed)."""
        self._tool = tool if tool in (DRAW, MARKER) else DRAW
        self.viewport().setCursor(QCursor(Qt.CursorShape.PointingHandCursor if self._tool == MARKER
                                          else Qt.CursorShape.CrossCursor))
        self._draw_preview()

    @property
    def tool(self) -> str:
        return self._tool

    def set_shape(self, paths) -> None:
        """The ideal primitive as paths [(points, closed), ...] in grid
        units, or None to join the handles (a segment, or a polygon when the
        input is closed)."""
        self._shape = None if paths is None else [([tuple(p) for p in pts], bool(closed))
                                                   for pts, closed in paths]
        self._refresh_points()

    def set_show_primitive(self, show: bool) -> None:
        self._show_primitive = bool(show)
        self._refresh_points()

    def set_palette(self, palette) -> None:
        """Recolour everything drawn over the image (a theme or colour
        preference changed); the image itself is composed by the caller."""
        self.palette = palette
        self.setBackground(palette.outside)
        self._box.setBackgroundColor(palette.outside)
        dark = QColor(palette.outside).lightness() < 128
        for axis in self.axes.values():
            axis.setPen(pg.mkPen("#8a94a1" if dark else "#6b7785"))
            axis.setTextPen(pg.mkPen("#c9d1d9" if dark else "#3d4754"))
        self.grid_lines.set_color(palette.grid)
        self.outlines.set_palette(palette)
        self.primitive.setPen(pg.mkPen(palette.primitive, width=2.5))
        self.preview.setPen(pg.mkPen(palette.primitive, width=1.5, style=Qt.PenStyle.DashLine))
        self.handles.setBrush(pg.mkBrush(translucent(palette.handle, 70)))
        self.handles.setPen(pg.mkPen(palette.handle_edge, width=2.5))
        self.rim.setBrush(pg.mkBrush(palette.handle))
        self.rim.setPen(pg.mkPen(palette.primitive, width=2.5))
        self.marker.setBrush(pg.mkBrush(palette.seed))
        self.marker.setPen(pg.mkPen(palette.handle, width=1.5))
        self.update()

    def set_grid_lines_visible(self, visible: bool) -> None:
        self.grid_lines.setVisible(bool(visible))

    def set_points(self, points, breaks=(), open_contour: bool = False) -> None:
        """Show these points; ``breaks``: where contours 2, 3, ... start;
        ``open_contour``: the last contour is still being drawn."""
        sketch = Sketch.of(points, breaks if self._rules.mode == CONTOURS else (), open_contour)
        if sketch != self._sketch:
            self._sketch = sketch
            self._refresh_points()

    @property
    def points(self) -> list[tuple]:
        return list(self._sketch.points)

    @property
    def sketch(self) -> Sketch:
        return self._sketch

    def labels(self) -> list[str]:
        return point_names(self._rules, len(self._sketch.points), self._sketch.breaks,
                           self._names)

    # ---------------------------------------------------------- frames
    def set_image(self, rgba: np.ndarray, changed=None) -> None:
        """Show an (H, W, 4) uint8 image, row 0 at y = 0. ``changed`` =
        (x0, y0, x1, y1), exclusive, says that ``rgba`` is the array on show,
        altered in place in those cells only: only they are repainted (a
        4096 x 4096 picture is not handed to Qt again for one cell)."""
        if changed is not None and rgba is self._shown:
            x0, y0, x1, y1 = changed
            if x1 > x0 and y1 > y0:
                self.image.update(QRectF(x0, y0, x1 - x0, y1 - y0))
            return
        # The item draws a QImage over this very array (no copy), so a
        # later change in place needs only the repaint above.
        self._shown = rgba
        self.image.setImage(rgba, autoLevels=False)
        height, width = rgba.shape[:2]
        if (width, height) != self._size:
            self.set_grid(width, height)

    def set_highlights(self, current=(), candidates=(), spans=()) -> None:
        """Outline the cells of the current step, the decision's candidates
        and the run of cells a span step works on."""
        self.outlines.set_layer("current", current)
        self.outlines.set_layer("candidate", candidates)
        self.outlines.set_spans(spans)

    def set_samples(self, xs=(), ys=(), hits=(), current: int = -1) -> None:
        """Dots at sample positions (grid units): a hit filled, a miss
        hollow, sample ``current`` larger and in the current step's colour."""
        xs, ys = np.asarray(xs, float).ravel(), np.asarray(ys, float).ravel()
        hits = np.asarray(hits, bool).ravel()
        self.samples.setVisible(bool(len(xs)))
        if not len(xs):
            if self._sample_data is not None:
                self.samples.setData([], [])
                self._sample_data = None
            return
        ink, now = self.palette.handle_edge, self.palette.current
        brushes, pens, sizes = [], [], []
        for k, hit in enumerate(hits):
            colour = now if k == current else ink
            brushes.append(pg.mkBrush(colour) if hit else pg.mkBrush(self.palette.handle))
            pens.append(pg.mkPen(colour, width=2.5 if k == current else 1.5))
            sizes.append(0.17 if k == current else 0.11)
        self.samples.setData(x=xs, y=ys, brush=brushes, pen=pens, size=sizes)
        self._sample_data = (xs, ys, hits, int(current))

    def sample_data(self):
        """(xs, ys, hits, current) of the sample dots on show, or None."""
        return self._sample_data

    def set_differences(self, cells) -> None:
        self.outlines.set_layer("difference", cells)

    # -------------------------------------------------------- geometry
    def set_handle_places(self, places=None) -> None:
        """Draw the handles at these grid positions, one per point (None: that one not drawn),
        and let none be dragged: for a grid that shows the points transformed (the pipeline's
        window space). None: the handles at the points again."""
        self._places = None if places is None else list(places)
        self._refresh_points()

    def anchor(self, point) -> QPointF:
        """Where a point's handle sits, in grid units."""
        x, y = point
        if self._integer:
            return QPointF(x + 0.5, y + 0.5)
        return QPointF(float(x), float(y))

    def scene_pos_of(self, grid_pos) -> QPointF:
        """Scene position of a grid position (x, y)."""
        return self._box.mapViewToScene(QPointF(*grid_pos))

    def widget_pos_of(self, grid_pos):
        """Position in the viewport widget (for mouse events) of a grid position."""
        return self.mapFromScene(self.scene_pos_of(grid_pos))

    def snap(self, view_pos: QPointF, fine: bool = False) -> tuple:
        """The point a position in grid units stands for, clamped to the grid.

        Whole pixels for integer inputs; real inputs snap to 1/8 px, easy to
        hit and to read, or with ``fine`` (Ctrl) to the 1/256 px sub-pixel
        grid the algorithms themselves use.
        """
        x, y = view_pos.x(), view_pos.y()
        if self._integer:
            return clamp((math.floor(x), math.floor(y)), *self._size, True)
        steps = FINE_SNAP if fine else COARSE_SNAP
        return clamp((round(x * steps) / steps, round(y * steps) / steps), *self._size, False)

    def pixel_at(self, scene_pos) -> tuple[int, int]:
        """The pixel under a scene position, clamped to the grid."""
        where = self._box.mapSceneToView(scene_pos)
        return clamp((math.floor(where.x()), math.floor(where.y())), *self._size, True)

    # ------------------------------------------------------------ edits
    def close_contour(self) -> bool:
        """Finish the contour being drawn (Enter, double-click)."""
        if not can_close(self._rules, self._sketch):
            return False
        self.gestured.emit(Close())
        return True

    def remove_last_point(self) -> bool:
        """Take the last point away (Backspace)."""
        if not self._sketch.points:
            return False
        self.editStarted.emit()
        self.gestured.emit(Remove(len(self._sketch.points) - 1))
        return True

    def keyPressEvent(self, event):  # noqa: N802
        key = event.key()
        if key in (Qt.Key.Key_Return, Qt.Key.Key_Enter) and self.close_contour():
            event.accept()
        elif key in (Qt.Key.Key_Backspace, Qt.Key.Key_Delete) and self.remove_last_point():
            event.accept()
        else:
            super().keyPressEvent(event)

    # ----------------------------------------------------------- mouse
    def _handle_at(self, scene_pos) -> int | None:
        if self._places is not None:  # handles at places of their own do not move the points
            return None
        best, best_distance = None, HANDLE_HIT
        for index, point in enumerate(self._sketch.points):
            distance = self._screen_distance(self.anchor(point), scene_pos)
            if distance <= best_distance:
                best, best_distance = index, distance
        return best

    def _screen_distance(self, grid_pos: QPointF, scene_pos) -> float:
        where = self._box.mapViewToScene(grid_pos)
        return math.hypot(where.x() - scene_pos.x(), where.y() - scene_pos.y())

    def _on_marker(self, scene_pos) -> bool:
        point = self._marker_point
        return point is not None and self._screen_distance(
            QPointF(point[0] + 0.5, point[1] + 0.5), scene_pos) <= HANDLE_HIT

    def _on_rim(self, scene_pos) -> bool:
        at = self._rim_position()
        return at is not None and self._screen_distance(at, scene_pos) <= HANDLE_HIT

    def _clicked(self, scene_pos, modifiers=Qt.KeyboardModifier.NoModifier,
                 double: bool = False) -> None:
        self.setFocus(Qt.FocusReason.MouseFocusReason)
        if modifiers & INSPECT:
            self.inspectRequested.emit(self.pixel_at(scene_pos))
            return
        if self._tool == MARKER and self._marker_name:
            self.editStarted.emit()
            self.markerPlaced.emit(self.pixel_at(scene_pos))
            return
        if double:
            # The first click of the pair placed its point already.
            self.close_contour()
            return
        self.editStarted.emit()
        point = self.snap(self._box.mapSceneToView(scene_pos), bool(modifiers & FINE))
        self.gestured.emit(Place(point, self._handle_at(scene_pos), bool(modifiers & NEW_CONTOUR)))

    def _drag_target(self, scene_pos, modifiers):
        """What a left-drag starting here moves: a point, the marker, the
        radius, a new circle; None pans the view."""
        handle = self._handle_at(scene_pos)
        if self._marker_point is not None and self._on_marker(scene_pos) and (
                handle is None or self._tool == MARKER):
            return ("marker",)
        if handle is not None:
            return ("point", handle)
        if self._circle and self._sketch.points and self._on_rim(scene_pos):
            return ("rim",)
        if self._rules.mode == CIRCLE and self._circle and self._tool == DRAW:
            # The press point becomes the centre; the drag is the radius.
            return ["circle", self.snap(self._box.mapSceneToView(scene_pos)), False]
        return None

    def _dragged(self, target, scene_pos, modifiers, finished: bool) -> None:
        kind = target[0]
        self.viewport().setCursor(QCursor(Qt.CursorShape.OpenHandCursor if finished
                                          else Qt.CursorShape.ClosedHandCursor))
        where = self._box.mapSceneToView(scene_pos)
        if kind == "point":
            point = self.snap(where, bool(modifiers & FINE))
            if self._sketch.points[target[1]] != point:
                self.gestured.emit(Move(target[1], point))
        elif kind == "marker":
            pixel = self.pixel_at(scene_pos)
            if pixel != self._marker_point:
                self.markerPlaced.emit(pixel)
        else:
            if kind == "circle" and not target[2]:
                target[2] = True
                self.gestured.emit(Place(target[1]))
            if self._sketch.points:  # the centre, once the model placed it
                self.radiusDragged.emit(*self._radii_to(where, modifiers))

    def _radii_to(self, where: QPointF, modifiers) -> tuple[float, float]:
        centre = self.anchor(self._sketch.points[0])
        dx, dy = where.x() - centre.x(), where.y() - centre.y()
        if self._circle == "radius":
            radius = math.hypot(dx, dy)
            return radius, radius
        rx, ry = abs(dx), abs(dy)
        if modifiers & EQUAL_RADII:
            rx = ry = max(rx, ry)
        return rx, ry

    def _mouse_moved(self, scene_pos) -> None:
        pixel = None
        if self._box.sceneBoundingRect().contains(scene_pos):
            where = self._box.mapSceneToView(scene_pos)
            x, y = math.floor(where.x()), math.floor(where.y())
            if 0 <= x < self._size[0] and 0 <= y < self._size[1]:
                pixel = (x, y)
            if self._box._dragging is None:
                self.viewport().setCursor(QCursor(self._cursor_shape(scene_pos)))
            self._cursor_at = where
            self._draw_preview()
            self.pointerMoved.emit((where.x(), where.y()))
        if pixel != self._hover:
            self._hover = pixel
            self.hoverChanged.emit(pixel)

    def _cursor_shape(self, scene_pos):
        if self._tool == MARKER:
            return Qt.CursorShape.PointingHandCursor
        handle = self._handle_at(scene_pos)
        if closes_at(self._rules, self._sketch, handle):
            return Qt.CursorShape.PointingHandCursor  # a click here closes the contour
        if handle is not None or self._on_marker(scene_pos) or self._on_rim(scene_pos):
            return Qt.CursorShape.OpenHandCursor
        return Qt.CursorShape.CrossCursor

    def leaveEvent(self, event):  # noqa: N802
        super().leaveEvent(event)
        self._cursor_at = None
        self._draw_preview()
        self.pointerMoved.emit(None)
        if self._hover is not None:
            self._hover = None
            self.hoverChanged.emit(None)

    def _context_menu(self, scene_pos, screen_pos) -> None:
        menu = QMenu(self)
        where = self.pixel_at(scene_pos)
        menu.addAction(f"Inspect pixel ({where[0]}, {where[1]})",
                       lambda: self.inspectRequested.emit(where))
        if self._marker_name:
            pixel = self.pixel_at(scene_pos)
            menu.addAction(f"Place the {self._marker_name} at ({pixel[0]}, {pixel[1]})",
                           lambda: (self.editStarted.emit(), self.markerPlaced.emit(pixel)))
        if self._rules.mode == CONTOURS and self._sketch.open:
            menu.addAction("Close the contour", self.close_contour)
        if self._sketch.points:
            menu.addAction("Remove the last point", self.remove_last_point)
        menu.addAction("Clear points", self.clearRequested.emit)
        menu.addSeparator()
        menu.addAction("Fit grid to view", self.fit)
        menu.exec(screen_pos.toPoint())

    # --------------------------------------------------------- drawing
    def _make_label(self, color) -> pg.TextItem:
        label = point_label(color)
        self._box.addItem(label)
        return label

    def _anchors(self) -> list:
        """Where the handles sit: at the points, or at the places given (None: not drawn)."""
        if self._places is None:
            return [self.anchor(p) for p in self._sketch.points]
        return [None if p is None else QPointF(*p) for p in self._places]

    def _refresh_points(self) -> None:
        anchors = self._anchors()
        self.handles.setData(pos=[(a.x(), a.y()) for a in anchors if a is not None])
        shown = len(anchors) if len(anchors) <= MAX_LABELS else 0
        while len(self._labels) < shown:
            self._labels.append(self._make_label(self.palette.handle_edge))
            self._labels[-1].show()
        while len(self._labels) > shown:
            self._box.removeItem(self._labels.pop())
        self._place_labels()
        self.primitive.setData(*self._primitive_xy(anchors))
        self._refresh_rim()
        self._draw_preview()

    def _primitive_xy(self, anchors):
        if not self._show_primitive or not anchors:
            return [], []
        paths = self._shape
        if paths is None:
            if not (all_placed(self._rules, self._sketch) and len(anchors) >= 2):
                return [], []
            paths = [([(a.x(), a.y()) for a in anchors], self._closed)]
        return path_xy(paths)

    def _place_labels(self) -> None:
        points = self._sketch.points
        anchors = self._anchors()
        if not anchors or not self._labels:
            return
        # Coordinates in the label while there are few points; with many the
        # points editor lists them and the labels only name them.
        with_numbers = self._rules.mode in (FIXED, CIRCLE)
        texts = [f"{name} ({number_text(p[0])}, {number_text(p[1])})" if with_numbers else name
                 for name, p in zip(self.labels(), points)]
        place_labels(self._box, self._labels, texts, anchors, self._y_down)

    def _rim_position(self) -> QPointF | None:
        if not self._circle or not self._sketch.points:
            return None
        centre = self.anchor(self._sketch.points[0])
        rx, ry = self._radii
        if self._circle == "radius":
            # On the circle, up and to the right of the centre.
            rx = ry = rx * math.sqrt(0.5)
        return QPointF(centre.x() + rx, centre.y() + ry)

    def _refresh_rim(self) -> None:
        at = self._rim_position()
        self.rim.setData(pos=[] if at is None else [(at.x(), at.y())])
        # An empty item still costs every repaint a Python bounding box.
        self.rim.setVisible(at is not None)

    def _refresh_marker(self) -> None:
        point = self._marker_point
        self.marker.setVisible(point is not None)
        if point is None:
            self.marker.setData(pos=[])
            self._marker_label.hide()
            return
        at = QPointF(point[0] + 0.5, point[1] + 0.5)
        brush = translucent(self.palette.seed, 90) if self._marker_automatic else self.palette.seed
        self.marker.setData(pos=[(at.x(), at.y())], brush=pg.mkBrush(brush))
        name = self._marker_name or "marker"
        self._marker_label.setText(f"{name} ({point[0]}, {point[1]})"
                                   + (" auto" if self._marker_automatic else ""))
        self._marker_label.setAnchor((-0.15, 0.5))
        self._marker_label.setPos(at)
        self._marker_label.show()

    def _draw_preview(self) -> None:
        """Dashed lines through the points of the primitive being drawn and
        on to the pointer, closing back to its first point for polygons."""
        waiting = pending(self._rules, self._sketch)
        if not waiting or not self._show_primitive or self._tool == MARKER:
            self.preview.setData([], [])
            return
        anchors = [self.anchor(self._sketch.points[k]) for k in waiting]
        if self._cursor_at is not None:
            anchors.append(self.anchor(self.snap(self._cursor_at)))
        if self._rules.mode in (CONTOURS, GROUPS) and len(anchors) > 2:
            anchors.append(anchors[0])
        self.preview.setData([a.x() for a in anchors], [a.y() for a in anchors])
