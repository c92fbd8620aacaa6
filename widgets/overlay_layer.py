"""Items over the grid for geometric overlays (app/render/overlays.py):
strokes in grid units, one line item per colour and width (NaN between
strokes), translucent fills as polygons and labels as text, drawn above
the pixels."""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF
from PySide6.QtGui import QBrush, QColor, QPolygonF
from PySide6.QtWidgets import QGraphicsPolygonItem


class OverlayLayer:
    """The overlay shapes of the step on show, on a grid view's view box."""

    def __init__(self, view_box, z: float = 3.2):
        self._box = view_box
        self._z = z
        self._items: dict[tuple, pg.PlotDataItem] = {}
        self._fills: list[QGraphicsPolygonItem] = []
        self._labels: list[pg.TextItem] = []

    def set_shapes(self, shapes) -> None:
        """Show ``shapes`` (``overlays.Shapes``: strokes, fills and labels)."""
        self.set_strokes(shapes.strokes)
        self._set_fills(shapes.fills)
        self._set_labels(shapes.labels)

    def set_strokes(self, strokes) -> None:
        """Show ``strokes`` (objects with ``points``, an (r, g, b) ``colour``
        and a ``width`` in screen pixels)."""
        by_pen: dict[tuple, tuple[list, list]] = {}
        for stroke in strokes:
            xs, ys = by_pen.setdefault((tuple(stroke.colour), stroke.width), ([], []))
            xs += [p[0] for p in stroke.points] + [math.nan]
            ys += [p[1] for p in stroke.points] + [math.nan]
        for pen, item in self._items.items():
            if pen not in by_pen:
                item.setData([], [])
        for pen, (xs, ys) in by_pen.items():
            item = self._items.get(pen)
            if item is None:
                item = pg.PlotDataItem(pen=pg.mkPen(pen[0], width=pen[1]), connect="finite")
                item.setZValue(self._z)
                self._box.addItem(item)
                self._items[pen] = item
            item.setData(np.array(xs, float), np.array(ys, float))

    def _set_fills(self, fills) -> None:
        for item in self._fills:
            self._box.removeItem(item)
        self._fills = []
        for fill in fills:
            item = QGraphicsPolygonItem(QPolygonF([QPointF(x, y) for x, y in fill.points]))
            item.setBrush(QBrush(QColor(*fill.colour, round(fill.alpha * 255))))
            item.setPen(pg.mkPen(None))
            item.setZValue(self._z - 0.1)  # under the strokes
            self._box.addItem(item)
            self._fills.append(item)

    def _set_labels(self, labels) -> None:
        while len(self._labels) > len(labels):
            self._box.removeItem(self._labels.pop())
        while len(self._labels) < len(labels):
            item = pg.TextItem(anchor=(0.5, 0.5), fill=pg.mkBrush(255, 255, 255, 190))
            font = item.textItem.font()
            font.setBold(True)
            font.setPointSizeF(font.pointSizeF() * 1.4)
            item.setFont(font)
            item.setZValue(self._z + 0.1)
            self._box.addItem(item)
            self._labels.append(item)
        for item, label in zip(self._labels, labels):
            item.setText(label.text, color=label.colour)
            item.setPos(QPointF(*label.at))

    def shown(self) -> dict[tuple, int]:
        """Points drawn per (colour, width) (for tests)."""
        return {pen: int(np.isfinite(item.getData()[0]).sum()) if item.getData()[0]
                is not None else 0 for pen, item in self._items.items()}

    def fills(self) -> list[tuple]:
        """(points, (r, g, b, a)) of each fill drawn (for tests)."""
        result = []
        for item in self._fills:
            polygon, colour = item.polygon(), item.brush().color()
            result.append((tuple((p.x(), p.y()) for p in polygon),
                           (colour.red(), colour.green(), colour.blue(), colour.alpha())))
        return result

    def labels(self) -> list[tuple]:
        """((x, y), text) of each label drawn (for tests)."""
        return [((item.pos().x(), item.pos().y()), item.textItem.toPlainText())
                for item in self._labels]
