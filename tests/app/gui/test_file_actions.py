"""Scene files and the export dialog, through the window's File menu."""
import json
import time
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QApplication, QFileDialog, QMessageBox

from app.render import export as ex
from app.gui import file_actions as fa
from app.model import scene as scenes
from app.gui.window import MainWindow
from tests.support import ROOT
from tests.support.gui import WAIT_MS

SCENES = ROOT / "resources" / "scenes"


@pytest.fixture
def settings(tmp_path):
    return QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)


pytestmark = pytest.mark.window(shown=False)


@pytest.fixture
def files(window, settings):
    return window.add_file_actions(settings)


@pytest.fixture
def messages(monkeypatch):
    """Message boxes are recorded instead of shown."""
    shown = []

    def shown_as(kind):
        def show(parent, title, text, *args, **kwargs):
            shown.append((kind, title, text))
            return QMessageBox.StandardButton.Ok
        return show

    monkeypatch.setattr(QMessageBox, "warning", shown_as("warning"))
    monkeypatch.setattr(QMessageBox, "information", shown_as("information"))
    return shown


def scene_of(window):
    player = window.player
    return (player.spec.name, player.input_points(), dict(player.options), player.grid,
            window.grid.y_down)


# -------------------------------------------------------------------- menu
def test_the_file_menu_holds_the_actions(window, files):
    menu = fa._file_menu(window)
    texts = [a.text() for a in menu.actions() if not a.isSeparator()]
    assert texts == ["&Open\u2026", "Open &Recent", "Open &Example", "&Save", "Save &As\u2026",
                     "&Export Animation\u2026", "Export Interactive &Page\u2026",
                     "Save algorithm &template\u2026", "Open &algorithm\u2026",
                     "Export &worksheet\u2026", "Export q&uestions\u2026", "&Quit"]
    assert files.export_action.shortcut().toString() == "Ctrl+E"
    assert files.open_action.shortcut().toString() == "Ctrl+O"
    assert files.save_action.shortcut().toString() == "Ctrl+S"
    assert window.file_actions is files
    assert not files.recent_menu.isEnabled()  # nothing opened yet


# ------------------------------------------------------------ round trips
def test_a_scene_survives_save_and_open(window, files, tmp_path, messages):
    window.set_scene("circle-midpoint", [(12, 10)], {"radius": 7}, (24, 20))
    window.set_y_down(True)
    window.player.seek(5)
    saved = scene_of(window)
    path = tmp_path / "circle.json"
    assert files.save_to(path)
    data = json.loads(path.read_text())
    assert data["algorithm"] == "circle-midpoint" and data["origin"] == "top-left"
    assert data["options"]["radius"] == 7 and data["view"]["step"] == 5

    window.set_scene("line-dda", [(1, 1), (5, 3)], None, (16, 12))
    window.set_y_down(False)
    assert scene_of(window) != saved
    assert files.open_path(path)
    assert scene_of(window) == saved
    assert window.player.index == 5
    assert files.path == path and files.recent() == [str(path.resolve())]
    assert messages == []


def test_polygons_with_holes_survive_too(window, files, tmp_path):
    contours = [[(2, 2), (28, 3), (26, 26), (3, 24)], [(10, 10), (18, 10), (14, 18)]]
    window.set_scene("polygon-scanline", contours, None, (32, 32))
    saved = scene_of(window)
    path = tmp_path / "holes.json"
    assert files.save_to(path)
    assert len(scenes.load(path).points) == 2
    window.set_scene("line-bresenham", [(1, 1), (9, 4)], None, (32, 32))
    assert files.open_path(path)
    assert scene_of(window) == saved


