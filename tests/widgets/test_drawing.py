"""The drawing tools' rules (no Qt needed)."""
import pytest

from app.model.drawing import (CIRCLE, CONTOURS, FIXED, GROUPS, Close, Move, Place, Remove,
                               Sketch, Tool, all_placed, apply, closes_at, labels, pending,
                               point_labels)


def run(tool, gestures, sketch=Sketch()):
    for gesture in gestures:
        sketch = apply(tool, sketch, gesture)
    return sketch


def test_fixed_set_starts_anew_once_complete():
    tool = Tool(FIXED, 2)
    d = run(tool, [Place((1, 1)), Place((5, 5))])
    assert d.points == ((1, 1), (5, 5))
    assert all_placed(tool, d) and pending(tool, d) == []
    # A press on a handle that did not move changes nothing.
    assert apply(tool, d, Place((5, 5), on_handle=1)) is d
    d = apply(tool, d, Place((9, 9)))
    assert d.points == ((9, 9),) and pending(tool, d) == [0]


def test_circle_click_moves_the_centre():
    assert run(Tool(CIRCLE, 1), [Place((4, 4)), Place((7, 2))]).points == ((7, 2),)


def test_contours_close_reopen_and_new_contour():
    tool = Tool(CONTOURS, 3)
    d = run(tool, [Place(p) for p in [(0, 0), (4, 0), (4, 4)]])
    assert d.open and not all_placed(tool, d) and pending(tool, d) == [0, 1, 2]
    assert closes_at(tool, d, 0) and not closes_at(tool, d, 1)
    d = apply(tool, d, Place((0, 0), on_handle=0))  # a click on the first vertex closes
    assert not d.open and all_placed(tool, d) and len(d.points) == 3
    # Shift+click: a second contour of the same polygon.
    d = apply(tool, d, Place((1, 1), new_contour=True))
    assert d.breaks == (3,) and d.open
    d = apply(tool, d, Place((2, 1)))
    assert apply(tool, d, Close()) is d  # two vertices are not a polygon yet
    d = apply(tool, apply(tool, d, Place((2, 2))), Close())
    assert not d.open
    assert labels(tool, len(d.points), d.breaks) == ["C1.P1", "C1.P2", "C1.P3",
                                                     "C2.P1", "C2.P2", "C2.P3"]
    # Backspace reopens the last contour; removing its last vertex drops it.
    for _ in range(3):
        d = apply(tool, d, Remove(len(d.points) - 1))
    assert d.points == ((0, 0), (4, 0), (4, 4)) and d.breaks == () and d.open
    # A plain click after closing starts a new polygon.
    d = run(tool, [Close(), Place((9, 9))], d)
    assert d.points == ((9, 9),) and d.breaks == () and d.open


def test_groups_share_a_vertex_on_click():
    tool = Tool(GROUPS, 3)
    d = run(tool, [Place(p) for p in [(0, 0), (4, 0), (0, 4)]])
    assert all_placed(tool, d)
    d = apply(tool, d, Place((3.9, 0.1), on_handle=1))  # on the vertex (4, 0): exactly there
    assert d.points[-1] == (4, 0) and pending(tool, d) == [3]
    d = run(tool, [Place((6, 6)), Place((0, 4), on_handle=2)], d)
    assert all_placed(tool, d) and len(d.points) == 6
    assert labels(tool, 6, (), ("P0", "P1", "P2"))[3:] == ["T2.P0", "T2.P1", "T2.P2"]


def test_move_changes_one_point_only():
    tool = Tool(FIXED, 2)
    d = Sketch.of([(1, 1), (5, 5)])
    assert apply(tool, d, Move(1, (6, 2))).points == ((1, 1), (6, 2))
    assert apply(tool, d, Move(1, (5, 5))) is d and apply(tool, d, Move(7, (0, 0))) is d


def test_sketch_of_keeps_only_breaks_inside_and_open_only_with_points():
    assert Sketch.of([(0, 0), (1, 0)], (0, 1, 2), True) == Sketch(((0, 0), (1, 0)), (1,), True)
    assert not Sketch.of([], (), True).open


def test_labels():
    assert point_labels(FIXED, 2, 2, (), ("P", "Q")) == ["P", "Q"]
    assert point_labels(CONTOURS, 3, 4, (), ()) == ["P1", "P2", "P3", "P4"]
    assert point_labels(GROUPS, 3, 3, (), ("P0", "P1", "P2")) == ["P0", "P1", "P2"]


def test_unknown_mode_and_gesture():
    with pytest.raises(ValueError):
        Tool("spline", 4)
    with pytest.raises(TypeError):
        apply(Tool(), Sketch(), "click")
