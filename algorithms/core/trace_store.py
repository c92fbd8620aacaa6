"""Where a Trace keeps its frames while it records and after: lean storage.

``Columns``  the frame columns (line, x, y, values), filled a chunk at a
             time and grown in place, so that recording never holds the
             frames twice (the chunks and the finished columns).
``frame_rows``  a list of plain frames as one such chunk, packed by struct.
``Records``  the rich records (Vars, Table, Note, Span), pickled in batches:
             a pickled batch takes a fraction of the memory of the Python
             objects (a Table of Fractions, say), and a batch is unpickled
             again when a record of it is asked for.
"""
from __future__ import annotations

import functools
import pickle
import struct
import threading
from collections import OrderedDict
from itertools import starmap

import numpy as np

GROWTH = 1.25  # the columns grow by a quarter when a chunk does not fit
BATCH = 512  # rich records pickled together
CACHED_BATCHES = 8  # unpickled batches kept for the next look-up


class Columns:
    """Frame columns of a run with ``k`` named values, grown as chunks arrive."""

    def __init__(self, names: tuple[str, ...], capacity: int):
        self.names = names
        self.count = 0
        self.line = np.empty(capacity, "u2")
        self.x = np.empty(capacity, "i4")
        self.y = np.empty(capacity, "i4")
        self.values = np.empty((capacity, len(names)))

    def append(self, rows: np.ndarray) -> None:
        """Copy a structured chunk (fields line, x, y, v0, v1, ...) in."""
        end = self.count + len(rows)
        if end > len(self.line):
            self._resize(max(end, int(len(self.line) * GROWTH)))
        at = self.count
        self.line[at:end], self.x[at:end], self.y[at:end] = rows["line"], rows["x"], rows["y"]
        for column, name in enumerate(self.names):
            self.values[at:end, column] = rows[name]
        self.count = end

    def finish(self) -> None:
        """Give the room beyond the last frame back."""
        self._resize(self.count)

    def _resize(self, rows: int) -> None:
        # resize() reallocates in place (for large blocks the C library
        # remaps pages rather than copying), so no second copy is held.
        # Nothing else refers to these arrays while the run records.
        for name in ("line", "x", "y"):
            getattr(self, name).resize(rows, refcheck=False)
        self.values.resize((rows, len(self.names)), refcheck=False)


@functools.lru_cache(maxsize=16)
def frame_dtype(k: int) -> np.dtype:
    """Rows of frames with k values: line, x, y, v0 ... (made once, not per
    run), packed without padding in the machine's byte order."""
    return np.dtype([("line", "u2"), ("x", "i4"), ("y", "i4")]
                    + [(f"v{n}", "f8") for n in range(k)])


@functools.lru_cache(maxsize=16)
def _frame_struct(k: int) -> struct.Struct:
    """The struct of a frame_dtype(k) row: "=" is the machine's byte order
    with standard sizes and no padding."""
    return struct.Struct("=Hii" + "d" * k)


def frame_rows(frames: list, k: int) -> np.ndarray:
    """Plain frames, tuples of integers line, x, y and k real numbers, as
    rows of frame_dtype(k); struct.error names what does not fit.

    struct packs a list of tuples about twice as fast as np.fromiter
    converts them, which sets each field of each row on its own. Values
    become the doubles float() gives, as numpy would make them.
    """
    return np.frombuffer(b"".join(starmap(_frame_struct(k).pack, frames)), frame_dtype(k))


class Records:
    """Rich records by step, pickled BATCH at a time in step order."""

    def __init__(self):
        self._pending: list = []
        self._batches: list = []  # bytes, or the list itself if it does not pickle
        self._cache: OrderedDict[int, list] = OrderedDict()
        self._lock = threading.Lock()
        self.steps = np.zeros(0, np.int64)  # set by finish(): ascending, one per record

    def add(self, record) -> None:
        self._pending.append(record)
        if len(self._pending) >= BATCH:
            self._seal()

    def finish(self, steps: np.ndarray) -> None:
        if self._pending:
            self._seal()
        self.steps = steps

    def get(self, step: int):
        """The record of ``step``, or None."""
        k = int(np.searchsorted(self.steps, step))
        if k == len(self.steps) or self.steps[k] != step:
            return None
        return self._batch(k // BATCH)[k % BATCH]

    def at_positions(self, positions: np.ndarray) -> list:
        """The records at these ascending positions in ``steps``."""
        out = []
        for batch, first in _runs(positions // BATCH):
            records = self._batch(batch)
            out += [records[k] for k in (positions[first] % BATCH).tolist()]
        return out

    def position(self, steps: np.ndarray) -> np.ndarray:
        """Positions in ``steps`` of the given steps (each must hold a record)."""
        return np.searchsorted(self.steps, steps)

    def _seal(self) -> None:
        try:
            self._batches.append(pickle.dumps(self._pending, pickle.HIGHEST_PROTOCOL))
        except (pickle.PicklingError, TypeError, AttributeError):
            self._batches.append(self._pending)  # kept as objects
        self._pending = []

    def _batch(self, index: int) -> list:
        sealed = self._batches[index]
        if isinstance(sealed, list):
            return sealed
        with self._lock:
            records = self._cache.get(index)
            if records is not None:
                self._cache.move_to_end(index)
                return records
        records = pickle.loads(sealed)
        with self._lock:
            self._cache[index] = records
            while len(self._cache) > CACHED_BATCHES:
                self._cache.popitem(last=False)
        return records


def _runs(batches: np.ndarray):
    """(batch, [positions in ``batches`` of that batch]) for each run of equal batches."""
    if not len(batches):
        return
    starts = np.flatnonzero(np.diff(batches)) + 1
    bounds = np.concatenate([[0], starts, [len(batches)]])
    for lo, hi in zip(bounds[:-1].tolist(), bounds[1:].tolist()):
        yield int(batches[lo]), slice(lo, hi)