@pytest.mark.parametrize("data, words", [
    (b'{"version": 1, "grid": ', "not valid JSON"),
    (b'{"version": 1, "grid": {"width": 8, "height": 8}, "algorithm": "nope", "primitives": []}',
     "algorithm"),
    (b'{"version": 1, "grid": {"width": 8, "height": 8}, "algorithm": "line-bresenham", '
     b'"primitives": [{"points": [[1, 1], [20, 3]]}]}', "outside"),
    (b"\xff\xfe\x00", "not a text file"),
])
def test_a_bad_file_says_why_and_changes_nothing(window, files, tmp_path, messages, data,
                                                 words):
    window.set_scene("line-bresenham", [(2, 3), (20, 9)], None, (24, 16))
    window.player.seek(4)
    before = scene_of(window), window.player.index
    path = tmp_path / "bad.json"
    path.write_bytes(data)
    assert not files.open_path(path)
    assert len(messages) == 1
    kind, title, message = messages[0]
    assert kind == "warning" and "bad.json" in message and words in message
    assert (scene_of(window), window.player.index) == before
    assert files.path is None and files.recent() == []


def test_a_missing_file_says_why(window, files, tmp_path, messages):
    assert not files.open_path(tmp_path / "gone.json")
    assert "cannot read" in messages[0][2]


# -------------------------------------------------------------- dialogs
def test_open_and_save_as_through_the_file_dialogs(window, files, tmp_path, monkeypatch,
                                                   messages):
    window.set_scene("line-bresenham", [(2, 3), (20, 9)], None, (24, 16))
    monkeypatch.setattr(QFileDialog, "getSaveFileName",
                        lambda *a, **k: (str(tmp_path / "mine"), ""))
    files.save_as_action.trigger()
    path = tmp_path / "mine.json"
    assert path.exists() and files.path == path

    # Save writes to the same file without asking.
    monkeypatch.setattr(QFileDialog, "getSaveFileName",
                        lambda *a, **k: pytest.fail("Save asked for a name"))
    window.set_scene("line-bresenham", [(1, 1), (15, 2)], None, (24, 16))
    files.save_action.trigger()
    assert scenes.load(path).points == ((1, 1), (15, 2))

    window.set_scene("line-dda", [(0, 0), (3, 3)], None, (8, 8))
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: (str(path), ""))
    files.open_action.trigger()
    assert window.player.spec.name == "line-bresenham"
    assert window.player.points == [(1, 1), (15, 2)]
    # Cancelled dialogs change nothing.
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: ("", ""))
    assert not files.open_dialog()
    assert messages == []


def test_save_is_atomic(window, files, tmp_path, monkeypatch, messages):
    path = tmp_path / "kept.json"
    assert files.save_to(path)
    before = path.read_bytes()
    window.set_scene("line-dda", [(0, 0), (7, 2)], None, (8, 8))

    def broken(source, target):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(scenes.os, "replace", broken)
    assert not files.save_to(path)
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir() if p.name != "settings.ini"] == ["kept.json"]
    assert "No space left" in messages[0][2]


def test_a_scene_still_being_drawn_is_not_saved(window, files, tmp_path, messages):
    window.set_points([(3, 3)])
    assert window.player.trace is None
    assert not files.save_to(tmp_path / "half.json")
    assert not (tmp_path / "half.json").exists()
    assert "Place all the points" in messages[0][2]


# ------------------------------------------------------ recent, examples
def test_recent_files_newest_first_and_capped(window, files, tmp_path, settings):
    paths = []
    for k in range(fa.MAX_RECENT + 2):
        window.set_scene("line-bresenham", [(1, 1), (5 + k, 3)], None, (24, 16))
        path = tmp_path / f"s{k}.json"
        files.save_to(path)
        paths.append(str(path.resolve()))
    assert files.recent() == paths[::-1][:fa.MAX_RECENT]
    entries = [a for a in files.recent_menu.actions() if a.text() in paths]
    assert len(entries) == fa.MAX_RECENT
    entries[-1].trigger()  # the oldest kept one
    assert window.player.points == [(1, 1), (5 + 2, 3)]
    # Another window with the same settings sees the list.
    other = MainWindow()
    try:
        # Opening it made it the newest.
        assert other.add_file_actions(settings).recent()[0] == paths[2]
    finally:
        other.deleteLater()


