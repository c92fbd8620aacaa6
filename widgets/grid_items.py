"""What the pixel grid draws over its image: pixel-numbered axes, the grid
lines, the outlined cells and spans, and the vertex handles."""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QLineF, QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFontMetricsF, QPen

from app.model.label_layout import place

from .dirty import cache_drawing, cells_box, update_boxes

# Grid lines appear once a cell is this many screen pixels wide, and reach
# full strength at FULL_CELL_PX.
MIN_CELL_PX = 5.0
FULL_CELL_PX = 14.0
# More outlined cells than this in view are not drawn one by one.
MAX_OUTLINES = 20000
OUTLINE_ORDER = ("difference", "candidate", "current")
HANDLE_SIZE = 15  # screen pixels
RIM_SIZE = 11     # the square handle on a circle's rim
MARKER_SIZE = 22  # the seed marker


class PixelAxis(pg.AxisItem):
    """An axis whose ticks stand at cell boundaries, at whole coordinates:
    pixel i is [i, i+1), so tick "k" is the left (or lower) edge of pixel k
    and a vertex typed as (3, 3) sits on the ticks 3 and 3.

    When a cell is large enough on screen to hold its number, the labels
    name the cells instead: "k" stands at the centre k + 1/2 of cell k,
    between the boundary ticks k and k + 1 (which keep their place)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.cells = 0          # cells along this axis (0: not known yet)
        self.widest = 0         # the largest cell index on either axis
        self.index_labels = False

    def set_cells(self, count: int, widest: int | None = None) -> None:
        """``count`` cells along this axis; ``widest``: the largest index
        on either axis, so that both axes (their cells are squares) choose
        the same labelling and never mix cell numbers with boundaries."""
        self.cells = int(count)
        self.widest = max(0, (count if widest is None else widest) - 1)
        self.picture = None
        self.update()

    def tickValues(self, minVal, maxVal, size):  # noqa: N802 (Qt naming)
        self.index_labels = self._cells_hold_labels(minVal, maxVal, size)
        if self.index_labels:
            # Every boundary in view, one level: each labels the cell after it.
            first, last = math.ceil(min(minVal, maxVal)), math.floor(max(minVal, maxVal))
            return [(1.0, [float(v) for v in range(first, last + 1)])]
        levels = []
        for spacing, values in super().tickValues(minVal, maxVal, size):
            if spacing >= 1:
                # Whole coordinates on the grid: 0 .. cells (its far edge).
                levels.append((spacing, [v for v in values if float(v).is_integer()
                                         and (self.cells <= 0 or 0 <= v <= self.cells)]))
        if not levels:
            first, last = math.ceil(minVal), math.floor(maxVal)
            levels = [(1.0, [float(v) for v in range(first, last + 1)])]
        return levels

    def _cells_hold_labels(self, low, high, size) -> bool:
        if self.cells <= 0 or high == low:
            return False
        cell_px = size / abs(high - low)
        metrics = QFontMetricsF(self.style["tickFont"] or self.font())
        return cell_px >= max(metrics.height() + 2,
                              metrics.horizontalAdvance(str(self.widest)) + 6)

    def tickStrings(self, values, scale, spacing):  # noqa: N802
        return [str(round(v)) for v in values]

    def generateDrawSpecs(self, p):  # noqa: N802
        specs = super().generateDrawSpecs(p)
        if specs is None or not self.index_labels:
            return specs
        axis_spec, tick_specs, text_specs = specs
        return axis_spec, tick_specs, self._cell_texts(text_specs)

    def _cell_texts(self, text_specs):
        """Move each boundary's label "k" half a cell on, to the centre of
        cell k; a boundary with no cell after it (the grid's far edge, or
        outside the grid) loses its label."""
        low, high = self.range
        if high == low:
            return text_specs
        bounds = self.mapRectFromParent(self.geometry())
        vertical = self.orientation in ("left", "right")
        # The same value-to-position scale pyqtgraph uses (signed: it
        # follows an inverted axis).
        per_unit = -bounds.height() / (high - low) if vertical else bounds.width() / (high - low)
        shift = per_unit / 2
        box = self.boundingRect()
        moved = []
        for rect, flags, text in text_specs:
            if not 0 <= int(text) < self.cells:
                continue
            rect = rect.translated(0, shift) if vertical else rect.translated(shift, 0)
            if box & rect == rect:
                moved.append((rect, flags, text))
        return moved


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
        self.set_color(color)

    def set_color(self, color: str) -> None:
        self._color = QColor(color)
        self._border = QColor(color).darker(125)
        self.update()

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
    """Outlines around cells, one layer per kind of highlight, and one box
    around each run of cells a span step fills or scans."""

    def __init__(self, palette, styles):
        super().__init__()
        self._size = (1, 1)
        self._styles = styles
        self._pens = {}
        self.set_palette(palette)
        self._layers = {name: np.zeros((0, 2), dtype=np.int64) for name in OUTLINE_ORDER}
        self._spans = np.zeros((0, 3), dtype=np.int64)

    def set_palette(self, palette) -> None:
        for name in OUTLINE_ORDER + ("span",):
            style = self._styles[name]
            pen = QPen(QColor(getattr(palette, "current" if name == "span" else name)))
            pen.setCosmetic(True)
            pen.setWidthF(style.width)
            pen.setJoinStyle(Qt.PenJoinStyle.MiterJoin)
            if style.dashed:
                pen.setStyle(Qt.PenStyle.DashLine)
                pen.setDashPattern([2.0, 1.5])
            self._pens[name] = pen
        # How far a cosmetic pen reaches past a cell's edge, in screen pixels.
        self._reach_px = max(pen.widthF() for pen in self._pens.values()) + 2.0
        self.update()

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
        update_boxes(self, (cells_box(old), cells_box(cells)), self._reach_px)

    def layer(self, name: str) -> np.ndarray:
        return self._layers[name]

    def set_spans(self, spans) -> None:
        """Runs (x_start, x_end, y): cells x_start .. x_end - 1 of row y."""
        spans = np.asarray(spans if spans is not None else (), dtype=np.int64).reshape(-1, 3)
        if spans.shape == self._spans.shape and np.array_equal(spans, self._spans):
            return
        old, self._spans = self._spans, spans
        update_boxes(self, (_spans_box(old), _spans_box(spans)), self._reach_px)

    @property
    def spans(self) -> np.ndarray:
        return self._spans

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
        if len(self._spans):
            painter.setPen(self._pens["span"])
            painter.drawRects([QRectF(float(a), float(y), float(b - a), 1.0)
                               for a, b, y in self._spans if b > a])


def _spans_box(spans):
    """The box around runs (x_start, x_end, y); None for none."""
    if not len(spans):
        return None
    return (float(spans[:, 0].min()), float(spans[:, 2].min()),
            float(spans[:, 1].max()), float(spans[:, 2].max()) + 1.0)


class Handles(pg.ScatterPlotItem):
    """Handles that leave every click to the view box: a click on a vertex
    closes a contour or shares the vertex, which the drawing tool decides."""

    def mouseClickEvent(self, ev):  # noqa: N802
        ev.ignore()


def translucent(color: str, alpha: int) -> QColor:
    """A ring handle: the pixel under it stays visible."""
    result = QColor(color)
    result.setAlpha(alpha)
    return result


def path_xy(paths) -> tuple[np.ndarray, np.ndarray]:
    """The x and y of [(points, closed), ...] as one line item draws them:
    each path after the other, a closed one back to its start, NaN between."""
    xs, ys = [], []
    for points, closed in paths:
        if not points:
            continue
        if closed:
            points = list(points) + [points[0]]
        xs += [p[0] for p in points] + [math.nan]
        ys += [p[1] for p in points] + [math.nan]
    return np.array(xs, dtype=float), np.array(ys, dtype=float)


def number_text(value) -> str:
    """A coordinate as a label shows it: 3 for 3.0, 2.125 as it is."""
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return f"{value:g}" if isinstance(value, float) else str(value)


def primitive_curves(palette) -> tuple[pg.PlotCurveItem, pg.PlotCurveItem]:
    """The ideal primitive (solid) and the preview of the one being drawn (dashed)."""
    primitive = pg.PlotCurveItem(pen=pg.mkPen(palette.primitive, width=2.5), antialias=True,
                                 connect="finite")
    primitive.setZValue(3)
    preview = pg.PlotCurveItem(pen=pg.mkPen(palette.primitive, width=1.5,
                                            style=Qt.PenStyle.DashLine), antialias=True)
    preview.setZValue(3)
    cache_drawing(primitive)
    return primitive, preview


def handle_items(palette) -> tuple[Handles, Handles, Handles]:
    """The vertex handles (rings), the circle's rim handle and the seed marker."""
    handles = Handles(pxMode=True, size=HANDLE_SIZE, symbol="o",
                      brush=pg.mkBrush(translucent(palette.handle, 70)),
                      pen=pg.mkPen(palette.handle_edge, width=2.5))
    handles.setZValue(4)
    rim = Handles(pxMode=True, size=RIM_SIZE, symbol="s", brush=pg.mkBrush(palette.handle),
                  pen=pg.mkPen(palette.primitive, width=2.5))
    rim.setZValue(4)
    marker = Handles(pxMode=True, size=MARKER_SIZE, symbol="star",
                     brush=pg.mkBrush(palette.seed), pen=pg.mkPen(palette.handle, width=1.5))
    marker.setZValue(6)
    cache_drawing(handles, rim, marker)
    return handles, rim, marker


