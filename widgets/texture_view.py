"""The texture panel: the texture level in use with the pixel's footprint and the texels
fetched, and beside it the grid coloured by the mip level each pixel read.

It shows what it is given (``app.render.texture_frame``) and nothing else. The pictures keep
at least a quarter of the window's height, so that a crowded dock column cannot squeeze them
to a strip, and the texts wrap, each whole in its tooltip.
"""
from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QEvent, Signal
from PySide6.QtWidgets import QHBoxLayout, QLabel, QPushButton, QVBoxLayout, QWidget

FOOTPRINT = (230, 30, 30)
SMALLEST_PICTURE = 120  # px: the pictures' height however small the window


def _plot(parent, background, name: str) -> tuple:
    plot = pg.PlotWidget(parent, enableMenu=False)  # no view menu is built
    plot.setAccessibleName(name)
    plot.setBackground(background)
    item = plot.getPlotItem()
    item.hideButtons()
    item.setMenuEnabled(False)
    item.hideAxis("bottom")
    item.hideAxis("left")
    box = plot.getViewBox()
    box.setAspectLocked(True)
    box.setMouseEnabled(False, False)
    image = pg.ImageItem(axisOrder="row-major")
    box.addItem(image)
    return plot, image


class TextureView(QWidget):
    """Texture with footprint (left) and mip levels on the grid (right)."""

    open_requested = Signal()  # the person asked to open a PNG as the texture

    def __init__(self, palette, parent=None):
        super().__init__(parent)
        self.texture_plot, self.texture_image = _plot(self, palette.outside, "Texture")
        self.level_plot, self.level_image = _plot(self, palette.outside, "Mip-map level")
        self.footprint = pg.PlotDataItem(pen=pg.mkPen(FOOTPRINT, width=2))
        self.texture_plot.getViewBox().addItem(self.footprint)
        self.fetches = pg.ScatterPlotItem(symbol="s", pen=pg.mkPen(FOOTPRINT, width=1.5))
        self.texture_plot.getViewBox().addItem(self.fetches)
        self.caption = QLabel(self)
        self.caption.setWordWrap(True)
        self.caption.setObjectName("textureCaption")
        self.legend = QLabel(self)
        self.legend.setWordWrap(True)
        self.legend.setObjectName("levelLegend")
        pictures = QHBoxLayout()
        pictures.addWidget(self.texture_plot, 3)
        pictures.addWidget(self.level_plot, 2)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 4, 6, 6)
        layout.addLayout(pictures, 1)
        self.open_button = QPushButton("Open texture\u2026", self)
        self.open_button.setObjectName("openTexture")
        self.open_button.setToolTip("Use a PNG file (sides powers of two) as the texture")
        self.open_button.clicked.connect(self.open_requested)
        below = QHBoxLayout()
        below.addWidget(self.caption, 1)
        below.addWidget(self.open_button)
        layout.addLayout(below)
        layout.addWidget(self.legend)
        self._sizes = {}
        self.footprint_points: list = []
        for label in (self.caption, self.legend):
            # Two lines at least: the dock may not take a wrapped label's height into account.
            label.setMinimumHeight(2 * label.fontMetrics().lineSpacing() + 2)

    def showEvent(self, event):  # noqa: N802 (Qt naming)
        self.window().installEventFilter(self)  # installed once: Qt moves a repeat to the front
        self._fit_pictures()
        super().showEvent(event)

    def eventFilter(self, watched, event):  # noqa: N802 (Qt naming)
        if watched is self.window() and event.type() == QEvent.Type.Resize:
            self._fit_pictures()
        return False

    def _fit_pictures(self) -> None:
        height = max(SMALLEST_PICTURE, self.window().height() // 4)
        for plot in (self.texture_plot, self.level_plot):
            plot.setMinimumHeight(height)

    def set_picture(self, picture) -> None:
        """Show a TexturePicture (None: clear)."""
        if picture is None:
            self.texture_image.clear()
            self.footprint.setData([], [])
            self.fetches.setData([])
            self._say(self.caption, "")
            return
        self._show(self.texture_plot, self.texture_image, picture.image, "texture")
        self.footprint_points = list(picture.footprint)
        if picture.footprint:
            xs = [p[0] for p in picture.footprint] + [picture.footprint[0][0]]
            ys = [p[1] for p in picture.footprint] + [picture.footprint[0][1]]
            self.footprint.setData(xs, ys)
        else:
            self.footprint.setData([], [])
        height = picture.image.shape[0]
        size = max(4.0, 200.0 / max(height, 1))
        self.fetches.setData([{"pos": (i + 0.5, j + 0.5), "size": size,
                               "brush": pg.mkBrush(255, 255, 0, int(60 + 180 * min(w * 4, 1)))}
                              for i, j, w in picture.texels])
        self._say(self.caption, picture.caption)

    def set_levels(self, rgba, legend: str = "") -> None:
        if rgba is None:
            self.level_image.clear()
        else:
            self._show(self.level_plot, self.level_image, rgba, "levels")
        self._say(self.legend, legend)

    @staticmethod
    def _say(label, text: str) -> None:
        label.setText(text)
        label.setToolTip(text)

    def set_y_down(self, y_down: bool) -> None:
        self.level_plot.getViewBox().invertY(bool(y_down))

    def _show(self, plot, image_item, rgba: np.ndarray, key: str) -> None:
        image_item.setImage(rgba, autoLevels=False, levels=(0, 255))
        height, width = rgba.shape[:2]
        if self._sizes.get(key) != (width, height):
            self._sizes[key] = (width, height)
            plot.getViewBox().setRange(xRange=(0, width), yRange=(0, height), padding=0.02)
