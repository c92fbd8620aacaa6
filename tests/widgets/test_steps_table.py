"""The steps view tells its table's rows a block at a time and makes a row's
text only when asked."""
from PySide6.QtCore import Qt

from algorithms.core import registry
from app.model.steptable import StepTable
from widgets.steps_table import StepsView


def test_rows_are_told_a_block_at_a_time_and_made_on_demand(qtbot):
    trace = registry.get("line-implicit-infinite").record(((0, 0), (99, 37)), {}, grid=(100, 80))
    table = StepTable(trace)
    made = []
    original = table.text_row
    table.text_row = lambda i: made.append(i) or original(i)
    view = StepsView()
    qtbot.addWidget(view)
    view.set_table(table)
    model = view.model
    assert len(table) > 3 * model.BLOCK and model.fetched == model.BLOCK
    assert len(set(made)) <= 64  # the column widths' sample: the first and last rows
    view.follow(len(table) - 1)
    assert model.fetched == len(table) and model.current == len(table) - 1
    last = model.index(len(table) - 1, 3)
    assert model.data(last) == str(trace.step(len(table) - 1).pixel or "")
    assert model.data(last, Qt.ItemDataRole.BackgroundRole) is not None
    assert len(set(made)) < 200, "rows were made that nobody looked at"
