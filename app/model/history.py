"""Undo and redo of every scene edit: points (drawn, dragged, typed),
contours, the algorithm, every option, the grid size and the origin.

An entry holds the whole scene as it was before an edit (a ``Scene``; its
title, description, view and bookmarks are no edits and stay at their defaults),
and the name of the edit for the Edit menu ("Undo move point"). Edits that
share a merge key while the entry is still open (one drag of a handle, one
spin box stepped by its arrows) collapse into one entry, so one undo takes
back the whole gesture. An entry equal to the scene it would restore is
skipped by undo and redo.
"""
from __future__ import annotations

import time
from dataclasses import dataclass

from app.model.scene import Scene

LIMIT = 200  # entries kept; the oldest go first
MERGE_SECONDS = 1.5  # typed or stepped edits of one field this close together merge


def describe(before: Scene, after: Scene) -> str:
    """What changed from ``before`` to ``after``, in a few words."""
    if before.algorithm != after.algorithm:
        return "algorithm switch"
    if before.grid != after.grid:
        return "grid size"
    if before.origin != after.origin:
        return "origin"
    if before.flat != after.flat:
        return _describe_points(tuple(before.flat), tuple(after.flat))
    if before.breaks != after.breaks:
        return "contours"
    old, new = dict(before.options), dict(after.options)
    names = [name for name in new if old.get(name) != new[name]]
    if names:
        return "change " + ", ".join("colours" if name == "colors" else name for name in names)
    return "edit"


def _describe_points(old: tuple, new: tuple) -> str:
    before, after = len(old), len(new)
    if after == 0:
        return "clear points"
    if after < before and not _kept_in_order(new, old):
        # The first click of a new segment (or circle) replaces the old points.
        return "start a new shape"
    if after > before:
        return "add point" + ("s" if after - before > 1 else "")
    if after < before:
        return "remove point" + ("s" if before - after > 1 else "")
    return "move point"


def _kept_in_order(new: tuple, old: tuple) -> bool:
    """Is ``new`` ``old`` with some points taken out?"""
    rest = iter(old)
    return all(any(point == kept for kept in rest) for point in new)


@dataclass
class Entry:
    snapshot: Scene
    label: str
    key: object = None
    until: float | None = None  # merging with this entry is open until then (None: always)


class EditHistory:
    def __init__(self, clock=time.monotonic):
        self.clock = clock
        self._undo: list[Entry] = []
        self._redo: list[Entry] = []
        self._open = False  # may the next edit merge with the top entry?

    def push(self, before: Scene, after: Scene, key=None, seconds: float | None = None):
        """Record an edit from ``before`` to ``after``. With a ``key`` equal to
        the top entry's, and within its time (``seconds`` after the last
        merged edit; None: no limit), the edit merges into that entry."""
        if before == after:
            return
        now = self.clock()
        top = self._undo[-1] if self._undo else None
        if (self._open and top is not None and key is not None and top.key == key
                and (top.until is None or now <= top.until)):
            top.label = describe(top.snapshot, after)
            top.until = None if seconds is None else now + seconds
            self._redo.clear()
            return
        self._undo.append(Entry(before, describe(before, after), key,
                                None if seconds is None else now + seconds))
        del self._undo[:-LIMIT]
        self._redo.clear()
        self._open = True

    def seal(self) -> None:
        """The next edit starts a new entry, whatever its key."""
        self._open = False

    def undo(self, current: Scene) -> Scene | None:
        return self._move(self._undo, self._redo, current)

    def redo(self, current: Scene) -> Scene | None:
        return self._move(self._redo, self._undo, current)

    def _move(self, source: list, target: list, current: Scene) -> Scene | None:
        self._open = False
        while source and source[-1].snapshot == current:
            source.pop()
        if not source:
            return None
        entry = source.pop()
        target.append(Entry(current, entry.label))
        return entry.snapshot

    def clear(self) -> None:
        self._undo.clear()
        self._redo.clear()
        self._open = False

    @property
    def can_undo(self) -> bool:
        return bool(self._undo)

    @property
    def can_redo(self) -> bool:
        return bool(self._redo)

    @property
    def undo_text(self) -> str:
        return self._undo[-1].label if self._undo else ""

    @property
    def redo_text(self) -> str:
        return self._redo[-1].label if self._redo else ""

    def __len__(self) -> int:
        return len(self._undo)
