"""The reasoning of a step drawn over the grid: the scan line and its
crossings, Bresenham's midpoint M, ... The window hands over the frame
model's guides (``lines``, ``dots``, ``labels`` in grid units, as
app/render/reasoning.py makes them); this item only draws them."""
from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QFont, QPen

from .dirty import points_box, update_boxes

# Screen pixels: line widths, and the radius of a dot.
LINE_PX = {"scan": 1.5, "pair": 5.0, "drop": 2.0}
DOT_PX = {"crossing": 5.0, "midpoint": 5.0}
# How far a line or dot reaches past its geometry, in screen pixels.
REACH_PX = max(max(LINE_PX.values()), max(DOT_PX.values())) + 2.0


class GuidesItem(pg.GraphicsObject):
    """Lines and dots in the guide colour, sized in screen pixels, and
    their labels as text items. Draws nothing for None."""

    def __init__(self, palette):
        super().__init__()
        self.guides = None
        self._size = (1, 1)
        self._labels: list[pg.TextItem] = []
        self._text_scale = 1.0  # the window's zoom (larger while presenting)
        self.setZValue(3.6)
        self.set_palette(palette)

    def set_palette(self, palette) -> None:
        self._colour = QColor(palette.guide)
        for label in self._labels:
            label.setColor(self._colour)
        self.update()

    def set_size(self, width: int, height: int) -> None:
        if (width, height) == self._size:
            return
        self.prepareGeometryChange()
        self._size = (width, height)
        self.update()

    def set_guides(self, guides) -> None:
        if guides == self.guides:
            return
        old, self.guides = self.guides, guides
        self._place_labels()
        update_boxes(self, (_box(old), _box(guides)), REACH_PX)

    def _place_labels(self) -> None:
        view = self.getViewBox()
        while self.guides and len(self._labels) < len(self.guides.labels):
            label = pg.TextItem(color=self._colour, anchor=(0, 1))
            label.base_font = label.textItem.font()
            label.base_font.setBold(True)
            self._scale_font(label)
            label.setZValue(3.7)
            if view is not None:
                view.addItem(label)
            self._labels.append(label)
        labels = self.guides.labels if self.guides else ()
        for k, label in enumerate(self._labels):
            if k < len(labels):
                x, y, text = labels[k]
                if label.toPlainText() != text:  # a new text lays itself out again
                    label.setText(text)
                label.setPos(QPointF(x + 0.1, y))
                label.show()
            else:
                label.hide()

    def set_text_scale(self, scale: float) -> None:
        """Labels at ``scale`` times their own size (the window's zoom)."""
        self._text_scale = float(scale)
        for label in self._labels:
            self._scale_font(label)

    def _scale_font(self, label) -> None:
        font = QFont(label.base_font)
        if font.pointSizeF() > 0:
            font.setPointSizeF(font.pointSizeF() * self._text_scale)
        label.setFont(font)

    def label_sizes(self) -> list[float]:
        """The point sizes of the labels on show, in order."""
        count = len(self.guides.labels) if self.guides else 0
        return [label.textItem.font().pointSizeF() for label in self._labels[:count]]

    def label_texts(self) -> list[str]:
        """The labels on show, in order."""
        count = len(self.guides.labels) if self.guides else 0
        return [label.toPlainText() for label in self._labels[:count]]

    def boundingRect(self):  # noqa: N802
        width, height = self._size
        return QRectF(-1, -1, width + 2, height + 2)

    def paint(self, painter, *args):
        view = self.getViewBox()
        if view is None or not self.guides:
            return
        pixel = view.viewPixelSize()
        unit = max(pixel[0], pixel[1], 1e-12)  # grid units per screen pixel
        for x0, y0, x1, y1, role in self.guides.lines:
            pen = QPen(self._colour)
            pen.setCosmetic(True)
            pen.setWidthF(LINE_PX.get(role, 1.5))
            pen.setCapStyle(Qt.PenCapStyle.FlatCap)
            painter.setPen(pen)
            painter.drawLine(QPointF(x0, y0), QPointF(x1, y1))
        painter.setPen(Qt.PenStyle.NoPen)
        painter.setBrush(QBrush(self._colour))
        for x, y, role in self.guides.dots:
            if role not in DOT_PX:
                continue  # samples: the grid draws its own sample dots
            radius = DOT_PX[role] * unit
            painter.drawEllipse(QPointF(x, y), radius, radius)


def _box(guides):
    """The box around a step's guide lines and dots (grid units); None for none."""
    if not guides:
        return None
    xs = [v for x0, _y0, x1, _y1, _role in guides.lines for v in (x0, x1)]
    ys = [v for _x0, y0, _x1, y1, _role in guides.lines for v in (y0, y1)]
    xs += [x for x, _y, _role in guides.dots]
    ys += [y for _x, y, _role in guides.dots]
    return points_box(xs, ys)
