"""A second picture of the grid: the depth buffer of a run that keeps one
(or its other buffer: accumulation, stencil).

It shows an image composed elsewhere (``app.render.depth_image``: near
dark, far light) cell for cell in the same frame as the pixel grid, with
the same origin and direction of y, and says what the greys mean.
"""
from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QLabel, QVBoxLayout, QWidget


def quiet_plot(palette, parent, name: str) -> pg.PlotWidget:
    """A plot that only shows: the view's background, no buttons, no menu,
    square units (the side views' common ground); ``name`` is what a screen
    reader calls it."""
    plot = pg.PlotWidget(parent, enableMenu=False)  # no view menu is built
    plot.setAccessibleName(name)
    plot.setBackground(palette.outside)
    item = plot.getPlotItem()
    item.hideButtons()
    item.setMenuEnabled(False)
    plot.getViewBox().setAspectLocked(True)
    return plot


class DepthView(QWidget):
    """The depth buffer beside the colour buffer. Its plot is made when the
    view is first shown or given an image: the dock is hidden at start, and
    a pyqtgraph plot is a noticeable part of opening the window."""

    def __init__(self, palette, parent=None):
        super().__init__(parent)
        self._palette = palette
        self.plot: pg.PlotWidget | None = None
        self.image: pg.ImageItem | None = None
        self.legend = QLabel(self)
        self.legend.setWordWrap(True)
        self.legend.setObjectName("depthLegend")
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 4, 6, 6)
        layout.setSpacing(4)
        layout.addWidget(self.legend)
        self._size = (0, 0)
        self._y_down = False
        self._rgba: np.ndarray | None = None

    def showEvent(self, event):  # noqa: N802 (Qt naming)
        self._build()
        super().showEvent(event)

    def _build(self) -> None:
        if self.plot is not None:
            return
        self.plot = quiet_plot(self._palette, self, "Buffer picture")
        item = self.plot.getPlotItem()
        item.hideAxis("bottom")
        item.hideAxis("left")
        box = self.plot.getViewBox()
        box.setMouseEnabled(False, False)
        box.setDefaultPadding(0.02)
        box.invertY(self._y_down)
        self.image = pg.ImageItem(axisOrder="row-major")
        box.addItem(self.image)
        self.layout().insertWidget(0, self.plot, 1)
        self.plot.show()  # made after its parent was shown: Qt would show it later

    def set_image(self, rgba: np.ndarray, near: float, far: float,
                  legend: str | None = None) -> None:
        """Show an (H, W, 4) uint8 image, row 0 at y = 0; ``near`` and
        ``far`` are the depths of the darkest and the lightest grey, which
        the legend says unless it is given."""
        self._build()
        self._rgba = rgba
        self.image.setImage(rgba, autoLevels=False)
        height, width = rgba.shape[:2]
        if (width, height) != self._size:
            self._size = (width, height)
            self.plot.getViewBox().setRange(xRange=(0, width), yRange=(0, height), padding=0.02)
        self.legend.setText(legend or f"near {near:.3g} = dark \u00b7 far {far:.3g} = light "
                                      "(never written: the clear depth)")

    def set_y_down(self, y_down: bool) -> None:
        self._y_down = bool(y_down)
        if self.plot is not None:
            self.plot.getViewBox().invertY(self._y_down)

    def image_data(self) -> np.ndarray | None:
        """The image on show."""
        return self._rgba
