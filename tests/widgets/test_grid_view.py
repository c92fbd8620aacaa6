"""The pixel grid view: clicks, drags, origin, grid lines, highlights."""
import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from app.model.drawing import Move, Place, Tool, apply
from app.render.compose import OUTLINE_STYLE, PALETTE
from widgets.grid_items import MIN_CELL_PX, visible_grid_lines
from widgets.grid_view import PixelGridView
from tests.support.gui import WAIT_MS

LEFT = Qt.MouseButton.LeftButton
NONE = Qt.KeyboardModifier.NoModifier


@pytest.fixture
def view(qtbot):
    v = PixelGridView(PALETTE, OUTLINE_STYLE)
    qtbot.addWidget(v)
    v.resize(640, 480)
    v.show()
    qtbot.waitExposed(v)
    v.set_input(2, True, ("P", "Q"))
    # pyqtgraph fits the view to the widget's final size a moment later.
    where = []

    def still():
        where.append(v.widget_pos_of((0.0, 0.0)))
        return len(where) > 2 and where[-1] == where[-2] == where[-3]
    qtbot.waitUntil(still, timeout=WAIT_MS)
    return v


def edits(view, tool=Tool()):
    """Apply the view's gestures as the window does and give it the
    result back; returns the list of points after each gesture."""
    seen = []

    def gestured(gesture):
        sketch = apply(tool, view.sketch, gesture)
        view.set_points(sketch.points, sketch.breaks, sketch.open)
        seen.append(list(sketch.points))
    view.gestured.connect(gestured)
    return seen


def click(view, grid_pos):
    QTest.mouseClick(view.viewport(), LEFT, NONE, view.widget_pos_of(grid_pos))


def drag(view, start, end, steps=6):
    a, b = view.widget_pos_of(start), view.widget_pos_of(end)
    QTest.mousePress(view.viewport(), LEFT, NONE, a)
    for k in range(1, steps + 1):
        QTest.mouseMove(view.viewport(), a + (b - a) * (k / steps))
    QTest.mouseRelease(view.viewport(), LEFT, NONE, b)


def test_two_clicks_place_a_segment_and_a_third_starts_anew(view):
    gestures = []
    view.gestured.connect(gestures.append)
    edited = edits(view)
    click(view, (5.5, 3.5))
    click(view, (20.2, 10.9))  # anywhere inside pixel (20, 10)
    assert edited == [[(5, 3)], [(5, 3), (20, 10)]]
    assert gestures == [Place((5, 3)), Place((20, 10))]
    click(view, (1.5, 1.5))
    assert edited[-1] == [(1, 1)]
    assert view.points == [(1, 1)]


def test_the_view_shows_only_the_points_it_is_given(view):
    view.set_points([(5, 3), (20, 10)])
    gestures = []
    view.gestured.connect(gestures.append)
    click(view, (1.5, 1.5))
    assert gestures == [Place((1, 1))]
    assert view.points == [(5, 3), (20, 10)]  # nobody applied the gesture


def test_clicks_are_clamped_to_the_grid(view):
    view.set_grid(10, 8)
    edited = edits(view)
    click(view, (-0.6, 3.5))
    assert edited[-1] == [(0, 3)]


def test_dragging_a_handle_moves_its_point(view):
    view.set_points([(5, 3), (20, 10)])
    gestures = []
    view.gestured.connect(gestures.append)
    edited = edits(view)
    drag(view, (20.5, 10.5), (25.5, 12.5))
    assert edited and edited[-1] == [(5, 3), (25, 12)]
    assert gestures[-1] == Move(1, (25, 12))
    assert view.points == [(5, 3), (25, 12)]


def test_dragging_empty_space_pans_instead(view):
    view.set_points([(5, 3), (20, 10)])
    before = view.view_box.viewRect()
    edited = edits(view)
    drag(view, (12.5, 18.5), (8.5, 14.5))
    assert edited == []
    assert view.view_box.viewRect() != before


