"""A menu entry that opens one window of a kind for the main window (the
compare window, the report, the gallery): made on first use, brought back
after. The entries are made with the main window; the windows' modules
load when a window is first opened (some 3 ms less of the start-up)."""
from __future__ import annotations

from PySide6.QtGui import QAction, QKeySequence

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


def compare_entry(window) -> WindowEntry:
    """View > Compare… (Ctrl+K) of the main window, and the compare window it opens."""
    menu = window.menus["view"]
    menu.addSeparator()
    action = QAction("&Compare\u2026", window)
    action.setShortcut(QKeySequence("Ctrl+K"))
    action.setToolTip("Compare algorithms side by side on the same primitives, stepped "
                      "together, with a diff of two of them (Ctrl+K)")
    menu.addAction(action)
    window.addAction(action)
    # Brought back, it catches up with what the main window did meanwhile.
    return WindowEntry(window, action, _compare_window, refresh=lambda made: made.main_changed())


def gallery_entry(window) -> WindowEntry:
    """Help > Examples and hard cases… of the main window, and the gallery it opens."""
    menu = window.menus["help"]
    action = QAction("&Examples and hard cases\u2026", window)
    action.setToolTip("Every shipped scene by family: the examples and the hard cases that "
                      "make the algorithms stumble, each with what to look for")
    action.setStatusTip(action.toolTip())
    first = menu.actions()[0] if menu.actions() else None
    menu.insertAction(first, action)
    return WindowEntry(window, action, _gallery)


def report_entry(window) -> WindowEntry:
    """Run > Report… of the main window, and the report dialog it opens."""
    menu = window.menus["run"]
    menu.addSeparator()
    action = QAction("&Report: speed against error\u2026", window)
    action.setShortcut(QKeySequence("Ctrl+R"))
    menu.addAction(action)
    return WindowEntry(window, action, _report)


def _compare_window(main):
    from app.gui.compare_window import CompareWindow
    return CompareWindow(main)


def _gallery(main):
    from app.gui.gallery import GalleryDialog
    return GalleryDialog(main)


def _report(main):
    from app.gui.report_window import ReportDialog
    return ReportDialog(main)
