"""Pseudo-code panel, variables panel and transport bar."""
import numpy as np
import pyqtgraph as pg
import pytest
from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QFont

from widgets.code_panel import CodePanel
from widgets.panels import CURRENT_LINE, VariablesPanel
from widgets.transport import TransportBar
from tests.support.gui import WAIT_MS


def test_code_panel_marks_one_line(qtbot):
    panel = CodePanel()
    qtbot.addWidget(panel)
    panel.set_code(["first", "    second", "third"], notes=("A note.",))
    assert panel.lines.rowCount() == 3
    assert panel.lines.item(1, 1).text() == "    second"
    assert panel.notes.text() == "A note."
    panel.set_current(1)
    assert panel.current == 1
    assert panel.lines.item(1, 1).background().color() == CURRENT_LINE
    assert panel.lines.item(1, 0).text().startswith("\u25b6")
    panel.set_current(2)
    assert panel.lines.item(1, 1).background().style() == Qt.BrushStyle.NoBrush
    assert not panel.lines.item(1, 0).text().startswith("\u25b6")
    panel.set_current(None)
    assert panel.current is None
    panel.set_code(["only"], notes=())
    assert panel.lines.rowCount() == 1 and panel.notes_area.isHidden()


def test_variables_panel_rows_and_changes(qtbot):
    panel = VariablesPanel()
    qtbot.addWidget(panel)
    panel.set_rows([("d", "1"), ("x", "4")])
    assert panel.rows() == [("d", "1"), ("x", "4")]
    panel.set_rows([("d", "-23"), ("x", "4")])
    assert panel.table.item(0, 1).text() == "-23"
    assert panel.table.item(0, 1).font().bold()        # changed
    assert not panel.table.item(1, 1).font().bold()    # unchanged
    panel.set_rows([("d", "-23")])
    assert panel.table.rowCount() == 1
    # Packed colours read as #rrggbb, with a swatch.
    panel.set_rows([("rgb", "16744448"), ("d", "2")], color_names=("rgb",))
    assert panel.table.item(0, 1).text() == "#ff8000"
    assert panel.table.item(0, 1).data(Qt.ItemDataRole.DecorationRole).name() == "#ff8000"
    assert panel.table.item(1, 1).data(Qt.ItemDataRole.DecorationRole) is None


def test_variables_plot_shows_and_hides(qtbot):
    """Shown for a series with values, when the panel has room for it."""
    panel = VariablesPanel()
    qtbot.addWidget(panel)
    panel.resize(320, 520)  # room for the rows and the plot
    panel.show()
    panel.set_series(np.array([np.nan, 1.0, -3.0, 5.0]), "d", decision=True)
    assert panel.plot.isVisible() and panel.zero.isVisible()
    panel.set_marker(2)
    assert panel.marker.value() == 2
    assert panel.marker_point() == (2.0, -3.0)
    panel.set_marker(0)  # no value at the Start frame
    assert panel.marker_point() is None
    panel.set_series(np.array([np.nan, np.nan]), "x")
    assert not panel.plot.isVisible()
    panel.set_series(None)
    assert not panel.plot.isVisible()


def test_transport_bar_signals_and_counter(qtbot):
    bar = TransportBar()
    qtbot.addWidget(bar)
    bar.set_range(26)
    bar.set_position(13)
    assert bar.counter.text() == "step 13 / 26"
    assert bar.timeline.maximum() == 26 and bar.timeline.value() == 13
    for button, signal in ((bar.first_button, bar.firstRequested),
                           (bar.back_button, bar.backRequested),
                           (bar.play_button, bar.playRequested),
                           (bar.forward_button, bar.forwardRequested),
                           (bar.last_button, bar.lastRequested)):
        with qtbot.waitSignal(signal, timeout=WAIT_MS):
            qtbot.mouseClick(button, Qt.MouseButton.LeftButton)
    with qtbot.waitSignal(bar.seekRequested, timeout=WAIT_MS) as blocker:
        bar.timeline.setValue(20)
    assert blocker.args == [20]
    # Positions set from outside do not echo back as seek requests.
    with qtbot.assertNotEmitted(bar.seekRequested):
        bar.set_position(5)
    bar.set_range(-1)
    assert bar.counter.text() == "no run" and not bar.play_button.isEnabled()