def test_every_shipped_scene_is_an_example_under_its_family(window, files, qtbot):
    files.examples_menu.aboutToShow.emit()  # the menu reads them as it opens
    submenus = [a.menu() for a in files.examples_menu.actions() if a.menu()]
    # A submenu per family, named as people read it, not one long flat list.
    titles = [m.title() for m in submenus]
    assert "Lines" in titles and "The 3-D pipeline" in titles and len(titles) == len(set(titles))
    entries = files.example_actions()
    every = sorted(p.relative_to(SCENES) for p in SCENES.rglob("*.json"))
    assert sorted(Path(a.data()).relative_to(SCENES) for a in entries) == every
    assert max(len(m.actions()) for m in submenus) < len(every) / 2
    for menu in submenus:
        families = {scenes.load(a.data()).spec.family for a in menu.actions()}
        assert len(families) == 1, menu.title()
    # Browse all… opens the gallery with the pictures.
    browse = files.examples_menu.actions()[0]
    assert "Browse" in browse.text()
    browse.trigger()
    assert window.gallery_entry.window.isVisible()
    qtbot.waitUntil(lambda: window.gallery_entry.window.thumbnails_done, timeout=4 * WAIT_MS)
    for entry in entries:
        path = Path(entry.data())
        entry.trigger()
        scene = scenes.load(path)
        assert window.player.spec.name == scene.algorithm
        assert window.player.grid == (scene.width, scene.height)
    # Examples are not saved over: Save asks for a new name.
    assert files.path is None and files.recent() == []


# ---------------------------------------------------------------- export
def wait_done(qtbot, controller):
    qtbot.waitUntil(lambda: not controller.busy and not controller.dialog.running,
                    timeout=20000)


def test_the_export_dialog_writes_a_gif(window, files, qtbot, tmp_path):
    window.set_scene("line-bresenham", [(2, 3), (20, 9)], None, (24, 16))
    window.player.seek(6)
    controller = files.export_animation()
    dialog = controller.dialog
    assert dialog.isVisible()
    last = len(window.player.trace) - 1
    assert dialog.values()["first"] == 0 and dialog.values()["last"] == last
    target = tmp_path / "from-here.gif"
    dialog.set_values({"gif": str(target), "scale": 4, "fps": 10, "hold": 0, "panel": "none",
                       "loop": False})
    dialog.range_current.setChecked(True)
    assert f"{last - 6 + 1} frames" in dialog.size_label.text()
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    wait_done(qtbot, controller)
    assert "Wrote" in dialog.message.text(), dialog.message.text()
    with Image.open(target) as image:
        assert image.n_frames == last - 6 + 1
        assert image.size == (24 * 4, 16 * 4 + ex.FrameRenderer(
            controller.scene, ex.ExportSettings(scale=4, panel="none"),
            controller.trace).caption_height)
        assert image.info["duration"] == 100 and "loop" not in image.info
    assert dialog.progress.value() == dialog.progress.maximum()
    # The bar says it is over, not still "writing the file".
    assert "writing" not in dialog.progress.text() and "Done" in dialog.progress.text()
    assert dialog.export_button.isEnabled() and not dialog.cancel_button.isEnabled()


def test_cancel_mid_export_leaves_no_gif(window, files, qtbot, tmp_path, monkeypatch):
    window.set_scene("polygon-scanline", [[(3, 4), (60, 10), (50, 58), (8, 40)]], None, (64, 64))
    original = ex.FrameRenderer.image

    def slow(self, index):
        time.sleep(0.01)
        return original(self, index)

    monkeypatch.setattr(ex.FrameRenderer, "image", slow)
    controller = files.export_animation()
    dialog = controller.dialog
    target = tmp_path / "never.gif"
    folder = tmp_path / "frames"
    dialog.set_values({"gif": str(target), "frames_dir": str(folder), "scale": 4})
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    assert dialog.running and dialog.cancel_button.isEnabled()
    assert not dialog.close_button.isEnabled()
    qtbot.waitUntil(lambda: dialog.progress.value() >= 5, timeout=20000)
    qtbot.mouseClick(dialog.cancel_button, Qt.MouseButton.LeftButton)
    wait_done(qtbot, controller)
    assert dialog.progress.value() < len(window.player.trace)
    assert "Cancelled" in dialog.message.text()
    assert not target.exists() and not folder.exists()
    assert [p.name for p in tmp_path.iterdir() if p.name != "settings.ini"] == []
    assert dialog.export_button.isEnabled()


