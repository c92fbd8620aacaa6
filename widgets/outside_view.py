"""The pipeline's side picture: the stage's triangles (the one at the step drawn apart), with
the camera and frustum, the clip planes or the frame of NDC or the window."""
from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QLabel, QVBoxLayout, QWidget

from widgets.depth_view import quiet_plot

SCENE_PEN = (40, 40, 40)
FRUSTUM_PEN = (25, 113, 194)
CURRENT_PEN = (230, 73, 55)


def _pairs(segments):
    if not segments:
        return np.zeros(0), np.zeros(0)
    flat = np.array([p for segment in segments for p in segment], dtype=float)
    return flat[:, 0], flat[:, 1]


class OutsideView(QWidget):
    """Shows an app.render.outside_view.OutsideView."""

    def __init__(self, palette, parent=None):
        super().__init__(parent)
        self.plot = quiet_plot(palette, self, "The scene seen from outside")
        box = self.plot.getViewBox()
        box.invertY(True)  # z grows downwards: the camera looks up the picture towards -z
        self.scene_lines = pg.PlotDataItem(connect="pairs", pen=pg.mkPen(SCENE_PEN, width=1.5))
        self.frustum_lines = pg.PlotDataItem(connect="pairs", pen=pg.mkPen(FRUSTUM_PEN, width=1.5))
        self.current_lines = pg.PlotDataItem(connect="pairs",
                                             pen=pg.mkPen(CURRENT_PEN, width=2.5))
        self.eye = pg.ScatterPlotItem(symbol="o", size=9, brush=pg.mkBrush(FRUSTUM_PEN))
        for part in (self.scene_lines, self.frustum_lines, self.current_lines, self.eye):
            box.addItem(part)
        self.caption = QLabel(self)
        self.caption.setWordWrap(True)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 4, 6, 6)
        layout.addWidget(self.plot, 1)
        layout.addWidget(self.caption)

    def set_view(self, view) -> None:
        if view is None:
            for part in (self.scene_lines, self.frustum_lines, self.current_lines):
                part.setData([], [])
            self.eye.setData([])
            self.caption.setText("")
            return
        self.scene_lines.setData(*_pairs(view.triangles))
        self.frustum_lines.setData(*_pairs(view.frustum))
        self.current_lines.setData(*_pairs(view.current))
        if view.eye is None:
            self.eye.setData([])
        else:
            self.eye.setData([view.eye[0]], [view.eye[1]])
        self.caption.setText(view.caption)
        self.caption.setToolTip(view.caption)
        box = self.plot.getViewBox()
        box.invertY(view.y_down)
        box.autoRange(padding=0.08)
