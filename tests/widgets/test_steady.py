"""Labels that change with every step (the step's caption, the step
counter) repaint themselves without laying out the window again."""
from PySide6.QtCore import QEvent, QObject

from widgets.panels import VariablesPanel
from widgets.transport import TransportBar
from tests.support.gui import WAIT_MS


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


def _shown_panel(qtbot) -> VariablesPanel:
    """A variables panel on screen with a one-line caption, settled."""
    panel = VariablesPanel()
    qtbot.addWidget(panel)
    panel.resize(320, 420)
    panel.show()
    qtbot.waitExposed(panel)
    panel.set_caption("<b>Step 1</b> of 90 · plots (1, 2)")
    qtbot.wait(20)
    return panel


def test_a_caption_of_the_same_height_lays_nothing_out_a_taller_one_does(qtbot):
    panel = _shown_panel(qtbot)
    asks = LayoutAsks(panel)
    for k in range(2, 12):
        panel.set_caption(f"<b>Step {k}</b> of 90 · plots ({k}, 2) · branch <b>E</b>")
        qtbot.wait(2)
    assert asks.count == 0
    assert panel.caption.text().startswith("<b>Step 11</b>")
    one_line = panel.caption.height()
    panel.set_caption("<b>Step 12</b> of 90 · " + " · ".join(["updates variables"] * 8))
    qtbot.waitUntil(lambda: panel.caption.height() > one_line, timeout=WAIT_MS)
    assert asks.count > 0
    # All of it in view: as tall as its text needs at its width.
    assert panel.caption.height() >= panel.caption.heightForWidth(panel.caption.width())


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
    assert bar.counter.width() >= bar.counter.sizeHint().width()  # the whole text shows


def test_a_new_style_sheet_gives_the_caption_the_room_it_asks(qtbot):
    panel = _shown_panel(qtbot)
    before = panel.caption.height()
    panel.setStyleSheet("QLabel#stepCaption { padding: 20px 0 20px 0; }")
    qtbot.waitUntil(lambda: panel.caption.height() >= before + 40, timeout=WAIT_MS)
