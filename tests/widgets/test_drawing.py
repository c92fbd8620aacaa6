"""The drawing tools' rules (no Qt needed)."""
import pytest

from app.model.drawing import CIRCLE, CONTOURS, FIXED, GROUPS, Drawing, point_labels


def test_fixed_set_starts_anew_once_complete():
    d = Drawing(FIXED, 2)
    assert d.click((1, 1)) and d.click((5, 5))
    assert d.complete() and d.pending() == []
    assert not d.click((5, 5), on_handle=1)  # a press on a handle that did not move
    assert d.click((9, 9)) and d.points == [(9, 9)]
    assert d.pending() == [0]


def test_circle_click_moves_the_centre():
    d = Drawing(CIRCLE, 1)
    d.click((4, 4))
    d.click((7, 2))
    assert d.points == [(7, 2)]


def test_contours_close_reopen_and_new_contour():
    d = Drawing(CONTOURS, 3)
    for p in [(0, 0), (4, 0), (4, 4)]:
        d.click(p)
    assert d.open and not d.complete() and d.pending() == [0, 1, 2]
    assert d.closes_at(0) and not d.closes_at(1)
    assert not d.click((0, 0), on_handle=0)  # a click on the first vertex closes
    assert not d.open and d.complete()
    # Shift+click: a second contour of the same polygon.
    d.click((1, 1), new_contour=True)
    assert d.breaks == (3,) and d.open
    d.click((2, 1))
    assert not d.close()  # two vertices are not a polygon yet
    d.click((2, 2))
    assert d.close() and d.labels() == ["C1.P1", "C1.P2", "C1.P3", "C2.P1", "C2.P2", "C2.P3"]
    # Backspace reopens the last contour; removing its last vertex drops it.
    for _ in range(3):
        d.remove_last()
    assert d.points == [(0, 0), (4, 0), (4, 4)] and d.breaks == () and d.open
    # A plain click after closing starts a new polygon.
    d.close()
    d.click((9, 9))
    assert d.points == [(9, 9)] and d.breaks == () and d.open


def test_groups_share_a_vertex_on_click():
    d = Drawing(GROUPS, 3)
    for p in [(0, 0), (4, 0), (0, 4)]:
        d.click(p)
    assert d.complete()
    d.click((3.9, 0.1), on_handle=1)  # on the vertex (4, 0): exactly there
    assert d.points[-1] == (4, 0) and d.pending() == [3]
    d.click((6, 6))
    d.click((0, 4), on_handle=2)
    assert d.complete() and len(d.points) == 6
    assert d.labels(("P0", "P1", "P2"))[3:] == ["T2.P0", "T2.P1", "T2.P2"]


def test_reset_keeps_an_open_contour_only_when_asked():
    d = Drawing(CONTOURS, 3)
    d.click((0, 0))
    d.click((1, 0))
    d.reset([(0, 0), (1, 0)], (), keep_open=True)
    assert d.open
    d.reset([(0, 0), (1, 0), (1, 1)], ())
    assert not d.open


def test_labels():
    assert point_labels(FIXED, 2, 2, (), ("P", "Q")) == ["P", "Q"]
    assert point_labels(CONTOURS, 3, 4, (), ()) == ["P1", "P2", "P3", "P4"]
    assert point_labels(GROUPS, 3, 3, (), ("P0", "P1", "P2")) == ["P0", "P1", "P2"]


def test_unknown_mode():
    with pytest.raises(ValueError):
        Drawing("spline", 4)
