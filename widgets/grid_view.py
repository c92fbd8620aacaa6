"""The magnified pixel grid: image of the raster, grid lines, outlines,
the ideal primitive and draggable vertex handles.

Coordinates in the view are grid units: pixel (i, j) is the square
[i, i+1) x [j, j+1) and its centre is (i + 1/2, j + 1/2). With the origin at
the bottom-left (the default) y grows upwards; with the origin at the top-left
the view's y axis is inverted, so the same numbers are drawn top-down and a
click reads its coordinates in that frame.

The view only displays: it is handed an RGBA image of the grid (row 0 at
y = 0), the cells to outline, and the points; it reports points the person
places or drags, and the pixel under the cursor.
"""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QLineF, QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QColor, QCursor, QPen
from PySide6.QtWidgets import QMenu


# Grid lines appear once a cell is this many screen pixels wide, and reach
# full strength at FULL_CELL_PX.
MIN_CELL_PX = 5.0
FULL_CELL_PX = 14.0
# More outlined cells than this in view are not drawn one by one.
MAX_OUTLINES = 20000
HANDLE_SIZE = 15  # screen pixels
HANDLE_HIT = 12   # screen pixels from a handle's centre that grab it
OUTLINE_ORDER = ("difference", "candidate", "current")


class PixelAxis(pg.AxisItem):
    """An axis whose ticks stand at pixel centres and read as pixel indices."""

    def tickValues(self, minVal, maxVal, size):  # noqa: N802 (Qt naming)
        levels = []
        for spacing, values in super().tickValues(minVal - 0.5, maxVal - 0.5, size):
            if spacing >= 1:
                levels.append((spacing, [v + 0.5 for v in values if float(v).is_integer()]))
        if not levels:
            first, last = math.ceil(minVal - 0.5), math.floor(maxVal - 0.5)
            levels = [(1.0, [v + 0.5 for v in range(first, last + 1)])]
        return levels

    def tickStrings(self, values, scale, spacing):  # noqa: N802
        return [str(math.floor(v)) for v in values]


def visible_grid_lines(left, right, bottom, top, width, height, cell_px):
    """The inner cell borders in view, or None when cells are too small.

    Returns ((xs, ys), (left, right, bottom, top)): the ranges of x and y
    at which vertical and horizontal lines are drawn, and the part of the
    grid in view they span. The count depends on the view alone, never on
    the grid's size.
    """
    if cell_px < MIN_CELL_PX:
        return None
    left, right = max(0.0, left), min(float(width), right)
    bottom, top = max(0.0, bottom), min(float(height), top)
    if left >= right or bottom >= top:
        return None
    xs = range(max(1, math.ceil(left)), min(width - 1, math.floor(right)) + 1)
    ys = range(max(1, math.ceil(bottom)), min(height - 1, math.floor(top)) + 1)
    return (xs, ys), (left, right, bottom, top)


class GridLinesItem(pg.GraphicsObject):
    """Cell borders, drawn only for the cells in view and only when cells are
    large enough on screen to tell apart. Cost depends on the view, not on
    the grid: a 4096 x 4096 grid draws the same few hundred lines as a small one."""

    def __init__(self, color: str):
        super().__init__()
        self._size = (1, 1)
        self._color = QColor(color)
        self._border = QColor(color).darker(125)

    def set_size(self, width: int, height: int) -> None:
        self.prepareGeometryChange()
        self._size = (width, height)
        self.update()

    def boundingRect(self):  # noqa: N802
        width, height = self._size
        return QRectF(0, 0, width, height)

    def paint(self, painter, *args):
        view = self.getViewBox()
        if view is None:
            return
        width, height = self._size
        rect = view.viewRect()
        pixel = view.viewPixelSize()
        cell_px = 1.0 / max(pixel[0], pixel[1], 1e-12)
        border = QPen(self._border)
        border.setCosmetic(True)
        border.setWidthF(1.0)
        bottom, top = min(rect.top(), rect.bottom()), max(rect.top(), rect.bottom())
        lines = visible_grid_lines(rect.left(), rect.right(), bottom, top, width, height, cell_px)
        if lines is not None:
            (xs, ys), (left, right, low, high) = lines
            color = QColor(self._color)
            strength = min(1.0, (cell_px - MIN_CELL_PX) / (FULL_CELL_PX - MIN_CELL_PX))
            color.setAlphaF(0.25 + 0.75 * strength)
            pen = QPen(color)
            pen.setCosmetic(True)
            pen.setWidthF(1.0)
            painter.setPen(pen)
            segments = [QLineF(x, low, x, high) for x in xs]
            segments += [QLineF(left, y, right, y) for y in ys]
            if segments:
                painter.drawLines(segments)
        painter.setPen(border)
        painter.setBrush(Qt.BrushStyle.NoBrush)
        painter.drawRect(QRectF(0, 0, width, height))


