"""Where exported frames go: one protocol, in the manner of matplotlib's
animation writers, and its writers.

A writer is set up once (``setup``), given each frame in order
(``grab_frame``, a Pillow palette image) and then either finished
(``finish``: the output appears, whole) or aborted (``abort``: nothing is
left behind). ``saving`` does that for several writers at once.

Every writer that writes files writes them atomically: the GIF goes to a
temporary file beside the target and is renamed over it at the end; PNG
frames go into a staging folder inside the target folder and are moved
into place together at the end. A failed or cancelled export leaves
neither a partial GIF nor a partial set of frames, and what a killed one
left is cleaned up by the next export to the same target. Temporary names
carry the process id, so a live export's files are never taken for
leftovers.
"""
from __future__ import annotations

import json
import os
import re
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Protocol, Sequence

import numpy as np
from PIL import Image, PngImagePlugin

from app.model.files import OutputRefused, remove_leftovers, target_of
from app.model.staging import StagedFolder
from app.render.gif_stream import GifStream
from app.render.settings import ExportError

FRAME_NAME = "frame_{:0{width}d}.png"
MANIFEST = ".rasterlab-frames.json"  # what the last export wrote into a frames folder
_FRAME_FILE = re.compile(r"^frame_\d{4,}\.(png|svg)$")


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
    """An animated GIF with one global palette, written frame by frame
    (``app.render.gif_stream``) to a temporary file beside ``path`` and
    renamed over it at the end: however long the export, one frame is held
    in memory.

    A frame identical to the one before it is joined into that frame,
    adding the durations (so a range where nothing visible changes takes
    fewer frames, and the same time).
    """

    def __init__(self, path, durations: Sequence[int], loop: bool = True):
        self.path = Path(path)
        self.durations = list(durations)
        self.loop = loop
        self.temporary: Path | None = None
        self._file = None
        self._gif: GifStream | None = None
        self._count = 0

    def setup(self, size, count, palette, transparent) -> None:
        self.target = target_of(self.path, ExportError)  # a link stays; its target is written
        self.temporary = temporary_beside(self.target)
        try:
            self._file = open(self.temporary, "wb")
            self._gif = GifStream(self._file, size, palette, transparent, self.loop)
        except OSError as error:
            raise self._failed(error) from None

    def grab_frame(self, image: Image.Image) -> None:
        duration = self.durations[self._count] if self._count < len(self.durations) else 0
        self._count += 1
        try:
            self._gif.add(np.asarray(image), duration)
        except OSError as error:
            raise self._failed(error) from None

    def finish(self) -> None:
        try:
            self._gif.close()
            self._file.flush()
            os.fsync(self._file.fileno())
            self._file.close()
            os.replace(self.temporary, self.target)
        except OSError as error:
            raise self._failed(error) from None

    def _failed(self, error: OSError) -> ExportError:
        return ExportError(f"cannot write {self.path} ({error.strerror or error})")

    def abort(self) -> None:
        if self._file is not None and not self._file.closed:
            self._file.close()
        if self.temporary is not None:
            self.temporary.unlink(missing_ok=True)