def test_y_down_origin_maps_clicks_in_that_frame(view):
    view.set_y_down(True)
    edited = edits(view)
    click(view, (3.5, 2.5))
    assert edited[-1] == [(3, 2)]
    # Pixel (3, 2) is near the top of the widget, pixel (3, 21) near the bottom.
    assert view.widget_pos_of((3.5, 2.5)).y() < view.widget_pos_of((3.5, 21.5)).y()
    view.set_y_down(False)
    assert view.widget_pos_of((3.5, 2.5)).y() > view.widget_pos_of((3.5, 21.5)).y()


def test_hover_reports_the_pixel_under_the_cursor(view, qtbot):
    seen = []
    view.hoverChanged.connect(seen.append)
    QTest.mouseMove(view.viewport(), view.widget_pos_of((7.3, 4.8)))
    qtbot.waitUntil(lambda: seen and seen[-1] == (7, 4), timeout=WAIT_MS)


def test_grid_lines_only_in_view_and_only_when_cells_are_large():
    # Zoomed out on a 4096 x 4096 grid: no lines at all.
    assert visible_grid_lines(0, 4096, 0, 4096, 4096, 4096, cell_px=0.2) is None
    # Zoomed in: only the few lines in view, whatever the grid's size.
    (xs, ys), span = visible_grid_lines(1000.2, 1040.7, 2000.5, 2030.1, 4096, 4096,
                                        cell_px=MIN_CELL_PX * 3)
    assert list(xs) == list(range(1001, 1041))
    assert list(ys) == list(range(2001, 2031))
    assert span == (1000.2, 1040.7, 2000.5, 2030.1)
    # The grid's own border is not an inner line.
    (xs, ys), _ = visible_grid_lines(-5, 50, -5, 50, 32, 24, cell_px=20)
    assert list(xs) == list(range(1, 32)) and list(ys) == list(range(1, 24))


def colours_at(view, grid_points):
    """The colours the view paints at these grid points (a fresh grab)."""
    picture = view.grab().toImage()
    return [picture.pixelColor(view.widget_pos_of(p)).name() for p in grid_points]


def test_image_and_outlines(view):
    image = np.zeros((24, 32, 4), np.uint8)
    image[..., 3] = 255
    image[4, 3] = (255, 0, 0, 255)  # row y, column x: cell (3, 4)
    view.set_image(image)
    assert view.image.image.shape == (24, 32, 4)
    # Inside a cell's left edge, where an outline is drawn, and its centre.
    edge_of_current, edge_of_difference = (3.03, 4.5), (1.03, 1.5)
    probes = [(3.5, 4.5), edge_of_current, edge_of_difference, (10.5, 10.5)]
    assert colours_at(view, probes) == ["#ff0000", "#ff0000", "#000000", "#000000"]
    view.set_highlights([(3, 4)], [(4, 4), (4, 5)])
    view.set_differences(np.array([[1, 1], [2, 2]]))
    assert view.outlines.layer("current").tolist() == [[3, 4]]
    assert view.outlines.layer("candidate").tolist() == [[4, 4], [4, 5]]
    assert view.outlines.layer("difference").tolist() == [[1, 1], [2, 2]]
    # The outlines are painted over the cells; the cells' insides keep their colour.
    assert colours_at(view, probes) == ["#ff0000", PALETTE.current, PALETTE.difference, "#000000"]
    # A new image of another size resizes the grid.
    view.set_image(np.zeros((10, 12, 4), np.uint8))
    assert view.grid_size == (12, 10)


def test_large_grid_paints(view):
    view.set_grid(4096, 4096)
    image = np.zeros((4096, 4096, 4), np.uint8)
    image[..., 3] = 255
    image[2015, 2020] = (0, 255, 0, 255)
    view.set_image(image)
    view.view_box.setRange(xRange=(2000, 2040), yRange=(2000, 2030), padding=0)
    assert colours_at(view, [(2020.5, 2015.5), (2010.5, 2010.5)]) == ["#00ff00", "#000000"]
    view.fit()
    # The whole grid in view: one cell is less than a screen pixel.
    assert colours_at(view, [(2048.5, 2048.5)]) == ["#000000"]