class LayoutAsks(QObject):
    """Counts the layout requests a widget receives."""

    def __init__(self, widget):
        super().__init__()
        self.count = 0
        widget.installEventFilter(self)

    def eventFilter(self, obj, event):  # noqa: N802
        if event.type() == QEvent.Type.LayoutRequest:
            self.count += 1
        return False


def test_a_new_caption_lays_nothing_out_around_it(qtbot):
    # A label's new text asks its layout for room, up to the main window;
    # the caption's row keeps its height whatever the text.
    panel = VariablesPanel()
    qtbot.addWidget(panel)
    panel.resize(320, 420)
    panel.show()
    qtbot.waitExposed(panel)
    panel.set_caption("<b>Step 1</b> of 90")
    qtbot.wait(20)
    asks, height = LayoutAsks(panel), panel.caption_area.height()
    for k in range(2, 12):
        panel.set_caption(f"<b>Step {k}</b> of 90 · plots ({k}, 2) · branch <b>E</b>" * (k % 3))
        qtbot.wait(2)
    assert asks.count == 0 and panel.caption_area.height() == height
    assert panel.caption.text().startswith("<b>Step 11</b>")


@pytest.mark.parametrize("scale", [1.0, 2.5])
def test_the_caption_shows_two_lines_whole_in_any_type(qtbot, scale):
    panel = VariablesPanel()
    qtbot.addWidget(panel)
    font = QFont(panel.caption.font())
    font.setPointSizeF(font.pointSizeF() * scale)
    panel.caption.setFont(font)
    panel.setFont(font)  # as the window's zoom does
    panel.set_caption("<b>Step 12</b> of 90<br>plots (5, 3)")
    panel.resize(320, 420)
    panel.show()
    qtbot.waitExposed(panel)
    caption = panel.caption
    assert caption.heightForWidth(caption.width()) <= panel.caption_area.viewport().height()


def test_the_step_counter_lays_nothing_out(qtbot):
    bar = TransportBar()
    qtbot.addWidget(bar)
    bar.show()
    qtbot.waitExposed(bar)
    bar.set_range(20_450)
    qtbot.wait(20)
    asks = LayoutAsks(bar)
    for index in (0, 9, 10, 999, 1_000, 20_450):
        bar.set_position(index)
        qtbot.wait(2)
    assert asks.count == 0
    assert bar.counter.text() == "step 20,450 / 20,450"


@pytest.mark.parametrize("scale", [1.0, 2.5])
def test_the_step_counter_shows_its_longest_text_whole_in_any_type(qtbot, scale):
    bar = TransportBar()
    qtbot.addWidget(bar)
    bar.set_range(20_450)
    font = QFont(bar.font())
    font.setPointSizeF(font.pointSizeF() * scale)
    font.setBold(True)  # as the window's style sheet draws it
    bar.setFont(font)
    bar.set_position(20_448)
    hint = bar.counter.sizeHint()
    assert bar.counter.width() >= hint.width() and bar.counter.height() >= hint.height()


def test_transport_speed(qtbot):
    bar = TransportBar()
    qtbot.addWidget(bar)
    with qtbot.waitSignal(bar.speedChanged, timeout=WAIT_MS) as blocker:
        bar.speed_box.setValue(120)
    assert blocker.args == [120.0]
    # The logarithmic slider spans 1 .. 2000 steps a second.
    bar.speed_slider.setValue(bar.speed_slider.maximum())
    assert bar.speed == 2000
    bar.speed_slider.setValue(0)
    assert bar.speed == 1
    bar.set_speed(1e6)
    assert bar.speed == 2000


def _dots(panel):
    """(step, value, colour name) of each of the decision variable's dots, in drawing order."""
    return [(spot.pos().x(), spot.pos().y(), spot.brush().color().name())
            for spot in panel.dots.points()]


