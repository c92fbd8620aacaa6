"""The player with contours, triangles drawn in threes, and several options
set at once."""
import pytest

from algorithms.core import registry
from algorithms.core.registry import InputError
from app.model.inputs import complete, flatten, runnable_input
from app.gui.player import Player
from app.model.examples import default_scene

OUTER = [(2.0, 2.0), (20.0, 2.0), (20.0, 16.0), (2.0, 16.0)]
HOLE = [(6.0, 6.0), (12.0, 6.0), (9.0, 11.0)]
pytestmark = pytest.mark.player("polygon-scanline", [OUTER, HOLE])


def test_contours_are_flat_points_and_breaks(player):
    assert player.points == OUTER + HOLE and player.breaks == (4,)
    assert player.input_points() == [OUTER, HOLE]
    expected = registry.get("polygon-scanline").record([OUTER, HOLE], {}, (32, 24))
    assert player.trace.written_pixels().tolist() == expected.written_pixels().tolist()


def test_a_contour_still_being_drawn_is_left_out(player):
    player.set_points(OUTER + HOLE[:2], (4,))
    assert player.input_points() == [OUTER] and player.trace is not None
    # Breaks past the end are dropped; None keeps the ones that still fit.
    player.set_points(OUTER + HOLE)
    assert player.breaks == (4,)


def test_triangles_run_on_whole_triangles_only(qtbot):
    p = Player()
    tri = [(2.0, 2.0), (12.0, 3.0), (6.0, 10.0)]
    p.set_scene("triangle-bbox", tri + [(20.0, 4.0)])
    assert p.input_points() == tri
    spec = registry.get("triangle-bbox")
    assert not complete(spec, tri[:2]) and complete(spec, tri + tri[:1])
    assert runnable_input(spec, tri * 2 + tri[:2]) == tri * 2


def test_switching_between_triangles_and_contours(qtbot):
    p = Player()
    mesh = [(2.0, 2.0), (12.0, 3.0), (6.0, 10.0), (12.0, 3.0), (18.0, 12.0), (6.0, 10.0)]
    p.set_scene("triangle-bbox", mesh)
    p.set_algorithm("polygon-scanline")
    assert p.points == mesh and p.breaks == (3,)  # one contour per triangle
    p.set_algorithm("triangle-pineda")
    assert p.points == mesh and p.breaks == ()


def test_a_refused_shape_falls_back_to_an_example(player):
    player.set_algorithm("polygon-convex")  # two contours: refused
    assert "one contour" in player.refusal
    assert player.trace is not None and player.breaks == ()
    points, breaks, _ = default_scene(registry.get("polygon-convex"), player.grid)
    assert player.points == points


def test_set_options_records_once_and_all_or_nothing(qtbot):
    p = Player()
    p.set_scene("ellipse-midpoint", [(16, 12)])
    recorded = []
    p.traceChanged.connect(lambda: recorded.append(1))
    p.set_options({"rx": 7, "ry": 3})
    assert (p.options["rx"], p.options["ry"]) == (7, 3) and len(recorded) == 1
    with pytest.raises(InputError):
        p.set_options({"rx": 5, "ry": -1})
    assert (p.options["rx"], p.options["ry"]) == (7, 3)


def test_restore_puts_back_points_and_options(player):
    player.restore(OUTER, (), dict(player.options, fill_rule="nonzero"))
    assert player.points == OUTER and player.options["fill_rule"] == "nonzero"


def test_flatten_accepts_both_shapes():
    spec = registry.get("polygon-scanline")
    assert flatten(spec, [OUTER, HOLE]) == (OUTER + HOLE, (4,))
    assert flatten(spec, OUTER) == (OUTER, ())
    assert flatten(registry.get("line-bresenham"), [(1, 2), (3, 4)]) == ([(1, 2), (3, 4)], ())
