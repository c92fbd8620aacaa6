"""The highlighted pseudo-code line stays in view: after every step, with
the pixel inspector open beside the code and a projector-sized window."""
import pytest

from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window(shown=True)


def marked_line_in_view(window) -> bool:
    table, line = window.code.lines, window.code.current
    top = table.rowViewportPosition(line)
    bottom = top + table.rowHeight(line)
    height = table.viewport().height()
    # The whole line when it fits; else at least its start.
    return top >= 0 and (bottom <= height or table.rowHeight(line) > height)


@pytest.mark.parametrize("algorithm", ["line-bresenham", "polygon-scanline"])
def test_the_marked_line_is_in_view_after_every_step(make_window, qtbot, algorithm):
    window = make_window(algorithm)
    window.resize(1280, 720)
    window.inspector.action.trigger()  # the inspector takes room from the code
    qtbot.waitUntil(lambda: window.inspector.dock.isVisible(), timeout=WAIT_MS)
    qtbot.wait(50)
    trace = window.player.trace
    steps = range(0, len(trace), max(1, len(trace) // 150))  # a lean walk through the run
    lines = set()
    for index in steps:
        window.player.seek(index)
        qtbot.wait(0)  # the view follows once the rows have their heights
        assert window.code.current == int(trace.line[index])
        assert marked_line_in_view(window), (index, window.code.current)
        lines.add(window.code.current)
    assert len(lines) > 3
    # Narrower and wider again: the rows re-wrap and the line stays in view.
    for width in (900, 1280):
        window.resize(width, 720)
        qtbot.waitUntil(lambda: marked_line_in_view(window), timeout=WAIT_MS)
