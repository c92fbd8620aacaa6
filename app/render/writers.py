"""Where exported frames go: one protocol, in the manner of matplotlib's
animation writers, and its writers.

A writer is set up once (``setup``), given each frame in order
(``grab_frame``, a Pillow palette image) and then either finished
(``finish``: the output appears, whole) or aborted (``abort``: nothing is
left behind). ``saving`` does that for several writers at once.

Every writer that writes files writes them atomically: the GIF goes to a
temporary file beside the target and is renamed over it at the end; PNG
frames go into a temporary folder inside the target folder and are moved
into place at the end. A failed or cancelled export leaves neither a
partial GIF nor a partial set of frames.
"""
from __future__ import annotations

import os
import re
import shutil
import tempfile
from collections import deque
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Protocol, Sequence

from PIL import Image

from app.render.settings import ExportError

FRAME_NAME = "frame_{:0{width}d}.png"
_FRAME_FILE = re.compile(r"^frame_\d{4,}\.png$")


class FrameWriter(Protocol):
    def setup(self, size: tuple[int, int], count: int, palette: bytes,
              transparent: int) -> None:
        """Get ready for ``count`` frames of ``size`` (width, height) drawn
        in ``palette``; ``transparent`` is its entry no drawn pixel uses."""

    def grab_frame(self, image: Image.Image) -> None:
        """Take the next frame."""

    def finish(self) -> None:
        """Write what was grabbed; the output appears whole."""

    def abort(self) -> None:
        """Leave nothing behind."""


@contextmanager
def saving(writers: Sequence[FrameWriter], size: tuple[int, int], count: int, palette: bytes,
           transparent: int) -> Iterator[Sequence[FrameWriter]]:
    """Set up every writer; finish them all when the block ends, or abort
    them all when it (or a writer) fails."""
    ready: list[FrameWriter] = []
    try:
        for writer in writers:
            ready.append(writer)
            writer.setup(size, count, palette, transparent)
        yield writers
        for writer in writers:
            writer.finish()
    except BaseException:
        for writer in ready:
            writer.abort()
        raise


class GifWriter:
    """An animated GIF with one global palette, written to a temporary
    file beside ``path`` and renamed over it at the end.

    Pillow joins a frame identical to the one before it into that frame,
    adding the durations (so a range where nothing visible changes takes
    fewer frames, and the same time).
    """

    def __init__(self, path, durations: Sequence[int], loop: bool = True):
        self.path = Path(path)
        self.durations = list(durations)
        self.loop = loop
        self.temporary: Path | None = None
        self._frames: deque = deque()

    def setup(self, size, count, palette, transparent) -> None:
        directory = _folder_of(self.path)
        if self.path.is_dir():
            raise ExportError(f"{self.path}: is a folder, not a file name")
        try:
            handle, name = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=".tmp",
                                            dir=directory)
        except OSError as error:
            raise ExportError(f"cannot write {self.path}: the folder {directory} is not writable "
                              f"({error.strerror or error})") from None
        os.close(handle)
        self.temporary = Path(name)
        _readable_by_all(self.temporary)
        self.palette, self.transparent = palette, transparent

    def grab_frame(self, image: Image.Image) -> None:
        self._frames.append(image)

    def finish(self) -> None:
        first = self._frames.popleft()
        extra = {"loop": 0} if self.loop else {}
        with open(self.temporary, "wb") as stream:
            # One global palette (no frame carries its own). With
            # ``optimize`` Pillow writes each frame after the first as the
            # box that changed, its unchanged pixels set to ``transparent``.
            first.save(stream, format="GIF", save_all=True, append_images=self._handed_over(),
                       duration=self.durations, palette=self.palette, optimize=True,
                       transparency=self.transparent, disposal=1, **extra)
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(self.temporary, self.path)

    def _handed_over(self):
        # Pillow keeps its own copy of every frame until it writes the
        # file; each of ours is dropped as soon as Pillow has taken it.
        while self._frames:
            yield self._frames.popleft()

    def abort(self) -> None:
        self._frames.clear()
        if self.temporary is not None:
            self.temporary.unlink(missing_ok=True)


class PngFolderWriter:
    """PNG frames frame_0000.png, ... written into a temporary folder
    inside ``directory`` and moved into place at the end. Frames of an
    earlier export to the same folder (frame_NNNN.png beyond this export's
    last) are removed then, so the folder holds one export."""

    def __init__(self, directory):
        self.directory = Path(directory)
        self.names: list[str] = []
        self.created = False
        self.temporary: Path | None = None

    def setup(self, size, count, palette, transparent) -> None:
        self.width = max(4, len(str(max(0, count - 1))))
        if self.directory.exists() and not self.directory.is_dir():
            raise ExportError(f"{self.directory}: is a file, not a folder")
        if not self.directory.exists():
            parent = _folder_of(self.directory)
            try:
                self.directory.mkdir()
            except OSError as error:
                raise ExportError(f"cannot make the folder {self.directory} in {parent} "
                                  f"({error.strerror or error})") from None
            self.created = True
        try:
            self.temporary = Path(tempfile.mkdtemp(prefix=".rasterlab-frames-",
                                                   dir=self.directory))
        except OSError as error:
            raise ExportError(f"cannot write in the folder {self.directory} "
                              f"({error.strerror or error})") from None

    def grab_frame(self, image: Image.Image) -> None:
        name = FRAME_NAME.format(len(self.names), width=self.width)
        image.save(self.temporary / name, format="PNG", compress_level=3)
        self.names.append(name)

    def finish(self) -> None:
        for name in self.names:
            os.replace(self.temporary / name, self.directory / name)
        keep = set(self.names)
        for old in self.directory.iterdir():
            if _FRAME_FILE.match(old.name) and old.name not in keep and old.is_file():
                old.unlink()
        self.temporary.rmdir()

    def abort(self) -> None:
        if self.temporary is not None:
            shutil.rmtree(self.temporary, ignore_errors=True)
        if self.created:
            try:
                self.directory.rmdir()
            except OSError:
                pass


class NullWriter:
    """Writes nothing: keeps the frames it is given (for tests and checks)."""

    def __init__(self):
        self.frames: list[Image.Image] = []
        self.size: tuple[int, int] | None = None
        self.finished = self.aborted = False

    def setup(self, size, count, palette, transparent) -> None:
        self.size = size

    def grab_frame(self, image: Image.Image) -> None:
        self.frames.append(image)

    def finish(self) -> None:
        self.finished = True

    def abort(self) -> None:
        self.aborted = True


def _readable_by_all(path: Path) -> None:
    # mkstemp makes files only their owner may read; an exported file gets
    # the permissions any new file gets.
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(path, 0o666 & ~umask)


def _folder_of(path: Path) -> Path:
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise ExportError(f"cannot write {path}: the folder {directory} does not exist")
    return directory
