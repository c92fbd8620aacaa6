"""The export dialog offers the step unit, the text size, axes and labels,
and says what a frame will stand for before anything is written."""
import pytest
from PIL import Image
from PySide6.QtCore import Qt

from algorithms.core.steps import Span
from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window(shown=False, files=True)


def test_a_frame_per_scan_line_from_the_dialog(window, qtbot, tmp_path):
    window.set_scene("polygon-scanline", [[(3, 4), (28, 6), (16, 20)]], None, (32, 24))
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    controller = window.file_actions.export_animation()
    dialog = controller.dialog
    target = tmp_path / "rows.gif"
    dialog.set_values({"gif": str(target), "scale": 4, "unit": "scanline", "text_size": 12,
                       "axes": True, "vertex_labels": True})
    settings = controller.export_settings()[0]
    assert (settings.unit, settings.text_size, settings.axes, settings.vertex_labels) == \
        ("scanline", 12, True, True)
    trace = window.player.trace
    rows = len({span.y for _, span in trace.records_of(Span) if span.x_end > span.x_start})
    # One frame per row that gets pixels, plus the set-up and the last step.
    assert f"{rows + 2} frames" in dialog.size_label.text()
    assert "scan line" in dialog.size_label.text()
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not controller.busy and not controller.dialog.running, timeout=20000)
    with Image.open(target) as image:
        assert image.n_frames <= rows + 2
