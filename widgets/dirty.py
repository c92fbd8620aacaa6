"""Repaint only the part of a grid item, or of the window, that changed.

An item over the grid (outlines, guides) covers the whole grid, so a plain
``update()`` repaints the whole view, image included: at 4096 x 4096 that
is most of a step's cost. These helpers repaint the boxes (in grid units)
of what was drawn before and of what is drawn now, widened by the screen
pixels a cosmetic pen or a dot reaches past its geometry.
"""
from __future__ import annotations

import numpy as np
from PySide6.QtCore import QRectF
from PySide6.QtWidgets import QGraphicsItem

Box = tuple[float, float, float, float]  # x0, y0, x1, y1 in grid units


def cells_box(cells) -> Box | None:
    """The box around cells (N, 2) of whole x, y, each a unit square; None for none."""
    cells = np.asarray(cells).reshape(-1, 2)
    if not len(cells):
        return None
    low, high = cells.min(axis=0), cells.max(axis=0)
    return float(low[0]), float(low[1]), float(high[0]) + 1.0, float(high[1]) + 1.0


def points_box(xs, ys) -> Box | None:
    """The box around points; None for none."""
    xs, ys = np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)
    if not xs.size:
        return None
    return float(xs.min()), float(ys.min()), float(xs.max()), float(ys.max())


def update_boxes(item, boxes, reach_px: float) -> None:
    """Repaint ``item`` over each box (None: nothing there), widened by
    ``reach_px`` screen pixels; the whole item when it is in no view yet."""
    view = item.getViewBox()
    if view is None:
        item.update()
        return
    pixel = view.viewPixelSize()
    pad = reach_px * max(pixel[0], pixel[1], 1e-12)
    for box in boxes:
        if box is None:
            continue
        x0, y0, x1, y1 = box
        item.update(QRectF(x0 - pad, y0 - pad, x1 - x0 + 2 * pad, y1 - y0 + 2 * pad))


def cache_drawing(*items) -> None:
    """Keep each item's drawing as a pixmap on screen: a repaint of a small
    area they overlap (the step's cell, the step marker) then copies the
    pixmap instead of running the item's Python ``paint``. Qt draws the
    item afresh when it changes or the view zooms."""
    for item in items:
        item.setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)


def fill_own_background(*widgets) -> None:
    """Each widget fills its own background before it paints, so it is
    opaque to Qt: repainting it (every step, for a caption, a counter or a
    table's cells) no longer repaints the window, the dock and the panel
    behind it first."""
    for widget in widgets:
        widget.setAutoFillBackground(True)
