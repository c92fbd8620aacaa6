"""The tables panel and the choice of snapshots it shows."""
from fractions import Fraction

from PySide6.QtCore import Qt

from algorithms.core.steps import Table
from app.model.tables import TableIndex, cell_text, changes
from app.model.tables import ShownTable
from widgets.tables import CHANGED_ROW, TablesPanel


class FakeTrace:
    """The two Trace queries TableIndex uses, over {step: record}."""

    def __init__(self, records):
        self._records = records

    def records_of(self, kind):
        return [(i, r) for i, r in sorted(self._records.items()) if isinstance(r, kind)]

    def record_at(self, i):
        return self._records.get(i)


AET = ("edge", "ymax", "x")


def aet(index_rows):
    return Table(line=6, name="AET", columns=AET, rows=tuple(index_rows))


def test_snapshot_at_or_before_the_step_and_its_changes():
    et = Table(line=1, name="ET", columns=("ymin", "edge"), rows=((2, "P1P2"), (3, "P2P3")))
    first = aet((("P1P2", 9, Fraction(5, 2)),))
    second = aet((("P1P2", 9, Fraction(3)), ("P2P3", 9, Fraction(7, 3))))
    index = TableIndex(FakeTrace({2: et, 6: first, 12: second}))
    assert index.names == ["ET", "AET"]
    assert index.at(1) == []
    assert [t.name for t in index.at(5)] == ["ET"]
    shown = {t.name: t for t in index.at(9)}
    assert shown["AET"].step == 6 and not shown["AET"].fresh
    assert shown["AET"].rows == (("P1P2", "9", "2.5"),)
    assert shown["AET"].changed_rows == frozenset()  # the first snapshot: nothing to compare
    shown = {t.name: t for t in index.at(12)}["AET"]
    assert shown.fresh and shown.rows[1] == ("P2P3", "9", "\u22482.3333")
    # P1P2 moved on (its x changed); P2P3 is new.
    assert shown.changed_rows == {0, 1}
    assert shown.changed_cells == {(0, 2)}
    assert shown.tooltips[(1, 2)].startswith("7/3 = ")


def test_changes_without_a_key_column():
    before = Table(line=0, name="stack", columns=("x", "y"), rows=((1, 2), (3, 4)))
    after = Table(line=0, name="stack", columns=("x", "y"), rows=((1, 2), (5, 6)))
    assert changes(after, before) == ({1}, set())


def test_cell_text():
    assert cell_text(Fraction(37, 16)) == "2.3125"
    assert cell_text(Fraction(6, 3)) == "2"
    assert cell_text(Fraction(-95, 3)) == "\u2248-31.667"
    assert cell_text(2.5) == "2.5" and cell_text("left") == "left"


def test_panel_shows_rows_and_highlights(qtbot):
    panel = TablesPanel()
    qtbot.addWidget(panel)
    table = ShownTable("AET", AET, (("a", "9", "2"), ("b", "9", "3")), 12, True,
                       frozenset({1}), frozenset({(1, 2)}))
    panel.set_tables([table])
    widget = panel.table_widget("AET")
    assert widget.rowCount() == 2 and widget.columnCount() == 3
    assert widget.horizontalHeaderItem(0).text() == "edge"
    assert widget.item(1, 2).text() == "3"
    assert widget.item(1, 0).background().color() == CHANGED_ROW
    # A changed row's text is dark on its light ground, whatever the theme's text colour.
    text = widget.item(1, 0).foreground()
    assert text.style() == Qt.BrushStyle.SolidPattern   # set, not the theme's
    assert text.color().lightnessF() < 0.3 < CHANGED_ROW.lightnessF()
    assert widget.item(0, 0).foreground().style() == Qt.BrushStyle.NoBrush
    assert widget.item(0, 0).background().style() == Qt.BrushStyle.NoBrush
    assert widget.item(1, 2).font().bold() and not widget.item(1, 1).font().bold()
    panel.set_side_by_side(True)
    panel.set_tables([])
    assert panel.tables() == [] and "No table" in panel.caption.text()
