"""Writing a file so that a failure never leaves half of it: the data goes to
a temporary file in the target's folder, which is renamed over the target
once it is complete and on disk."""
from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path


def write_atomically(path: Path, data: bytes, error=OSError) -> None:
    """Write ``data`` to ``path`` whole or not at all.

    Failures raise ``error`` (an exception class taking one message) with a
    one-line reason that names the file. A file that exists keeps its
    permissions; a new one gets those the umask allows, as a plain ``open``
    would give it. A symbolic link stays: its target is replaced.
    """
    path = _through_links(Path(path), error)
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise error(f"{path}: the folder {directory} does not exist")
    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
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
