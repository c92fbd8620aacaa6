"""Every family in the window: drawing each kind of input with the mouse
and the keyboard, the panels that follow the step, the coverage overlay,
and inputs an algorithm refuses."""
import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from algorithms.core import registry
from algorithms.core.registry import format_value
from algorithms.core.steps import Span, Table, Vars
from app.render.compose import PALETTE, coverage_counts
from app.model.tables import cell_text
from tests.support.gui import drag, settle
from app.gui.window import MainWindow

LEFT = Qt.MouseButton.LeftButton
NONE = Qt.KeyboardModifier.NoModifier
SHIFT = Qt.KeyboardModifier.ShiftModifier
CTRL = Qt.KeyboardModifier.ControlModifier


@pytest.fixture
def open_window(qtbot):
    def make(algorithm):
        w = MainWindow(algorithm)
        qtbot.addWidget(w)
        w.show()
        qtbot.waitExposed(w)
        settle(qtbot, w)
        return w
    return make


def click(window, pos, modifier=NONE):
    grid = window.grid
    QTest.mouseClick(grid.viewport(), LEFT, modifier, grid.widget_pos_of(pos))


def double_click(window, pos):
    """As a real double-click arrives: press, release, double-click, release."""
    viewport, at = window.grid.viewport(), window.grid.widget_pos_of(pos)
    QTest.mouseClick(viewport, LEFT, NONE, at)
    QTest.mouseDClick(viewport, LEFT, NONE, at)
    QTest.mouseRelease(viewport, LEFT, NONE, at)


def key(window, which):
    QTest.keyClick(window.grid, which)


def expected(name, points, options=None, grid=(32, 24)):
    return registry.get(name).record(points, options or {}, grid)


def pixels_filled(trace, index):
    return int(trace.raster_at(index).counts.sum())


def pixels(trace):
    return trace.written_pixels().tolist()


# ------------------------------------------------------------------ circles
def test_circle_by_click_and_drag(open_window, qtbot):
    w = open_window("circle-midpoint")
    drag(qtbot, w, (10.5, 12.5), (16.5, 12.5))  # from an empty cell: centre, radius 6
    assert w.player.points == [(10, 12)] and w.player.options["radius"] == 6
    assert w.options.editor("radius").value() == 6
    assert pixels(w.player.trace) == pixels(expected("circle-midpoint", [(10, 12)],
                                                     {"radius": 6}))
    # The ideal circle follows.
    xs, ys = w.grid.primitive.getData()
    xs, ys = xs[np.isfinite(xs)], ys[np.isfinite(ys)]  # NaN separates paths
    assert np.allclose(np.hypot(xs - 10.5, ys - 12.5), 6)
    # The square rim handle changes the radius only.
    rim = w.grid.rim.data
    drag(qtbot, w, (rim["x"][0], rim["y"][0]), (10.5 + 3, 12.5 + 4))
    assert w.player.points == [(10, 12)] and w.player.options["radius"] == 5
    assert w.options.editor("radius").value() == 5
    w.undo()
    assert w.player.options["radius"] == 6


def test_ellipse_radii_from_the_drag_vector(open_window, qtbot):
    w = open_window("ellipse-midpoint")
    drag(qtbot, w, (8.5, 10.5), (15.5, 14.5))
    assert w.player.points == [(8, 10)]
    assert (w.player.options["rx"], w.player.options["ry"]) == (7, 4)
    drag(qtbot, w, (20.5, 10.5), (27.5, 14.5), SHIFT)  # Shift keeps them equal
    assert (w.player.options["rx"], w.player.options["ry"]) == (7, 7)