def drawn_ticks(view, name):
    """(label, viewport position) of every tick label the axis draws, and
    the viewport positions of its tick marks."""
    from PySide6.QtGui import QImage, QPainter
    axis = view.axes[name]
    image = QImage(10, 10, QImage.Format.Format_ARGB32)
    painter = QPainter(image)
    try:
        _line, ticks, texts = axis.generateDrawSpecs(painter)
    finally:
        painter.end()
    assert len(texts) >= 3
    labels = [(text, view.mapFromScene(axis.mapToScene(rect.center())))
              for rect, _flags, text in texts]
    marks = [view.mapFromScene(axis.mapToScene(start)) for _pen, start, _end in ticks]
    assert marks
    return labels, marks


def check_axes(view, qtbot, y_down, cells_labelled):
    """Tick marks stand at cell boundaries (whole coordinates); a label
    names the boundary k (pixel k just after it, pixel k - 1 just before)
    or, when cells hold their numbers, the cell under the label's centre."""
    qtbot.wait(100)  # pyqtgraph lays the axes out after the range settles
    middle = view.viewport().rect().center()
    cell = abs(view.widget_pos_of((1.0, 0.0)).x() - view.widget_pos_of((0.0, 0.0)).x())
    near = max(1, min(3, round(cell / 3)))
    checked = 0
    for name, index in (("bottom", 0), ("left", 1)):
        axis = view.axes[name]
        labels, marks = drawn_ticks(view, name)
        assert axis.index_labels == cells_labelled, name
        # Screen y grows downwards: with y up, larger y is higher on screen.
        growing = 1 if name == "bottom" or y_down else -1

        def pixel(along):
            point = _point(along, middle.y()) if name == "bottom" else _point(middle.x(), along)
            return view.pixel_at(view.mapToScene(point))[index]
        for mark in marks:
            value = view.view_box.mapSceneToView(view.mapToScene(mark))
            value = value.x() if name == "bottom" else value.y()
            # A whole coordinate, to within a screen pixel.
            assert abs(value - round(value)) * cell <= 1.0, (name, value)
            checked += 1
        for label, spot in labels:
            k = int(label)
            along = spot.x() if name == "bottom" else spot.y()
            if cells_labelled:
                assert pixel(along) == k, (name, label)
            elif 1 <= k < view.grid_size[index]:
                assert (pixel(along + near * growing), pixel(along - near * growing)) == (k, k - 1)
            checked += 1
    assert checked >= 8


@pytest.mark.parametrize("y_down", [False, True])
def test_axis_ticks_stand_at_cell_boundaries(view, qtbot, y_down):
    """A large grid: cells too small for their numbers, boundaries labelled."""
    view.set_grid(120, 90)
    view.set_y_down(y_down)
    view.fit()
    check_axes(view, qtbot, y_down, cells_labelled=False)


@pytest.mark.parametrize("y_down", [False, True])
def test_large_cells_are_labelled_by_index_at_their_centres(view, qtbot, y_down):
    """Zoomed in, each cell's number stands at its centre i + 1/2 and the
    ticks stay at the boundaries; zoomed out again, the boundaries are
    labelled once more."""
    view.set_y_down(y_down)
    view.view_box.setRange(xRange=(3, 13), yRange=(2, 10), padding=0)
    check_axes(view, qtbot, y_down, cells_labelled=True)
    labels, _marks = drawn_ticks(view, "bottom")
    assert {int(text) for text, _ in labels} >= set(range(4, 12))


def _point(x, y):
    from PySide6.QtCore import QPoint
    return QPoint(round(x), round(y))


def test_the_pointer_reports_its_real_coordinates(view, qtbot):
    seen = []
    view.pointerMoved.connect(seen.append)
    QTest.mouseMove(view.viewport(), view.widget_pos_of((7.25, 4.75)))
    qtbot.waitUntil(lambda: bool(seen) and seen[-1] is not None, timeout=WAIT_MS)
    x, y = seen[-1]
    assert abs(x - 7.25) < 0.1 and abs(y - 4.75) < 0.1


