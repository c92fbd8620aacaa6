"""The window's named widgets keep their colours in both themes, in the
main window and in the windows and dialogs made later; the main window
itself has no style sheet (under one, every widget of the window goes
through Qt's slower style-sheet style)."""
import numpy as np
import pytest
from PySide6.QtGui import QColor
from PySide6.QtWidgets import QWidget

pytestmark = pytest.mark.window(shown=True)

# The look as designed: name -> (light, dark) colour of its text.
TEXT = {
    "section": ("#55606d", "#9aa7b5"),
    "summary": ("#55606d", "#9aa7b5"),
    "stepCaption": ("#1d2733", "#e6edf3"),
    "seriesTitle": ("#55606d", "#9aa7b5"),
    "codeNotes": ("#4b5563", "#c9d1d9"),
    "legend": ("#3d4754", "#c9d1d9"),
    "cursor": ("#3d4754", "#c9d1d9"),
    "differences": ("#b0245f", "#b0245f"),
    "coverage": ("#c2255c", "#c2255c"),
}
# name -> (light, dark) colour of its ground.
GROUND = {
    "transport": ("#f3f5f8", "#232a33"),
    "codeNotes": ("#f3f5f8", "#232a33"),
    "codeLines": ("#ffffff", "#1b2027"),
}


def named(root, name) -> list:
    found = root.findChildren(QWidget, name)
    assert found, f"no widget named {name!r}"
    return found


def text_colour(widget) -> str:
    widget.ensurePolished()
    return widget.palette().color(widget.foregroundRole()).name()


def ground_colour(widget) -> str:
    """The ground's colour; a table's is its viewport's, under its cells."""
    shown = widget.viewport() if hasattr(widget, "viewport") else widget
    widget.ensurePolished()
    return shown.palette().color(shown.backgroundRole()).name()


def painted_ground(widget) -> str:
    """The colour most of ``widget``'s grabbed pixels have."""
    image = widget.grab().toImage()
    rgb = np.array([[image.pixelColor(x, y).name() for x in range(0, image.width(), 3)]
                    for y in range(0, image.height(), 3)])
    colours, counts = np.unique(rgb, return_counts=True)
    return str(colours[counts.argmax()])


def test_the_main_window_has_no_style_sheet_of_its_own(window, theme):
    assert window.styleSheet() == ""
    theme("dark")
    assert window.styleSheet() == ""


@pytest.mark.parametrize("which", [0, 1])
def test_named_widgets_take_the_colours_of_the_theme(window, qtbot, theme, which):
    theme(("light", "dark")[which])
    qtbot.wait(10)
    for name, colours in TEXT.items():
        for widget in named(window, name):
            assert text_colour(widget) == colours[which], (name, widget)
    for name, colours in GROUND.items():
        for widget in named(window, name):
            assert ground_colour(widget) == colours[which], (name, widget)
    assert painted_ground(window.transport) == GROUND["transport"][which]


def test_back_to_light_after_dark(window, qtbot, theme):
    theme("dark")
    theme("light")
    qtbot.wait(10)
    assert text_colour(named(window, "stepCaption")[0]) == TEXT["stepCaption"][0]
    assert painted_ground(window.transport) == GROUND["transport"][0]


def test_the_toolbar_follows_the_theme(window, qtbot, theme):
    """The drawing tools' bar has a sheet of its own (its spacing); it is
    styled again when the theme changes, or it would keep the light ground."""
    bar = named(window, "drawingTools")[0]
    theme("dark")
    qtbot.wait(10)
    dark_ground = QColor(painted_ground(bar))
    assert dark_ground.lightnessF() < 0.3, dark_ground.name()
    theme("light")
    qtbot.wait(10)
    assert QColor(painted_ground(bar)).lightnessF() > 0.7


def test_windows_made_later_take_the_theme(window, qtbot, theme):
    compare = window.compare_entry.open()
    qtbot.wait(10)
    assert text_colour(named(compare, "stepCounter")[0]) == window.palette().text().color().name()
    assert ground_colour(named(compare, "transport")[0]) == GROUND["transport"][0]
    theme("dark")  # and follow a change of theme while open
    assert ground_colour(named(compare, "transport")[0]) == GROUND["transport"][1]
    theme("light")
    assert ground_colour(named(compare, "transport")[0]) == GROUND["transport"][0]
    compare.close()


@pytest.mark.window(files=True)
def test_the_export_dialog_takes_the_theme(window, qtbot, theme):
    theme("dark")
    controller = window.file_actions.export_animation()
    label = controller.dialog.size_label
    assert text_colour(label) == TEXT["summary"][1]
    controller.dialog.reject()


def test_the_coverage_legend_shows_the_overlaps_patterns(window):
    def colours_of(k):
        image = window.coverage_legend.chips[k][0].pixmap().toImage()
        return {image.pixelColor(x, y).name() for x in range(2, 12) for y in range(2, 12)}
    # Written once: its colour alone; twice, three times or more: marked in the ground colour.
    assert colours_of(1) == {"#4999c6"}
    assert colours_of(2) == {"#b35900", "#fbfcfd"}
    assert colours_of(3) == {"#3d1f5c", "#fbfcfd"}
