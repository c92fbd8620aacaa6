"""Where the program writes, and how.

``write_atomically``: a failure never leaves half a file; the data goes to a
temporary file in the target's folder, which is renamed over the target once
it is complete and on disk.

``check_outputs``: the one output policy every command checks before it does
any work (``OutputRefused``, one line):

- an existing target must be a regular file (a folder where a folder is
  written); a device, FIFO or socket is never written;
- no output is an input of the command or another of its outputs, compared
  after resolving links (and hard links, by device and inode);
- a symbolic link is written through: its target gets the new content and
  the link stays (``target_of``, used by every writer);
- a file the program did not write is replaced only with ``force``: an
  existing non-empty file that is not of the format written, and in a frames
  folder a frame the export would write over that the folder's manifest
  does not list (``app.render.writers.foreign_frames``; the frames writer
  checks it once it knows the frame count, before drawing a frame).
"""
from __future__ import annotations

import glob
import json
import os
import re
import stat
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable

from app.model.processes import owner_pid, process_alive


def write_atomically(path: Path, data: bytes, error=OSError) -> None:
    """Write ``data`` to ``path`` whole or not at all.

    Failures raise ``error`` (an exception class taking one message) with a
    one-line reason that names the file. A file that exists keeps its
    permissions; a new one gets those the umask allows, as a plain ``open``
    would give it. A symbolic link stays: its target is replaced. A target
    that is not a regular file is refused (``target_of``).
    """
    path = target_of(path, error)
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise error(f"{path}: the folder {directory} does not exist")
    remove_leftovers(path)
    try:
        # Named with our process id, so that a write killed half-way is
        # removed by the next one (remove_leftovers).
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.{os.getpid()}.",
                                             suffix=".tmp", dir=directory)
    except OSError as failure:
        raise error(f"{path}: cannot write in {directory} "
                    f"({failure.strerror or failure})") from None
    try:
        try:
            stream = os.fdopen(handle, "wb")
        except BaseException:
            os.close(handle)  # fdopen failed, so nothing else will close it
            raise
        with stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        # mkstemp makes the file owner-only. By its name, not its descriptor:
        # Windows Pythons before 3.13 refuse a descriptor (and there a mode
        # only sets or clears read-only).
        os.chmod(temporary, _mode_for(path))
        os.replace(temporary, path)
    except BaseException as failure:
        Path(temporary).unlink(missing_ok=True)
        if isinstance(failure, OSError):
            # An OSError made in code may carry a message but no strerror.
            raise error(f"{path}: cannot write the file ({failure.strerror or failure})") from None
        raise


def remove_leftovers(path: Path) -> list[Path]:
    """Delete the temporary files that killed writes to ``path`` left beside
    it (``.NAME.<pid>.<random>.tmp`` of a process that is gone, or
    ``.NAME.<random>.tmp`` from before names carried the process id)."""
    prefix = f".{path.name}."
    pattern = re.compile(re.escape(prefix) + r"(\d+\.)?[a-z0-9_]{8}\.tmp$")
    directory = path.parent if str(path.parent) else Path(".")
    removed = []
    for leftover in directory.glob(glob.escape(prefix) + "*.tmp"):
        pid = owner_pid(leftover.name, prefix)
        if (pattern.match(leftover.name) and leftover.is_file() and not leftover.is_symlink()
                and (pid is None or not process_alive(pid))):
            leftover.unlink(missing_ok=True)
            removed.append(leftover)
    return removed


def target_of(path, error=OSError) -> Path:
    """The file a write to ``path`` replaces: ``path`` itself, or the final
    target of a symbolic link (the link stays). Refused (``error``) when it
    exists and is not a regular file: a folder, device, FIFO or socket."""
    path = Path(path)
    target = _through_links(path, error)
    try:
        mode = os.stat(target).st_mode
    except OSError:  # no file yet (or no folder for it: the write says so)
        return target
    if not stat.S_ISREG(mode):
        raise error(f"{path}: {_not_a_file(mode)}")
    return target


