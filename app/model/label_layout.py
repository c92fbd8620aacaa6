"""Where the grid puts the names of the points, so that no two overlap.

Each label sits above or below its point (away from the middle of the
points, so it does not cover the primitive). Points close together would
put their labels on top of one another; a label that would overlap one
already placed moves further out on its side, then to the other side,
until it is clear. Everything is in screen pixels with y down, and the
label sizes are given, so nothing here needs a font or Qt.
"""
from __future__ import annotations

from dataclasses import dataclass

GAP = 4.0     # pixels between a point and its label, and between labels
TRIES = 12    # positions tried on each side before giving up (keeps the first)


@dataclass(frozen=True)
class Rect:
    """A label's rectangle on screen: left, top, width, height (y down)."""

    left: float
    top: float
    width: float
    height: float

    def intersects(self, other: "Rect") -> bool:
        return (self.left < other.left + other.width and other.left < self.left + self.width
                and self.top < other.top + other.height and other.top < self.top + self.height)

    @property
    def centre(self) -> tuple[float, float]:
        return self.left + self.width / 2, self.top + self.height / 2


def place(anchors, sizes, above) -> list[Rect]:
    """One rectangle per label: label k (``sizes[k]`` = width, height)
    centred over (``above[k]`` true) or under its point ``anchors[k]``,
    moved out by whole label heights where it would overlap a label placed
    before it."""
    placed: list[Rect] = []
    for (x, y), (width, height), up in zip(anchors, sizes, above):
        candidates = [_at(x, y, width, height, side, k)
                      for side in ((up, not up)) for k in range(TRIES)]
        rect = next((c for c in candidates if not any(c.intersects(p) for p in placed)),
                    candidates[0])
        placed.append(rect)
    return placed


def _at(x: float, y: float, width: float, height: float, up: bool, k: int) -> Rect:
    """The k-th position on one side: k label heights (and gaps) further out."""
    out = GAP + k * (height + GAP)
    top = y - out - height if up else y + out
    return Rect(x - width / 2, top, width, height)
