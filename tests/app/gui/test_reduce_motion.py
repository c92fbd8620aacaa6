"""Reduce motion (Preferences), and nothing playing on its own (WCAG 2.2.2)."""
import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QApplication

from app.gui import preferences as prefs_module
from app.gui.preferences import ANIMATED_EFFECTS, Preferences, PreferencesDialog, default_values
from app.model.shipped import scene_files


@pytest.fixture
def settings(tmp_path):
    return QSettings(str(tmp_path / "prefs.ini"), QSettings.Format.IniFormat)


@pytest.fixture
def system(monkeypatch):
    """``system(True)``: the system asks for reduced motion (read afresh)."""
    def says(reduced):
        monkeypatch.setattr(prefs_module, "reduce_motion", lambda: reduced)
        prefs_module.system_reduce_motion.cache_clear()
    yield says
    prefs_module.system_reduce_motion.cache_clear()


@pytest.mark.parametrize("reduced", [True, False])
def test_unset_it_follows_the_system(settings, system, reduced):
    system(reduced)
    assert Preferences(settings).get("reduce_motion") is reduced
    assert default_values()["reduce_motion"] is reduced


def test_a_stored_choice_wins_over_the_system(settings, system):
    system(True)
    prefs = Preferences(settings)
    prefs.set("reduce_motion", False)
    assert prefs.get("reduce_motion") is False


def test_a_damaged_value_falls_back_to_the_system(settings, system):
    system(True)
    settings.setValue("appearance/reduce_motion", "sometimes")
    assert Preferences(settings).get("reduce_motion") is True


def test_the_dialog_shows_and_returns_it(qtbot, system):
    system(False)
    dialog = PreferencesDialog()
    qtbot.addWidget(dialog)
    values = default_values()
    values["reduce_motion"] = True
    dialog.set_values(values)
    assert dialog.reduce_motion.isChecked()
    dialog.reduce_motion.setChecked(False)
    assert dialog.values()["reduce_motion"] is False


def test_reduce_motion_stops_the_animated_effects_and_docks(window):
    controller = window.preferences
    values = controller.prefs.values()
    try:
        controller.apply({**values, "reduce_motion": True})
        assert not window.isAnimated()
        assert not any(QApplication.isEffectEnabled(e) for e in ANIMATED_EFFECTS)
        controller.apply({**values, "reduce_motion": False})
        assert window.isAnimated()
    finally:
        controller.apply(values)


def test_no_shipped_scene_starts_playing_when_opened(make_window):
    window = make_window(files=True)
    opened = []
    for path in scene_files():
        assert window.file_actions.open_path(path, remember=False), path
        assert not window.player.playing, path.name
        opened.append(path.name)
    # The animated ones among them: temporal aliasing and motion blur.
    assert {"aa-temporal-accumulation.json", "aa-motion-blur-jittered.json"} <= set(opened)


def test_play_has_a_visible_pause_and_space_pauses(qtbot, window):
    window.activateWindow()
    window.player.seek(0)
    window.player.set_speed(2)  # long enough to need its pause
    from PySide6.QtTest import QTest
    QTest.keyClick(window, Qt.Key.Key_Space)
    assert window.player.playing
    button = window.transport.play_button
    assert button.isVisible() and "Pause" in button.toolTip()
    QTest.keyClick(window, Qt.Key.Key_Space)
    assert not window.player.playing
