"""An animated GIF written frame by frame, so that an export of thousands of
frames holds one frame in memory, not all of them.

Pillow's ``save(save_all=True)`` keeps every frame until it writes the
file. Here the file's header and global palette are written first; each
frame is then compared with the one before and only the box that changed
is encoded (by Pillow's GIF encoder, ``GifImagePlugin.getdata``), its
unchanged pixels set to the transparent entry and the frame left in place
(disposal 1), as Pillow's own ``optimize`` does. A frame identical to the
one before is not written: its time is added to that frame's.
"""
from __future__ import annotations

import math
import struct

import numpy as np
from PIL import GifImagePlugin, Image

LONGEST = 65535  # hundredths of a second: the most one GIF frame can last


class GifStream:
    """Writes frames of palette indices into the open binary ``stream``.

    ``palette`` is the palette's bytes (RGB triples, the transparent entry
    among them at index ``transparent``); ``loop`` repeats the animation
    for ever. Call ``add`` per frame with its duration in milliseconds, then
    ``close``.
    """

    def __init__(self, stream, size: tuple[int, int], palette: bytes, transparent: int,
                 loop: bool = True):
        self.stream = stream
        self.size = size
        self.palette = palette
        self.transparent = transparent
        self.frames_written = 0
        self._previous: np.ndarray | None = None
        self._pending = None  # (indices, (left, top), hundredths)
        self._header(loop)

    def _header(self, loop: bool) -> None:
        width, height = self.size
        entries = len(self.palette) // 3
        bits = max(1, math.ceil(math.log2(max(2, entries))))
        table = self.palette + bytes(3 * (2 ** bits - entries))
        self.stream.write(b"GIF89a" + struct.pack("<HHBBB", width, height, 0x80 | (bits - 1),
                                                  0, 0) + table)
        if loop:
            self.stream.write(b"!\xff\x0bNETSCAPE2.0\x03\x01" + struct.pack("<H", 0) + b"\x00")

    def add(self, frame: np.ndarray, milliseconds: int) -> None:
        """One frame: an (h, w) uint8 array of palette indices."""
        hundredths = max(0, round(milliseconds / 10))
        previous = self._previous
        if previous is None:
            self._pending = (frame, (0, 0), hundredths)
        else:
            changed = frame != previous
            if not changed.any() and self._pending[2] + hundredths <= LONGEST:
                indices, where, time = self._pending
                self._pending = (indices, where, time + hundredths)
                return
            self._flush()
            rows = np.flatnonzero(changed.any(axis=1))
            columns = np.flatnonzero(changed.any(axis=0))
            if len(rows) == 0:  # identical, but the frame before is full
                rows, columns = np.array([0]), np.array([0])
            top, bottom = int(rows[0]), int(rows[-1]) + 1
            left, right = int(columns[0]), int(columns[-1]) + 1
            box = frame[top:bottom, left:right].copy()
            box[~changed[top:bottom, left:right]] = self.transparent
            self._pending = (box, (left, top), hundredths)
        self._previous = frame.copy()

    def _flush(self) -> None:
        if self._pending is None:
            return
        indices, (left, top), hundredths = self._pending
        self._pending = None
        # Graphic control: leave the frame in place (disposal 1), its
        # transparent entry shows the frame before, and its time.
        self.stream.write(b"!\xf9\x04" + struct.pack("<BHBB", (1 << 2) | 1, hundredths,
                                                     self.transparent, 0))
        image = Image.fromarray(np.ascontiguousarray(indices), "P")
        for chunk in GifImagePlugin.getdata(image, offset=(left, top)):
            self.stream.write(chunk)
        self.frames_written += 1

    def close(self) -> None:
        """Write the last frame and the trailer."""
        self._flush()
        self.stream.write(b";")