def _not_a_file(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "is a folder, not a file name"
    kind = ("a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else
            "a FIFO" if stat.S_ISFIFO(mode) else
            "a socket" if stat.S_ISSOCK(mode) else "not a regular file")
    return f"is {kind}; RasterLab writes only regular files"


def _through_links(path: Path, error) -> Path:
    """The file a save replaces: a link's target, so that the link stays."""
    if not path.is_symlink():
        return path
    target = Path(os.path.realpath(path))
    if target.is_symlink():  # realpath stops inside a loop of links
        raise error(f"{path}: a loop of symbolic links")
    return target  # a dangling link's target is made, as a plain open would


def _mode_for(path: Path) -> int:
    try:
        return stat.S_IMODE(os.stat(path).st_mode)
    except OSError:  # no file yet
        return 0o666 & ~_umask()


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


# ------------------------------------------------------------ output policy
class OutputRefused(ValueError):
    """An output the policy refuses; the message is the one line to print."""


# The first bytes of each format the program writes: an existing file that
# does not start so was not written by it (see ``not_ours``).
SIGNATURES = {
    "gif": (b"GIF87a", b"GIF89a"),
    "mp4": (b"ftyp",),  # after the first box's 4-byte size
    "webm": (b"\x1a\x45\xdf\xa3",),
    "pdf": (b"%PDF-",),
    "html": (b"<!DOCTYPE html", b"<!doctype html"),
    "tex": (b"% RasterLab",),
    "xml": (b"<?xml",),
    "json": (b"{",),
    "zip": (b"PK\x03\x04",),
    "csv": (b"id,passed,",),  # the header of `check --csv`
    "gift": (b"// RasterLab",),  # the first comment of a question bank in GIFT
}


@dataclass(frozen=True)
class Output:
    """One output of a command: the option that names it (for messages),
    its path, whether it is a folder, and ``foreign(path)``: why an
    existing target was not written by the program (None: it was, or may
    be replaced); it may raise OutputRefused for what no ``force`` allows."""

    option: str
    path: str | os.PathLike
    folder: bool = False
    foreign: Callable[[Path], str | None] | None = None


def listed(manifest: str) -> Callable[[Path], str | None]:
    """``Output.foreign`` for one of the files a command writes together into
    a folder (a report, a worksheet), with the folder's ``manifest``: the
    JSON list of the names the program last wrote there. A file it does not
    list was not written by RasterLab."""
    def foreign(path: Path) -> str | None:
        try:
            names = json.loads((Path(path).parent / manifest).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            names = []
        if isinstance(names, list) and Path(path).name in names:
            return None
        return "was not written by RasterLab"
    return foreign


def manifest_bytes(names: Iterable[str]) -> bytes:
    """The text of a folder's manifest (see ``listed``)."""
    return (json.dumps(sorted(names)) + "\n").encode("utf-8")


def not_ours(kind: str) -> Callable[[Path], str | None]:
    """``Output.foreign`` for a file of format ``kind`` (a SIGNATURES key):
    an empty file, or one of that format, may be replaced."""
    def foreign(path: Path) -> str | None:
        with open(path, "rb") as stream:
            head = stream.read(16)
        if not head:
            return None
        start = head[4:] if kind == "mp4" else head
        if any(start.startswith(mark) for mark in SIGNATURES[kind]):
            return None
        return f"is not a {kind.upper()} file RasterLab wrote"
    return foreign


def check_outputs(outputs: Iterable[Output], inputs: Iterable = (), force: bool = False) -> None:
    """Refuse (OutputRefused) what the policy of this module's text forbids,
    before any work: the first problem, in one line. ``inputs`` are the
    files the command reads (None entries are skipped)."""
    read = {_identity(path): path for path in inputs if path is not None}
    written: dict = {}
    for output in outputs:
        if output.path is None:
            continue
        path = Path(output.path)
        _check_kind(output, path)
        identity = _identity(path)
        if identity in read:
            raise OutputRefused(f"{output.option} {path}: is the input {read[identity]} of this "
                                "command; write the output to another name")
        if identity in written:
            raise OutputRefused(f"{output.option} {path}: is also the output of "
                                f"{written[identity].option}; give each output its own name")
        written[identity] = output
    for output in written.values():
        _check_foreign(output, Path(output.path), force)


def check_folders(outputs: Iterable[Output]) -> None:
    """Refuse (OutputRefused) an output whose folder does not exist or cannot
    be written, for commands that would find it only after long work (a
    check's cases). A file inside a folder output is the folder's to make."""
    outputs = [output for output in outputs if output.path is not None]
    made = {Path(output.path) for output in outputs if output.folder}
    for output in outputs:
        folder = Path(output.path).parent
        if folder in made:
            continue
        where = f"{output.option} {output.path}"
        if not folder.is_dir():
            raise OutputRefused(f"{where}: the folder {folder} does not exist")
        if not os.access(folder, os.W_OK):
            raise OutputRefused(f"{where}: the folder {folder} cannot be written")


def _check_kind(output: Output, path: Path) -> None:
    where = f"{output.option} {path}"
    if path.is_symlink() and not path.exists():
        if Path(os.path.realpath(path)).is_symlink():
            raise OutputRefused(f"{where}: a loop of symbolic links")
        return  # a dangling link: its target is made
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return  # nothing there yet (a missing folder is the writer's to report)
    if output.folder:
        if not stat.S_ISDIR(mode):
            raise OutputRefused(f"{where}: is not a folder")
    elif not stat.S_ISREG(mode):
        raise OutputRefused(f"{where}: {_not_a_file(mode)}")


def _check_foreign(output: Output, path: Path, force: bool) -> None:
    where = f"{output.option} {path}"
    if output.foreign is None or not path.exists():
        return
    try:
        reason = output.foreign(path)  # may refuse whatever force says
    except OSError as error:
        raise OutputRefused(f"{where}: cannot be read ({error.strerror or error})") from None
    if reason and not force:
        raise OutputRefused(f"{where}: {reason}; give --force to replace it")


def _identity(path) -> tuple:
    """What two names of one file share: the device and inode of a file that
    exists (links and hard links alike), else the resolved path."""
    try:
        found = os.stat(path)
    except OSError:
        return ("path", os.path.normcase(os.path.realpath(path)))
    return ("file", found.st_dev, found.st_ino)
