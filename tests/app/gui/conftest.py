"""The main window and the player, made once here for every window test.

A module or a test says how its window is made with
``pytest.mark.window(*args, **kwargs)``: the arguments of ``make_window``
below. Without the mark, ``window`` is a window on screen showing the demo
scene. ``pytest.mark.player(...)`` says the scene of a player without a window.
"""
import pytest
from PySide6.QtCore import QSettings

from algorithms.core import registry
from app.gui.player import Player
from app.gui.window import MainWindow
from tests.support.gui import settle


@pytest.fixture
def data(tmp_path, monkeypatch):
    """A data folder of the test's own: recovery copies and the error log."""
    folder = tmp_path / "data"
    monkeypatch.setenv("RASTERLAB_DATA_DIR", str(folder))
    return folder


def _marked(request) -> dict:
    marker = request.node.get_closest_marker("window")
    return {"args": marker.args, **marker.kwargs} if marker else {}


@pytest.fixture
def make_window(request, qtbot, tmp_path):
    """``make_window(*args, shown=True, settled=False, files=False,
    recovery=False, sync_wait=None, **kwargs)``: a MainWindow(*args, **kwargs).

    ``shown`` puts it on screen; ``settled`` also waits until its grid view
    has taken its final place. ``files`` installs the file actions with a
    settings file of the test's own. ``recovery`` installs them and the
    recovery of unsaved work in the test's data folder (add_recovery's
    ``delay_ms`` and ``poll_ms`` may be given): such a window is closed at the
    end without the question about unsaved work, so it is not given to qtbot,
    which would close it with the question still armed. ``sync_wait`` is how
    long an edit waits for its recording. The window mark's arguments are the
    defaults.
    """
    made = []

    def make(*args, shown=True, settled=False, files=False, recovery=False,
             sync_wait=None, delay_ms=20, poll_ms=None, **kwargs):
        window = MainWindow(*args, **kwargs)
        if sync_wait is not None:
            window.player.sync_wait = sync_wait
        if files or recovery:
            window.add_file_actions(QSettings(str(tmp_path / "settings.ini"),
                                              QSettings.Format.IniFormat))
        if recovery:
            timing = {"delay_ms": delay_ms} | ({} if poll_ms is None else {"poll_ms": poll_ms})
            window.add_recovery(request.getfixturevalue("data") / "recovery", **timing)
            made.append(window)
        else:
            qtbot.addWidget(window)
        if shown or settled:
            window.show()
            qtbot.waitExposed(window)
        if settled:
            settle(qtbot, window)
        return window

    marked = _marked(request)
    args = marked.pop("args", ())

    def make_marked(*more, **options):
        return make(*(more or args), **(marked | options))
    yield make_marked
    for window in made:
        window.player.pause()
        window.removeEventFilter(window.recovery)
        window.recovery.shutdown()
        window.close()
        window.deleteLater()


@pytest.fixture
def window(make_window):
    """The test's window, made as its window mark says; a recording still
    running at the end is cancelled before the window goes."""
    window = make_window()
    yield window
    window.player.stop_recording()


@pytest.fixture
def theme(window):
    """``theme("dark")`` and ``theme("light")``: the window's preferences
    applied with that theme; light again at the end."""
    def use(name):
        values = window.preferences.prefs.values()
        values["theme"] = name
        window.preferences.apply(values)
    yield use
    use("light")  # the application's look is shared by the tests after this one


@pytest.fixture
def player(request, qtbot):
    """A player without a window showing the scene of the test's player mark,
    ``pytest.mark.player(algorithm, points, options=None, grid=(32, 24),
    sync_wait=None)``: the scene is recorded before the player is handed
    over, and ``sync_wait`` (if given) applies to the edits after it. A
    recording still running at the end is cancelled."""
    marker = request.node.get_closest_marker("player")
    scene = dict(marker.kwargs)
    sync_wait = scene.pop("sync_wait", None)
    made = Player()
    made.set_scene(*marker.args, **scene)
    if sync_wait is not None:
        made.sync_wait = sync_wait
    yield made
    made.stop_recording()


@pytest.fixture
def forget_student_algorithms():
    """The registry is the process's: a student's algorithm leaves with its test."""
    yield
    for spec in registry.all_specs():
        if spec.name.startswith("student-"):
            registry.unregister(spec.name)
