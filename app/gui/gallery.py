"""Help > Examples and hard cases…: the catalogue of shipped scenes, browsed.

``gallery_entry(window)`` makes the entry of the window's Help menu (File >
Open Example > Browse all… opens the same dialog). The dialog lists the
catalogue (app/model/catalogue.py) family by family under a heading each:
every scene's title, the one line that says what to look for, and its
algorithm; a small picture of each run's last frame follows once it is
drawn (one scene at a time, so the dialog opens at once). Open (or a
double-click) loads the scene into the window, through the File menu's
actions when they are installed.
"""
from __future__ import annotations

from html import escape
from pathlib import Path

from PySide6.QtCore import QSize, Qt, QTimer
from PySide6.QtGui import QImage, QPixmap
from PySide6.QtWidgets import (QDialog, QDialogButtonBox, QHBoxLayout, QLabel, QListWidget,
                               QListWidgetItem, QMessageBox, QVBoxLayout, QWidget)

from algorithms.core.registry import InputError

from app.render import compose as render
from app.model import catalogue
from app.model import scene as scenes
from app.model.catalogue import Example
from app.model.scene import SceneError, one_line

THUMBNAIL = QSize(112, 84)
MAX_THUMBNAIL_CELLS = 4096 * 512  # a bigger grid is shown without a picture