class CellOutlines(pg.GraphicsObject):
    """Outlines around cells, one layer per kind of highlight."""

    def __init__(self, palette, styles):
        super().__init__()
        self._size = (1, 1)
        self._styles = styles
        self._pens = {}
        for name in OUTLINE_ORDER:
            style = styles[name]
            pen = QPen(QColor(getattr(palette, name)))
            pen.setCosmetic(True)
            pen.setWidthF(style.width)
            pen.setJoinStyle(Qt.PenJoinStyle.MiterJoin)
            if style.dashed:
                pen.setStyle(Qt.PenStyle.DashLine)
                pen.setDashPattern([2.0, 1.5])
            self._pens[name] = pen
        self._layers = {name: np.zeros((0, 2), dtype=np.int64) for name in OUTLINE_ORDER}

    def set_size(self, width: int, height: int) -> None:
        self.prepareGeometryChange()
        self._size = (width, height)
        self.update()

    def set_layer(self, name: str, cells) -> None:
        cells = np.asarray(cells if cells is not None else (), dtype=np.int64).reshape(-1, 2)
        old = self._layers[name]
        if old.shape == cells.shape and np.array_equal(old, cells):
            return
        self._layers[name] = cells
        self.update()

    def layer(self, name: str) -> np.ndarray:
        return self._layers[name]

    def boundingRect(self):  # noqa: N802
        width, height = self._size
        return QRectF(-1, -1, width + 2, height + 2)

    def paint(self, painter, *args):
        view = self.getViewBox()
        if view is None:
            return
        rect = view.viewRect()
        x0, x1 = rect.left() - 1, rect.right() + 1
        y0, y1 = min(rect.top(), rect.bottom()) - 1, max(rect.top(), rect.bottom()) + 1
        pixel = view.viewPixelSize()
        cell_px = 1.0 / max(pixel[0], pixel[1], 1e-12)
        painter.setBrush(Qt.BrushStyle.NoBrush)
        for name in OUTLINE_ORDER:
            cells = self._layers[name]
            if not len(cells):
                continue
            seen = cells[(cells[:, 0] >= x0) & (cells[:, 0] <= x1)
                         & (cells[:, 1] >= y0) & (cells[:, 1] <= y1)]
            if not len(seen) or len(seen) > MAX_OUTLINES:
                continue
            # Insets only make sense while a cell is several pixels wide.
            inset = self._styles[name].inset if cell_px >= 10 else 0.0
            size = 1.0 - 2 * inset
            painter.setPen(self._pens[name])
            painter.drawRects([QRectF(float(x) + inset, float(y) + inset, size, size)
                               for x, y in seen])


