"""The window draws the same reasoning on its grid as an exported frame."""
import pytest

from algorithms.core.steps import Note, Span
from app.model.scene import load
from app.render.export import ExportSettings, FrameRenderer
from app.render.reasoning import step_guides
from tests.support import ROOT
from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window(shown=False)


def _show(qtbot, window, name):
    scene = load(ROOT / "resources" / "scenes" / f"{name}.json")
    window.set_scene(scene.algorithm, scene.points, scene.options, (scene.width, scene.height))
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    return scene


@pytest.mark.parametrize("y_down", [False, True])
def test_scan_line_guides_follow_the_step_in_both_origins(qtbot, window, y_down):
    scene = _show(qtbot, window, "polygon-star-evenodd")
    window.set_y_down(y_down)
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    trace = window.player.trace
    span_step = int(trace.steps_of(Span)[5])
    window.player.seek(span_step)
    qtbot.wait(10)
    shown = window.guides.item.guides
    row = trace.record_at(span_step).y
    assert ("scan" in {line[4] for line in shown.lines}
            and all(line[1] == row + 0.5 for line in shown.lines))
    assert "pair" in {line[4] for line in shown.lines}
    # The exporter draws the very same guides for the step.
    renderer = FrameRenderer(scene.replace(origin="top-left" if y_down else "bottom-left"),
                             ExportSettings(scale=4), trace)
    assert step_guides(trace, trace.state_at(span_step), renderer.ideal) == shown
    assert window.guides.item.label_texts() == [f"y + \u00bd = {row + 0.5:g}"]


def test_bresenham_shows_m_and_no_guides_without_a_run(qtbot, window):
    _show(qtbot, window, "demo-bresenham")
    trace = window.player.trace
    step = next(i for i in range(len(trace)) if len(trace.candidates_at(i)) == 2)
    window.player.seek(step)
    qtbot.wait(10)
    assert [role for _, _, role in window.guides.item.guides.dots] == ["midpoint"]
    window.guides.show(None, None)
    assert window.guides.item.guides is None


def test_the_left_out_note_leaves_the_status_line_once_the_scan_lines_start(qtbot, window):
    # Two horizontal edges: "2 edge(s) left out" while the edge table is
    # built, and not at every step after it.
    window.set_scene("polygon-scanline", [[(2, 2), (10, 2), (10, 8), (2, 8)]], None, (16, 12))
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    trace = window.player.trace
    note = int(trace.steps_of(Note)[0])
    window.player.seek(note)
    qtbot.wait(10)
    assert "left out" in window.message.text()
    window.player.seek(int(trace.steps_of(Span)[0]))
    qtbot.wait(10)
    assert "left out" not in window.message.text()


def test_the_label_at_m_follows_the_origin(qtbot, window):
    """The same step reads "line above M" with y up and "line below M"
    once the origin moves to the top-left (the picture flips)."""
    _show(qtbot, window, "demo-bresenham")
    trace = window.player.trace
    steps = [i for i in range(len(trace)) if len(trace.candidates_at(i)) == 2]
    step = next(i for i in steps if trace.step(i).branch == "NE")
    window.player.seek(step)
    qtbot.wait(10)
    (before,) = window.guides.item.label_texts()
    window.set_y_down(True)
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    window.player.seek(step)
    qtbot.wait(10)
    (after,) = window.guides.item.label_texts()
    words = {"above": "below", "below": "above", "left of": "right of", "right of": "left of"}
    side = next(word for word in words if f"line {word} M" in before)
    # Turned upside down, the diagonal step is drawn going down-right: SE.
    assert before.endswith(": NE") and after.endswith(": SE (code: NE)")
    assert after.removesuffix(": SE (code: NE)") == before.removesuffix(": NE").replace(
        f"line {side} M", f"line {words[side]} M")