def test_a_long_decision_run_is_dots_coloured_by_branch(qtbot):
    from widgets.panels import BRANCH_COLORS, SERIES_DOTS, UNDECIDED_COLOR
    p = VariablesPanel()
    qtbot.addWidget(p)
    rng = np.random.default_rng(7)
    long = rng.integers(-30, 30, size=5000).astype(float)
    # Branches that do not follow the sign: the panel must show these.
    taken = rng.integers(-1, 2, size=5000).astype(np.int8)
    p.set_series(long, "d", decision=True, branches=(taken, ("E", "NE")))
    # No line: thousands of zigzags would fill the plot solid.
    assert p.curve.xData is None or len(p.curve.xData) == 0
    assert "E" in p.plot_title.text() and "NE" in p.plot_title.text()
    # The oracle: each dot stands on its step's value in its step's branch's colour.
    colour = {0: BRANCH_COLORS[0], 1: BRANCH_COLORS[1], -1: UNDECIDED_COLOR}
    dots = _dots(p)
    assert len(dots) > SERIES_DOTS and p.dots.isVisible()
    for x, y, name in dots:
        assert x == int(x) and y == long[int(x)] and name == colour[int(taken[int(x)])]
    assert {name for _x, _y, name in dots} == set(colour.values())
    # Where dots overlap, a branch's lie over those that decide nothing,
    # the second branch's over the first's (as drawn in that order).
    layer = {UNDECIDED_COLOR: 0, BRANCH_COLORS[0]: 1, BRANCH_COLORS[1]: 2}
    layers = [layer[name] for _x, _y, name in dots]
    assert layers == sorted(layers)
    # A short run keeps its line under the dots.
    p.set_series(long[:40], "d", decision=True, branches=(taken[:40], ("E", "NE")))
    assert len(p.curve.xData) == 40
    short = _dots(p)
    assert sorted(x for x, _y, _n in short) == list(range(40))
    assert sum(name == BRANCH_COLORS[0] for _x, _y, name in short) == int((taken[:40] == 0).sum())
    # A value that does not decide keeps its line however long the run, and no dots.
    p.set_series(np.cumsum(long), "x", decision=False)
    assert len(p.curve.xData) > SERIES_DOTS and not _dots(p) and not p.dots.isVisible()


def test_the_run_plot_is_a_bare_view_with_two_axes(qtbot):
    """No PlotItem (its options form and title cost start-up time), no
    menus, no buttons; the mouse pans along the steps only."""
    p = VariablesPanel()
    qtbot.addWidget(p)
    items = p.plot.scene().items()
    assert not [item for item in items if isinstance(item, (pg.PlotItem, pg.ButtonItem))]
    assert {id(a) for a in items if isinstance(a, pg.AxisItem)} == \
        {id(a) for a in p.plot_axes.values()}
    assert sorted(p.plot_axes) == ["bottom", "left"]
    for axis in p.plot_axes.values():
        assert axis.linkedView() is p.plot_view
        assert (axis.pen().color().name(), axis.textPen().color().name()) == ("#8a94a1", "#3d4754")
    assert p.plot_view.menu is None and not p.plot_view.menuEnabled()
    assert p.plot_view.mouseEnabled() == [True, False]
    assert p.curve.opts["autoDownsample"] and p.curve.opts["clipToView"]