def thumbnail(scene: scenes.Scene) -> QImage | None:
    """The run's last frame as a small picture, or None when it cannot be drawn cheaply."""
    if scene.width * scene.height > MAX_THUMBNAIL_CELLS:
        return None
    try:
        trace = scene.spec.record(scene.points, scene.options, grid=(scene.width, scene.height))
        raster = trace.raster_at(len(trace) - 1)
    except InputError:
        return None
    scale = max(1, min(8, THUMBNAIL.width() // scene.width, THUMBNAIL.height() // scene.height))
    image = render.top_down(render.compose(raster, scale=scale, grid_lines=False),
                            scene.origin == "top-left")
    image = image.copy()  # QImage keeps a pointer: the array must stay contiguous and alive
    height, width = image.shape[:2]
    picture = QImage(image.data, width, height, 4 * width, QImage.Format.Format_RGBA8888)
    return picture.scaled(THUMBNAIL, Qt.AspectRatioMode.KeepAspectRatio,
                          Qt.TransformationMode.SmoothTransformation).copy()


class GalleryDialog(QDialog):
    """A non-modal list of the catalogue, under a heading per family; Open
    loads one scene into the window. ``folder`` lists that folder's scenes
    instead of the shipped ones."""

    def __init__(self, window, folder: Path | None = None):
        super().__init__(window)
        self.window_ = window
        self.setWindowTitle("Examples and hard cases")
        self.setModal(False)
        self.resize(720, 640)
        intro = QLabel("Every example RasterLab ships, family by family: what each shows "
                       "or what makes it hard, and what to look for. Open one to step "
                       "through it.")
        intro.setWordWrap(True)
        self.list = QListWidget()
        self.list.setSpacing(2)
        self.list.setToolTip("Double-click a scene to open it in the window")
        self.list.setAccessibleName("Scenes")
        # Selected rows stay light, so that the dark text on them stays readable.
        self.list.setStyleSheet("QListWidget::item:selected { background: #d3e4f6; }")
        paths = None if folder is None else sorted(Path(folder).glob("*.json"))
        self.cases = catalogue.examples(paths)
        self.pictures: list[QLabel] = []
        self.rows: list[int] = []  # the list row of each case (headings sit between)
        for family, entries in catalogue.by_family(self.cases):
            self._add_heading(catalogue.family_title(family))
            for case in entries:
                self.rows.append(self.list.count())
                self._add_row(case)
        self.list.itemDoubleClicked.connect(lambda item: self._open_list_row(self.list.row(item)))
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        self.open_button = buttons.addButton("Open", QDialogButtonBox.ButtonRole.AcceptRole)
        self.open_button.setToolTip("Load the selected scene into the window")
        buttons.button(QDialogButtonBox.StandardButton.Close).setToolTip("Close this list")
        self.open_button.setEnabled(False)
        self.list.currentRowChanged.connect(
            lambda row: self.open_button.setEnabled(row in self.rows))
        buttons.accepted.connect(lambda: self._open_list_row(self.list.currentRow()))
        buttons.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        layout.addWidget(intro)
        layout.addWidget(self.list, 1)
        layout.addWidget(buttons)
        self._pending = list(range(len(self.cases)))
        self.thumbnails_done = not self._pending
        QTimer.singleShot(0, self, self._next_thumbnail)

    def item(self, case: int) -> QListWidgetItem:
        """The list's row of the ``case``-th scene."""
        return self.list.item(self.rows[case])

    def _add_heading(self, title: str) -> None:
        """A family's heading: a bold row that cannot be selected or opened."""
        item = QListWidgetItem(title)
        font = item.font()
        font.setBold(True)
        item.setFont(font)
        item.setFlags(Qt.ItemFlag.ItemIsEnabled)  # drawn as text, never selected
        self.list.addItem(item)

    def _add_row(self, case: Example) -> None:
        """One row: the picture (drawn later) beside the title, the explanation and the
        algorithm. The labels let mouse clicks through, so the row selects and opens."""
        item = QListWidgetItem()
        item.setData(Qt.ItemDataRole.AccessibleTextRole, case.text())
        item.setToolTip(f"{case.scene.description}\n{case.name}")
        row = QWidget()
        picture = QLabel()
        picture.setFixedSize(THUMBNAIL)
        picture.setAlignment(Qt.AlignmentFlag.AlignCenter)
        spec, scene = case.scene.spec, case.scene
        text = QLabel(f"<b>{escape(case.title)}</b><br>{escape(scene.description)}"
                      f"<br><span style='color:#5b6675'>{escape(spec.title)} ({spec.name}), "
                      f"{scene.width} x {scene.height} grid</span>")
        text.setWordWrap(True)
        text.setTextFormat(Qt.TextFormat.RichText)
        for label in (picture, text):
            label.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)
        layout = QHBoxLayout(row)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addWidget(picture)
        layout.addWidget(text, 1)
        row.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)
        item.setSizeHint(QSize(0, THUMBNAIL.height() + 12))
        self.list.addItem(item)
        self.list.setItemWidget(item, row)
        self.pictures.append(picture)

    def _next_thumbnail(self) -> None:
        """Draw one scene's picture, then let the event loop breathe before the next."""
        if not self._pending:
            self.thumbnails_done = True
            return
        row = self._pending.pop(0)
        picture = thumbnail(self.cases[row].scene)
        if picture is not None:
            self.pictures[row].setPixmap(QPixmap.fromImage(picture))
        else:
            self.pictures[row].setText("(large grid)")
        QTimer.singleShot(0, self, self._next_thumbnail)

    def _open_list_row(self, row: int) -> bool:
        return row in self.rows and self.open_row(self.rows.index(row))

    def open_row(self, case: int) -> bool:
        """Load the ``case``-th scene into the window; say why if it cannot be."""
        if not 0 <= case < len(self.cases):
            return False
        path = self.cases[case].path
        actions = getattr(self.window_, "file_actions", None)
        if actions is not None:
            return actions.open_path(path, remember=False)
        return _open_directly(self.window_, path)


def _open_directly(window, path: Path) -> bool:
    """Without the File menu's actions: show the scene through the window's own methods."""
    try:
        scene = scenes.load(path)
        window.set_scene(scene.algorithm, scene.points, scene.options, (scene.width, scene.height))
        window.set_y_down(scene.origin == "top-left")
    except (SceneError, InputError) as error:
        QMessageBox.warning(window, "Examples", f"Cannot open {path.name}:\n{one_line(str(error))}")
        return False
    return True
