"""The points to plot for a value over a run of any length.

A plot a few hundred pixels wide cannot show two million steps; handing
them all to pyqtgraph costs a noticeable pause each time a long run is
installed. Past ``LIMIT`` known values the run is cut into buckets of
consecutive steps and each bucket keeps its lowest and highest value (in
step order), which draws the same outline at screen resolution.
"""
from __future__ import annotations

import numpy as np

LIMIT = 4096


def plot_points(values: np.ndarray, limit: int = LIMIT) -> tuple[np.ndarray, np.ndarray]:
    """(steps, values) of the finite values, thinned to at most ``limit``."""
    steps = np.flatnonzero(np.isfinite(values))
    known = values[steps]
    if len(steps) <= limit:
        return steps.astype(np.float64), known
    size = -(-len(steps) // max(1, limit // 2))
    full = len(known) // size
    body = known[:full * size].reshape(full, size)  # a view: no copy of a long run
    base = np.arange(full) * size
    low, high = base + body.argmin(axis=1), base + body.argmax(axis=1)
    if full * size < len(known):  # the last, shorter bucket
        tail = known[full * size:]
        low = np.append(low, full * size + tail.argmin())
        high = np.append(high, full * size + tail.argmax())
    picks = np.stack([np.minimum(low, high), np.maximum(low, high)], axis=1).ravel()
    return steps[picks].astype(np.float64), known[picks]
