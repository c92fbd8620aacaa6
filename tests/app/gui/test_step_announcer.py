"""A person's step is said to assistive technology (and shown in the status
bar); playback and a new run are not; View > Describe step says it on
demand; without Qt's announcement event the status bar alone speaks."""
from __future__ import annotations

import pytest

from app.gui import step_announcer
from app.model.step_words import describe
from tests.support.gui import WAIT_MS

pytestmark = pytest.mark.window("line-bresenham", ((0, 0), (5, 2)), grid=(12, 8))


@pytest.fixture(autouse=True)
def own_files(tmp_path, monkeypatch):
    monkeypatch.setenv("RASTERLAB_SETTINGS", str(tmp_path / "settings.ini"))
    monkeypatch.setenv("RASTERLAB_DATA_DIR", str(tmp_path / "data"))


@pytest.fixture
def heard(window):
    said = []
    window.announcer.announced.connect(lambda text, how: said.append((text, how)))
    return said


def start_at(window, heard, qtbot, index: int) -> None:
    """Show step ``index`` (said, as a seek is), then forget what was said."""
    if window.player.index != index:
        window.player.seek(index)
        qtbot.waitUntil(lambda: len(heard) == 1, timeout=WAIT_MS)
    heard.clear()


def test_a_step_forward_is_announced_and_shown(window, heard, qtbot):
    start_at(window, heard, qtbot, 1)
    window.actions_["forward"].trigger()
    qtbot.waitUntil(lambda: len(heard) == 1, timeout=WAIT_MS)
    text, how = heard[0]
    # Bresenham from (0, 0) to (5, 2): d = 2dy - dx = -1 at the first decision.
    assert text == f"step 2 of {len(window.player.trace) - 1}: d = -1, at most 0, so E: plot (1, 0)"
    assert how == ("announcement" if step_announcer.EVENT is not None else "status")
    assert window.statusBar().currentMessage() == text


def test_home_end_and_a_drag_of_the_slider_are_each_said_once(window, heard, qtbot):
    last = len(window.player.trace) - 1
    start_at(window, heard, qtbot, 2)
    window.actions_["last"].trigger()
    qtbot.waitUntil(lambda: len(heard) == 1, timeout=WAIT_MS)
    assert heard[-1][0].startswith(f"step {last} of {last}:")
    for index in (1, 2, 3, 4):  # a drag passes through steps quickly
        window.transport.timeline.setValue(index)
    qtbot.waitUntil(lambda: len(heard) == 2, timeout=WAIT_MS)
    qtbot.wait(3 * step_announcer.SETTLE_MS)
    assert [text for text, _ in heard[1:]] == [describe(window.player.trace, 4)]


def test_playback_and_a_new_run_say_nothing(window, heard, qtbot):
    # Play from the last step goes back to step 0 first: that is playback too.
    start_at(window, heard, qtbot, len(window.player.trace) - 1)
    window.player.set_speed(200)
    window.player.toggle()
    qtbot.waitUntil(lambda: not window.player.playing, timeout=WAIT_MS)
    assert window.player.index == len(window.player.trace) - 1
    qtbot.wait(3 * step_announcer.SETTLE_MS)
    assert heard == []
    window.set_points([(0, 0), (7, 3)])
    qtbot.waitUntil(lambda: window.player.trace is not None
                    and window.player.points[1] == (7, 3), timeout=WAIT_MS)
    qtbot.wait(3 * step_announcer.SETTLE_MS)
    assert heard == []


def test_describe_step_says_the_step_on_demand_with_ctrl_d(window, heard):
    action = window.announcer.action
    assert action in window.menus["view"].actions()
    assert action.shortcut().toString() == "Ctrl+D"
    others = [a.text() for a in window.findChildren(type(action))
              if a is not action and a.shortcut().toString() == "Ctrl+D"]
    assert others == []
    window.player.seek(3)
    action.trigger()
    assert heard[-1][0] == f"step 3 of {len(window.player.trace) - 1}: d = 3, above 0, so NE: plot (2, 1)"


def test_without_the_announcement_event_the_status_bar_speaks(window, heard, monkeypatch):
    monkeypatch.setattr(step_announcer, "EVENT", None)
    window.player.seek(6)
    window.announcer.describe_now()
    text, how = heard[-1]
    assert how == "status"
    assert text.endswith("d = -5, at most 0, so E: plot (5, 2)")
    assert window.statusBar().currentMessage() == text


def test_the_numbers_setting_reaches_the_words(make_window):
    window = make_window("polygon-scanline", [[(1, 1), (8, 2), (5, 7)]], grid=(12, 10))
    window.numbers.set_numbers("exact")
    window.player.seek(7)
    text = window.announcer.describe_now()
    assert "crosses the edges at x = 4/3, 9/2; fill pixels 1 to 3 of row 1" in text
    window.numbers.set_numbers("decimal")
    assert "4/3 (1.3333)" in window.announcer.describe_now()
