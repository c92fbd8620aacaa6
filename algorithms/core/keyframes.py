"""Compact keyframes of a trace: what ``Trace.raster_at`` starts its replay from.

A full raster of a 4096 x 4096 grid is 64 MiB of int32 counts (and 128 MiB
of int64 colours), so a few plain copies fill any memory budget and leave
long replays between them. Here a keyframe is stored as

* a ``Delta`` from the keyframe before it: the pixels the steps in between
  wrote, with their count, colour and depth after them (the steps between
  two keyframes write at most that many pixels); or
* a ``Dense`` copy, in the smallest dtype that holds its counts and
  colours, once the deltas since the last dense copy would cost more to
  apply than a copy.

Restoring a keyframe copies the dense keyframe before it and applies the
deltas after that one, which is a few numpy assignments.
"""
from __future__ import annotations

import numpy as np

from algorithms.core.raster import NO_COLOR, Raster

# The most pixel changes applied from deltas before a dense copy is kept:
# an assignment of this many pixels costs about what a dense copy of a
# large grid does.
CHAIN_PIXELS = 1 << 19


def smallest_unsigned(most: int):
    """The smallest unsigned dtype that holds 0..most."""
    for dtype in (np.uint8, np.uint16, np.uint32):
        if most <= np.iinfo(dtype).max:
            return np.dtype(dtype)
    return np.dtype(np.int64)


def color_dtype(values: np.ndarray):
    """int32 when every packed colour (and NO_COLOR) fits in it, else int64."""
    values = values[~np.isnan(values)]
    if not values.size:
        return np.dtype(np.int32)
    low, high = int(np.min(values)), int(np.max(values))
    fits = np.iinfo(np.int32).min <= min(low, NO_COLOR) and high <= np.iinfo(np.int32).max
    return np.dtype(np.int32 if fits else np.int64)


class Dense:
    """A whole raster, counts in the smallest unsigned dtype they fit."""

    def __init__(self, raster: Raster):
        self.counts = raster.counts.astype(smallest_unsigned(int(raster.counts.max(initial=0))))
        self.colors = None if raster.colors is None else raster.colors.copy()
        self.depth = None if raster.depth is None else raster.depth.copy()

    def nbytes(self) -> int:
        return sum(a.nbytes for a in (self.counts, self.colors, self.depth) if a is not None)


class Delta:
    """The pixels some steps wrote, with their values after those steps."""

    def __init__(self, touched: np.ndarray, after: Raster):
        # Kept as intp: numpy would convert int32 indices to intp on every
        # restore, which doubles the cost of applying a delta.
        self.flat = np.unique(touched[touched >= 0]).astype(np.intp)
        counts = after.counts.reshape(-1)[self.flat]
        self.counts = counts.astype(smallest_unsigned(int(counts.max(initial=0))))
        self.colors = None if after.colors is None else after.colors.reshape(-1)[self.flat]
        self.depth = None if after.depth is None else after.depth.reshape(-1)[self.flat]

    def __len__(self) -> int:
        return len(self.flat)

    def nbytes(self) -> int:
        return sum(a.nbytes for a in (self.flat, self.counts, self.colors, self.depth)
                   if a is not None)

    def apply(self, raster: Raster) -> None:
        raster.counts.reshape(-1)[self.flat] = self.counts
        if self.colors is not None:
            raster.colors.reshape(-1)[self.flat] = self.colors
        if self.depth is not None:
            raster.depth.reshape(-1)[self.flat] = self.depth


class Keyframes:
    """Snapshots of a run every ``gap`` steps; slot 0 is the empty raster.

    Dense copies take at most ``dense_budget`` bytes in all; past it the
    chains of deltas grow instead.
    """

    def __init__(self, empty: Raster, gap: int, dense_budget: int):
        self.empty = empty
        self.gap = gap
        self.slots: list[Dense | Delta | None] = [None]
        self._chain = 0  # pixels in the deltas since the last dense slot
        self._dense_left = dense_budget

    def add(self, touched: np.ndarray, raster: Raster) -> None:
        """Keep ``raster``, the state after the next ``gap`` steps, which
        wrote the flat pixels ``touched`` (-1 for none)."""
        delta = Delta(touched, raster)
        if self._chain + len(delta) > CHAIN_PIXELS and self._dense_left > 0:
            dense = Dense(raster)
            if dense.nbytes() <= self._dense_left:
                self._dense_left -= dense.nbytes()
                self.slots.append(dense)
                self._chain = 0
                return
            self._dense_left = 0  # the budget is spent: deltas from here on
        self.slots.append(delta)
        self._chain += len(delta)

    def __len__(self) -> int:
        return len(self.slots)

    def nbytes(self) -> int:
        return sum(slot.nbytes() for slot in self.slots if slot is not None)

    def restore(self, slot: int, counts_dtype, colors_dtype) -> Raster:
        """A fresh raster in the given dtypes, holding keyframe ``slot``."""
        base = slot
        while base > 0 and not isinstance(self.slots[base], Dense):
            base -= 1
        raster = Raster.__new__(Raster)
        raster.width, raster.height = self.empty.width, self.empty.height
        raster.replaces = self.empty.replaces
        if base == 0:
            shape = self.empty.counts.shape
            raster.counts = np.zeros(shape, counts_dtype)
            raster.colors = (None if self.empty.colors is None
                             else np.full(shape, NO_COLOR, colors_dtype))
            raster.depth = None if self.empty.depth is None else np.full(shape, np.nan)
        else:
            dense = self.slots[base]
            raster.counts = dense.counts.astype(counts_dtype)
            raster.colors = None if dense.colors is None else dense.colors.astype(colors_dtype)
            raster.depth = None if dense.depth is None else dense.depth.copy()
        for k in range(base + 1, slot + 1):
            self.slots[k].apply(raster)
        return raster
