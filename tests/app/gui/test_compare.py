"""Compare mode in the window: View > Compare…, driven as a person drives it."""
from fractions import Fraction

import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QWheelEvent
from PySide6.QtWidgets import QApplication

from app.model import compare
from app.gui.compare_window import WINDOW_KEY
from app.gui.window import DEMO_POINTS
from tests.support.bresenham import bresenham_pixels
from tests.support.compare_oracles import FLOAT32_BITS, FLOAT64_BITS, dda_pixels, diff_counts
from tests.support.gui import WAIT_MS


@pytest.fixture
def comparing(window, qtbot):
    window.compare_entry.action.trigger()
    c = window.compare_entry.window
    qtbot.waitExposed(c)
    return c


def choose_preset(c, key):
    box = c.preset_box
    box.setCurrentIndex(box.findData(key))
    box.activated.emit(box.currentIndex())


def shown_counts(c) -> dict:
    counts = c.view.legend.counts
    numbers = {key: int(label.text().replace(",", "")) for key, label in counts.items()}
    return {"only A": numbers["only A"], "only B": numbers["only B"],
            "both": numbers["both, same value"] + numbers["both, different value"],
            "both, different value": numbers["both, different value"]}


def test_view_menu_opens_compare_mode_with_ctrl_k(window):
    action = window.compare_entry.action
    assert action in window.menus["view"].actions()
    assert action.shortcut().toString() == "Ctrl+K"
    assert action.toolTip()


def test_compare_mode_shows_the_right_diff_counts_for_a_known_pair(comparing):
    c = comparing
    # The main window shows Bresenham on the demo line; compare mode sets
    # it against DDA (the neighbour in its family) on the same points.
    assert [pane.algorithm for pane in c.panes] == ["line-bresenham", "line-dda"]
    expected = diff_counts(bresenham_pixels(*DEMO_POINTS), dda_pixels(*DEMO_POINTS, FLOAT64_BITS),
                           32, 24)
    assert shown_counts(c) == expected
    assert expected["only A"] > 0  # slope 5/12 has ties: the pair really differs
    assert f"{expected['only A']:,} only in A" in c.view.diff.message.text()


def test_float32_against_float64_on_a_long_line(comparing):
    c = comparing
    choose_preset(c, "dda-precision")
    line = ((0, 0), (4095, 192))
    expected = diff_counts(dda_pixels(*line, FLOAT32_BITS), dda_pixels(*line, FLOAT64_BITS),
                           4096, 200)
    assert shown_counts(c) == expected
    assert "dtype=float32" in c.view.panes[0].title.text()
    # Next difference zooms every view onto a cell that differs.
    x, y = c.next_difference()
    assert (x, y) in set(map(tuple, c.current_diff.cells().tolist()))
    for grid in c.view.grids():
        (x0, x1), (y0, y1) = grid.view_box.viewRange()
        assert x0 < x + 0.5 < x1 and y0 < y + 0.5 < y1 and x1 - x0 < 100


