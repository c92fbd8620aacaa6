"""The vertex table: exact typed coordinates, per-vertex colour, z and w,
refusals, keyboard editing, rows, and staying in step with the grid."""
from fractions import Fraction

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QColorDialog

from app.gui.window import MainWindow
from widgets.vertex_table import VertexTable
from tests.support.gui import WAIT_MS

LEFT = Qt.MouseButton.LeftButton
NONE = Qt.KeyboardModifier.NoModifier


@pytest.fixture
def make(qtbot):
    def build(algorithm):
        w = MainWindow(algorithm)
        qtbot.addWidget(w)
        w.show()
        qtbot.waitExposed(w)
        return w
    return build


def set_triangles(w, points):
    """Start from these vertices (typed into an emptied table, row by row)."""
    w.clear_points()
    table = w.points
    for x, y in points:
        table.add_row()
        row = len(w.player.points) - 1
        assert table.type_value(row, "x", str(x)) or w.player.points[row][0] == x
        assert table.type_value(row, "y", str(y)) or w.player.points[row][1] == y
    assert w.player.points == [(float(x), float(y)) for x, y in points]


# ------------------------------------------------------------ the widget
def test_widget_emits_typed_values_exactly(qtbot):
    table = VertexTable()
    qtbot.addWidget(table)
    table.set_input(3, (), False, open_ended=True, group_size=3)
    table.set_grid(32, 24)
    table.set_points([(1.0, 2.0), (9.5, 3.0), (4.0, 11.0)], ["P0", "P1", "P2"])
    table.set_attributes(["colors", "z", "w"], {"z": (0.5, 0.25, 1.0)})
    with qtbot.waitSignal(table.edited, timeout=WAIT_MS) as blocker:
        assert table.type_value(1, "x", " 3.00390625 ")
    points, breaks, values = blocker.args
    assert points[1] == (float(Fraction("3.00390625")), 3.0) and breaks == ()
    assert values["z"] == (0.5, 0.25, 1.0)
    # A first colour gives the others their defaults: one colour per vertex.
    with qtbot.waitSignal(table.edited, timeout=WAIT_MS) as blocker:
        assert table.type_value(2, "colors", "#A0B0C0")
    colors = blocker.args[2]["colors"]
    assert len(colors) == 3 and colors[2] == "#a0b0c0"
    assert table.cell_text(0, "z") == "0.5" and table.cell_text(0, "w") == ""


@pytest.mark.parametrize("column, text, words", [
    ("x", "abc", "not a number"),
    ("x", "nan", "not a finite number"),
    ("y", "inf", "not a finite number"),
    ("x", "-0.5", "outside the grid"),
    ("y", "24.01", "outside the grid"),
    ("w", "0", "greater than 0"),
    ("w", "-2", "greater than 0"),
    ("z", "1e400", "not a finite number"),
    ("colors", "red", "#rrggbb"),
    ("colors", "#12345", "#rrggbb"),
])
def test_widget_refuses_bad_text(qtbot, column, text, words):
    table = VertexTable()
    qtbot.addWidget(table)
    table.set_input(3, (), False, open_ended=True, group_size=3)
    table.set_grid(32, 24)
    table.set_points([(1.0, 2.0), (9.5, 3.0), (4.0, 11.0)])
    table.set_attributes(["colors", "z", "w"], {})
    with qtbot.assertNotEmitted(table.edited):
        with qtbot.waitSignal(table.refused, timeout=WAIT_MS) as blocker:
            assert not table.type_value(0, column, text)
    assert words in blocker.args[0]
    assert words in table.message.text() and not table.message.isHidden()


def test_whole_pixel_algorithms_take_whole_numbers(make):
    w = make("line-bresenham")
    before = w.player.scene
    assert not w.points.type_value(1, "x", "7.5")
    assert "whole" in w.message.text() and w.player.scene == before
    assert not w.points.type_value(1, "x", "32")  # the grid is 32 wide: 0 .. 31
    assert "outside the grid" in w.message.text() and w.player.scene == before
    assert w.points.type_value(1, "x", "31")
    assert w.player.points[1] == (31, 15) and isinstance(w.player.points[1][0], int)


