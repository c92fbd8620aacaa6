"""The transport's icons stand out from the bar in both themes: a contrast
ratio (WCAG's, from the relative luminance of grabbed pixels) of at least
3:1, the least asked of the parts of a control."""
import numpy as np
import pytest

pytestmark = pytest.mark.window(shown=True)


def luminance(rgb) -> float:
    channel = np.asarray(rgb, float) / 255
    linear = np.where(channel <= 0.04045, channel / 12.92, ((channel + 0.055) / 1.055) ** 2.4)
    return float(linear @ [0.2126, 0.7152, 0.0722])


def contrast(a, b) -> float:
    high, low = sorted((luminance(a), luminance(b)), reverse=True)
    return (high + 0.05) / (low + 0.05)


def pixels(widget) -> np.ndarray:
    image = widget.grab().toImage().convertToFormat(widget.grab().toImage().Format.Format_RGB888)
    data = np.frombuffer(image.constBits(), np.uint8, image.sizeInBytes())
    rows = data.reshape(image.height(), image.bytesPerLine())[:, :image.width() * 3]
    return rows.reshape(image.height(), image.width(), 3)


def icon_contrast(button) -> float:
    """The most common colour is the background; the icon is the most
    common colour clearly unlike it (its fill, not the blended rim)."""
    rgb = pixels(button).reshape(-1, 3).astype(int)
    colours, counts = np.unique(rgb, axis=0, return_counts=True)
    background = colours[counts.argmax()]
    unlike = np.abs(colours - background).sum(axis=1) > 30
    assert unlike.any(), "no icon drawn"
    ink = colours[unlike][counts[unlike].argmax()]
    return contrast(background, ink)


@pytest.mark.parametrize("name", ["light", "dark"])
def test_transport_icons_contrast_with_the_bar(window, qtbot, theme, name):
    theme(name)
    qtbot.wait(20)
    t = window.transport
    buttons = (t.first_button, t.back_button, t.play_button, t.forward_button, t.last_button)
    for button in buttons:
        assert icon_contrast(button) >= 3.0, (name, button.toolTip(), icon_contrast(button))
    window.player.toggle()  # the pause icon too
    qtbot.wait(20)
    assert icon_contrast(t.play_button) >= 3.0
    window.player.pause()