def test_export_problems_show_in_the_dialog(window, files, qtbot, tmp_path):
    controller = files.export_animation()
    dialog = controller.dialog
    dialog.set_values({"gif": str(tmp_path / "no" / "such" / "x.gif")})
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    wait_done(qtbot, controller)
    assert "does not exist" in dialog.message.text()
    dialog.set_values({"gif": "", "frames_dir": ""})
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    assert not controller.busy and "Choose where to export" in dialog.message.text()


def test_escape_while_exporting_cancels(window, files, qtbot, tmp_path, monkeypatch):
    window.set_scene("polygon-scanline", [[(3, 4), (60, 10), (50, 58), (8, 40)]], None, (64, 64))
    original = ex.FrameRenderer.image
    monkeypatch.setattr(ex.FrameRenderer, "image",
                        lambda self, i: (time.sleep(0.01), original(self, i))[1])
    controller = files.export_animation()
    dialog = controller.dialog
    dialog.set_values({"gif": str(tmp_path / "x.gif"), "scale": 2})
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    qtbot.keyClick(dialog, Qt.Key.Key_Escape)
    assert dialog.isVisible()  # still open until the export has stopped
    wait_done(qtbot, controller)
    assert not (tmp_path / "x.gif").exists()
    qtbot.keyClick(dialog, Qt.Key.Key_Escape)
    assert not dialog.isVisible()


def test_ctrl_e_opens_the_export_dialog(window, files, qtbot):
    window.show()
    qtbot.waitExposed(window)
    window.activateWindow()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is window, timeout=WAIT_MS)
    target = QApplication.focusWidget() or window
    qtbot.keyClick(target, Qt.Key.Key_E, Qt.KeyboardModifier.ControlModifier)
    qtbot.waitUntil(lambda: files.export_controller is not None, timeout=WAIT_MS)
    assert files.export_controller.dialog.isVisible()
    files.export_controller.dialog.close()


def test_nothing_to_export_without_a_run(window, files, messages):
    window.set_points([(3, 3)])
    assert files.export_animation() is None
    assert "no run to export" in messages[0][2]


def test_the_dialog_exports_what_the_command_line_exports(window, files, qtbot, tmp_path):
    """Same scene, same choices: the window's export and `rasterlab export`
    give the same frames."""
    path = tmp_path / "same.json"
    window.set_scene("line-bresenham", [(2, 3), (20, 9)], None, (24, 16))
    files.save_to(path)
    controller = files.export_animation()
    dialog = controller.dialog
    dialog.set_values({"gif": str(tmp_path / "window.gif"), "scale": 5, "panel": "variables",
                       "theme": "dark"})
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    wait_done(qtbot, controller)
    ex.export(scenes.load(path),
              ex.ExportSettings(scale=5, panel="variables", theme="dark"),
              gif=tmp_path / "command.gif")
    with Image.open(tmp_path / "window.gif") as a, Image.open(tmp_path / "command.gif") as b:
        assert a.n_frames == b.n_frames
        for k in range(a.n_frames):
            a.seek(k)
            b.seek(k)
            assert np.array_equal(np.asarray(a.convert("RGB")), np.asarray(b.convert("RGB")))


# ------------------------------------- an open whose run records in the background
# A flood fill of a 1024 x 1024 square: far too long to record at once.
BIG_FILL = {"version": 1, "title": "big fill", "description": "", "grid": {"width": 1030,
            "height": 1030}, "origin": "top-left", "algorithm": "flood-fill", "options": {},
            "primitives": [{"points": [[0, 0], [1025, 0], [1025, 1025], [0, 1025]]}],
            "view": {"compare": True, "speed": 3}, "bookmarks": [{"step": 1, "name": "b"}]}


