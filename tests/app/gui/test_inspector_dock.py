"""The pixel inspector's dock in the window: hovering, pinning, unpinning."""
from fractions import Fraction

import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from tests.support.gui import WAIT_MS
from tests.support.inspector_oracles import GRID, TRIANGLE, assert_weight, edge_values, snapped

pytestmark = pytest.mark.window("triangle-bbox", TRIANGLE, grid=GRID, settled=True)


def test_hovering_and_pinning_fill_the_dock(window, qtbot):
    w = window
    assert w.inspector.action in w.menus["view"].actions()
    w.inspector.action.trigger()
    assert w.inspector.dock.isVisible()
    grid, panel = w.grid, w.inspector.panel
    es = edge_values(snapped(TRIANGLE), (5, 4))
    QTest.mouseMove(grid.viewport(), grid.widget_pos_of((5.5, 4.5)))
    qtbot.waitUntil(lambda: panel.rows().get("pixel", "").startswith("(5, 4) "), timeout=WAIT_MS)
    rows = panel.rows()
    assert [Fraction(rows[f"e{k}"].split()[0]) for k in range(3)] == es
    assert_weight(rows["alpha"], es[0] / sum(es))
    # Alt+click pins the pixel (and places no point): it stays while the
    # pointer moves and the step changes.
    points = list(w.player.points)
    QTest.mouseClick(grid.viewport(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.AltModifier,
                     grid.widget_pos_of((5.5, 4.5)))
    assert w.inspector.pinned == (5, 4)
    assert w.player.points == points
    QTest.mouseMove(grid.viewport(), grid.widget_pos_of((9.5, 6.5)))
    w.player.seek(0)
    rows = panel.rows()
    assert rows["pixel"].startswith("(5, 4) ") and rows["at step"].startswith("0 of")
    assert rows["visited"] == "never"
    assert panel.unpin.isVisible() and w.inspector.outline.isVisible()
    w.player.to_last()
    assert panel.rows()["plotted"].startswith("once")
    panel.unpin.click()
    assert w.inspector.pinned is None and not w.inspector.outline.isVisible()
    # The menu's "Inspect pixel" pins too; Esc lets go.
    grid.inspectRequested.emit((9, 6))
    assert panel.rows()["pixel"].startswith("(9, 6) ") and panel.unpin.isVisible()
    w.activateWindow()
    QTest.keyClick(w, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: w.inspector.pinned is None, timeout=WAIT_MS)
    # I pins the pixel under the pointer.
    QTest.mouseMove(grid.viewport(), grid.widget_pos_of((3.5, 2.5)))
    qtbot.waitUntil(lambda: w.inspector.hovered == (3, 2), timeout=WAIT_MS)
    QTest.keyClick(w, Qt.Key.Key_I)
    qtbot.waitUntil(lambda: w.inspector.pinned == (3, 2), timeout=WAIT_MS)
