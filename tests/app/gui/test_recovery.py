"""No lost work: unsaved changes, the recovery file, closing, and the
handler of uncaught exceptions."""
import threading

import pytest
from PySide6.QtWidgets import QFileDialog, QMessageBox

from app.gui import recovery as recovery_module
from app.model import scene as scenes
from app.gui.crash import CrashHandler
from app.gui.recovery import PREFIX, content, pending_recoveries
from app.gui.window import DEMO_POINTS
from tests.support.gui import WAIT_MS

BUTTONS = QMessageBox.StandardButton
RESTORE, DISCARD, LATER = recovery_module.RESTORE, recovery_module.DISCARD, \
    recovery_module.LATER


pytestmark = pytest.mark.window(shown=False, recovery=True)


@pytest.fixture
def answers(monkeypatch):
    """QMessageBox.question answers from a list; every question is recorded."""
    asked, queue = [], []

    def question(parent, title, text, *args, **kwargs):
        asked.append((title, text))
        return queue.pop(0)
    monkeypatch.setattr(QMessageBox, "question", question)
    monkeypatch.setattr(recovery_module, "ask_restore",
                        lambda parent, when: question(parent, "Restore", when))
    monkeypatch.setattr(QMessageBox, "warning",
                        lambda parent, title, text, *a, **k: asked.append((title, text)))
    return queue, asked


def line_scene(points, width=32, height=24, title=""):
    return scenes.Scene(algorithm="line-bresenham", points=[list(p) for p in points],
                        width=width, height=height, title=title)


def points_in(path):
    return scenes.load(path).points


# ------------------------------------------------------------ dirty flag
def test_title_and_dirty_flag(window):
    recovery = window.recovery
    assert not recovery.dirty and not window.isWindowModified()
    assert window.windowTitle().startswith("Untitled[*]")
    assert "Bresenham" in window.windowTitle()
    window.player.seek(0)  # moving through the steps is not an edit
    assert not recovery.dirty
    window.set_option("symmetric", True)
    assert recovery.dirty and window.isWindowModified()
    window.set_option("symmetric", False)  # back to the saved scene
    assert not recovery.dirty and not window.isWindowModified()
    window.grid_editor.origin.setCurrentIndex(1)  # the origin is part of the scene
    assert recovery.dirty
    window.grid_editor.origin.setCurrentIndex(0)
    assert not recovery.dirty


def test_a_change_made_without_a_signal_is_seen(window, qtbot):
    window.set_y_down(True)
    qtbot.waitUntil(lambda: window.recovery.dirty, timeout=WAIT_MS)


def test_autosave_writes_a_loadable_file(window, qtbot):
    recovery = window.recovery
    window.set_points([(1, 2), (20, 9)])
    qtbot.waitUntil(recovery.path.exists, timeout=WAIT_MS)
    loaded = scenes.load(recovery.path)
    assert (loaded.algorithm, loaded.points) == ("line-bresenham", ((1, 2), (20, 9)))
    assert (loaded.width, loaded.height) == (32, 24)
    # A scene with a point still missing is not written over the good copy.
    window.set_points([(5, 5)])
    recovery.autosave()
    assert points_in(recovery.path) == ((1, 2), (20, 9))


def test_the_slow_look_does_not_put_off_the_autosave(make_window, qtbot):
    # The look for unsaved changes comes more often than the autosave delay;
    # with nothing new it must not restart the delay.
    window = make_window(delay_ms=300, poll_ms=40)
    window.set_points([(1, 2), (20, 9)])
    qtbot.waitUntil(window.recovery.path.exists, timeout=WAIT_MS)
    assert points_in(window.recovery.path) == ((1, 2), (20, 9))


def test_a_clean_save_removes_the_recovery_file(window, qtbot, tmp_path):
    recovery = window.recovery
    window.set_points([(1, 2), (20, 9)])
    qtbot.waitUntil(recovery.path.exists, timeout=WAIT_MS)
    assert window.file_actions.save_to(tmp_path / "mine.json")
    assert not recovery.path.exists() and not recovery.dirty
    assert window.windowTitle().startswith("mine.json[*]")
    window.set_points([(3, 2), (20, 9)])
    assert recovery.dirty


def test_opening_a_file_is_clean(window, tmp_path, answers):
    path = tmp_path / "other.json"
    scenes.save(line_scene([(0, 0), (9, 3)], title="Other"), path)
    window.set_option("symmetric", True)
    answers[0].append(BUTTONS.Discard)
    assert window.file_actions.open_path(path)
    assert not window.recovery.dirty
    assert window.player.points == [(0, 0), (9, 3)]


