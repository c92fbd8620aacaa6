"""View > Colour vision: the window as a person with protanopia,
deuteranopia or tritanopia sees it, so a lecturer can check a slide.

The preview is a separate window that shows a grab of the main window
passed through the simulation of app/render/vision.py (the one the palette
test checks). A grab of the whole window is simulated, rather than the
grid's colours alone, because the panels, legends, plot and chips carry
meaning in colour too, and a grab is what the screen shows, whatever drew
it. The grab is taken again twice a second and simulated only when it
changed; it is scaled to the preview's size first, as the simulation costs
time per pixel. Esc, or choosing Normal, closes it.
"""
from __future__ import annotations

import hashlib

import numpy as np
from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QAction, QActionGroup, QImage, QPixmap
from PySide6.QtWidgets import QDialog, QLabel, QVBoxLayout

NORMAL = "normal"
# app/render/vision.py's DEFICIENCIES; that module (daltonlens, Pillow) is
# loaded when a preview first opens, not with the window.
CHOICES = (NORMAL, "protanopia", "deuteranopia", "tritanopia")
REFRESH_MS = 500


def rgb_of(image: QImage) -> np.ndarray:
    """(H, W, 3) uint8 copy of a QImage's colours."""
    image = image.convertToFormat(QImage.Format.Format_RGB888)
    width, height, stride = image.width(), image.height(), image.bytesPerLine()
    rows = np.frombuffer(image.constBits(), np.uint8, count=stride * height).reshape(height, stride)
    return rows[:, :3 * width].reshape(height, width, 3).copy()


def image_of(rgb: np.ndarray) -> QImage:
    """A QImage owning a copy of (H, W, 3) uint8 colours."""
    rgb = np.ascontiguousarray(rgb)
    height, width = rgb.shape[:2]
    return QImage(rgb.data, width, height, 3 * width, QImage.Format.Format_RGB888).copy()


class ColourVisionPreview(QDialog):
    """A live, simulated picture of ``source`` (a widget, the main window)."""

    def __init__(self, source, deficiency: str, parent=None):
        super().__init__(parent)
        self.source = source
        self.picture = QLabel(self)
        self.picture.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.picture.setMinimumSize(320, 200)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.picture)
        self._last = None  # digest of the last grab simulated
        self.timer = QTimer(self)
        self.timer.setInterval(REFRESH_MS)
        self.timer.timeout.connect(self.refresh)
        self.set_deficiency(deficiency)
        size = source.size()
        self.resize(max(480, size.width() * 3 // 4), max(320, size.height() * 3 // 4))

    def set_deficiency(self, deficiency: str) -> None:
        self.deficiency = deficiency
        title = f"Colour vision preview: {deficiency}"
        self.setWindowTitle(title)
        self.setAccessibleName(title)
        self.picture.setAccessibleName(f"The main window as seen with {deficiency}")
        self.setAccessibleDescription("A simulated picture of the main window, refreshed as it "
                                      "changes. Esc closes it.")
        self._last = None
        self.refresh()

    def showEvent(self, event):  # noqa: N802
        super().showEvent(event)
        self.timer.start()
        self.refresh()

    def hideEvent(self, event):  # noqa: N802
        self.timer.stop()
        super().hideEvent(event)

    def resizeEvent(self, event):  # noqa: N802
        super().resizeEvent(event)
        self._last = None

    def grab_rgb(self) -> np.ndarray:
        """The source window's pixels, scaled to fit the preview."""
        grab = self.source.grab().toImage()
        room = self.picture.size()
        if grab.width() > room.width() or grab.height() > room.height():
            grab = grab.scaled(room, Qt.AspectRatioMode.KeepAspectRatio,
                               Qt.TransformationMode.SmoothTransformation)
        return rgb_of(grab)

    def refresh(self) -> None:
        """Simulate the source window again, if it changed since last time."""
        rgb = self.grab_rgb()
        digest = (rgb.shape, hashlib.blake2b(rgb.tobytes(), digest_size=16).digest())
        if digest == self._last:
            return
        self._last = digest
        from app.render.vision import simulate_rgb
        self.shown = simulate_rgb(rgb, self.deficiency)
        self.picture.setPixmap(QPixmap.fromImage(image_of(self.shown)))


def install(window, view_menu) -> None:
    """View > Colour vision: Normal, Protanopia, Deuteranopia, Tritanopia."""
    menu = view_menu.addMenu("Colour &vision")
    menu.setToolTip("Preview the window as a person with a colour-vision deficiency sees it")
    group = QActionGroup(window)
    window.colour_vision_actions = {}
    for name in CHOICES:
        act = QAction(name.capitalize(), window, checkable=True)
        act.setChecked(name == NORMAL)
        act.triggered.connect(lambda _on=False, name=name: show_preview(window, name))
        group.addAction(act)
        menu.addAction(act)
        window.colour_vision_actions[name] = act
        window.actions_[f"colour-vision-{name}"] = act
    window.colour_vision = None


def show_preview(window, name: str) -> None:
    """Open (or switch) the preview for ``name``; Normal closes it."""
    preview = window.colour_vision
    if name == NORMAL:
        if preview is not None:
            preview.close()
        return
    if preview is None:
        preview = window.colour_vision = ColourVisionPreview(window, name, window)
        preview.finished.connect(lambda _result: _closed(window))
    else:
        preview.set_deficiency(name)
    window.colour_vision_actions[name].setChecked(True)
    preview.show()
    preview.raise_()


def _closed(window) -> None:
    window.colour_vision_actions[NORMAL].setChecked(True)