def test_the_marked_line_wraps_whole_never_cut(qtbot):
    from PySide6.QtGui import QFontMetrics
    p = CodePanel()
    qtbot.addWidget(p)
    p.resize(400, 400)
    p.show()
    text = "if d <= 0:  d += incrE;  x += 1;  plot(x, y)"
    p.set_code(["start", text, "done"])
    table = p.lines
    narrow = QFontMetrics(table.font()).horizontalAdvance(text)
    numbers = table.columnWidth(0)
    # A column narrower than the line: it wraps, marked or not ...
    for _ in range(5):
        p.resize(p.width() + narrow * 2 // 3 - table.columnWidth(1), 400)
        qtbot.wait(10)
    p.set_current(0)
    qtbot.wait(20)
    one_line = table.rowHeight(0)
    # ... and marked, in bold, it keeps all of its text in view.
    p.set_current(1)
    qtbot.wait(20)
    item = table.item(1, 1)
    metrics = QFontMetrics(item.font())
    needed = metrics.boundingRect(0, 0, table.columnWidth(1) - 8, 10_000,
                                  int(Qt.TextFlag.TextWordWrap), text).height()
    assert item.font().bold() and needed > one_line  # two lines or more
    assert table.rowHeight(1) >= needed  # so the row grows: the end is kept
    # The numbers' column holds the marked number and keeps its width
    # from step to step (no re-measuring of every row).
    number_font = table.item(1, 0).font()
    assert QFontMetrics(number_font).horizontalAdvance(table.item(1, 0).text()) < numbers
    assert table.columnWidth(0) == numbers
    assert item.font().family() == table.font().family()  # the code's own type
    assert table.textElideMode() == Qt.TextElideMode.ElideNone


def test_stepping_between_lines_keeps_each_row_as_tall_as_its_text(qtbot):
    # Marked or not, each line is as tall as its text wraps at the column's width.
    from PySide6.QtGui import QFontMetrics
    p = CodePanel()
    qtbot.addWidget(p)
    p.show()
    texts = ["start", "if d <= 0:  d += incrE;  x += 1;  plot(x, y)",
             "else:  d += incrNE;  x += 1;  y += 1;  plot(x, y)", "done"]
    p.set_code(texts)
    table = p.lines

    def needed(row):
        """The text's wrapped height in its item's font, measured here."""
        item = table.item(row, 1)
        return QFontMetrics(item.font()).boundingRect(
            0, 0, table.columnWidth(1) - 8, 10_000, int(Qt.TextFlag.TextWordWrap),
            item.text()).height()

    for width in (260, 600, 260):  # wrapped, then one line each, then wrapped again
        p.resize(width, 400)
        qtbot.wait(20)
        for line in (1, 2, 1, 2, 0, 1):
            p.set_current(line)
            for row in range(len(texts)):
                assert needed(row) <= table.rowHeight(row) <= needed(row) + 12, (width, line, row)


def test_variables_panel_sets_only_the_cells_that_changed(qtbot):
    panel = VariablesPanel()
    qtbot.addWidget(panel)
    first = [("x", "4"), ("y", "2"), ("d", "-3")]
    panel.set_rows(first)
    panel.set_rows(first)
    touched = []
    panel.table.itemChanged.connect(lambda item: touched.append((item.row(), item.column())))
    panel.set_rows(first)
    assert touched == []  # the same rows: no cell is set again (none repaints)
    panel.set_rows([("x", "5"), ("y", "2"), ("d", "-3")])
    assert set(touched) == {(0, 1)} and panel.table.item(0, 1).font().bold()
    touched.clear()
    panel.set_rows([("x", "5"), ("y", "2"), ("d", "-3")])
    assert set(touched) == {(0, 1)}  # x no longer changed: back to plain type
    assert not panel.table.item(0, 1).font().bold()
    assert panel.rows() == [("x", "5"), ("y", "2"), ("d", "-3")]


def test_a_decision_of_three_branches_colours_each_and_names_each(qtbot):
    from widgets.panels import BRANCH_COLORS, UNDECIDED_COLOR
    p = VariablesPanel()
    qtbot.addWidget(p)
    values = np.arange(30, dtype=float) - 15
    taken = np.array([-1, 0, 1, 2] * 7 + [2, 0], dtype=np.int8)
    p.set_series(values, "count", decision=True, branches=(taken, ("reflex", "blocked", "ear")))
    colour = {-1: UNDECIDED_COLOR, 0: BRANCH_COLORS[0], 1: BRANCH_COLORS[1], 2: BRANCH_COLORS[2]}
    dots = _dots(p)
    assert sorted(x for x, _y, _n in dots) == list(range(30))
    for x, _y, name in dots:
        assert name == colour[int(taken[int(x)])]
    assert len(set(colour.values())) == 4  # four kinds, four colours
    # Colour is not the only cue: each kind has its own marker shape too,
    # and the title names each branch beside that shape (as text).
    shape = {-1: "o", 0: "s", 1: "t", 2: "d"}
    for spot in p.dots.points():
        assert spot.symbol() == shape[int(taken[int(spot.pos().x())])]
    title = p.plot_title.text()
    for k, (branch, glyph) in enumerate(zip(("reflex", "blocked", "ear"), "\u25a0\u25bc\u25c6")):
        assert f"color:{BRANCH_COLORS[k]}'>{glyph} {branch}</span>" in title
