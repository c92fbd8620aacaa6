"""The colour bar of the coverage-error map: blue where a run covers a
pixel too little, white where it is right, vermillion where it covers too much,
with the largest error at either end."""
from __future__ import annotations

from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QColor, QLinearGradient, QPainter, QPixmap
from PySide6.QtWidgets import QHBoxLayout, QLabel, QWidget

from app.model.colours import LIGHT

# The ends of the map (app/render/compose.py error_image with signed=True).
TOO_LITTLE, RIGHT, TOO_MUCH = LIGHT.too_little, "#ffffff", LIGHT.too_much


class ErrorScale(QWidget):
    """"too little −m [blue–white–red] +m too much"."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.low = QLabel(self)
        self.bar = QLabel(self)
        self.high = QLabel(self)
        self.bar.setPixmap(_gradient(96, 12))
        layout = QHBoxLayout(self)
        layout.setContentsMargins(6, 0, 6, 0)
        layout.setSpacing(4)
        for part in (self.low, self.bar, self.high):
            layout.addWidget(part)
        self.setToolTip("Coverage error per pixel, estimate \u2212 exact: blue where the run "
                        "covers too little, red where it covers too much, white where it "
                        "is right")
        self.set_range(0.0)

    def set_range(self, top: float) -> None:
        """The largest error, at both ends of the bar."""
        self.low.setText(f"too little \u2212{top:.3g}")
        self.high.setText(f"+{top:.3g} too much")


def _gradient(width: int, height: int) -> QPixmap:
    pixmap = QPixmap(width, height)
    pixmap.fill(Qt.GlobalColor.transparent)
    gradient = QLinearGradient(0, 0, width, 0)
    for at, color in ((0.0, TOO_LITTLE), (0.5, RIGHT), (1.0, TOO_MUCH)):
        gradient.setColorAt(at, QColor(color))
    painter = QPainter(pixmap)
    painter.fillRect(QRectF(0, 0, width, height), gradient)
    painter.setPen(QColor("#6b7785"))
    painter.drawRect(QRectF(0.5, 0.5, width - 1, height - 1))
    painter.end()
    return pixmap
