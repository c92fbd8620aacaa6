"""Undo and redo of what the person drew: points, contours and the options
a gesture on the grid sets (a radius, a seed).

The window remembers the scene as it was when a gesture starts; a gesture
that changed nothing leaves an entry equal to the scene, which undo skips.
"""
from __future__ import annotations

from dataclasses import dataclass

LIMIT = 200  # entries kept; the oldest go first


@dataclass(frozen=True)
class Snapshot:
    points: tuple
    breaks: tuple
    options: tuple  # (name, value) pairs of the options a gesture sets

    @classmethod
    def of(cls, points, breaks, options: dict) -> "Snapshot":
        return cls(tuple(tuple(p) for p in points), tuple(breaks),
                   tuple(sorted(options.items())))


class EditHistory:
    def __init__(self):
        self._undo: list[Snapshot] = []
        self._redo: list[Snapshot] = []

    def remember(self, snapshot: Snapshot) -> None:
        """The scene before an edit: it becomes the one undo returns to."""
        if self._undo and self._undo[-1] == snapshot:
            return
        self._undo.append(snapshot)
        del self._undo[:-LIMIT]
        self._redo.clear()

    def undo(self, current: Snapshot) -> Snapshot | None:
        while self._undo and self._undo[-1] == current:
            self._undo.pop()
        if not self._undo:
            return None
        self._redo.append(current)
        return self._undo.pop()

    def redo(self, current: Snapshot) -> Snapshot | None:
        while self._redo and self._redo[-1] == current:
            self._redo.pop()
        if not self._redo:
            return None
        self._undo.append(current)
        return self._redo.pop()

    def clear(self) -> None:
        self._undo.clear()
        self._redo.clear()

    @property
    def can_undo(self) -> bool:
        return bool(self._undo)

    @property
    def can_redo(self) -> bool:
        return bool(self._redo)