@pytest.fixture
def held(make_window, tmp_path, monkeypatch, messages):
    """A window showing a.json, opened and clean, whose next recording waits
    for ``gate`` (then does ``then``: record, or raise); big.json is beside."""
    window = make_window(recovery=True, shown=False)
    small = tmp_path / "a.json"
    window.set_scene("circle-midpoint", [(12, 10)], {"radius": 7}, (24, 20))
    assert window.file_actions.save_to(small) and window.file_actions.open_path(small)
    big = tmp_path / "big.json"
    big.write_text(json.dumps(BIG_FILL))
    gate, then = __import__("threading").Event(), {"do": window.player.session.outcome}
    monkeypatch.setattr(window.player.session, "outcome",
                        lambda *a, **k: gate.wait(10) and then["do"](*a, **k))
    window.player.sync_wait = 0.0
    return window, small, big, gate, then


def shown_state(window):
    files = window.file_actions
    return (scene_of(window), files.path, files.title, window.recovery.dirty,
            window.isWindowModified(), window.windowTitle(), window.compare.isChecked(),
            window.player.speed, list(files.bookmarks))


def assert_open_undone(qtbot, window, small, big, before):
    assert shown_state(window) == before
    saved_big, saved_small = big.read_bytes(), small.read_bytes()
    window.recovery.check()
    assert not window.recovery.dirty and window.file_actions.path == small
    assert window.file_actions.save()  # Ctrl+S: the scene on show goes to its own file
    assert big.read_bytes() == saved_big  # never the previous scene over the opened file
    assert scenes.load(small).algorithm == "circle-midpoint" and saved_small


def test_an_open_cancelled_while_recording_changes_nothing(qtbot, held):
    window, small, big, gate, _then = held
    before = shown_state(window)
    assert window.file_actions.open_path(big)
    assert window.player.recording and window.file_actions.opening
    window.recovery.check()
    assert window.file_actions.path == small and not window.recovery.dirty
    with qtbot.waitSignal(window.player.recordingFinished, timeout=WAIT_MS):
        window.recording_status.shortcut.activated.emit()  # Esc
    gate.set()
    assert not window.file_actions.opening
    assert_open_undone(qtbot, window, small, big, before)


def test_an_open_whose_run_fails_changes_nothing(qtbot, held):
    window, small, big, gate, then = held
    before = shown_state(window)

    def fail(*_args, **_kwargs):
        raise MemoryError()
    then["do"] = fail
    assert window.file_actions.open_path(big) and window.player.recording
    with qtbot.waitSignal(window.player.recordingFinished, timeout=WAIT_MS) as finished:
        gate.set()
    assert "MemoryError" in finished.args[0]
    assert_open_undone(qtbot, window, small, big, before)


def test_a_reopened_last_scene_cancelled_at_start_changes_nothing(qtbot, held, monkeypatch):
    from app.gui import preferences
    window, small, big, gate, _then = held
    window.file_actions._remember(big)  # the last scene opened
    prefs = window.preferences.prefs
    get = prefs.get
    monkeypatch.setattr(prefs, "get", lambda name: True if name == "reopen_last" else get(name))
    before = shown_state(window)
    assert preferences.reopen_last_scene(window) and window.player.recording
    with qtbot.waitSignal(window.player.recordingFinished, timeout=WAIT_MS):
        window.player.cancel_recording()
    gate.set()
    assert_open_undone(qtbot, window, small, big, before)


def test_an_open_recorded_in_the_background_is_opened_when_done(qtbot, held):
    window, small, big, gate, _then = held
    assert window.file_actions.open_path(big) and window.player.recording
    with qtbot.waitSignal(window.player.recordingFinished, timeout=60_000) as finished:
        gate.set()
    assert finished.args[0] == ""
    assert window.file_actions.path == big and window.file_actions.title == "big fill"
    window.recovery.check()
    assert not window.recovery.dirty and window.windowTitle().startswith("big.json")
    assert window.player.session.scene.origin == "top-left" and window.grid.y_down