def test_linked_stepping_by_progress_lands_on_the_expected_steps(comparing):
    c = comparing
    choose_preset(c, "supersample")
    c.link_box.setCurrentText("progress")
    lasts = [run.last for run in c.runs]
    top = max(lasts)
    assert c.transport.timeline.maximum() == top
    for position in (0, 1, top // 3, top // 2, top - 1, top):
        c.transport.timeline.setValue(position)  # as a drag of the slider does
        for pane, last in zip(c.view.panes, lasts):
            exact = Fraction(position * last, top)
            expected = int(exact + Fraction(1, 2))
            if last:  # the exact-coverage pane has one frame and no caption
                assert pane.message.text().startswith(f"Step {expected:,} of {last:,}")
    # By frame, a shorter run holds at its end.
    c.link_box.setCurrentText("frame")
    c.transport.timeline.setValue(top // 2)
    assert c.indices() == [min(top // 2, last) for last in lasts]
    # Step buttons move the shared position by one.
    c.transport.back_button.click()
    assert c.position == top // 2 - 1


def test_zoom_on_one_pane_moves_the_others(comparing, qtbot):
    c = comparing
    grids = c.view.grids()
    before = grids[0].view_box.viewRange()
    target = grids[1]
    centre = QPointF(target.viewport().rect().center())
    event = QWheelEvent(centre, QPointF(target.viewport().mapToGlobal(centre.toPoint())),
                        QPoint(0, 0), QPoint(0, 240), Qt.MouseButton.NoButton,
                        Qt.KeyboardModifier.NoModifier, Qt.ScrollPhase.NoScrollPhase, False)
    QApplication.sendEvent(target.viewport(), event)
    after = target.view_box.viewRange()
    assert after[0][1] - after[0][0] < 0.9 * (before[0][1] - before[0][0])  # zoomed in
    for grid in grids:
        (x0, x1), (y0, y1) = grid.view_box.viewRange()
        assert abs(x0 - after[0][0]) < 0.5 and abs(x1 - after[0][1]) < 0.5
        assert abs(y0 - after[1][0]) < 0.5 and abs(y1 - after[1][1]) < 0.5


def test_every_preset_opens_and_runs(comparing):
    c = comparing
    for k in range(c.preset_box.count()):
        key = c.preset_box.itemData(k)
        choose_preset(c, key)
        assert c.preset_key == key
        assert all(run.ok for run in c.runs), (key, [run.error for run in c.runs])
        assert len(c.view.panes) == len(c.panes) == len(c.runs)
        assert c.current_diff is not None and all(c.view.legend.counts[name].text()
                                                  for name in compare.DIFF_CLASSES)
        if key != WINDOW_KEY:
            assert c.pair == compare.preset(key).diff
        c.transport.firstRequested.emit()
        c.transport.forwardRequested.emit()
        assert c.position == min(1, c.last)


def test_a_pane_that_does_not_take_the_primitives_says_why(comparing):
    c = comparing
    header = c.view.panes[1].header
    header.algorithm.setCurrentIndex(header.algorithm.findData("circle-midpoint"))
    header.algorithm.activated.emit(header.algorithm.currentIndex())
    assert c.panes[1].algorithm == "circle-midpoint"
    message = c.view.panes[1].message.text()
    assert "takes 1 point" in message and "2 points" in message
    assert "No diff" in c.view.diff.message.text()
    assert c.view.legend.counts["only A"].text() == ""


def test_bad_options_are_refused_and_the_last_good_ones_kept(comparing):
    c = comparing
    edit = c.view.panes[1].header.options
    edit.setText("dtype=float32")
    edit.editingFinished.emit()
    assert c.panes[1].options == (("dtype", "float32"),)
    assert "dtype=float32" in c.view.panes[1].title.text()
    edit.setText("dtype=float16")
    edit.editingFinished.emit()
    assert c.panes[1].options == (("dtype", "float32"),)
    assert "float16" in c.view.panes[1].message.text()
    assert c.runs[1].ok


def test_two_to_four_panes_and_the_diff_pair(comparing):
    c = comparing
    choose_preset(c, "supersample")
    assert len(c.panes) == 3 and c.pair == (1, 2)
    c.add_button.click()
    assert len(c.view.panes) == 4 and not c.add_button.isEnabled()
    c.add_button.click()
    assert len(c.view.panes) == 4
    for _ in range(3):
        c.view.panes[0].header.remove.click()
    assert len(c.view.panes) == 2 and not c.view.panes[0].header.remove.isEnabled()
    assert sorted(c.pair) == [0, 1]
    # A pane is never diffed against itself: picking A's pane for B swaps the two.
    a, b = c.pair
    c.b_box.setCurrentIndex(a)
    c.b_box.activated.emit(a)
    assert c.pair == (b, a)
    assert (c.a_box.currentIndex(), c.b_box.currentIndex()) == (b, a)
    c.a_box.setCurrentIndex(a)
    c.a_box.activated.emit(a)
    assert c.pair == (a, b)


def test_the_panes_follow_the_main_window_points(window, comparing):
    c = comparing
    window.set_points([(2, 3), (30, 20)])
    assert c.runs[0].points == [(2, 3), (30, 20)]
    expected = diff_counts(bresenham_pixels((2, 3), (30, 20)),
                           dda_pixels((2, 3), (30, 20), FLOAT64_BITS), 32, 24)
    assert shown_counts(c) == expected


def test_reopening_catches_up_with_the_main_window(window, comparing, qtbot):
    c = comparing
    c.close()
    window.set_algorithm("line-dda")
    window.set_points([(1, 1), (25, 9)])
    window.set_y_down(True)
    window.compare_entry.action.trigger()
    assert window.compare_entry.window is c and c.isVisible()
    # The algorithm the main window shows now, against the one before it.
    assert [pane.algorithm for pane in c.panes] == ["line-dda", "line-bresenham"]
    assert all(run.points == [(1, 1), (25, 9)] for run in c.runs)
    assert all(grid.y_down for grid in c.view.grids())


def test_a_triangle_still_being_drawn_is_left_out(window, comparing):
    window.set_algorithm("triangle-bbox")
    triangle = [(2.0, 2.0), (20.0, 4.0), (9.0, 17.0)]
    window.set_points(triangle + [(25.0, 20.0)])  # a fourth point starts triangle 2
    comparing.apply_preset(WINDOW_KEY)
    assert comparing.runs[0].ok and comparing.runs[0].points == triangle


def test_play_runs_every_pane_to_its_end_and_stops(comparing, qtbot):
    c = comparing
    c.transport.set_speed(2000)
    c.transport.firstRequested.emit()
    assert c.position == 0
    c.transport.playRequested.emit()
    assert c.playing
    qtbot.waitUntil(lambda: not c.playing, timeout=WAIT_MS)
    assert c.position == c.last
    assert c.indices() == [run.last for run in c.runs]


@pytest.mark.parametrize("keys", [(Qt.Key.Key_Escape, Qt.KeyboardModifier.NoModifier),
                                  (Qt.Key.Key_W, Qt.KeyboardModifier.ControlModifier)])
def test_esc_and_ctrl_w_close_compare(comparing, qtbot, keys):
    from PySide6.QtTest import QTest
    c = comparing
    c.activateWindow()
    QTest.keyClick(c.view.grids()[0], *keys)
    qtbot.waitUntil(lambda: not c.isVisible(), timeout=WAIT_MS)


def test_n_zooms_to_the_next_difference(comparing, qtbot):
    from PySide6.QtTest import QTest
    c = comparing
    differing = set(bresenham_pixels(*DEMO_POINTS)) ^ set(dda_pixels(*DEMO_POINTS, FLOAT64_BITS))
    assert differing  # the oracles: the demo pair differs
    QTest.keyClick(c.view.grids()[0], Qt.Key.Key_N)
    qtbot.wait(20)
    for grid in c.view.grids():
        (x0, x1), (y0, y1) = grid.view_box.viewRange()
        # Zoomed in: under half the grid's width (the panes' shape sets the
        # height), around a differing cell.
        assert x1 - x0 < 16 or y1 - y0 < 12, (x0, x1, y0, y1)
        assert any(x0 < x + 0.5 < x1 and y0 < y + 0.5 < y1 for x, y in differing)


def test_the_dda_caption_counts_the_pixels_that_differ(comparing):
    c = comparing
    choose_preset(c, "dda-bresenham")
    a = set(bresenham_pixels(*DEMO_POINTS))
    b = set(dda_pixels(*DEMO_POINTS, FLOAT64_BITS))
    words = {1: "one pixel", 2: "two pixels"}
    assert len(a - b) in words  # the oracle's count, said in words by the caption
    assert f"differ in {words[len(a - b)]}" in c.description.text()
    assert "float64" in c.description.text()


def test_compare_opens_within_the_screen(comparing):
    room = comparing.screen().availableGeometry()
    assert comparing.frameGeometry().width() <= room.width()
    assert comparing.frameGeometry().height() <= room.height()


def test_compare_defaults_to_an_algorithm_of_the_same_family(window, qtbot):
    from algorithms.core import registry
    window.set_scene("triangle-bbox", [(2, 2), (20, 4), (10, 18)], None, (24, 20))
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    window.picker.setCurrentItem(window.picker.item_for("flood-fill"))  # as a person picks it
    qtbot.waitUntil(lambda: window.player.spec.name == "flood-fill", timeout=WAIT_MS)
    window.compare_entry.action.trigger()
    c = window.compare_entry.window
    families = {registry.get(pane.algorithm).family for pane in c.panes}
    assert families == {"fill"}, c.panes
