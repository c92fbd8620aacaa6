"""The keys a lecturer steps with, wherever the focus is: the arrows,
Home/End and Space (the Run menu's), PageDown/PageUp as well (what presenter
clickers send) and B for a blank, black screen, as presentation programs
have it.

The window's shortcuts reach it from any widget but one that takes typing:
a text field keeps the arrows and Space while it has the focus. So the
focus leaves the algorithm search once it has done its work (Enter picks
the algorithm), and a scene opened from the gallery or a file gives the
keyboard back to the window's grid.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import QWidget

CLICKER_KEYS = {"forward": "PgDown", "back": "PgUp"}


class BlankScreen(QWidget):
    """Black over the whole window; a click or B again takes it away."""

    def __init__(self, window):
        super().__init__(window)
        self.setObjectName("blankScreen")
        self.setAutoFillBackground(True)
        palette = self.palette()
        palette.setColor(self.backgroundRole(), Qt.GlobalColor.black)
        self.setPalette(palette)
        self.hide()

    def mousePressEvent(self, event):  # noqa: N802
        self.hide()


class PresenterKeys(QObject):
    def __init__(self, window):
        super().__init__(window)
        self.window = window
        for key, extra in CLICKER_KEYS.items():
            action = window.actions_[key]
            action.setShortcuts([*action.shortcuts(), QKeySequence(extra)])
        self.blank = BlankScreen(window)
        window.add_action(window.menus["view"], "blank", "&Blank screen", "B",
                          self.toggle_blank).setToolTip(
            "Black out the window, as a presentation does (B again, or a click, brings it back)")
        window.picker_search.returnPressed.connect(self.focus_grid)
        window.installEventFilter(self)

    def toggle_blank(self) -> None:
        if self.blank.isVisible():
            self.blank.hide()
            return
        self.blank.setGeometry(self.window.rect())
        self.blank.show()
        self.blank.raise_()

    def focus_grid(self) -> None:
        """The keyboard to the main window's grid, so that the keys step."""
        window = self.window
        if window.isVisible():
            window.activateWindow()
        window.grid.setFocus(Qt.FocusReason.OtherFocusReason)

    def eventFilter(self, obj, event) -> bool:  # noqa: N802
        if event.type() == QEvent.Type.Resize and self.blank.isVisible():
            self.blank.setGeometry(self.window.rect())
        return False
