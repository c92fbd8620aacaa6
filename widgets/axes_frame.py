"""A view box with an axis to its left and one below, as a PlotItem lays
them out, without the rest of a PlotItem (its title, top and right axes,
buttons and options form): the grid view and the variables panel's plot."""
from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtWidgets import QGraphicsGridLayout, QGraphicsItem, QSizePolicy


def axes_frame(box, axes) -> pg.GraphicsWidget:
    """``box`` with ``axes["left"]`` to its left and ``axes["bottom"]``
    below, linked to it: 1 px margins, no spacing, the axes stacked over
    the box's edge (some 6 ms less of the window's start-up than a
    PlotItem, for the grid view)."""
    frame = pg.GraphicsWidget()
    frame.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
    layout = QGraphicsGridLayout()
    layout.setContentsMargins(1, 1, 1, 1)
    layout.setSpacing(0)
    frame.setLayout(layout)
    layout.addItem(box, 0, 1)
    for name, row, column in (("bottom", 1, 1), ("left", 0, 0)):
        axis = axes[name]
        axis.linkToView(box)
        layout.addItem(axis, row, column)
        axis.setZValue(0.5)  # over the view box's edge, as in a PlotItem
        axis.setFlag(QGraphicsItem.GraphicsItemFlag.ItemNegativeZStacksBehindParent)
    for k in range(2):
        layout.setRowPreferredHeight(k, 0)
        layout.setRowMinimumHeight(k, 0)
        layout.setColumnPreferredWidth(k, 0)
        layout.setColumnMinimumWidth(k, 0)
    layout.setRowStretchFactor(0, 100)
    layout.setRowStretchFactor(1, 1)
    layout.setColumnStretchFactor(0, 1)
    layout.setColumnStretchFactor(1, 100)
    return frame

