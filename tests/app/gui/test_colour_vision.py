"""View > Colour vision: a live preview of the window as seen with a
colour-vision deficiency, closed by Esc."""
from __future__ import annotations

import numpy as np
from daltonlens import simulate
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor, QImage

from app.gui import colour_vision

# A saturated red: a protanope sees it as a dark olive, not red.
RED = (220, 30, 30)


def _expected(colour, deficiency):
    """The colour as daltonlens's Machado 2009 simulation sees it, asked here directly."""
    image = np.array([[colour]], np.uint8)
    return simulate.Simulator_Machado2009().simulate_cvd(image, deficiency, severity=1.0)[0, 0]


def test_the_view_menu_offers_each_colour_vision(window):
    names = [a.text() for a in window.colour_vision_actions.values()]
    assert names == ["Normal", "Protanopia", "Deuteranopia", "Tritanopia"]
    assert window.colour_vision_actions["normal"].isChecked()


def test_a_pixel_of_the_window_shows_as_simulated_and_esc_closes(window, qtbot, monkeypatch):
    # A grab of known colours stands in for the window, so that no font or
    # style of this machine matters: a red square on white.
    picture = QImage(200, 120, QImage.Format.Format_RGB888)
    picture.fill(QColor("#ffffff"))
    for x in range(40, 80):
        for y in range(30, 70):
            picture.setPixelColor(x, y, QColor(*RED))
    monkeypatch.setattr(colour_vision.ColourVisionPreview, "grab_rgb",
                        lambda self: colour_vision.rgb_of(picture))
    window.colour_vision_actions["protanopia"].trigger()
    preview = window.colour_vision
    qtbot.waitExposed(preview)
    assert preview.isVisible() and window.colour_vision_actions["protanopia"].isChecked()
    assert preview.accessibleName() == "Colour vision preview: protanopia"
    assert "protanopia" in preview.picture.accessibleName()
    shown = colour_vision.rgb_of(preview.picture.pixmap().toImage())
    protan = _expected(RED, simulate.Deficiency.PROTAN)
    assert shown[50, 60].tolist() == protan.tolist()
    assert shown[5, 5].tolist() == _expected((255, 255, 255), simulate.Deficiency.PROTAN).tolist()
    assert abs(int(protan[0]) - RED[0]) > 60  # the simulation did change the red
    # Another deficiency, the same preview, another picture.
    window.colour_vision_actions["tritanopia"].trigger()
    assert window.colour_vision is preview
    shown = colour_vision.rgb_of(preview.picture.pixmap().toImage())
    assert shown[50, 60].tolist() == _expected(RED, simulate.Deficiency.TRITAN).tolist()
    assert preview.accessibleName() == "Colour vision preview: tritanopia"
    # Esc closes it and the menu goes back to Normal.
    qtbot.keyClick(preview, Qt.Key.Key_Escape)
    assert not preview.isVisible()
    assert window.colour_vision_actions["normal"].isChecked()


def test_the_preview_grabs_the_window_itself(window, qtbot):
    window.colour_vision_actions["deuteranopia"].trigger()
    preview = window.colour_vision
    qtbot.waitExposed(preview)
    grab = preview.grab_rgb()
    room = preview.picture.size()
    assert grab.shape[2] == 3 and grab.shape[1] <= room.width() and grab.shape[0] <= room.height()
    assert preview.shown.shape == grab.shape
    window.colour_vision_actions["normal"].trigger()
    assert not preview.isVisible()


def test_rgb_of_and_image_of_are_inverse():
    rgb = np.arange(5 * 7 * 3, dtype=np.uint8).reshape(5, 7, 3)
    assert np.array_equal(colour_vision.rgb_of(colour_vision.image_of(rgb)), rgb)
