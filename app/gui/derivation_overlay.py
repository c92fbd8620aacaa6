"""s and n of the Bresenham derivation drawn on the grid at the step on show.

``DerivationOverlay(window)`` adds two short segments and their labels to
the grid: s from the lower candidate's centre to the ideal line, n from the
line to the upper candidate's centre (app/model/derivation.py works them
out). They show only for runs whose steps carry s and n.
"""
from __future__ import annotations

import pyqtgraph as pg

from app.model.colours import OKABE_ITO
from app.model.derivation import distance_segments

# Okabe-Ito hues (app/model/colours.py) that stay apart with any common
# colour-vision deficiency; each segment also carries its name.
COLOURS = {"s": OKABE_ITO["bluish green"], "n": OKABE_ITO["vermillion"]}
LABEL = '<span style="color: {colour}; font-weight: bold; font-size: 11pt; background: #ffffffd0">' \
        '{name} = {value:.3g}</span>'


class DerivationOverlay:
    def __init__(self, window):
        self.window = window
        self.items = {}
        for name, colour in COLOURS.items():
            curve = pg.PlotCurveItem(pen=pg.mkPen(colour, width=4))
            label = pg.TextItem("", anchor=(0, 0.5))
            for item in (curve, label):
                item.setZValue(6)
                item.setVisible(False)
                window.grid.view_box.addItem(item)
            self.items[name] = (curve, label)
        window.player.frameChanged.connect(lambda _index: self.refresh())
        window.player.traceChanged.connect(self.refresh)

    def segments(self) -> list:
        player = self.window.player
        if player.trace is None:
            return []
        return distance_segments(list(player.shown_scene.flat), player.trace, player.index)

    def refresh(self) -> None:
        shown = {name: (value, start, end) for name, value, start, end in self.segments()}
        for name, (curve, label) in self.items.items():
            if name not in shown:
                curve.setVisible(False)
                label.setVisible(False)
                continue
            value, (x0, y0), (x1, y1) = shown[name]
            curve.setData([x0, x1], [y0, y1])
            label.setHtml(LABEL.format(colour=COLOURS[name], name=name, value=value))
            label.setPos(max(x0, x1) + 0.55, (y0 + y1) / 2)
            curve.setVisible(True)
            label.setVisible(True)