def _open_by(window, how, path, monkeypatch):
    """Open ``path`` the way a person would: the dialog, the recent list,
    the examples menu or the gallery."""
    files = window.file_actions
    if how == "dialog":
        monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: (str(path), ""))
        files.open_dialog()
    elif how == "recent":
        files._remember(path)
        files.recent_menu.actions()[0].trigger()
    elif how == "example":
        files.example_actions()[0].trigger()
    else:
        from app.gui.gallery import GalleryDialog
        GalleryDialog(window).open_row(0)


@pytest.mark.parametrize("how", ["dialog", "recent", "example", "gallery"])
def test_every_open_asks_before_replacing_unsaved_work(window, tmp_path, answers, how,
                                                       monkeypatch):
    queue, asked = answers
    path = tmp_path / "other.json"
    scenes.save(line_scene([(0, 0), (9, 3)], title="Other"), path)
    window.edits.once(lambda: window.set_points([(1, 2), (20, 9)]))  # an undoable edit
    assert window.recovery.dirty
    queue.append(BUTTONS.Cancel)
    _open_by(window, how, path, monkeypatch)
    assert len(asked) == 1 and "before opening another scene" in asked[0][1]
    assert window.player.points == [(1, 2), (20, 9)] and window.recovery.dirty
    window.undo()  # the undo history is kept too
    assert window.player.points != [(1, 2), (20, 9)]
    window.redo()
    queue.append(BUTTONS.Discard)
    _open_by(window, how, path, monkeypatch)
    assert len(asked) == 2 and window.player.points != [(1, 2), (20, 9)]
    assert not window.recovery.dirty


def test_a_clean_scene_opens_without_asking(window, tmp_path, answers, monkeypatch):
    queue, asked = answers
    path = tmp_path / "other.json"
    scenes.save(line_scene([(0, 0), (9, 3)], title="Other"), path)
    _open_by(window, "dialog", path, monkeypatch)
    assert asked == [] and window.player.points == [(0, 0), (9, 3)]


# ---------------------------------------------------------------- close
def test_a_clean_window_closes_without_asking(window, answers):
    queue, asked = answers
    window.show()
    assert window.close()
    assert asked == []


def test_cancel_keeps_the_window_open(window, qtbot, answers):
    queue, asked = answers
    recovery = window.recovery
    window.show()
    window.set_points([(1, 2), (20, 9)])
    qtbot.waitUntil(recovery.path.exists, timeout=WAIT_MS)
    queue.append(BUTTONS.Cancel)
    assert not window.close()
    assert window.isVisible() and len(asked) == 1
    assert "Save the changes to Untitled" in asked[0][1]
    assert recovery.path.exists()
    queue.append(BUTTONS.Discard)
    assert window.close()
    assert not recovery.path.exists()
    assert pending_recoveries(recovery.folder) == []


def test_save_on_close_and_a_cancelled_save_dialog(window, answers, monkeypatch, tmp_path):
    queue, asked = answers
    window.show()
    window.set_points([(1, 2), (20, 9)])
    target = tmp_path / "closing.json"
    chosen = [("", ""), (str(target), "")]
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: chosen.pop(0))
    queue.append(BUTTONS.Save)
    assert not window.close()  # the save dialog was cancelled: the window stays
    assert window.isVisible() and not target.exists()
    queue.append(BUTTONS.Save)
    assert window.close()
    assert points_in(target) == ((1, 2), (20, 9))


# -------------------------------------------------------------- restore
def leave_recovery_file(folder, scene, name=f"{PREFIX}4242-1.json"):
    """A recovery file as a killed program leaves it: no lock held."""
    folder.mkdir(parents=True, exist_ok=True)
    scenes.save(scene, folder / name)
    return folder / name


def test_restore_offers_the_scene_and_marks_it_unsaved(make_window, data, answers):
    queue, asked = answers
    left = leave_recovery_file(data / "recovery", line_scene([(2, 3), (25, 20)], 40, 30))
    window = make_window()
    queue.append(RESTORE)
    assert window.recovery.offer()
    assert asked[0][1].count(":") == 2  # the time the copy was written
    assert window.player.points == [(2, 3), (25, 20)] and window.player.grid == (40, 30)
    assert window.recovery.dirty and window.isWindowModified()
    # The restored scene is in this program's own file now; the old one is gone.
    assert not left.exists()
    assert points_in(window.recovery.path) == ((2, 3), (25, 20))
    queue.append(BUTTONS.Discard)
    assert window.close()


def test_discard_removes_the_file(make_window, data, answers):
    queue, asked = answers
    left = leave_recovery_file(data / "recovery", line_scene([(2, 3), (25, 20)]))
    window = make_window()
    queue.append(DISCARD)
    assert not window.recovery.offer()
    assert not left.exists()
    assert window.player.points == list(DEMO_POINTS)
    assert not window.recovery.dirty