# ---------------------------------------------------------- in the window
def test_typed_values_become_the_points_exactly(make):
    w = make("triangle-bbox")
    typed = ("3.00390625", "17.125", "0.1")
    for row, text in enumerate(typed):
        assert w.points.type_value(row, "x", text)
    assert [p[0] for p in w.player.points[:3]] == [float(Fraction(t)) for t in typed]
    assert [w.points.cell_text(row, "x") for row in range(3)] == list(typed)
    # The run gets them as typed (it snaps to 1/256 px itself).
    assert w.player.trace.start is not None and w.grid.points[:3] == w.player.points[:3]


def test_bad_values_leave_the_scene_unchanged_with_a_message(make):
    w = make("triangle-perspective")
    before, pixels = w.player.scene, w.player.trace.written_pixels().tolist()
    for column, text in (("x", "twelve"), ("y", "-1"), ("w", "0"), ("z", "nan")):
        assert not w.points.type_value(0, column, text)
        assert w.player.scene == before
        assert w.points.message.text() and w.message.text() == w.points.message.text()
    assert w.player.trace.written_pixels().tolist() == pixels
    assert not w.history.can_undo


def packed(hex_colour):
    return int(hex_colour[1:], 16)


def test_colour_and_depth_reach_the_z_buffer(make):
    w = make("zbuffer")
    near_first = [(2, 2), (20, 2), (2, 20), (4, 4), (24, 4), (4, 22)]
    set_triangles(w, near_first)
    table = w.points
    for row in range(6):
        assert table.type_value(row, "colors", "#ff0000" if row < 3 else "#0000ff")
        assert table.type_value(row, "z", "0.2" if row < 3 else "0.6")
    assert w.player.options["z"] == (0.2, 0.2, 0.2, 0.6, 0.6, 0.6)
    colours = w.player.final_raster().colors
    # Pixel (6, 6): its centre is inside both; the nearer (smaller z) wins.
    assert colours[6, 6] == packed("#ff0000")
    assert colours[19, 5] == packed("#0000ff")  # the second triangle only
    for row in range(3, 6):
        assert table.type_value(row, "z", "0.1")
    assert w.player.final_raster().colors[6, 6] == packed("#0000ff")
    w.undo()  # the last z typed: the second triangle is partly far again
    w.undo()
    w.undo()
    assert w.player.final_raster().colors[6, 6] == packed("#ff0000")


def test_w_reaches_the_perspective_run(make):
    w = make("triangle-bbox")
    vertices = [(2, 2), (28, 2), (2, 22)]
    set_triangles(w, vertices)
    table = w.points
    colours = ("#ff0000", "#00ff00", "#0000ff")
    for row, colour in enumerate(colours):
        assert table.type_value(row, "colors", colour)
    ws = (1, 4, 1)
    for row, value in enumerate(ws):
        assert table.type_value(row, "w", str(value))
    w.options.editor("perspective").setChecked(True)
    assert w.player.options["perspective"] is True and w.player.options["w"] == (1.0, 4.0, 1.0)
    x, y = 10, 6
    got = int(w.player.final_raster().colors[y, x])
    # The oracle: barycentric weights of the pixel centre in exact fractions,
    # divided by w and normalised, then each channel rounded.
    (ax, ay), (bx, by), (cx, cy) = vertices
    px, py = Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2)
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    alpha = ((bx - px) * (cy - py) - (by - py) * (cx - px)) / area
    beta = ((cx - px) * (ay - py) - (cy - py) * (ax - px)) / area
    gamma = 1 - alpha - beta
    over = [alpha / ws[0], beta / ws[1], gamma / ws[2]]
    weights = [v / sum(over) for v in over]
    channels = [sum(wk * ((packed(c) >> shift) & 255) for wk, c in zip(weights, colours))
                for shift in (16, 8, 0)]
    want = [int(c + Fraction(1, 2)) for c in channels]
    have = [(got >> shift) & 255 for shift in (16, 8, 0)]
    assert all(abs(a - b) <= 1 for a, b in zip(have, want)), (have, want)
    # Screen-space shading would give the green vertex (w = 4) more weight.
    assert have[1] < round(255 * float(beta)) - 10