# ----------------------------------------------------------------- polygons
def test_polygon_with_a_hole_and_its_tables(open_window, qtbot):
    w = open_window("polygon-scanline")
    w.clear_points()
    assert "vertices" in w.message.text()
    outer = [(3, 3), (28, 3), (28, 21), (16, 12), (3, 21)]  # concave at (16, 12)
    for point in outer[:-1]:
        click(w, point)
    double_click(w, outer[-1])  # places the last vertex and closes the polygon
    assert not w.player.sketch.open
    hole = [(6, 5), (12, 5), (9.125, 9.25)]
    click(w, hole[0], SHIFT)  # Shift+click: a new contour
    click(w, hole[1])
    click(w, (9.13, 9.26), CTRL)  # Ctrl: to 1/256 px
    key(w, Qt.Key.Key_Return)
    assert w.player.points[:7] == [tuple(map(float, p)) for p in outer] + [(6.0, 5.0), (12.0, 5.0)]
    fine = w.player.points[7]  # as near as a screen pixel allows, on the 1/256 px grid
    assert all((v * 256).is_integer() and abs(v - t) < 0.1 for v, t in zip(fine, (9.13, 9.26)))
    assert w.player.breaks == (5,) and not w.player.sketch.open
    contours = w.player.input_points()
    assert len(contours) == 2
    trace = expected("polygon-scanline", contours)
    assert pixels(w.player.trace) == pixels(trace)
    # Every point is listed for editing by keyboard.
    assert w.points.row_count() == 8 and w.points.label_text(5) == "C2.P1"
    # Stepping: the tables panel shows the latest ET and AET at or before the step.
    assert w.tables_dock.isVisible()
    tables = trace.records_of(Table)
    aet_steps = [i for i, r in tables if r.name == "AET"]
    for index in (aet_steps[0], aet_steps[3] + 1, aet_steps[len(aet_steps) // 2]):
        w.transport.timeline.setValue(index)
        shown = {t.name: t for t in w.tables.tables()}
        for name in ("ET", "AET"):
            record = [r for i, r in tables if r.name == name and i <= index][-1]
            widget = w.tables.table_widget(name)
            assert widget.rowCount() == len(record.rows)
            for r, row in enumerate(record.rows):
                assert [widget.item(r, c).text() for c in range(len(row))] == \
                    [cell_text(v) for v in row]
        assert shown["AET"].fresh == (index in aet_steps)
    # A Span step is outlined as one box around its run.
    span_step = next(i for i, r in trace.records_of(Span) if r.x_end > r.x_start)
    w.transport.timeline.setValue(span_step)
    record = trace.record_at(span_step)
    assert w.grid.outlines.spans.tolist() == [[record.x_start, record.x_end, record.y]]


def test_backspace_and_a_refused_vertex(open_window, qtbot):
    w = open_window("polygon-convex")
    w.clear_points()
    for point in [(4, 4), (20, 4), (20, 18)]:
        click(w, point)
    good = list(w.player.points)
    click(w, (15, 10))  # would make it concave: refused, the last good run stays
    assert w.player.points == good and w.player.trace is not None
    assert "convex" in w.message.text()
    assert w.player.sketch.open  # still drawing the same contour
    click(w, (4, 18))
    assert len(w.player.points) == 4 and w.message.text() == ""
    key(w, Qt.Key.Key_Backspace)
    assert w.player.points == good


# --------------------------------------------------------------- flood fill
def test_flood_fill_outline_seed_and_stepping(open_window, qtbot):
    w = open_window("flood-fill")
    w.clear_points()
    outline = [(3, 3), (25, 4), (22, 20), (5, 18)]
    for x, y in outline:
        click(w, (x + 0.5, y + 0.5))
    key(w, Qt.Key.Key_Return)
    assert w.player.points == outline and w.player.options["seed"] == "auto"
    # The seed tool: a click places the seed, the option follows.
    QTest.keyClick(w, Qt.Key.Key_S)
    assert w.grid.tool == "marker"
    click(w, (12.5, 10.5))
    assert w.player.options["seed"] == (12, 10) and w.grid.marker_point == (12, 10)
    assert w.options.editor("seed").currentText() == "12,10"
    # A seed on the boundary is refused: the message says why, the seed stays.
    click(w, (3.5, 3.5))
    assert w.player.options["seed"] == (12, 10) and "boundary" in w.message.text()
    QTest.keyClick(w, Qt.Key.Key_S)
    assert w.grid.tool == "draw"
    trace = expected("flood-fill", [outline], {"seed": (12, 10)})
    assert pixels(w.player.trace) == pixels(trace)
    # Stepping through the fill: the stack's size and head read on one row each.
    index = 20 + min(i for i, r in trace.records_of(Vars) if "next" in r.values)
    w.player.first()
    for _ in range(index):
        w.player.forward()
    rows = dict(w.variables.rows())
    assert rows["size"] == format_value(trace.variables_at(index)["size"])
    assert rows["next"] == trace.variables_at(index)["next"]
    # The seed marker can be dragged too.
    drag(qtbot, w, (12.5, 10.5), (14.5, 9.5))
    assert w.player.options["seed"] == (14, 9)


# ---------------------------------------------------------------- triangles
def test_two_triangles_and_their_edge_values(open_window, qtbot):
    w = open_window("triangle-bbox")
    w.clear_points()
    for point in [(4, 4), (20, 5), (10, 18)]:
        click(w, point)
    assert w.player.trace is not None  # one whole triangle runs already
    click(w, (20, 5))  # on a vertex: the same point exactly
    assert "2 more points" in w.message.text()
    click(w, (26, 16))
    click(w, (10, 18))
    assert w.player.points == [(4.0, 4.0), (20.0, 5.0), (10.0, 18.0),
                               (20.0, 5.0), (26.0, 16.0), (10.0, 18.0)]
    assert [w.points.label_text(k) for k in range(6)][3:] == ["T2.P0", "T2.P1", "T2.P2"]
    trace = w.player.trace
    assert pixels(trace) == pixels(expected("triangle-bbox", w.player.points))
    # A test that fails one edge and one that passes all three.
    values = [trace.step(i).values for i in range(len(trace))]
    outside = next(i for i, v in enumerate(values)
                   if "e0" in v and min(v["e0"], v["e1"], v["e2"]) < 0 < max(v["e0"], v["e1"]))
    inside = next(i for i, v in enumerate(values)
                  if "e0" in v and min(v["e0"], v["e1"], v["e2"]) > 0)
    w.transport.timeline.setValue(outside)
    chips = w.variables.chip_texts()
    assert "outside" in chips and "not filled" in chips
    negative = next(n for n in ("e0", "e1", "e2") if values[outside][n] < 0)
    assert f"{negative} < 0" in chips
    # Vermillion and blue (Okabe-Ito), and the sign written: not colour alone.
    assert w.variables.value_color(negative).name() == "#d55e00"
    assert w.variables.value_text(negative).startswith("-")
    tested = sum(1 for i in range(outside + 1) if trace.step(i).kind in ("plot", "visit")
                 and trace.step(i).pixel is not None and trace.step(i).record is None)
    filled = pixels_filled(trace, outside)
    assert f"{tested:,} tested \u00b7 {filled:,} filled" in chips
    w.transport.timeline.setValue(inside)
    chips = w.variables.chip_texts()
    assert "inside" in chips and "filled" in chips
    assert w.variables.value_color("e0").name() == "#0072b2"
    assert w.variables.value_text("e0") == "+" + dict(w.variables.rows())["e0"]


@pytest.mark.parametrize("name", ["aa-supersample", "aa-adaptive"])
def test_four_clicks_make_one_triangle_and_a_point(open_window, name):
    """The antialiasing family reads its points three at a time (shape
    triangles): the fourth click starts a second triangle."""
    w = open_window(name)
    assert w.player.options["shape"] == "triangles"
    w.clear_points()
    corners = [(4, 4), (20, 5), (10, 18), (24, 8)]
    for point in corners:
        click(w, point)
    assert w.player.points == [tuple(float(v) for v in p) for p in corners]
    assert not w.message.styleSheet()  # no refusal
    assert "2 more points for triangle 2" in w.message.text()
    assert [w.points.label_text(k) for k in range(4)] == ["T1.P1", "T1.P2", "T1.P3", "T2.P1"]
    assert w.grid.labels()[:4] == ["T1.P1", "T1.P2", "T1.P3", "T2.P1"]
    # The run draws the one whole triangle: its exact coverage is not empty.
    assert w.player.trace is not None and not w.player.trace.truncated
    for point in [(30, 20), (14, 22)]:
        click(w, point)
    assert len(w.player.points) == 6 and "more point" not in w.message.text()
    assert w.points.label_text(5) == "T2.P3"
    w.set_option("shape", "thick-line")  # the same points read two at a time
    assert w.grid.labels()[:3] == ["S1.P1", "S1.P2", "S2.P1"]


def test_coverage_counts_overlaps_of_two_triangles(open_window, qtbot):
    w = open_window("triangle-scan")
    w.options.valueEdited.emit("fill_rule", "inclusive")
    # Two triangles sharing the edge x = 16.5, which runs through a column
    # of pixel centres.
    mesh = [(4.0, 4.0), (16.5, 3.5), (16.5, 20.5), (16.5, 3.5), (28.0, 12.0), (16.5, 20.5)]
    w.set_points(mesh)
    w.coverage.setChecked(True)
    assert w.coverage_action.isChecked() and w.coverage_legend.isVisibleTo(w)
    w.player.to_last()
    final = expected("triangle-scan", mesh, {"fill_rule": "inclusive"}).raster_at(-1)
    overlaps = int((final.counts >= 2).sum())
    assert overlaps > 0  # the shared edge's centres go to both triangles
    assert coverage_counts(final)[2] + coverage_counts(final)[3] == overlaps
    assert w.coverage_label.text().startswith(f"{overlaps:,} pixel")
    y, x = np.argwhere(final.counts == 2)[0]
    twice = int(PALETTE.coverage[2].lstrip("#"), 16)
    twice_rgb = [twice >> 16, (twice >> 8) & 255, twice & 255]
    assert w.grid.image.image[y, x, :3].tolist() == twice_rgb
    # Over the grid, the same cell is enlarged and striped "/" in the background colour.
    layer = w.coverage_display.patterns
    assert layer.isVisible()
    scale = layer.image.shape[0] // final.counts.shape[0]
    assert scale >= 4 and layer.image.shape[1] == final.counts.shape[1] * scale
    cell = layer.image[y * scale:(y + 1) * scale, x * scale:(x + 1) * scale, :3]
    ground = int(PALETTE.background.lstrip("#"), 16)
    assert cell[2, 2].tolist() == [ground >> 16, (ground >> 8) & 255, ground & 255]
    assert cell[2, 3].tolist() == twice_rgb
    # The top-left rule gives each shared pixel to one triangle only.
    w.options.valueEdited.emit("fill_rule", "top-left")
    assert w.coverage_label.text() == "No pixel covered twice"
    assert not layer.isVisible()
    w.options.valueEdited.emit("fill_rule", "inclusive")
    assert layer.isVisible()
    QTest.keyClick(w, Qt.Key.Key_C)
    assert not w.coverage.isChecked() and w.coverage_label.text() == ""
    assert not layer.isVisible()


def test_degenerate_triangle_note_in_the_status_bar(open_window):
    w = open_window("triangle-bbox")
    w.set_points([(2.0, 2.0), (10.0, 10.0), (18.0, 18.0)])
    assert w.player.trace is not None
    assert "no area" in w.message.text()


# ------------------------------------------------------------ all of them
def test_every_algorithm_can_be_selected_and_stepped(open_window):
    w = open_window("line-bresenham")
    def expected_mode(spec):
        # The drawing tool follows the shape of the inputs: one centre with
        # a radius is dragged out as a circle.
        names = {option.name for option in spec.options}
        if (spec.inputs.count == 1 and not spec.inputs.multiple
                and names & {"radius", "rx"}):
            return "circle"
        if spec.inputs.contours:
            return "contours"
        return "groups" if spec.inputs.multiple else "fixed"

    for spec in registry.all_specs():
        w.picker.setCurrentItem(w.picker.item_for(spec.name))
        player = w.player
        assert player.spec.name == spec.name, w.message.text()
        assert player.trace is not None, spec.name
        player.first()
        for _ in range(3):
            player.forward()
        player.step(10)
        player.to_last()
        has_tables = len(player.trace.steps_of(Table)) > 0
        assert w.tables_dock.isVisibleTo(w) == has_tables, spec.name
        assert w.transport.counter.text() == f"step {player.last:,} / {player.last:,}"
        assert w.grid.mode == expected_mode(spec), spec.name


def test_cracks_of_a_strict_mesh_are_outlined_with_coverage_on(open_window):
    # Two triangles sharing the edge (4, 4)-(12, 12): with the strict rule
    # the centres exactly on that diagonal belong to neither.
    w = open_window("triangle-bbox")
    w.set_points([(4, 4), (12, 4), (12, 12), (4, 4), (12, 12), (4, 12)])
    w.set_option("fill_rule", "strict")
    w.player.to_last()
    assert w.grid.outlines.layer("difference").size == 0 or not w.coverage.isChecked()
    w.coverage.setChecked(True)
    outlined = {tuple(c) for c in w.grid.outlines.layer("difference").tolist()}
    # Centres (i + 1/2, i + 1/2) on the diagonal from 4.5 to 11.5, worked out by hand.
    assert outlined == {(i, i) for i in range(4, 12)}
    assert "8 cracks outlined" in w.coverage_label.text()
    w.coverage.setChecked(False)
    assert "crack" not in w.coverage_label.text()