def test_not_now_keeps_the_file_for_the_next_start(make_window, data, answers):
    queue, asked = answers
    left = leave_recovery_file(data / "recovery", line_scene([(2, 3), (25, 20)]))
    queue.append(LATER)
    assert not make_window().recovery.offer()
    assert left.exists() and window_count(asked) == 1
    queue.append(RESTORE)
    later = make_window()
    assert later.recovery.offer() and later.player.points == [(2, 3), (25, 20)]


def window_count(asked):
    return sum(1 for title, _ in asked if title == "Restore")


@pytest.mark.parametrize("text", ["{ not json", '{"version": 1, "algorithm": "no-such"}', ""])
def test_a_broken_recovery_file_is_set_aside(make_window, data, answers, text):
    queue, asked = answers
    folder = data / "recovery"
    folder.mkdir(parents=True)
    broken = folder / f"{PREFIX}77-1.json"
    broken.write_text(text)
    window = make_window()
    queue.append(RESTORE)
    assert not window.recovery.offer()
    title, message = asked[-1]
    assert "cannot be restored" in message and "set aside as" in message
    assert not broken.exists()
    aside = [p for p in folder.iterdir() if ".broken-" in p.name]
    assert len(aside) == 1 and aside[0].read_text() == text
    assert window.player.points == list(DEMO_POINTS) and not window.recovery.dirty
    assert pending_recoveries(folder) == []  # never offered again


def test_a_running_programs_file_is_not_offered(make_window, data, answers):
    first = make_window()
    first.set_points([(1, 2), (20, 9)])
    assert first.recovery.autosave()
    second = make_window()
    assert not second.recovery.offer()  # asks nothing: the first program is alive
    assert answers[1] == [] and first.recovery.path.exists()
    for w in (first, second):
        w.recovery.shutdown()
    assert not first.recovery.path.exists()


# ---------------------------------------------------------------- crash
@pytest.fixture
def shown(monkeypatch):
    messages = []
    monkeypatch.setattr(QMessageBox, "critical",
                        lambda parent, title, text, *a, **k: messages.append(text))
    return messages


@pytest.fixture
def handler(window, data):
    installed = window.add_crash_handler(data)
    yield installed
    installed.uninstall()


def test_an_exception_in_a_slot_is_logged_and_shown_once(window, handler, shown, qtbot):
    before = content(window.file_actions.current_scene())

    def broken(name, value):
        raise RuntimeError("the option store is broken")
    window.player.set_option = broken
    for value in (True, False, True):  # a burst: three failing slots
        window.options.valueEdited.emit("symmetric", value)
    qtbot.waitUntil(lambda: len(shown) == 1, timeout=WAIT_MS)
    qtbot.wait(50)
    assert len(shown) == 1 and handler.count == 3
    assert "RuntimeError: the option store is broken" in shown[0]
    assert "and 2 more errors" in shown[0] and str(handler.log_file) in shown[0]
    log = handler.log_file.read_text()
    assert log.count("Traceback (most recent call last)") == 3
    assert "in broken" in log
    assert content(window.file_actions.current_scene()) == before
    # The window goes on working.
    del window.player.set_option
    window.options.valueEdited.emit("symmetric", True)
    assert window.player.options["symmetric"] is True


def test_an_exception_in_a_thread_is_shown_in_the_window(window, handler, shown, qtbot):
    def work():
        raise ValueError("bad worker")
    thread = threading.Thread(target=work)
    thread.start()
    thread.join()
    qtbot.waitUntil(lambda: len(shown) == 1, timeout=WAIT_MS)
    assert "ValueError: bad worker" in shown[0]


def test_without_a_window_one_line_on_stderr(tmp_path, capsys):
    handler = CrashHandler(None, tmp_path)
    try:
        raise KeyError("lost")
    except KeyError as error:
        handler.handle(type(error), error, error.__traceback__)
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "KeyError: 'lost'" in err
    assert "KeyError: 'lost'" in (tmp_path / "rasterlab.log").read_text()


def test_a_log_folder_that_cannot_be_made_is_said_once_at_the_first_error(tmp_path, capsys):
    (tmp_path / "file").write_text("")
    handler = CrashHandler(None, tmp_path / "file" / "logs")  # under a file: no folder
    assert capsys.readouterr().err == ""  # nothing is made, nor said, before an error
    for _ in range(2):
        try:
            raise KeyError("lost")
        except KeyError as error:
            handler.handle(type(error), error, error.__traceback__)
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 3 and "cannot keep an error log" in lines[0]
    assert all("unexpected error: KeyError: 'lost'" in line for line in lines[1:])


def test_help_menu_opens_the_log_folder(window, handler, monkeypatch, data):
    opened = []
    monkeypatch.setattr("app.gui.crash.QDesktopServices.openUrl",
                        lambda url: opened.append(url.toLocalFile()) or True)
    act = next(a for a in window.menus["help"].actions() if "log folder" in a.text())
    assert act.toolTip()
    act.trigger()
    assert opened == [str(data)]