def test_saving_while_an_open_records_is_refused(qtbot, held, messages):
    # The scene is already the opened file's, the name still the previous
    # file's: a save then wrote big.json's scene into a.json.
    window, small, big, gate, _then = held
    saved_small = small.read_bytes()
    assert window.file_actions.open_path(big) and window.player.recording
    assert not window.file_actions.save()
    assert small.read_bytes() == saved_small
    assert messages[-1][0] == "information" and "big.json" in messages[-1][2]
    with qtbot.waitSignal(window.player.recordingFinished, timeout=WAIT_MS):
        window.player.cancel_recording()
    gate.set()


def test_the_dialog_exports_every_format_at_once(window, files, qtbot, tmp_path):
    window.set_scene("line-bresenham", [(2, 3), (12, 7)], None, (16, 10))
    controller = files.export_animation()
    dialog = controller.dialog
    targets = {"mp4": tmp_path / "a.mp4", "webm": tmp_path / "a.webm", "pdf": tmp_path / "a.pdf",
               "svg_dir": tmp_path / "svg", "html": tmp_path / "a.html"}
    dialog.set_values({"gif": "", "scale": 8, **{k: str(v) for k, v in targets.items()}})
    qtbot.mouseClick(dialog.export_button, Qt.MouseButton.LeftButton)
    wait_done(qtbot, controller)
    text = dialog.message.text()
    assert text.startswith("Wrote") and "interactive page" in text, text
    frames = len(window.player.trace)
    assert len(list(targets["svg_dir"].glob("frame_*.svg"))) == frames
    assert all(path.exists() for path in targets.values())
    assert "a.gif" not in {p.name for p in tmp_path.iterdir()}


def test_export_interactive_page_asks_only_for_the_page(window, files):
    window.set_scene("line-bresenham", [(2, 3), (12, 7)], None, (16, 10))
    controller = files.export_page()
    values = controller.dialog.values()
    assert values["gif"] == "" and values["html"].endswith(".html")
    assert files.export_page_action.shortcut().toString() == "Ctrl+Shift+E"


# ------------------------------------------------------- shipped scenes
def test_a_shipped_scene_opened_by_file_open_is_not_saved_over(window, files, tmp_path,
                                                               monkeypatch, messages):
    shipped = SCENES / "line-centre-ties.json"
    before = shipped.read_bytes()
    asked = []

    def save_dialog(parent, title, start, *args, **kwargs):
        asked.append(start)
        return str(tmp_path / "mine.json"), ""
    monkeypatch.setattr(QFileDialog, "getSaveFileName", save_dialog)
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: (str(shipped), ""))
    assert files.open_dialog()  # File > Open…, not the examples menu
    window.player.seek(1)
    assert files.save()  # Ctrl+S
    # Save acted as Save As: asked for a name, starting outside the program's folder.
    assert len(asked) == 1 and not Path(asked[0]).resolve().is_relative_to(ROOT)
    assert shipped.read_bytes() == before
    assert scenes.load(tmp_path / "mine.json").algorithm == scenes.load(shipped).algorithm
    # Now the scene is the user's file: Save writes it without asking.
    assert files.save() and len(asked) == 1
    # Saving into the program's folder by name is refused with a message.
    assert not files.save_to(shipped) and messages and shipped.read_bytes() == before


def test_exports_of_a_shipped_scene_start_in_the_documents_folder(window, files):
    from PySide6.QtCore import QStandardPaths
    documents = Path(QStandardPaths.writableLocation(
        QStandardPaths.StandardLocation.DocumentsLocation))
    assert files.open_path(SCENES / "rendering" / "textured-floor.json")
    controller = files.export_animation()
    target = Path(controller.dialog.values()["gif"])
    assert not target.resolve().is_relative_to(ROOT)
    assert target.parent == documents and target.name == "textured-floor.gif"
    # A stored export folder inside the program's folder is not used either.
    files.settings.setValue("export/folder", str(SCENES))
    target = Path(files.export_animation().dialog.values()["gif"])
    assert target.parent == documents