class _GridViewBox(pg.ViewBox):
    """A ViewBox that places points on click and drags handles, and pans
    or zooms otherwise."""

    def __init__(self, owner):
        super().__init__(lockAspect=True, enableMenu=False)
        self._owner = owner
        self._dragging = None

    def mouseClickEvent(self, ev):  # noqa: N802
        if ev.button() == Qt.MouseButton.LeftButton:
            ev.accept()
            self._owner._clicked(ev.scenePos())
        elif ev.button() == Qt.MouseButton.RightButton:
            ev.accept()
            self._owner._context_menu(ev.screenPos())
        else:
            super().mouseClickEvent(ev)

    def mouseDragEvent(self, ev, axis=None):  # noqa: N802
        if ev.button() == Qt.MouseButton.LeftButton:
            if ev.isStart():
                self._dragging = self._owner._handle_at(ev.buttonDownScenePos())
            if self._dragging is not None:
                ev.accept()
                self._owner._dragged(self._dragging, ev.scenePos(), ev.isFinish())
                if ev.isFinish():
                    self._dragging = None
                return
        super().mouseDragEvent(ev, axis)


class PixelGridView(pg.PlotWidget):
    """The grid of pixels, with everything drawn over it."""

    #: The points after a click or a drag (a list of (x, y), possibly fewer
    #: than the algorithm takes while the person is still placing them).
    pointsEdited = Signal(list)
    #: The pixel under the cursor, (x, y) in the current frame, or None.
    hoverChanged = Signal(object)
    #: The person asked to clear the points (context menu).
    clearRequested = Signal()

    def __init__(self, palette, outline_styles, parent=None):
        self._box = _GridViewBox(self)
        super().__init__(parent, viewBox=self._box,
                         axisItems={"bottom": PixelAxis("bottom"), "left": PixelAxis("left")})
        self.palette = palette
        self.setBackground(palette.outside)
        plot = self.getPlotItem()
        plot.hideButtons()
        plot.setMenuEnabled(False)
        for name in ("bottom", "left"):
            axis = plot.getAxis(name)
            axis.setPen(pg.mkPen("#6b7785"))
            axis.setTextPen(pg.mkPen("#3d4754"))
        self._box.setBackgroundColor(palette.outside)
        self._box.setDefaultPadding(0.02)

        self.image = pg.ImageItem(axisOrder="row-major")
        self.image.setZValue(0)
        self.grid_lines = GridLinesItem(palette.grid)
        self.grid_lines.setZValue(1)
        self.outlines = CellOutlines(palette, outline_styles)
        self.outlines.setZValue(2)
        self.primitive = pg.PlotCurveItem(pen=pg.mkPen(palette.primitive, width=2.5),
                                          antialias=True, connect="finite")
        self.primitive.setZValue(3)
        self.preview = pg.PlotCurveItem(pen=pg.mkPen(palette.primitive, width=1.5,
                                                     style=Qt.PenStyle.DashLine),
                                        antialias=True)
        self.preview.setZValue(3)
        self.handles = pg.ScatterPlotItem(pxMode=True, size=HANDLE_SIZE, symbol="o",
                                          brush=pg.mkBrush(_translucent(palette.handle, 70)),
                                          pen=pg.mkPen(palette.handle_edge, width=2.5))
        self.handles.setZValue(4)
        for item in (self.image, self.grid_lines, self.outlines, self.primitive,
                     self.preview, self.handles):
            self._box.addItem(item)
        self._labels: list[pg.TextItem] = []

        self._size = (0, 0)
        self._points: list[tuple] = []
        self._count = 2
        self._integer = True
        self._names: tuple[str, ...] = ()
        self._closed = False
        self._y_down = False
        self._hover = None
        self._drag_origin = None
        self._show_primitive = True
        self._shape = None
        self._open_ended = False
        # The view keeps the whole grid in sight as the widget resizes until
        # the person pans or zooms.
        self._auto_fit = True
        self._box.sigRangeChangedManually.connect(self._manual_range)

        self.scene().sigMouseMoved.connect(self._mouse_moved)
        self.viewport().setMouseTracking(True)
        self.setCursor(QCursor(Qt.CursorShape.CrossCursor))
        self.set_grid(32, 24)

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
                  open_ended: bool = False) -> None:
        """How many points the algorithm takes and whether they are whole pixels.

        With ``open_ended`` (a polygon, say) every click adds a point; the
        context menu clears them. Otherwise a click after all ``count``
        points are placed starts a new set.
        """
        self._count, self._integer, self._names = count, integer, tuple(names)
        self._closed = count >= 3 if closed is None else closed
        self._open_ended = bool(open_ended)
        self._refresh_points()

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

    def set_points(self, points) -> None:
        points = [tuple(p) for p in points]
        if points == self._points:
            return
        self._points = points
        self._refresh_points()

    @property
    def points(self) -> list[tuple]:
        return list(self._points)

    # ---------------------------------------------------------- frames
    def set_image(self, rgba: np.ndarray) -> None:
        """Show an (H, W, 4) uint8 image, row 0 at y = 0."""
        self.image.setImage(rgba, autoLevels=False)
        height, width = rgba.shape[:2]
        if (width, height) != self._size:
            self.set_grid(width, height)

    def set_highlights(self, current=(), candidates=()) -> None:
        """Outline the cells of the current step and the decision's candidates."""
        self.outlines.set_layer("current", current)
        self.outlines.set_layer("candidate", candidates)

    def set_differences(self, cells) -> None:
        self.outlines.set_layer("difference", cells)

    # -------------------------------------------------------- geometry
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

    def snap(self, view_pos: QPointF) -> tuple:
        """The point a position in grid units stands for, clamped to the grid."""
        width, height = self._size
        if self._integer:
            x = min(max(math.floor(view_pos.x()), 0), width - 1)
            y = min(max(math.floor(view_pos.y()), 0), height - 1)
            return (x, y)
        # Real inputs: 1/16 of a pixel is fine enough to point with.
        x = min(max(round(view_pos.x() * 16) / 16, 0.0), float(width))
        y = min(max(round(view_pos.y() * 16) / 16, 0.0), float(height))
        return (x, y)

    # ----------------------------------------------------------- mouse
    def _handle_at(self, scene_pos) -> int | None:
        best, best_distance = None, HANDLE_HIT
        for index, point in enumerate(self._points):
            where = self._box.mapViewToScene(self.anchor(point))
            distance = math.hypot(where.x() - scene_pos.x(), where.y() - scene_pos.y())
            if distance <= best_distance:
                best, best_distance = index, distance
        return best

    def _clicked(self, scene_pos) -> None:
        if self._handle_at(scene_pos) is not None and self._complete():
            return  # a click on a handle is a drag that did not move
        point = self.snap(self._box.mapSceneToView(scene_pos))
        if len(self._points) >= self._count and not self._open_ended:
            points = [point]  # all placed: a click starts a new primitive
        else:
            points = self._points + [point]
        self._points = points
        self._refresh_points()
        self.pointsEdited.emit(list(points))

    def _dragged(self, index: int, scene_pos, finished: bool) -> None:
        if index >= len(self._points):
            return
        point = self.snap(self._box.mapSceneToView(scene_pos))
        self.viewport().setCursor(QCursor(Qt.CursorShape.OpenHandCursor if finished
                                          else Qt.CursorShape.ClosedHandCursor))
        if point == self._points[index]:
            return
        points = list(self._points)
        points[index] = point
        self._points = points
        self._refresh_points()
        self.pointsEdited.emit(list(points))

    def _mouse_moved(self, scene_pos) -> None:
        pixel = None
        if self._box.sceneBoundingRect().contains(scene_pos):
            where = self._box.mapSceneToView(scene_pos)
            x, y = math.floor(where.x()), math.floor(where.y())
            if 0 <= x < self._size[0] and 0 <= y < self._size[1]:
                pixel = (x, y)
            on_handle = self._handle_at(scene_pos) is not None
            if self._box._dragging is None:
                shape = Qt.CursorShape.OpenHandCursor if on_handle else Qt.CursorShape.CrossCursor
                self.viewport().setCursor(QCursor(shape))
            self._update_preview(where)
        if pixel != self._hover:
            self._hover = pixel
            self.hoverChanged.emit(pixel)

    def leaveEvent(self, event):  # noqa: N802
        super().leaveEvent(event)
        self.preview.setData([], [])
        if self._hover is not None:
            self._hover = None
            self.hoverChanged.emit(None)

    def _context_menu(self, screen_pos) -> None:
        menu = QMenu(self)
        menu.addAction("Fit grid to view", self.fit)
        menu.addAction("Clear points", self.clearRequested.emit)
        menu.exec(screen_pos.toPoint())

    def _complete(self) -> bool:
        if self._open_ended:
            return len(self._points) >= self._count
        return len(self._points) == self._count

    # --------------------------------------------------------- drawing
    def _refresh_points(self) -> None:
        anchors = [self.anchor(p) for p in self._points]
        self.handles.setData(pos=[(a.x(), a.y()) for a in anchors])
        while len(self._labels) < len(anchors):
            label = pg.TextItem(color=self.palette.handle_edge, anchor=(0, 1),
                                fill=pg.mkBrush(255, 255, 255, 215),
                                border=pg.mkPen(200, 206, 214))
            font = label.textItem.font()
            font.setBold(True)
            font.setPointSizeF(font.pointSizeF() * 1.1)
            label.setFont(font)
            label.setZValue(5)
            self._box.addItem(label)
            self._labels.append(label)
        while len(self._labels) > len(anchors):
            self._box.removeItem(self._labels.pop())
        self._place_labels()
        complete = self._complete() and len(self._points) >= 2
        complete = complete or (self._shape is not None and len(self._points) >= self._count)
        if complete and self._show_primitive:
            paths = self._shape
            if paths is None:
                paths = [([(a.x(), a.y()) for a in anchors], self._closed)]
            xs, ys = [], []
            for points, closed in paths:
                if not points:
                    continue
                if closed:
                    points = list(points) + [points[0]]
                xs += [p[0] for p in points] + [math.nan]
                ys += [p[1] for p in points] + [math.nan]
            self.primitive.setData(np.array(xs, dtype=float), np.array(ys, dtype=float))
        else:
            self.primitive.setData([], [])
        if complete:
            self.preview.setData([], [])

    def _place_labels(self) -> None:
        anchors = [self.anchor(p) for p in self._points]
        if not anchors:
            return
        cx = sum(a.x() for a in anchors) / len(anchors)
        cy = sum(a.y() for a in anchors) / len(anchors)
        for index, (label, point, at) in enumerate(zip(self._labels, self._points, anchors)):
            name = self._names[index] if index < len(self._names) else f"P{index + 1}"
            label.setText(f"{name} ({_number(point[0])}, {_number(point[1])})")
            # Above or below the handle, away from the middle of the points,
            # so a label does not cover the primitive (on screen, whichever
            # way y runs).
            dy = at.y() - cy
            if self._y_down:
                dy = -dy
            if dy == 0:
                dy = at.x() - cx if len(anchors) > 1 else 1.0
            label.setAnchor((0.5, 1.35) if dy >= 0 else (0.5, -0.35))
            label.setPos(at)

    def _update_preview(self, where) -> None:
        if not self._points or self._complete() or not self._show_primitive:
            self.preview.setData([], [])
            return
        target = self.anchor(self.snap(where))
        anchors = [self.anchor(p) for p in self._points] + [target]
        self.preview.setData([a.x() for a in anchors], [a.y() for a in anchors])


def _translucent(color: str, alpha: int) -> QColor:
    """A ring handle: the pixel under it stays visible."""
    result = QColor(color)
    result.setAlpha(alpha)
    return result


def _number(value) -> str:
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return f"{value:g}" if isinstance(value, float) else str(value)