def test_a_picture_changed_in_place_repaints_only_its_cells(view, qtbot):
    from tests.support.gui import off_cell_edges, on_screen, repainted
    picture = np.full((24, 32, 4), 255, np.uint8)
    view.set_image(picture)
    qtbot.wait(20)
    handed = []
    original = view.image.setImage
    view.image.setImage = lambda *args, **kwargs: (handed.append(1), original(*args, **kwargs))
    picture[5:7, 10:13] = (200, 30, 30, 255)
    view.set_image(picture, changed=(10, 5, 13, 7))
    qtbot.wait(20)
    shown, whole = on_screen(view), repainted(view)
    red = (whole[..., 2] == 200) & (whole[..., 1] == 30)
    assert red.sum() >= 6 * MIN_CELL_PX ** 2  # six cells, each several pixels wide
    inside = off_cell_edges(view)
    assert np.array_equal(shown[inside], whole[inside])  # the screen shows them too
    assert not handed  # without handing the picture over again
    view.set_image(picture.copy())  # another array is handed over
    assert handed


def _plot_widget_as_before(view):
    """The oracle: a PlotWidget built as the grid view was before it left
    out the PlotItem, with the same axes, pens, colours, cells, size and range."""
    import pyqtgraph as pg
    from widgets.grid_items import PixelAxis
    plot = pg.PlotWidget(viewBox=pg.ViewBox(lockAspect=True, enableMenu=False),
                         axisItems={"bottom": PixelAxis("bottom"), "left": PixelAxis("left")})
    plot.setBackground(PALETTE.outside)
    item = plot.getPlotItem()
    item.hideButtons()
    item.setMenuEnabled(False)
    width, height = view.grid_size
    for name, count in (("bottom", width), ("left", height)):
        axis = item.getAxis(name)
        axis.setPen(pg.mkPen("#6b7785"))
        axis.setTextPen(pg.mkPen("#3d4754"))
        axis.set_cells(count, max(width, height))
    item.getViewBox().setBackgroundColor(PALETTE.outside)
    plot.resize(view.size())
    return plot


def test_the_grid_is_a_bare_view_box_with_two_pixel_axes(view, qtbot):
    """No PlotItem (its options form, title, two more axes and buttons
    cost start-up time), yet the same frame: the view box and its two
    axes where a PlotItem puts them, drawn the same."""
    import pyqtgraph as pg
    from PySide6.QtCore import QRect
    from widgets.grid_items import PixelAxis
    items = view.scene().items()
    assert not [i for i in items if isinstance(i, (pg.PlotItem, pg.ButtonItem, pg.LabelItem))]
    assert {id(a) for a in items if isinstance(a, pg.AxisItem)} == \
        {id(a) for a in view.axes.values()}
    for name, axis in view.axes.items():
        assert isinstance(axis, PixelAxis) and axis.orientation == name
        assert axis.linkedView() is view.view_box
        assert (axis.pen().color().name(), axis.textPen().color().name()) == ("#6b7785", "#3d4754")
    assert view.view_box.menu is None

    plot = _plot_widget_as_before(view)
    qtbot.addWidget(plot)
    plot.show()
    qtbot.waitExposed(plot)
    box = plot.getViewBox()
    (x0, x1), (y0, y1) = view.view_box.viewRange()
    box.setRange(xRange=(x0, x1), yRange=(y0, y1), padding=0)
    qtbot.waitUntil(lambda: box.sceneBoundingRect() == view.view_box.sceneBoundingRect()
                    and box.viewRange() == view.view_box.viewRange(), timeout=WAIT_MS)
    for name, axis in view.axes.items():
        assert axis.sceneBoundingRect() == plot.getPlotItem().getAxis(name).sceneBoundingRect()
    # The axes' strips, clear of the view box (whose contents differ), are
    # the same pictures.
    inner = view.view_box.sceneBoundingRect()
    left = int(inner.left())
    bottom = int(inner.bottom()) + 1
    strips = (QRect(0, 0, left, view.height()),
              QRect(0, bottom, view.width(), view.height() - bottom))
    for strip in strips:
        assert strip.width() > 10 and strip.height() > 10
        ours, theirs = view.grab(strip).toImage(), plot.grab(strip).toImage()
        assert ours == theirs
        # Something is drawn there: the axis line, ticks and labels.
        colours = {ours.pixelColor(x, y).name() for x in range(ours.width())
                   for y in range(0, ours.height(), 2)}
        assert len(colours) > 3
