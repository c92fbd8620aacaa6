"""Scene files and animation export in the window's File menu.

``MainWindow.add_file_actions()`` adds to the File menu:
Open…, Open Recent, Open Example (the catalogue of shipped scenes, a
submenu per family), Save, Save As… and Export Animation…
(Ctrl+E). It reads and changes the window's scene only through the
window's public methods (``set_scene``, ``set_y_down``, the player, the
transport's speed), so the window itself knows nothing of files.

Opening a file that cannot be used shows why and leaves the scene on show
as it was. Shipped scenes (anything inside the program's own folder) are
read-only: Save on one acts as Save As, and saves and exports start in the
user's documents folder. Saving writes a temporary file and renames it over the target
(``app.scene.save``), so a failed save never leaves half a file.
"""
from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, QSettings, Qt, Signal
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QFileDialog, QMenu, QMessageBox

from algorithms.core.registry import InputError

from app.gui.appdata import documents_dir, open_settings
from app.model import catalogue, shipped
from app.model import scene as scenes
from app.model.scene import Scene, SceneError, one_line

if TYPE_CHECKING:
    from app.gui.export_job import ExportController

RECENT_KEY = "scenes/recent"
MAX_RECENT = 8
SCENE_FILTER = "RasterLab scenes (*.json);;All files (*)"


