"""Line items over the grid for geometric overlays: strokes in grid units,
one line item per colour (NaN between strokes), drawn above the pixels."""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg


class OverlayLayer:
    """The overlay strokes of the step on show, on a grid view's view box."""

    def __init__(self, view_box, z: float = 3.2):
        self._box = view_box
        self._z = z
        self._items: dict[tuple, pg.PlotDataItem] = {}

    def set_strokes(self, strokes) -> None:
        """Show ``strokes`` (objects with ``points`` and an (r, g, b) ``colour``)."""
        by_colour: dict[tuple, tuple[list, list]] = {}
        for stroke in strokes:
            xs, ys = by_colour.setdefault(tuple(stroke.colour), ([], []))
            xs += [p[0] for p in stroke.points] + [math.nan]
            ys += [p[1] for p in stroke.points] + [math.nan]
        for colour, item in self._items.items():
            if colour not in by_colour:
                item.setData([], [])
        for colour, (xs, ys) in by_colour.items():
            item = self._items.get(colour)
            if item is None:
                item = pg.PlotDataItem(pen=pg.mkPen(colour, width=2), connect="finite")
                item.setZValue(self._z)
                self._box.addItem(item)
                self._items[colour] = item
            item.setData(np.array(xs, float), np.array(ys, float))

    def shown(self) -> dict[tuple, int]:
        """Points drawn per colour (for tests)."""
        return {colour: int(np.isfinite(item.getData()[0]).sum()) if item.getData()[0]
                is not None else 0 for colour, item in self._items.items()}
