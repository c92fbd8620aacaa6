"""Replacing several files of a folder together.

The new files are written into a staging folder inside the target folder
(``.rasterlab-<kind>-<pid>-<random>``). Once every file is there, a journal
(``.commit.json``) naming them is written into the staging folder; from then
on the change is decided: the files are moved into place, the files the
journal says to remove are removed, and the staging folder goes. A process
killed before the journal leaves a staging folder without one, which the
next run for the same folder deletes; killed after it, the next run
finishes the moves. A staging folder whose process is still alive is left
alone, so two exports to one folder do not undo each other.
"""
from __future__ import annotations

import ctypes
import json
import os
import re
import shutil
import stat
import sys
import tempfile
from pathlib import Path
from typing import Iterable

from app.model.files import write_atomically

JOURNAL = ".commit.json"


def process_alive(pid: int) -> bool:
    """Whether a process with this id runs (ours counts as alive)."""
    if pid == os.getpid():
        return True
    if sys.platform == "win32":
        # os.kill(pid, 0) is no probe there: signal 0 is CTRL_C_EVENT.
        return _windows_process_alive(pid)
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return True
    return True


QUERY_LIMITED_INFORMATION = 0x1000  # the least access that reads an exit code
ACCESS_DENIED = 5
STILL_ACTIVE = 259


def _windows_process_alive(pid: int, kernel32=None, last_error=None) -> bool:
    """Whether a process runs, asked of Windows: a process we may not open
    exists; one we may open runs until it has an exit code. ``kernel32`` and
    ``last_error`` stand in for ctypes' in tests."""
    if kernel32 is None:
        kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
        last_error = ctypes.get_last_error
    if not 0 < pid < 2 ** 32:
        return False
    handle = kernel32.OpenProcess(QUERY_LIMITED_INFORMATION, False, pid)
    if not handle:
        return last_error() == ACCESS_DENIED
    try:
        code = ctypes.c_ulong()
        if not kernel32.GetExitCodeProcess(handle, ctypes.byref(code)):
            return True  # it could be opened, so it exists
        return code.value == STILL_ACTIVE
    finally:
        kernel32.CloseHandle(handle)


def owner_pid(name: str, prefix: str) -> int | None:
    """The process id in a leftover's name ``<prefix><pid>-...``; None for
    a name without one (written before names carried it: its writer is
    long gone)."""
    match = re.match(re.escape(prefix) + r"(\d+)[-.]", name)
    return int(match.group(1)) if match else None


class StagedFolder:
    """Files written into ``stage`` and moved into ``target`` together by
    ``commit``; ``discard`` leaves the target as it was. ``error`` is the
    exception class (taking one message) failures raise."""

    def __init__(self, target, kind: str, error=OSError):
        self.target = Path(target)
        self.prefix = f".rasterlab-{kind}-"
        self.error = error
        self.stage: Path | None = None

    def open(self) -> Path:
        """Clean up what killed runs left here, then make the staging folder."""
        self.recover()
        try:
            self.stage = Path(tempfile.mkdtemp(prefix=f"{self.prefix}{os.getpid()}-",
                                               dir=self.target))
        except OSError as failure:
            raise self.error(f"cannot write in the folder {self.target} "
                             f"({failure.strerror or failure})") from None
        return self.stage

    def recover(self) -> list[Path]:
        """Finish or delete the staging folders of runs that were killed;
        returns the ones handled."""
        handled = []
        for leftover in sorted(self.target.glob(self.prefix + "*")):
            pid = owner_pid(leftover.name, self.prefix)
            if (leftover.is_symlink() or not leftover.is_dir()
                    or (pid is not None and process_alive(pid))):
                continue
            journal = leftover / JOURNAL
            if journal.is_file():
                try:
                    plan = json.loads(journal.read_text(encoding="utf-8"))
                    self._move(leftover, plan["names"], plan["remove"])
                except (OSError, ValueError, KeyError, TypeError):
                    pass  # a damaged journal: the staged files are dropped below
            shutil.rmtree(leftover, ignore_errors=True)
            handled.append(leftover)
        return handled

    def commit(self, names: Iterable[str], remove: Iterable[str] = ()) -> None:
        """Move ``names`` (files in the staging folder) into the target and
        remove the target's files ``remove``: all of it, or after a kill the
        next ``open`` or ``recover`` finishes it."""
        names, remove = list(names), [name for name in remove if name not in set(names)]
        for name in names + remove:
            if Path(name).name != name or name.startswith(self.prefix):
                raise ValueError(f"not a plain file name: {name!r}")
        blocked = [name for name in names if _taken(self.target / name)]
        if blocked:  # found now, before anything has moved
            raise self.error(f"{self.target / blocked[0]} is a folder, link, device or FIFO: "
                             "files are moved into the folder only over regular files")
        plan = json.dumps({"names": names, "remove": remove}).encode("utf-8")
        try:
            write_atomically(self.stage / JOURNAL, plan, self.error)
            self._move(self.stage, names, remove)
        except OSError as failure:
            raise self.error(f"cannot write in the folder {self.target} "
                             f"({failure.strerror or failure})") from None
        shutil.rmtree(self.stage, ignore_errors=True)
        self.stage = None

    def discard(self) -> None:
        if self.stage is not None:
            shutil.rmtree(self.stage, ignore_errors=True)
            self.stage = None

    def _move(self, stage: Path, names, remove) -> None:
        # Moves already done by a killed run are skipped, so this can run twice.
        for name in names:
            if (stage / name).exists():
                os.replace(stage / name, self.target / name)
        for name in remove:
            path = self.target / name
            if path.is_file() and not path.is_symlink():
                path.unlink()


def _taken(path: Path) -> bool:
    """Whether ``path`` is there and not a regular file: a set of files is
    renamed into place, which would replace a link or a device itself."""
    try:
        return not stat.S_ISREG(os.lstat(path).st_mode)
    except OSError:
        return False
