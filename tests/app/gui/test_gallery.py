"""Help > Examples and hard cases…: every shipped scene is listed under its family,
opens and runs to the end."""
import json
import shutil

import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QMessageBox

from app import cli
from app.gui import gallery as gal
from app.model import scene as scenes
from app.gui.window import MainWindow
from tests.support import ROOT
from tests.support.gui import WAIT_MS

FOLDER = ROOT / "resources" / "scenes"
SHIPPED = sorted(FOLDER.rglob("*.json"))
FAMILIES = ("lines", "circles", "polygons", "fill", "triangles", "visibility", "antialias",
            "textures", "pipeline")
# The hard cases the issue names, by the scene that shows each.
NAMED = ("line-float32-drift", "line-centre-ties", "line-reversed", "circle-radius-1",
         "circle-radius-2", "polygon-horizontal-edges", "polygon-star-evenodd",
         "polygon-star-nonzero", "triangle-sliver", "triangle-fan-32", "triangle-mesh-1e6",
         "triangle-behind-eye", "painter-cyclic", "aa-siemens-star")


pytestmark = pytest.mark.window(shown=False, files=True)


@pytest.fixture
def dialog(window, qtbot):
    found = window.gallery_entry.open()
    qtbot.waitUntil(lambda: found.thumbnails_done, timeout=WAIT_MS)
    return found


def _family(algorithm):
    from algorithms.core import registry
    return registry.get(algorithm).family


def written_cells(window):
    raster = window.player.final_raster()
    return {(int(x), int(y)) for y, x in zip(*raster.counts.nonzero())}


def test_the_gallery_lists_every_scene_by_family_with_its_explanation(window, dialog):
    assert set(NAMED) <= {p.stem for p in SHIPPED}
    # Every scene, those of rendering/ too, each once.
    assert sorted(c.path for c in dialog.cases) == SHIPPED and not dialog.isModal()
    # Family by family (in the registry's order), a heading before each.
    families = [json.loads(c.path.read_text())["algorithm"] for c in dialog.cases]
    families = [_family(a) for a in families]
    assert families == sorted(families, key=FAMILIES.index)
    headings = [dialog.list.item(r).text() for r in range(dialog.list.count())
                if not dialog.list.item(r).flags() & Qt.ItemFlag.ItemIsSelectable]
    assert len(headings) == len(set(families)) and "The 3-D pipeline" in headings
    # Within the lines, the lecture order of the named cases holds.
    lines = [c.name for c in dialog.cases if c.name in NAMED[:3]]
    assert lines == list(NAMED[:3])
    for row, case in enumerate(dialog.cases):
        data = json.loads(case.path.read_text())
        text = dialog.item(row).data(Qt.ItemDataRole.AccessibleTextRole)
        assert data["title"] in text and data["description"] in text and data["algorithm"] in text
        # One line, saying something.
        assert "\n" not in data["description"] and len(data["description"]) > 40
        assert not dialog.pictures[row].pixmap().isNull(), case.name
    action = next(a for a in window.menus["help"].actions() if "hard cases" in a.text())
    assert action.toolTip()


def test_every_hard_case_opens_in_the_window_and_runs_to_the_end(window, dialog, capsys):
    for row, case in enumerate(dialog.cases):
        assert dialog.open_row(row), case.name
        player = window.player
        assert player.spec.name == case.scene.algorithm, case.name
        assert player.grid == (case.scene.width, case.scene.height), case.name
        player.to_last()
        assert len(player) > 1 and player.index == player.last, case.name
        assert window._error == "", (case.name, window._error)
        assert not player.trace.truncated, case.name
        # The command line runs the same scene to the same pixels.
        assert cli.main(["run", "--scene", str(case.path), "--json"]) == 0, case.name
        out = json.loads(capsys.readouterr().out)
        assert out["algorithm"] == case.scene.algorithm and out["steps"] == len(player)
        assert {tuple(p) for p in out["pixels"]} == written_cells(window), case.name


def test_run_scene_exits_0_with_json_for_every_scene(run_cli):
    # Every scene through the command line's code; the first also as a
    # program of its own (a process start per scene took a minute).
    for k, path in enumerate(SHIPPED):
        status, out, err = run_cli("run", "--scene", path, "--json", child=k == 0)
        assert status == 0, (path.name, err)
        assert json.loads(out)["algorithm"] == scenes.load(path).algorithm


def test_the_help_menu_opens_one_dialog_and_a_double_click_opens_a_scene(window, qtbot):
    action = next(a for a in window.menus["help"].actions() if "hard cases" in a.text())
    action.trigger()
    first = window.gallery_entry.window
    action.trigger()
    assert window.gallery_entry.window is first and first.isVisible()
    row = next(n for n, c in enumerate(first.cases) if c.name == "triangle-behind-eye")
    item = first.item(row)
    first.list.scrollToItem(item)
    centre = first.list.visualItemRect(item).center()
    QTest.mouseClick(first.list.viewport(), Qt.MouseButton.LeftButton, pos=centre)
    QTest.mouseDClick(first.list.viewport(), Qt.MouseButton.LeftButton, pos=centre)
    scene = first.cases[row].scene
    assert window.player.spec.name == "triangle-perspective"
    assert window.player.options["near"] == scene.options["near"]
    assert tuple(window.player.input_points()) == scene.points
    assert first.isVisible()  # non-modal: it stays open beside the window
    # Its pictures are drawn one per turn of the event loop: all drawn before
    # qtbot deletes the dialog, so none is drawn into a deleted label later.
    qtbot.waitUntil(lambda: first.thumbnails_done, timeout=WAIT_MS)


def test_open_works_without_the_file_menu_and_a_broken_file_is_refused(qtbot, tmp_path,
                                                                         monkeypatch):
    shown = []
    monkeypatch.setattr(QMessageBox, "warning", lambda *args: shown.append(args[2]))
    window = MainWindow()
    qtbot.addWidget(window)
    folder = tmp_path / "scenes"
    folder.mkdir()
    shutil.copy(ROOT / "resources" / "scenes" / "triangle-fan-32.json", folder)
    shutil.copy(ROOT / "resources" / "scenes" / "polygon-star-nonzero.json", folder)
    (folder / "broken.json").write_text("{not json")
    dialog = gal.GalleryDialog(window, folder)
    qtbot.addWidget(dialog)
    assert [c.name for c in dialog.cases] == ["polygon-star-nonzero", "triangle-fan-32"]
    assert dialog.open_row(1) and window.player.spec.name == "triangle-incremental"
    (folder / "polygon-star-nonzero.json").write_text("[]")  # spoiled after listing
    assert not dialog.open_row(0)
    assert window.player.spec.name == "triangle-incremental" and "polygon-star-nonzero" in shown[0]
    assert not dialog.open_row(5)
    qtbot.waitUntil(lambda: dialog.thumbnails_done, timeout=WAIT_MS)
