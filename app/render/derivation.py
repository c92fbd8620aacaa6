"""s and n of the Bresenham derivation drawn into an exported frame, as the
window draws them (app/gui/derivation_overlay.py): two bars along the minor
axis at the column being decided, s in the candidate colour, n in the
difference colour. Works on the frame's palette indices; no Qt.
"""
from __future__ import annotations

import numpy as np

from app.model.derivation import distance_segments


def draw_distances(frame: np.ndarray, renderer, index: int) -> None:
    """Draw step ``index``'s s and n into the grid part of ``frame`` (top row first)."""
    points = renderer.scene.points
    marks = distance_segments(points, renderer.trace, index)
    if not marks:
        return
    scale = renderer.settings.scale
    height = renderer.trace.height * scale
    half = max(1, scale // 8)  # the bar's half width, in image pixels
    palette = renderer.theme.palette
    colours = {"s": renderer.colours.index_of(palette.candidate),
               "n": renderer.colours.index_of(palette.difference)}
    for name, _, (x0, y0), (x1, y1) in marks:
        left, right = sorted((round(x0 * scale), round(x1 * scale)))
        low, high = sorted((round(y0 * scale), round(y1 * scale)))
        left, right = max(left - half, 0), min(right + half, frame.shape[1])
        low, high = max(low - half, 0), min(high + half, height)
        if left >= right or low >= high:
            continue
        rows = slice(low, high) if renderer.y_down else slice(height - high, height - low)
        frame[rows, left:right] = colours[name]
