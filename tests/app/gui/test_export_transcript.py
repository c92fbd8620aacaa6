"""The export dialog's transcript check box: on by default, reaching the
outputs, and a file in the transcript's place refused before any work."""
from __future__ import annotations

import pytest


@pytest.fixture(autouse=True)
def own_files(tmp_path, monkeypatch):
    monkeypatch.setenv("RASTERLAB_SETTINGS", str(tmp_path / "settings.ini"))
    monkeypatch.setenv("RASTERLAB_DATA_DIR", str(tmp_path / "data"))


def test_the_transcript_box_is_on_and_reaches_the_outputs(window, tmp_path):
    window.add_file_actions()
    controller = window.file_actions.export_animation()
    dialog = controller.dialog
    assert dialog.transcript.isChecked()
    dialog.set_values({"gif": str(tmp_path / "a.gif")})
    assert controller.export_settings()[1].transcript
    dialog.transcript.setChecked(False)
    assert not controller.export_settings()[1].transcript
    dialog.reject()


def test_a_file_in_the_transcripts_place_is_not_replaced(window, tmp_path):
    window.add_file_actions()
    controller = window.file_actions.export_animation()
    notes = tmp_path / "a.txt"
    notes.write_text("my own notes\n", encoding="utf-8")
    controller.dialog.set_values({"gif": str(tmp_path / "a.gif")})
    controller.start()
    assert controller.thread is None
    assert "not a transcript RasterLab wrote" in controller.dialog.message.text()
    assert notes.read_text(encoding="utf-8") == "my own notes\n"
    controller.dialog.reject()