class FileActions(QObject):
    """The File menu's scene and export actions for one window."""

    # The scene on show is now the one in a file (or an example): its path,
    # or None for an example.
    saved = Signal(object)
    opened = Signal(object)
    # A scene put in new bookmarks (the list object is replaced).
    bookmarksChanged = Signal()
    # An open that recorded in the background was cancelled or failed: the
    # scene on show before it is back.
    reverted = Signal()

    def __init__(self, window, settings: QSettings | None = None):
        super().__init__(window)
        self.window = window
        if settings is None:
            settings = open_settings()  # honours $RASTERLAB_SETTINGS
        self.settings = settings
        self.path: Path | None = None
        # What a scene file holds beyond what the window edits; kept from
        # the file opened last and written back on save.
        self.title = ""
        self.description = ""
        # Bookmarks made before the file actions came keep their place.
        self.bookmarks: list = [dict(b) for b in window.bookmarks]
        self.export_controller: ExportController | None = None
        # (path, what to put back) of a file whose run still records.
        self._opening: tuple | None = None
        self._build_menu()

    # ------------------------------------------------------------- menu
    def _build_menu(self) -> None:
        window = self.window
        menu = _file_menu(window)
        first = menu.actions()[0] if menu.actions() else None

        def action(text, shortcut, slot):
            act = QAction(text, window)
            if shortcut is not None:
                act.setShortcut(QKeySequence(shortcut))
            act.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
            act.triggered.connect(slot)
            menu.insertAction(first, act)
            window.addAction(act)  # the shortcut works wherever the focus is in the window
            return act

        self.open_action = action("&Open\u2026", QKeySequence.StandardKey.Open, self.open_dialog)
        self.recent_menu = QMenu("Open &Recent", window)
        menu.insertMenu(first, self.recent_menu)
        self.examples_menu = QMenu("Open &Example", window)
        menu.insertMenu(first, self.examples_menu)
        menu.insertSeparator(first)
        self.save_action = action("&Save", QKeySequence.StandardKey.Save, self.save)
        self.save_as_action = action("Save &As\u2026", QKeySequence.StandardKey.SaveAs,
                                     self.save_as)
        menu.insertSeparator(first)
        self.export_action = action("&Export Animation\u2026", "Ctrl+E", self.export_animation)
        self.export_page_action = action("Export Interactive &Page\u2026", "Ctrl+Shift+E",
                                         self.export_page)
        if first is not None:
            menu.insertSeparator(first)
        # The shipped scenes are read when the menu first opens, not with
        # the window: reading them all is a good part of start-up.
        self.examples_menu.aboutToShow.connect(self._fill_examples)
        self._fill_recent()

    def _fill_examples(self) -> None:
        """The catalogue: Browse all… (the gallery, with pictures), then a
        submenu per family, its scenes by title."""
        if self.examples_menu.actions():
            return
        gallery = getattr(self.window, "gallery_entry", None)
        if gallery is not None:
            self.examples_menu.addAction("&Browse all\u2026", gallery.open)
            self.examples_menu.addSeparator()
        for family, entries in catalogue.by_family(catalogue.examples()):
            submenu = self.examples_menu.addMenu(catalogue.family_title(family))
            for entry in entries:
                act = submenu.addAction(entry.title)
                act.setData(str(entry.path))
                act.setToolTip(entry.scene.description)
                act.triggered.connect(
                    lambda checked=False, p=entry.path: self.open_path(p, remember=False))
            submenu.setToolTipsVisible(True)
        self.examples_menu.setEnabled(not self.examples_menu.isEmpty())

    def example_actions(self) -> list[QAction]:
        """Every scene's entry of Open Example, family by family."""
        self._fill_examples()
        return [act for menu_act in self.examples_menu.actions() if menu_act.menu()
                for act in menu_act.menu().actions()]

    def recent(self) -> list[str]:
        value = self.settings.value(RECENT_KEY, [])
        if isinstance(value, str):
            value = [value]  # QSettings gives a single string for a one-item list
        return [str(v) for v in value or []]

    def _remember(self, path: Path) -> None:
        text = str(Path(path).resolve())
        paths = [text] + [p for p in self.recent() if p != text]
        self.settings.setValue(RECENT_KEY, paths[:MAX_RECENT])
        self.settings.sync()
        self._fill_recent()

    def _fill_recent(self) -> None:
        self.recent_menu.clear()
        for text in self.recent():
            act = self.recent_menu.addAction(text)
            act.triggered.connect(lambda checked=False, p=text: self.open_path(p))
        if self.recent():
            self.recent_menu.addSeparator()
            self.recent_menu.addAction("Clear the list", self._clear_recent)
        self.recent_menu.setEnabled(bool(self.recent()))

    def _clear_recent(self) -> None:
        self.settings.setValue(RECENT_KEY, [])
        self._fill_recent()

    # ------------------------------------------------------------ scenes
    def current_scene(self) -> Scene:
        """The scene on show, as a scene file holds it (without a contour or
        a triangle still being drawn)."""
        window, session = self.window, self.window.player.session
        view = {"step": int(session.index), "speed": float(window.player.speed),
                "compare": bool(window.compare.isChecked())}
        return session.scene.replace(points=session.input_points(), title=self.title,
                                     description=self.description, view=view,
                                     bookmarks=self.bookmarks)

    def apply_scene(self, scene: Scene) -> None:
        """Show ``scene`` in the window; raises InputError (and changes
        nothing) when the window cannot show it."""
        window = self.window
        window.set_scene(scene.algorithm, scene.points, scene.options,
                         (scene.width, scene.height))
        window.set_y_down(scene.origin == "top-left")
        view = scene.view
        if "compare" in view:
            window.compare.setChecked(bool(view["compare"]))
        if "speed" in view:
            window.transport.set_speed(view["speed"])
        window.overlays.switch_on(view.get("overlays", ()))
        if "step" in view:
            from app.gui.recording import seek_when_recorded  # a long run may still be recording
            seek_when_recorded(window.player, int(view["step"]))
        self.title, self.description = scene.title, scene.description
        self.bookmarks = [dict(b) for b in scene.bookmarks]
        self.bookmarksChanged.emit()

    def may_replace(self) -> bool:
        """Unsaved changes are saved, discarded or kept (Cancel: False)
        before another scene replaces them, as on Quit."""
        recovery = self.window.recovery  # it knows what is unsaved
        return recovery is None or recovery.confirm_close("opening another scene")

    def open_dialog(self) -> bool:
        if not self.may_replace():
            return False
        start = str(self.path.parent) if self.path else str(Path.home())
        path, _ = QFileDialog.getOpenFileName(self.window, "Open scene", start, SCENE_FILTER)
        return self.open_path(path, asked=True) if path else False

    def open_path(self, path, remember: bool = True, asked: bool = False) -> bool:
        """Open a scene file; on failure say why and change nothing.

        A scene too large to record at once records in the background: the
        file counts as opened (its name, the unsaved mark) only once its run
        is installed. Cancelled or failed, the scene on show, its name and
        its unsaved mark stay as they were, so a later save cannot write the
        previous scene over the file. Unsaved changes are asked about
        first unless ``asked``."""
        if not asked and not self.may_replace():
            return False
        path = Path(path)
        # A second open while the first still records goes back to what
        # was on show before the first.
        before = self._opening[1] if self._opening else self._snapshot()
        try:
            scene = scenes.load(path)
            self.apply_scene(scene)
        except (SceneError, InputError) as error:
            QMessageBox.warning(self.window, "Open scene",
                                f"Cannot open {path.name}:\n{one_line(str(error))}")
            return False
        if self.window.player.recording:
            self._open_when_recorded(path, remember, before)
        else:
            self._opening = None
            self._opened(path, remember)
        return True

    @property
    def opening(self) -> bool:
        """Is a file opened whose run still records in the background?"""
        return self._opening is not None

    def _snapshot(self) -> dict:
        """What an open changes beside the session's scene, to put back."""
        window = self.window
        return {"title": self.title, "description": self.description,
                "bookmarks": [dict(b) for b in self.bookmarks],
                "compare": window.compare.isChecked(), "speed": window.player.speed,
                "y_down": window.grid.y_down}

    def _open_when_recorded(self, path: Path, remember: bool, before: dict) -> None:
        token = (path, before)
        self._opening = token

        def done(message: str) -> None:
            self.window.player.recordingFinished.disconnect(done)
            if self._opening is not token:
                return  # a newer open took its place
            self._opening = None
            if message:  # cancelled or failed: the previous scene is back
                self._put_back(before)
                self._status(f"Not opened {path.name}: {one_line(message)}")
            else:
                self._opened(path, remember)
        self.window.player.recordingFinished.connect(done)

    def _put_back(self, before: dict) -> None:
        window = self.window
        self.title, self.description = before["title"], before["description"]
        self.bookmarks = before["bookmarks"]
        self.bookmarksChanged.emit()
        window.compare.setChecked(before["compare"])
        window.transport.set_speed(before["speed"])
        # The origin was set on the scene kept on show too: set it back.
        window.set_y_down(before["y_down"])
        self.reverted.emit()

    def _opened(self, path: Path, remember: bool) -> None:
        self.path = path if remember else None
        if remember:
            self._remember(path)
        self._status(f"Opened {path.name}")
        self.opened.emit(self.path)

    @property
    def writable_path(self) -> Path | None:
        """The file Save writes to: the one opened or saved last, unless it
        is a shipped scene (read-only: Save asks for a new name)."""
        if self.path is None or shipped.is_program_file(self.path):
            return None
        return self.path

    def save(self) -> bool:
        if self.writable_path is None:
            return self.save_as()
        return self.save_to(self.path)

    def save_as(self) -> bool:
        name = self.path.name if self.path else "scene.json"
        start = str(self.writable_path or documents_dir() / name)
        path, _ = QFileDialog.getSaveFileName(self.window, "Save scene as", start, SCENE_FILTER)
        if not path:
            return False
        path = Path(path)
        if not path.suffix:
            path = path.with_suffix(".json")
        return self.save_to(path)

    def save_to(self, path) -> bool:
        """Save the scene on show to ``path`` (atomically); say why if not."""
        path = Path(path)
        if shipped.is_program_file(path):
            QMessageBox.warning(self.window, "Save scene",
                                f"{path.name} is in RasterLab's own folder, which is read-only: "
                                "save the scene somewhere else.")
            return False
        if self.window.player.trace is None:
            QMessageBox.warning(self.window, "Save scene",
                                "Place all the points first: a scene is saved with a full input.")
            return False
        if self._opening is not None:
            # The scene is the opened file's while the name is still the
            # previous file's: saving now would put one over the other.
            QMessageBox.information(self.window, "Save scene",
                                    f"{self._opening[0].name} is still being opened: save when "
                                    "its run is recorded, or cancel it (Esc) first.")
            return False
        try:
            scenes.save(self.current_scene(), path)
        except (SceneError, ValueError) as error:
            QMessageBox.warning(self.window, "Save scene",
                                f"Cannot save {path.name}:\n{one_line(str(error))}")
            return False
        self.path = path
        self._remember(path)
        self._status(f"Saved {path.name}")
        self.saved.emit(path)
        return True

    # ------------------------------------------------------------ export
    def export_page(self) -> "ExportController | None":
        """The export dialog set to write only the interactive page (HTML)."""
        controller = self.export_animation()
        if controller is not None:
            gif = controller.dialog.values()["gif"]
            controller.dialog.set_values({"gif": "", "html": str(Path(gif).with_suffix(".html"))})
        return controller

    def export_animation(self) -> "ExportController | None":
        """Open the export dialog for the run on show."""
        window = self.window
        player = window.player
        player.pause()
        refusal = _not_exportable(player)
        if refusal:
            QMessageBox.information(window, "Export animation", refusal)
            return None
        # Build the replay caches now, so that an export running beside the
        # window never builds them at the same time as the window does.
        player.trace.raster_at(len(player.trace) - 1)
        differences = player.differences if len(player.differences) else None
        scene = self.current_scene()
        if self.export_controller is not None:
            old, self.export_controller = self.export_controller, None
            old.close()
            old.dialog.deleteLater()
            old.deleteLater()
        # The export machinery (Pillow, the writers) loads on first use,
        # not with the window.
        from app.gui.export_job import EXPORT_FOLDER_KEY, ExportController
        folder = self.settings.value(EXPORT_FOLDER_KEY, "")
        if not folder or shipped.is_program_file(folder):
            folder = self.writable_path.parent if self.writable_path else documents_dir()
        name = (self.path.stem if self.path else scene.algorithm) + ".gif"
        self.export_controller = ExportController(window, scene, player.trace, differences,
                                                  str(Path(folder) / name), self.settings)
        self.export_controller.dialog.open()
        return self.export_controller

    def _status(self, text: str) -> None:
        self.window.statusBar().showMessage(text, 4000)


def _not_exportable(player) -> str:
    """Why the player's run cannot be exported now, or ""."""
    if player.trace is None:
        return "there is no run to export: place the points first"
    if player.recording:
        return ("the new run is still recording: export when it has finished, "
                "or cancel it to export the run on show")
    return ""


def _file_menu(window) -> QMenu:
    for action in window.menuBar().actions():
        menu = action.menu()
        if menu is not None and action.text().replace("&", "") == "File":
            return menu
    return window.menuBar().addMenu("&File")
