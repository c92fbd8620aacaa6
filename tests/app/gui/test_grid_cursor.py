"""The grid's keyboard cursor and F6, driven by key events on the window."""
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QCursor
from PySide6.QtTest import QTest

pytestmark = pytest.mark.window(settled=True)

SHIFT = Qt.KeyboardModifier.ShiftModifier


def key(window, name, modifier=Qt.KeyboardModifier.NoModifier):
    """A key pressed where the focus is, as a person presses it."""
    QTest.keyClick(window.focusWidget() or window, getattr(Qt.Key, f"Key_{name}"), modifier)


def cursor_on(qtbot, window):
    window.activateWindow()
    window.grid.clearFocus()  # the grid has the focus from the start, not by Tab
    window.grid.setFocus(Qt.FocusReason.TabFocusReason)
    qtbot.waitUntil(lambda: window.keyboard.cursor.active)
    return window.keyboard.cursor


def test_tab_to_the_grid_shows_the_cursor_and_the_arrows_move_it(qtbot, window):
    cursor = cursor_on(qtbot, window)
    step = window.player.index
    cursor.move_to(3, 4)
    key(window, "Right")
    key(window, "Up")
    key(window, "Right", SHIFT)
    assert cursor.cell == (9, 5)
    assert window.player.index == step  # the arrows moved the cursor, not the step
    assert window.keyboard.label.text().startswith("cursor (9, 5)")
    assert all(ring.isVisible() for ring in cursor._rings)
    assert cursor._rings[0].rect().topLeft().toTuple() == (9.0, 5.0)


def test_up_goes_up_the_screen_with_the_origin_top_left(qtbot, window):
    window.set_y_down(True)
    cursor = cursor_on(qtbot, window)
    cursor.move_to(3, 4)
    key(window, "Up")
    assert cursor.cell == (3, 3)


def test_the_cursor_stops_at_the_grid_edge(qtbot, window):
    cursor = cursor_on(qtbot, window)
    cursor.move_to(1, 1)
    key(window, "Left", SHIFT)
    key(window, "Down", SHIFT)
    assert cursor.cell == (0, 0)


def test_without_the_cursor_the_arrows_step(qtbot, window):
    cursor_on(qtbot, window)
    key(window, "K")  # the cursor off
    assert not window.keyboard.cursor.active
    assert not window.keyboard.label.isVisible()
    window.player.seek(0)
    key(window, "Right")
    assert window.player.index == 1


def test_a_click_on_the_grid_hides_the_cursor(qtbot, window):
    cursor = cursor_on(qtbot, window)
    window.grid.clearFocus()
    window.grid.setFocus(Qt.FocusReason.MouseFocusReason)
    assert not cursor.active
    assert not any(ring.isVisible() for ring in cursor._rings)


def test_enter_places_the_points_of_a_line(qtbot, window):
    window.clear_points()
    cursor = cursor_on(qtbot, window)
    cursor.move_to(2, 3)
    key(window, "Return")
    for _ in range(4):
        key(window, "Right", SHIFT)
    key(window, "Up")
    key(window, "Return")
    assert window.player.points == [(2, 3), (22, 4)]


def test_enter_picks_a_point_up_the_arrows_move_it_and_esc_puts_it_back(qtbot, window):
    window.set_points([(4, 5), (28, 15)])
    cursor = cursor_on(qtbot, window)
    cursor.move_to(4, 5)
    assert "picks up the point" in cursor.hint()
    key(window, "Return")
    assert cursor.held == "point"
    key(window, "Right")
    key(window, "Right")
    assert window.player.points[0] == (6, 5)
    key(window, "Escape")
    assert cursor.held is None
    assert window.player.points[0] == (4, 5)
    key(window, "Return")
    key(window, "Down")
    key(window, "Return")  # dropped
    key(window, "Down")
    assert window.player.points == [(4, 4), (28, 15)]
    window.undo()  # the move is one step to undo
    assert window.player.points == [(4, 5), (28, 15)]


@pytest.mark.window("circle-midpoint", settled=True)
def test_a_circle_centre_then_its_radius_by_the_arrows(qtbot, window):
    window.clear_points()
    cursor = cursor_on(qtbot, window)
    cursor.move_to(10, 10)
    key(window, "Return")
    assert window.player.points == [(10, 10)]
    assert cursor.held == "rim"
    for _ in range(6):
        key(window, "Right")
    key(window, "Return")
    assert window.player.options["radius"] == 6
    # The rim handle can be picked up again where it is drawn.
    rim = window.grid._rim_position()
    cursor.move_to(int(rim.x()), int(rim.y()))
    key(window, "Return")
    assert cursor.held == "rim"
    key(window, "Right", SHIFT)
    key(window, "Return")
    assert window.player.options["radius"] > 6


@pytest.mark.window("flood-fill", settled=True)
def test_the_seed_is_placed_with_the_seed_tool_and_moved_by_picking_it_up(qtbot, window):
    cursor = cursor_on(qtbot, window)
    key(window, "S")  # the seed tool
    cursor.move_to(12, 9)
    assert cursor.hint() == "Enter places the seed"
    key(window, "Return")
    assert window.player.options["seed"] == (12, 9)
    key(window, "Return")  # on the seed: picked up
    assert cursor.held == "marker"
    key(window, "Left")
    key(window, "Return")
    assert window.player.options["seed"] == (11, 9)


@pytest.mark.window("polygon-scanline", settled=True)
def test_enter_on_the_first_vertex_closes_the_contour(qtbot, window):
    window.clear_points()
    cursor = cursor_on(qtbot, window)
    for cell in ((2, 2), (12, 2), (7, 10)):
        cursor.move_to(*cell)
        key(window, "Return")
    cursor.move_to(2, 2)
    assert cursor.hint() == "Enter closes the contour"
    key(window, "Return")
    assert not window.grid.sketch.open
    assert len(window.player.points) == 3


def test_f6_goes_round_the_grid_and_the_docks(qtbot, window):
    cursor_on(qtbot, window)
    regions = window.keyboard.regions()
    assert regions[0] is window.grid and len(regions) >= 3
    seen = []
    for _ in range(len(regions)):
        key(window, "F6")
        focus = window.focusWidget()
        seen.append(next(r for r in regions if r is focus or r.isAncestorOf(focus)))
    assert seen == regions[1:] + regions[:1]
    key(window, "F6", SHIFT)
    assert regions[-1].isAncestorOf(window.focusWidget())


def test_the_focus_ring_follows_keyboard_focus(qtbot, window):
    cursor_on(qtbot, window)
    key(window, "F6")
    ring = window.keyboard.ring
    assert ring.isVisible() and ring.target is window.focusWidget()
    target = ring.target
    corner = target.mapTo(window, target.rect().topLeft())
    assert ring.geometry().contains(corner)


def test_every_menu_of_the_menu_bar_has_a_mnemonic(window):
    titles = [action.text() for action in window.menuBar().actions()]
    assert titles and all("&" in title for title in titles)
    letters = [title[title.index("&") + 1].lower() for title in titles]
    assert len(set(letters)) == len(letters)


def test_a_click_gives_the_focus_without_a_ring(qtbot, window):
    window.activateWindow()
    search = window.picker_search
    QCursor.setPos(search.mapToGlobal(search.rect().center()))  # the pointer is where it clicks
    QTest.mouseClick(search, Qt.MouseButton.LeftButton)
    assert search.hasFocus()
    assert not window.keyboard.ring.isVisible()
    key(window, "Tab")  # then the keyboard moves it: the ring shows
    assert window.keyboard.ring.isVisible()
    assert window.keyboard.ring.target is window.focusWidget() is not search
