"""A menu entry that opens one window of a kind for the main window (the
compare window, the report, the gallery): made on first use, brought back
after."""
from __future__ import annotations

from PySide6.QtGui import QAction

from app.gui.look import apply_look


class WindowEntry:
    """``action`` opens ``make(main)``, the first time made, then shown
    again (``refresh(window)`` lets it catch up with the main window)."""

    def __init__(self, main, action: QAction, make, refresh=None):
        self.main = main
        self.action = action
        self.window = None
        self._make = make
        self._refresh = refresh
        action.triggered.connect(self.open)

    def open(self):
        fresh = self.window is None
        if fresh:
            self.window = self._make(self.main)
            apply_look(self.window, self.main.dark)
        self.window.show()
        self.window.raise_()
        self.window.activateWindow()
        if not fresh and self._refresh is not None:
            self._refresh(self.window)
        return self.window