class PngFolderWriter:
    """PNG frames frame_0000.png, ... written into a staging folder inside
    ``directory`` and moved into place together at the end
    (``app.model.staging``: a kill leaves either the old frames or, once
    the next export to the folder has run, the new ones).

    The folder's manifest (MANIFEST) lists the frames the last export
    wrote; frames of that export beyond this one's last are removed, and
    nothing else: files the program did not write stay. A frame this export
    would write over that the manifest does not list (a user's own) is
    refused before any frame is drawn (``foreign_frames``) unless
    ``replace``.
    """

    SUFFIX = ".png"

    def __init__(self, directory, replace: bool = False):
        self.directory = Path(directory)
        self.replace = replace
        self.names: list[str] = []
        self.created = False
        self.staged: StagedFolder | None = None

    @property
    def temporary(self) -> Path | None:
        return self.staged.stage if self.staged is not None else None

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
        names = [FRAME_NAME.format(k, width=self.width).replace(".png", self.SUFFIX)
                 for k in range(count)]
        try:
            foreign = foreign_frames(self.SUFFIX, names)(self.directory)
        except OutputRefused as error:
            raise ExportError(str(error)) from None
        if foreign and not self.replace:
            raise ExportError(f"{self.directory}: {foreign}; give --force to replace it")
        self.staged = StagedFolder(self.directory, "frames", ExportError)
        self.staged.open()

    def grab_frame(self, image: Image.Image) -> None:
        name = FRAME_NAME.format(len(self.names), width=self.width)
        try:
            image.save(self.temporary / name, format="PNG", compress_level=3,
                       pnginfo=_alt_text(image))
        except OSError as error:
            raise self._failed(error) from None
        self.names.append(name)

    def finish(self) -> None:
        earlier = written_frames(self.directory)
        manifest = json.dumps({"frames": self.names}, indent=0).encode("utf-8")
        try:
            (self.temporary / MANIFEST).write_bytes(manifest)
        except OSError as error:
            raise self._failed(error) from None
        self.staged.commit(self.names + [MANIFEST], remove=earlier)

    def abort(self) -> None:
        if self.staged is not None:
            self.staged.discard()
        if self.created:
            try:
                self.directory.rmdir()
            except OSError:
                pass

    def _failed(self, error: OSError) -> ExportError:
        return ExportError(f"cannot write the frames in the folder {self.directory} "
                           f"({error.strerror or error})")


def _alt_text(image: Image.Image) -> PngImagePlugin.PngInfo:
    """The frame's alt text (``app.render.alt_text``, put in ``image.info``
    by the export) as PNG tEXt chunks: Title and Description."""
    info = PngImagePlugin.PngInfo()
    for key in ("Title", "Description"):
        if key in image.info:
            info.add_text(key, image.info[key])
    return info


def foreign_frames(suffix: str, names=None):
    """``app.model.files.Output.foreign`` for a frames folder of ``suffix``
    (.png, .svg): the first of ``names`` (the frames an export writes) that
    is there and that the folder's manifest does not list, as a reason.
    With ``names`` None (the check before the run is recorded, when the
    count of frames is not known yet) any such frame counts, so that a
    user's frame is found before the work rather than after it. A frame
    name that is a link or not a regular file is refused whatever
    ``--force`` says (OutputRefused): frames are moved into place as a set,
    never written through a link."""
    def foreign(directory: Path) -> str | None:
        directory = Path(directory)
        if not directory.is_dir():
            return None
        with os.scandir(directory) as entries:
            found = {entry.name: entry.is_file(follow_symlinks=False) for entry in entries
                     if _FRAME_FILE.match(entry.name) and entry.name.endswith(suffix)}
        for name in sorted(found):
            if not found[name]:
                raise OutputRefused(f"{directory / name}: is a link or not a regular file; "
                                    "frames are written only over regular files")
        ours = set(written_frames(directory))
        for name in sorted(found) if names is None else names:
            if name in found and name not in ours:
                return f"{name} was not written by RasterLab" + (
                    " and the export's frames may replace it" if names is None else "")
        return None
    return foreign


def written_frames(directory: Path) -> list[str]:
    """The frames the folder's manifest says an export wrote there (none
    when there is no readable manifest)."""
    try:
        names = json.loads((directory / MANIFEST).read_text(encoding="utf-8"))["frames"]
    except (OSError, ValueError, KeyError, TypeError):
        return []
    if not isinstance(names, list):
        return []
    return [name for name in names if isinstance(name, str) and _FRAME_FILE.match(name)]


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


def temporary_beside(path: Path) -> Path:
    """A new empty temporary file beside ``path`` (named so that
    ``remove_leftovers`` finds it once its process is gone), after removing
    what killed exports to ``path`` left; refused when ``path`` is not a
    regular file (``target_of``) or its folder cannot be written."""
    path = target_of(path, ExportError)
    directory = _folder_of(path)
    remove_leftovers(path)
    try:
        handle, name = tempfile.mkstemp(prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp",
                                        dir=directory)
    except OSError as error:
        raise ExportError(f"cannot write {path}: the folder {directory} is not writable "
                          f"({error.strerror or error})") from None
    os.close(handle)
    _readable_by_all(Path(name))
    return Path(name)


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
