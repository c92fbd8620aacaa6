"""View > Exact fractions: the numbers setting (decimal or exact,
app/model/notation.py) of the window's panels and steps table.

``NumbersSetting(window)`` reads the stored preference, adds the checkable
entry, and on a change stores it and shows every panel (variables, tables,
caption values) and the steps table again in the new form at once.
"""
from __future__ import annotations

from PySide6.QtCore import QObject
from PySide6.QtGui import QAction


class NumbersSetting(QObject):
    """The window's numbers setting and its View menu entry."""

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.numbers = window.preferences.prefs.get("numbers")
        self.action = QAction("Exact fractions", window)
        self.action.setCheckable(True)
        self.action.setChecked(self.numbers == "exact")
        self.action.setToolTip("Show values the algorithm keeps exactly as fractions p/q, as "
                               "the lecture notes print them (an edge table's 1/m as -5/2, "
                               "Bresenham's m, barycentric weights); off: decimals")
        self.action.toggled.connect(lambda on: self.set_numbers("exact" if on else "decimal"))
        window.menus["view"].addAction(self.action)

    def set_numbers(self, numbers: str) -> None:
        """Use ``numbers`` everywhere in the window, and remember it."""
        if numbers == self.numbers:
            return
        self.numbers = numbers
        self.window.preferences.prefs.set("numbers", numbers)
        self.action.blockSignals(True)
        self.action.setChecked(numbers == "exact")
        self.action.blockSignals(False)
        self.window.numbers_changed()
