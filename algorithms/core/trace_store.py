"""Where a Trace keeps its frames while it records and after: lean storage.

``Columns``  the frame columns (line, x, y, values), filled a chunk at a
             time and grown in place, so that recording never holds the
             frames twice (the chunks and the finished columns).
``Packer``   plain frames to bytes numpy reads in place, the fast way to
             record long runs of tuples.
``Records``  the rich records (Vars, Table, Note, Span), pickled in batches:
             a pickled batch takes a fraction of the memory of the Python
             objects (a Table of Fractions, say), and a batch is unpickled
             again when a record of it is asked for.
"""
from __future__ import annotations

import functools
import marshal
import pickle
import struct
import threading
from collections import OrderedDict
from itertools import islice, starmap

import numpy as np

GROWTH = 1.25  # the columns grow by a quarter when a chunk does not fit
BATCH = 512  # rich records pickled together
SMALL_BATCH = 8  # a last batch shorter than this is kept as objects
PART = 1024  # plain frames listed and packed together
CACHED_BATCHES = 8  # unpickled batches kept for the next look-up
SPARE_BUFFERS = 2  # packing buffers kept for the next recordings
SPARE_BYTES = 1 << 20  # and only small ones: a long run pays for its buffer many times over

# Packing buffers of finished recordings, for the next ones to reuse:
# fresh pages cost more than the packing itself on short runs (the C
# library gives freed memory back to the system and faults it in again).
_spare_buffers: list = []


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


class Packer:
    """Plain frames, tuples of integers line, x, y and k numbers, to bytes.

    Three formats, each tried while the frames fit it: marshal while every
    value is an int within 32 bits (the fastest: one C call a list, read in
    place by a dtype with offsets), struct with 64-bit integers while every
    value is an integer, then struct with doubles. struct packs a list of
    tuples into rows about twice as fast as numpy converts them one tuple
    at a time; the columns turn integers into the same doubles numpy would.
    """

    def __init__(self, k: int, head):
        self._formats = list(_pack_formats(k))
        self.dtype = self._formats[0][1]
        self._buffer = _spare_buffers.pop() if _spare_buffers else memoryview(b"")
        self._carry = [head]  # frames read but not yet packed
        self.left: list = []  # the frames that would not pack in any format

    def chunk(self, frames, size: int):
        """Up to ``size`` frames as rows, and whether more may follow. The
        frames are listed and packed PART at a time (a list that small stays
        in the processor's cache) into one buffer reused for every chunk,
        whose pages are touched once, not once a chunk. A list that does not
        pack is carried to the next chunk in the next format (at most twice:
        the formats only widen), or, with no format left, kept in ``left``
        and the packing ends."""
        filled = 0
        for done in range(0, size, PART):
            want = min(PART, size - done)
            part = list(islice(frames, max(0, want - len(self._carry))))
            if self._carry:
                part[:0], self._carry = self._carry, []
            piece = self.pack(part)
            if piece is None:
                rows = np.frombuffer(self._buffer[:filled], self.dtype)
                if self._widen():
                    self._carry = part
                else:
                    self.left = part
                return rows, not self.left
            self._room(filled + len(piece))
            self._buffer[filled:filled + len(piece)] = piece
            filled += len(piece)
            if len(part) < want:
                return np.frombuffer(self._buffer[:filled], self.dtype), False
        return np.frombuffer(self._buffer[:filled], self.dtype), True

    def _room(self, size: int) -> None:
        """A buffer of at least ``size`` bytes, grown by doubling (a short
        run never asks for a whole chunk's worth), its bytes kept."""
        if len(self._buffer) < size:
            grown = memoryview(np.empty(max(size, 2 * len(self._buffer)), np.uint8))
            grown[:len(self._buffer)] = self._buffer
            self._buffer = grown

    def close(self) -> None:
        """Hand the buffer on to the next recording; the rows taken from it
        must have been copied out."""
        if len(_spare_buffers) < SPARE_BUFFERS and 0 < len(self._buffer) <= SPARE_BYTES:
            _spare_buffers.append(self._buffer)
        self._buffer = memoryview(b"")

    def pack(self, frames: list):
        """The frames as rows of ``dtype`` (bytes), or None if one does not pack."""
        return self._formats[0][0](frames)

    def _widen(self) -> bool:
        """Go on with the next format; False when none is left."""
        self._formats.pop(0)
        if self._formats:
            self.dtype = self._formats[0][1]
        return bool(self._formats)


@functools.lru_cache(maxsize=16)
def frame_dtype(k: int, value: str = "f8") -> np.dtype:
    """Rows of frames with k values: line, x, y, v0 ... (made once, not per run)."""
    return np.dtype([("line", "u2"), ("x", "i4"), ("y", "i4")]
                    + [(f"v{n}", value) for n in range(k)])


@functools.lru_cache(maxsize=16)
def _pack_formats(k: int) -> tuple:
    """(pack, dtype) of frames with k values: small integers, integers, doubles."""
    return (_marshal_format(k),) + tuple(
        (_struct_pack(struct.Struct("=Hii" + code * k).pack), frame_dtype(k, kind))
        for code, kind in (("q", "i8"), ("d", "f8")))


def _struct_pack(pack):
    def rows(frames: list) -> bytes | None:
        try:
            return b"".join(starmap(pack, frames))
        except (struct.error, TypeError, ValueError, OverflowError):
            return None
    return rows


def _marshal_format(k: int) -> tuple:
    """(pack, dtype) of frames whose k + 3 items are all ints of 32 bits.

    marshal (version 2, which writes no back-references) writes a list of
    such tuples as fixed 5-byte cells: a tuple's head "(" and its length,
    then "i" and 4 little-endian bytes per int. A list of n frames packs
    when its length is n cells of each frame, every cell's tag is the one
    such a frame has there, and the low byte of every tuple's length is
    k + 3. That proves the layout: an object of another size puts its own
    tag where a cell's tag is checked, and a longer tuple (or one nested in
    it) would leave too few cells for the other frames. Anything else (a
    bool, a float, a bigger int, a numpy scalar, a subclass) is left to the
    struct formats, as is a line the line column cannot hold.
    """
    cells = k + 4
    stride = 5 * cells
    fields = ["line", "x", "y"] + [f"v{n}" for n in range(k)]
    dtype = np.dtype({"names": fields, "formats": ["<i4"] * (k + 3),
                      "offsets": [6 + 5 * n for n in range(k + 3)], "itemsize": stride})
    tags = (b"(" + b"i" * (cells - 1)) * PART  # the tags of a list's cells
    lengths = bytes([k + 3]) * PART
    zeros = bytes(PART)

    def rows(frames: list):
        n = len(frames)
        if n > PART:  # longer than the checks' patterns
            return None
        try:
            data = marshal.dumps(frames, 2)
        except ValueError:
            return None
        if len(data) != 5 + n * stride:
            return None
        # cells from byte 5 on; a frame's length at byte 1 of its cells, the
        # two high bytes of its line (0 for lines 0 to 65535) at bytes 8 and 9
        if (data[5::5] != tags[:n * cells] or data[6::stride] != lengths[:n]
                or data[13::stride] != zeros[:n] or data[14::stride] != zeros[:n]):
            return None
        return memoryview(data)[5:]
    return rows, dtype


class Records:
    """Rich records by step, pickled BATCH at a time in step order (a last
    batch of fewer than SMALL_BATCH records stays as the objects)."""

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
        if len(self._pending) >= SMALL_BATCH:
            self._seal()
        elif self._pending:  # a few records (a line's Start): pickling saves nothing
            self._batches.append(self._pending)
            self._pending = []
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
