"""The drawing rules as the session applies them, against an oracle written
here from the rules app/model/drawing.py documents: random gesture sequences
give the points the oracle builds, each gesture is one undo entry, and
undoing it puts back the scene before it."""
import random

import pytest

from algorithms.core.registry import InputError
from app.model.drawing import Close, Move, Place, Remove
from app.model.session import Session

GRID = (16, 12)


class Oracle:
    """The points kept as a list of contours (one contour outside contour
    mode) and whether the last one is still being drawn."""

    def __init__(self, mode: str, count: int, points):
        self.mode, self.count = mode, count
        self.contours = [list(points)]
        self.open = False

    @property
    def flat(self) -> list:
        return [p for contour in self.contours for p in contour]

    @property
    def breaks(self) -> tuple:
        sizes = [len(c) for c in self.contours]
        return tuple(sum(sizes[:k]) for k in range(1, len(sizes)))

    def apply(self, gesture) -> None:
        kind = type(gesture).__name__.lower()
        getattr(self, kind)(gesture)
        self.contours = [c for c in self.contours if c] or [[]]
        self.open = self.open and bool(self.flat)

    def place(self, g) -> None:
        flat, last = self.flat, self.contours[-1]
        if self.mode == "groups":
            last.append(flat[g.on_handle] if g.on_handle is not None else g.point)
        elif self.mode == "fixed":
            if g.on_handle is not None and len(flat) >= self.count:
                return
            self.contours = [[g.point]] if len(flat) >= self.count else [flat + [g.point]]
        else:
            first = len(flat) - len(last)
            if self.open and g.on_handle == first and len(last) >= self.count:
                self.open = False
            elif g.on_handle is None or g.new_contour:
                if g.new_contour and flat:
                    self.contours.append([g.point])
                elif not self.open:
                    self.contours = [[g.point]]
                else:
                    last.append(g.point)
                self.open = True

    def move(self, g) -> None:
        k = g.index
        for contour in self.contours:
            if k < len(contour):
                contour[k] = g.point
                return
            k -= len(contour)

    def remove(self, g) -> None:
        k = g.index
        for contour in self.contours:
            if k < len(contour):
                del contour[k]
                break
            k -= len(contour)
        self.open = self.mode == "contours"

    def close(self, g) -> None:
        if self.mode == "contours" and self.open and len(self.contours[-1]) >= self.count:
            self.open = False


def random_point(rng, integer: bool):
    if integer:
        return (rng.randrange(GRID[0]), rng.randrange(GRID[1]))
    return (rng.randrange(GRID[0] * 8) / 8, rng.randrange(GRID[1] * 8) / 8)


def random_gesture(rng, n: int, integer: bool):
    roll = rng.random()
    if n and roll < 0.15:
        return Move(rng.randrange(n), random_point(rng, integer))
    if n and roll < 0.25:
        return Remove(n - 1 if rng.random() < 0.7 else rng.randrange(n))
    if roll < 0.32:
        return Close()
    handle = rng.randrange(n) if n and rng.random() < 0.25 else None
    return Place(random_point(rng, integer), handle, rng.random() < 0.15)


CASES = [("line-bresenham", "fixed", 2, True, [(1, 1), (9, 4)]),
         ("triangle-bbox", "groups", 3, False, [(1.0, 1.0), (9.0, 1.0), (4.0, 8.0)]),
         ("polygon-scanline", "contours", 3, False, [(1.0, 1.0), (9.0, 1.0), (4.0, 8.0)])]


def make_session(algorithm, points) -> Session:
    session = Session()
    session.sync_wait = None
    session.set_scene(algorithm, points, {}, GRID)
    return session


@pytest.mark.parametrize("seed", [1, 2, 3])
@pytest.mark.parametrize("algorithm, mode, count, integer, start", CASES)
def test_random_gestures_match_the_oracle_and_undo_one_by_one(algorithm, mode, count,
                                                                integer, start, seed):
    rng = random.Random(seed)
    session, oracle = make_session(algorithm, start), Oracle(mode, count, start)
    scenes = [session.scene]
    for k in range(30):
        gesture = random_gesture(rng, len(session.points), integer)
        before = session.scene
        try:
            with session.edit(("gesture", k)):
                session.draw(gesture)
            oracle.apply(gesture)
        except InputError:
            assert session.scene == before  # refused: nothing changes
            continue
        assert session.points == oracle.flat, (k, gesture)
        assert session.breaks == oracle.breaks, (k, gesture)
        assert session.sketch.open == oracle.open, (k, gesture)
        if session.scene != before:
            scenes.append(session.scene)
    while len(scenes) > 1:
        scenes.pop()
        assert session.undo() is not None
        assert session.points == list(scenes[-1].flat)
        assert session.breaks == scenes[-1].breaks
    assert not session.history.can_undo


def test_a_drag_is_one_undo_entry():
    session = make_session("line-bresenham", [(1, 1), (9, 4)])
    with session.edit(("gesture", 1)):
        for x in range(10, 14):
            session.draw(Move(1, (x, 5)))
    assert session.points == [(1, 1), (13, 5)]
    session.undo()
    assert session.points == [(1, 1), (9, 4)] and not session.history.can_undo


def test_an_open_contour_stays_open_only_while_its_points_stay():
    session = make_session("polygon-scanline", [(1.0, 1.0), (9.0, 1.0), (4.0, 8.0)])
    session.draw(Place((12.0, 2.0)))  # a click after a finished polygon starts a new one
    assert session.points == [(12.0, 2.0)] and session.sketch.open
    session.draw(Place((14.0, 2.0)))
    session.draw(Place((13.0, 6.0)))
    assert session.sketch.open and session.trace is not None
    session.draw(Close())
    assert not session.sketch.open and len(session.points) == 3
    session.draw(Remove(2))  # Backspace reopens the contour
    assert session.sketch.open
    session.set_points([(1.0, 1.0), (9.0, 1.0), (4.0, 8.0)])  # typed: finished
    assert not session.sketch.open