def test_keyboard_typing_tab_and_enter(make, qtbot):
    w = make("triangle-bbox")
    view = w.points.view
    view.setFocus()
    view.setCurrentIndex(w.points.model.index(0, 0))
    qtbot.waitUntil(lambda: QApplication.focusWidget() is view, timeout=WAIT_MS)
    QTest.keyClick(view, Qt.Key.Key_6)  # typing replaces the value
    QTest.keyClicks(QApplication.focusWidget(), ".25")
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Tab)
    assert w.player.points[0][0] == 6.25
    assert view.currentIndex().column() == 1
    QTest.keyClicks(QApplication.focusWidget(), "7.5")
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Return)
    assert w.player.points[0] == (6.25, 7.5)
    assert (view.currentIndex().row(), view.currentIndex().column()) != (0, 1)
    # Ctrl+Z, with the table's focus and no cell being edited, undoes.
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Escape)
    view.setFocus()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is view, timeout=WAIT_MS)
    QTest.keyClick(view, Qt.Key.Key_Z, Qt.KeyboardModifier.ControlModifier)
    assert w.player.points[0][1] != 7.5 and w.player.points[0][0] == 6.25


def test_rows_added_and_removed_with_insert_and_delete(make, qtbot):
    w = make("polygon-scanline")
    points, breaks = list(w.player.points), w.player.breaks
    view = w.points.view
    view.setFocus()
    view.setCurrentIndex(w.points.model.index(1, 0))
    qtbot.waitUntil(lambda: QApplication.focusWidget() is view, timeout=WAIT_MS)
    QTest.keyClick(view, Qt.Key.Key_Insert)
    assert len(w.player.points) == len(points) + 1
    assert w.player.points[:2] == points[:2] and w.player.points[3:] == points[2:]
    assert w.points.row_count() == len(points) + 1
    view.setCurrentIndex(w.points.model.index(2, 0))
    QTest.keyClick(view, Qt.Key.Key_Delete)
    assert w.player.points == points and w.player.breaks == breaks
    assert w.actions_["undo"].text() == "&Undo remove point"


def test_contours_are_grouped(make):
    w = make("polygon-scanline")
    outer = [(3, 3), (28, 3), (28, 21), (3, 21)]
    hole = [(10, 8), (20, 8), (15, 16)]
    w.set_scene("polygon-scanline", [outer, hole])
    table = w.points
    assert [table.label_text(k) for k in (0, 4, 6)] == ["C1.P1", "C2.P1", "C2.P3"]
    tint = Qt.ItemDataRole.BackgroundRole
    model = table.model
    assert model.data(model.index(0, 0), tint) is None
    assert model.data(model.index(4, 0), tint) is not None
    # Removing a vertex of the outer contour keeps the hole a hole.
    table.view.setCurrentIndex(model.index(1, 0))
    table.remove_row()
    assert w.player.breaks == (3,) and w.player.points[3:] == [(10, 8), (20, 8), (15, 16)]


def test_table_follows_a_drag_on_the_grid(make, qtbot):
    w = make("line-bresenham")
    viewport = w.grid.viewport()
    a, b = w.grid.widget_pos_of((28.5, 15.5)), w.grid.widget_pos_of((22.5, 9.5))
    QTest.mousePress(viewport, LEFT, NONE, a)
    for k in range(1, 5):
        QTest.mouseMove(viewport, a + (b - a) * (k / 4))
        qtbot.wait(15)
    QTest.mouseRelease(viewport, LEFT, NONE, b)
    assert w.player.points[1] == (22, 9)
    assert (w.points.cell_text(1, "x"), w.points.cell_text(1, "y")) == ("22", "9")


def test_double_click_on_a_colour_opens_the_dialog(make, monkeypatch):
    w = make("line-bresenham")
    monkeypatch.setattr(QColorDialog, "getColor",
                        staticmethod(lambda *args, **kwargs: QColor("#123456")))
    assert w.points.column_names() == ["x", "y", "colors"]
    model, view = w.points.model, w.points.view
    index = model.index(1, 2)
    view.edit(index, view.EditTrigger.DoubleClicked, None)
    assert w.player.options["colors"][1] == "#123456"
    assert w.points.cell_text(1, "colors") == "#123456"
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) == QColor("#123456")


def test_every_control_has_a_tooltip(make):
    w = make("triangle-perspective")
    table = w.points
    assert table.view.toolTip() and table.add_button.toolTip() and table.remove_button.toolTip()
    model = table.model
    for column in range(model.columnCount()):
        assert model.headerData(column, Qt.Orientation.Horizontal, Qt.ItemDataRole.ToolTipRole)