def point_label(color) -> pg.TextItem:
    """A point's name on the grid (hidden until placed): bold, on white."""
    label = pg.TextItem(color=color, anchor=(0, 1), fill=pg.mkBrush(255, 255, 255, 215),
                        border=pg.mkPen(200, 206, 214))
    font = label.textItem.font()
    font.setBold(True)
    font.setPointSizeF(font.pointSizeF() * 1.1)
    label.setFont(font)
    label.setZValue(5)
    label.hide()
    return label


def place_labels(box, labels, texts, anchors, y_down: bool) -> None:
    """Each point's label by its handle (anchors in grid units, None: the
    label hidden), above or below it, away from the middle of the points, so
    that a label does not cover the primitive (on screen, whichever way y
    runs); labels of points close together are moved apart (app/model/label_layout.py)."""
    placed = [a for a in anchors if a is not None]
    cx = sum(a.x() for a in placed) / max(1, len(placed))
    cy = sum(a.y() for a in placed) / max(1, len(placed))
    shown, at_points, above = [], [], []
    for label, text, at in zip(labels, texts, anchors):
        label.setVisible(at is not None)
        if at is None:
            continue
        label.setText(text)
        dy = -(at.y() - cy) if y_down else at.y() - cy
        if dy == 0:
            dy = at.x() - cx if len(placed) > 1 else 1.0
        shown.append(label)
        at_points.append(at)
        above.append(dy >= 0)
    if shown:
        place_point_labels(box, shown, at_points, above)


def place_point_labels(box, labels, anchors, above) -> None:
    """Put each label over (or under) its point, moved apart where labels of
    points close together would overlap (app/model/label_layout.py); the
    layout is in screen pixels, so it is done again when the view changes."""
    screen = [box.mapViewToScene(at) for at in anchors]
    sizes = [(label.textItem.boundingRect().width(), label.textItem.boundingRect().height())
             for label in labels]
    rects = place([(p.x(), p.y()) for p in screen], sizes, above)
    for label, rect in zip(labels, rects):
        label.setAnchor((0.5, 0.5))
        label.setPos(box.mapSceneToView(QPointF(*rect.centre)))
