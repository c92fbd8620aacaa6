"""A picture with several image pixels per grid cell, laid over a grid.

The compare diff and the coverage-error map carry patterns inside their
cells (app/render/patterns.py) so that colour is not their only cue; the
grid's own image has one pixel per cell, so the patterned picture is shown
by this item instead, stretched over the same cells.
"""
from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QRectF


class PatternLayer(pg.ImageItem):
    """An image over the cells (0, 0) .. (width, height) of a view box."""

    def __init__(self, view_box, z: float = 0.5):
        super().__init__(axisOrder="row-major")
        self.setZValue(z)  # above the grid's image, below its lines and outlines
        self.setVisible(False)
        view_box.addItem(self)

    def show_cells(self, rgba: np.ndarray, width: int, height: int) -> None:
        """Show ``rgba`` (row 0 at y = 0) over a grid of width x height cells."""
        self.setImage(rgba, autoLevels=False)
        self.setRect(QRectF(0, 0, width, height))
        self.setVisible(True)

    def clear(self) -> None:
        self.setVisible(False)
