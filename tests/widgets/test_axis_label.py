"""The axis of the grid view and the run plot sets its label's text only
when the label shows a text, and then as a pyqtgraph axis would."""
import pyqtgraph as pg
import pytest

from widgets.axes_frame import Axis


@pytest.fixture
def axes(qtbot):
    return Axis("left"), pg.AxisItem("left")


def label_text(axis) -> str:
    return axis.label.toPlainText().strip()


def test_a_label_set_shows_as_pyqtgraphs_does(axes):
    for axis in axes:
        axis.setLabel("value", units="px")
        axis.setRange(0, 4096)
    ours, theirs = axes
    assert label_text(ours) == label_text(theirs) == "value (kpx)"  # 4096 px: SI prefix
    assert ours.label.isVisible() == theirs.label.isVisible()


def test_a_label_shown_again_takes_the_text_set_while_hidden(axes):
    for axis in axes:
        axis.enableAutoSIPrefix(False)  # then showing does not set the label
        axis.setLabel("first")
        axis.showLabel(False)
        axis.setLabel("second")
        axis.showLabel(False)
        axis.setTextPen("#336699")
        axis.showLabel(True)
    ours, theirs = axes
    assert label_text(ours) == label_text(theirs) == "second"
    assert ours.label.toHtml().count("#336699") == theirs.label.toHtml().count("#336699") > 0


def test_no_label_no_text_set(qtbot, monkeypatch):
    calls = []
    axis = Axis("bottom")
    monkeypatch.setattr(axis.label, "setHtml", calls.append, raising=False)
    for k in range(20):
        axis.setRange(0, k + 1)
        axis.setTextPen("#%02x0000" % k)
    assert calls == []
    assert label_text(axis) == ""
