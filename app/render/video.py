"""Video for slides: MP4 (H.264) and WebM (VP9) writers of the export's frames.

The writers follow the frame-writer protocol of ``app.render.writers``
(setup, grab_frame, finish, abort). PyAV brings its own FFmpeg, with the
encoders, in its wheel, so nothing is installed beside it.

Timing is exact: the stream counts in milliseconds and frame k starts at
round(k * 1000 / fps) ms, as the GIF's frames do to within its 10 ms
steps. The hold on the last frame is the last frame repeated once at the
moment the hold ends, so a player shows it for the whole hold and the
video's duration is the GIF's. Frames are padded to even sizes with the
background colour (4:2:0 chroma needs even sides) and converted to full
colour: nothing of the GIF's 256-colour limit remains.

The file is written to a temporary name beside the target and renamed over
it when finished, so a failed, cancelled or killed export leaves no partial
video (a killed one's leftovers are removed by the next export to the
same target, as for the GIF).
"""
from __future__ import annotations

import os
from fractions import Fraction
from pathlib import Path

import numpy as np

from app.render.settings import ExportError
from app.model.files import target_of
from app.render.writers import temporary_beside

# (container, codec, options) per kind. CRF 18 keeps the flat cells and thin
# lines of a frame free of visible artefacts; "+faststart" puts the index
# first so a slide can start the video before all of it is read.
KINDS = {
    "mp4": ("mp4", "libx264", {"crf": "18", "preset": "medium", "movflags": "+faststart"}),
    "webm": ("webm", "libvpx-vp9", {"crf": "20", "b": "0", "row-mt": "1"}),
}
# The largest frame H.264 level 5.1 plays (what PowerPoint and Keynote take).
MAX_SIDE = 4096
MAX_AREA = 4096 * 2304
TIME_BASE = Fraction(1, 1000)


class VideoWriter:
    """An MP4 or WebM video of the exported frames (see the module text)."""

    def __init__(self, path, kind: str, fps: float, hold: float = 0.0):
        if kind not in KINDS:
            raise ExportError(f"unknown video kind {kind!r}: mp4 or webm")
        self.path, self.kind = Path(path), kind
        self.fps, self.hold = float(fps), float(hold)
        self.temporary: Path | None = None
        self._container = self._stream = None
        self._count = 0
        self._last = None
        self._durations: dict[int, int] = {}  # ms, by start time

    def setup(self, size, count, palette, transparent) -> None:
        width, height = (side + side % 2 for side in size)
        if max(width, height) > MAX_SIDE or width * height > MAX_AREA:
            raise ExportError(f"frames of {size[0]}x{size[1]} pixels are too large for a video "
                              f"slides can play (at most {MAX_SIDE} pixels a side and "
                              f"{MAX_AREA:,} pixels): export at a smaller scale")
        self.target = target_of(self.path, ExportError)
        self.temporary = temporary_beside(self.target)
        self.size = (width, height)
        self._background = np.frombuffer(palette[:3], np.uint8) if palette else np.zeros(3, np.uint8)
        container, codec, options = KINDS[self.kind]
        import av  # loaded only when a video is written: start-up does not pay for FFmpeg

        self._av = av
        muxer = {k: v for k, v in options.items() if k == "movflags"}
        self._container = av.open(str(self.temporary), mode="w", format=container, options=muxer)
        stream = self._container.add_stream(codec, rate=max(1, round(self.fps)))
        stream.width, stream.height, stream.pix_fmt = width, height, "yuv420p"
        stream.time_base = TIME_BASE
        stream.codec_context.time_base = TIME_BASE
        stream.options = {k: v for k, v in options.items() if k != "movflags"}
        self._stream = stream

    def grab_frame(self, image) -> None:
        pixels = self._padded(np.asarray(image.convert("RGB")))
        self._last = pixels
        self._encode(pixels, self._start(self._count), self._frame_ms(self._count))
        self._count += 1

    def finish(self) -> None:
        try:
            if self._last is not None:
                self._finish_hold()
            self._mux(self._stream.encode(None))
            self._container.close()
            self._container = None
            os.replace(self.temporary, self.target)
        except (OSError, self._av.error.FFmpegError) as error:
            self.abort()
            raise ExportError(f"cannot write {self.path} ({_reason(error)})") from None

    def abort(self) -> None:
        if self._container is not None:
            try:
                self._container.close()
            except Exception:  # noqa: BLE001 - closing a half-written file; it is removed next
                pass
            self._container = None
        if self.temporary is not None:
            self.temporary.unlink(missing_ok=True)

    # ------------------------------------------------------------ helpers
    def _start(self, k: int) -> int:
        return round(k * 1000 / self.fps)

    def _frame_ms(self, k: int) -> int:
        return self._start(k + 1) - self._start(k)

    def _finish_hold(self) -> None:
        """Stretch the last frame over the hold: it is shown again where the
        hold ends, for one frame, so the video lasts as long as the GIF."""
        hold = round(self.hold * 1000)
        last = self._count - 1
        if hold <= 0:
            return
        again = self._start(self._count) + hold - self._frame_ms(last)
        self._durations[self._start(last)] = again - self._start(last)
        self._encode(self._last, again, self._frame_ms(last))

    def _padded(self, pixels: np.ndarray) -> np.ndarray:
        height, width = pixels.shape[:2]
        if (width, height) == self.size:
            return pixels
        out = np.empty((self.size[1], self.size[0], 3), np.uint8)
        out[:] = self._background
        out[:height, :width] = pixels
        return out

    def _encode(self, pixels: np.ndarray, pts: int, duration: int) -> None:
        frame = self._av.VideoFrame.from_ndarray(np.ascontiguousarray(pixels), format="rgb24")
        frame.pts, frame.time_base = pts, TIME_BASE
        self._durations[pts] = duration
        try:
            self._mux(self._stream.encode(frame))
        except self._av.error.FFmpegError as error:
            raise ExportError(f"cannot write {self.path} ({_reason(error)})") from None

    def _mux(self, packets) -> None:
        # The encoder gives every packet one frame of 1/rate; a container
        # that sums packet durations (MP4) would then lose the hold.
        for packet in packets:
            packet.duration = self._durations.get(packet.pts, packet.duration)
            self._container.mux(packet)


def _reason(error) -> str:
    return getattr(error, "strerror", None) or str(error)
