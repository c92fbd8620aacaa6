"""Writing a file so that a failure never leaves half of it: the data goes to
a temporary file in the target's folder, which is renamed over the target
once it is complete and on disk."""
from __future__ import annotations

import os
import tempfile
from pathlib import Path


def write_atomically(path: Path, data: bytes, error=OSError, keep_private: bool = False) -> None:
    """Write ``data`` to ``path`` whole or not at all.

    Failures raise ``error`` (an exception class taking one message) with a
    one-line reason that names the file. A new file gets the permissions
    the umask allows, as a plain ``open`` would give it, unless
    ``keep_private`` keeps mkstemp's owner-only mode.
    """
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
        if not keep_private:
            os.chmod(temporary, 0o666 & ~_umask())
        os.replace(temporary, path)
    except BaseException as failure:
        Path(temporary).unlink(missing_ok=True)
        if isinstance(failure, OSError):
            # An OSError made in code may carry a message but no strerror.
            raise error(f"{path}: cannot write the file ({failure.strerror or failure})") from None
        raise


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
