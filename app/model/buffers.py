"""The second per-pixel buffer a run keeps besides the colour buffer
(``Start.buffer_value``): the accumulation buffer that supersampling and
motion blur sum their samples in, or a stencil a later primitive respects.

Unlike the depth buffer, which only written pixels change, these buffers
change on frames that write no colour (a sample added, a stencil bit set),
so they are read from the recorded value column directly: at step i a
pixel holds the last value a frame with that pixel set since the buffer
was last cleared (a ``Vars`` record whose ``cleared`` names the buffer),
NaN where nothing has.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from algorithms.core.steps import Vars


@dataclass(frozen=True)
class SideBuffer:
    """A run's second buffer at one step: its name and its values, (H, W),
    row 0 at y = 0, NaN where nothing was set since it was cleared."""

    name: str
    values: np.ndarray

    def at(self, x: int, y: int) -> float:
        return float(self.values[y, x])


def has_side_buffer(trace) -> bool:
    return trace is not None and trace.start is not None and trace.start.buffer_value is not None


def cleared_at(trace, i: int) -> int:
    """The step the buffer was last cleared at, up to step i (0: the start)."""
    name = trace.start.buffer_name
    for step, record in reversed(trace.records_of(Vars, lo=0, hi=i + 1)):
        if record.values.get("cleared") == name:
            return step
    return 0


def side_buffer(trace, i: int) -> SideBuffer | None:
    """The run's second buffer after step i, or None when it keeps none."""
    if not has_side_buffer(trace):
        return None
    i = int(i) % len(trace)
    lo = cleared_at(trace, i)
    values = trace.series(trace.start.buffer_value)[lo:i + 1]
    x = trace.x[lo:i + 1].astype(np.int64)
    y = trace.y[lo:i + 1].astype(np.int64)
    keep = ~np.isnan(values) & (x >= 0) & (x < trace.width) & (y >= 0) & (y < trace.height)
    image = np.full(trace.height * trace.width, np.nan)
    flat = (y * trace.width + x)[keep][::-1]
    # each pixel's last value: its first in reversed order
    pixels, first = np.unique(flat, return_index=True)
    image[pixels] = values[keep][::-1][first]
    return SideBuffer(trace.start.buffer_name, image.reshape(trace.height, trace.width))
