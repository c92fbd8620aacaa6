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

Anyone who can write in the target folder can plant a staging folder, so
recovery trusts a journal only when it is a regular file carrying this
program's marker and naming plain file names (no folder, no ``..``, no
drive): then every move and removal stays inside the target folder. Any
other journal is left where it is, with one line on stderr.
"""
from __future__ import annotations

import json
import os
import shutil
import stat
import sys
import tempfile
from pathlib import Path
from typing import Iterable

from app.model.files import manifest_bytes, write_atomically
from app.model.processes import owner_pid, process_alive

JOURNAL = ".commit.json"
MARKER = {"rasterlab": "staging", "version": 1}  # what every journal of ours carries
MAX_JOURNAL_BYTES = 16 * 2 ** 20  # far above the names of the largest export


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
        returns the ones handled. One whose journal is not ours or is
        damaged is left as it is, and said once on stderr."""
        handled, foreign = [], []
        for leftover in sorted(self.target.glob(self.prefix + "*")):
            pid = owner_pid(leftover.name, self.prefix)
            if (leftover.is_symlink() or not leftover.is_dir()
                    or (pid is not None and process_alive(pid))):
                continue
            journal = leftover / JOURNAL
            if os.path.lexists(journal):
                plan = self._plan(journal)
                if plan is None:
                    foreign.append(leftover)
                    continue
                try:
                    self._move(leftover, *plan)
                except OSError:
                    pass  # a file in the way: dropped below, as later it could undo newer files
            shutil.rmtree(leftover, ignore_errors=True)
            handled.append(leftover)
        if foreign:
            print(f"rasterlab: left alone {len(foreign)} staging folder(s) whose journal is "
                  f"foreign or damaged: {str(foreign[0])!r}", file=sys.stderr)
        return handled

    def _plan(self, journal: Path) -> tuple[list, list] | None:
        """The names to move and to remove of a journal of ours; None for
        any other file (not ours, damaged, or naming what it may not)."""
        try:
            plan = json.loads(_read_journal(journal).decode("utf-8"))
        except (OSError, ValueError):
            return None
        if not isinstance(plan, dict) or any(plan.get(k) != v for k, v in MARKER.items()):
            return None
        names, remove = plan.get("names"), plan.get("remove")
        if not isinstance(names, list) or not isinstance(remove, list):
            return None
        if not all(self._plain(name) for name in names + remove):
            return None
        return names, remove

    def _plain(self, name) -> bool:
        """Whether ``name`` is a file name of the target folder itself: no
        separator of any system, not ``.`` or ``..``, no drive or stream
        (``:``), not a staging folder or journal."""
        return (isinstance(name, str) and name not in ("", ".", "..", JOURNAL)
                and not any(char in name for char in "/\\:\0")
                and Path(name).name == name and not name.startswith(self.prefix))

    def commit(self, names: Iterable[str], remove: Iterable[str] = ()) -> None:
        """Move ``names`` (files in the staging folder) into the target and
        remove the target's files ``remove``: all of it, or after a kill the
        next ``open`` or ``recover`` finishes it."""
        names, remove = list(names), [name for name in remove if name not in set(names)]
        for name in names + remove:
            if not self._plain(name):
                raise ValueError(f"not a plain file name: {name!r}")
        blocked = [name for name in names if _taken(self.target / name)]
        if blocked:  # found now, before anything has moved
            raise self.error(f"{self.target / blocked[0]} is a folder, link, device or FIFO: "
                             "files are moved into the folder only over regular files")
        plan = json.dumps({**MARKER, "names": names, "remove": remove}).encode("utf-8")
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


def _read_journal(path: Path) -> bytes:
    """A journal's bytes: a regular file (not a link, FIFO or device, which
    could hang or mislead the read) of at most MAX_JOURNAL_BYTES."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOFOLLOW", 0)
    if os.path.islink(path):
        raise OSError(f"{path} is a link")
    handle = os.open(path, flags)
    try:
        status = os.fstat(handle)
        if not stat.S_ISREG(status.st_mode) or status.st_size > MAX_JOURNAL_BYTES:
            raise OSError(f"{path} is not a journal")
        return os.read(handle, MAX_JOURNAL_BYTES + 1)
    finally:
        os.close(handle)


def listed_names(folder, manifest: str) -> list[str]:
    """The names ``folder``'s manifest lists (app/model/files.py ``listed``):
    the files the program last wrote there; [] when it has none to read."""
    try:
        names = json.loads((Path(folder) / manifest).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return []
    return [name for name in names if isinstance(name, str)] if isinstance(names, list) else []


def write_folder(folder, kind: str, names: list[str], fill, manifest: str,
                 keep: Iterable[str] = (), remove: Iterable[str] = ()) -> list[Path]:
    """Write the files ``names`` into ``folder`` together: ``fill(stage)``
    writes them into the staging folder; the folder's ``manifest`` then
    lists them and ``keep`` (files written there before that stay the
    program's), and ``remove`` goes. A failure leaves the folder as it was,
    removes the folders made for it, and names the folder, not the stage.
    Returns the paths written."""
    folder = Path(folder)
    made = [parent for parent in [folder, *folder.parents] if not parent.exists()]
    folder.mkdir(parents=True, exist_ok=True)
    staged = StagedFolder(folder, kind)
    try:
        stage = staged.open()
        try:
            fill(stage)
        except OSError as error:  # named where the person will look for the file
            raise OSError(str(error).replace(str(stage), str(folder))) from None
        remove = list(remove)
        write_atomically(stage / manifest, manifest_bytes((set(names) | set(keep)) - set(remove)))
        staged.commit(list(names) + [manifest], remove=remove)
        return [folder / name for name in names]
    except BaseException:
        staged.discard()
        for parent in made:  # deepest first; a folder that holds anything stays
            try:
                parent.rmdir()
            except OSError:
                break
        raise


def write_bytes(files: dict[str, bytes]):
    """A ``fill`` for ``write_folder`` that writes ``files`` (name -> bytes)."""
    def fill(stage: Path) -> None:
        for name, data in files.items():
            write_atomically(stage / name, data)
    return fill
