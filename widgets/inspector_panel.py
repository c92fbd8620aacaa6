"""The pixel inspector's panel: a tree of sections and label/value rows.

It shows rows made elsewhere (``app.inspector``); it only displays them,
and offers a button to unpin a pinned pixel.
"""
from __future__ import annotations

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (QHBoxLayout, QHeaderView, QLabel, QToolButton, QTreeWidget,
                               QTreeWidgetItem, QVBoxLayout, QWidget)

HINT = ("Hover over a pixel to inspect it; right-click it, Alt+click it or press I over "
        "it to pin it.")


class InspectorPanel(QWidget):
    """Sections (Trace, Triangle, Depth, Samples, Coverage) of label/value rows."""

    #: The person asked to unpin the pinned pixel.
    unpinRequested = Signal()

    def __init__(self, parent=None):
        super().__init__(parent)
        self.title = QLabel(HINT, self)
        self.title.setObjectName("inspectorTitle")
        self.title.setWordWrap(True)
        self.unpin = QToolButton(self)
        self.unpin.setText("Unpin")
        self.unpin.setToolTip("Stop inspecting the pinned pixel and follow the pointer "
                              "again (Esc)")
        self.unpin.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.unpin.clicked.connect(self.unpinRequested.emit)
        self.unpin.setVisible(False)
        self.tree = QTreeWidget(self)
        self.tree.setObjectName("inspectorRows")
        self.tree.setAccessibleName("Inspected pixel")
        self.tree.setColumnCount(2)
        self.tree.setHeaderLabels(["Quantity", "Value"])
        self.tree.setRootIsDecorated(False)
        self.tree.setAlternatingRowColors(True)
        self.tree.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.tree.setToolTip("What is known about the inspected pixel at the step on show")
        header = self.tree.header()
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.ResizeToContents)
        header.setStretchLastSection(True)
        top = QHBoxLayout()
        top.setContentsMargins(0, 0, 0, 0)
        top.addWidget(self.title, 1)
        top.addWidget(self.unpin, 0, Qt.AlignmentFlag.AlignTop)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(top)
        layout.addWidget(self.tree, 1)
        self._shown = None
        self._items: list[QTreeWidgetItem] = []

    def set_rows(self, rows, title: str = "", pinned: bool = False) -> None:
        """Show rows (section, label, value), grouped by section in order."""
        rows = [tuple(row) for row in rows]
        self.title.setText(title or HINT)
        self.unpin.setVisible(pinned)
        if rows == self._shown:
            return
        if self._shown is not None and [r[:2] for r in rows] == [r[:2] for r in self._shown]:
            self._update_values(rows)
            return
        self._shown = rows
        self._items = []
        self.tree.setUpdatesEnabled(False)
        self.tree.clear()
        section_item = None
        for section, label, value in rows:
            if section_item is None or section_item.text(0) != section:
                section_item = QTreeWidgetItem(self.tree, [section, ""])
                font = section_item.font(0)
                font.setBold(True)
                section_item.setFont(0, font)
                section_item.setFirstColumnSpanned(True)
            item = QTreeWidgetItem(section_item, [label, value])
            item.setToolTip(1, value)
            self._items.append(item)
        self.tree.expandAll()
        self.tree.setUpdatesEnabled(True)

    def _update_values(self, rows) -> None:
        # The same rows as before (stepping with a pixel pinned): only the
        # values that changed are set, which keeps stepping cheap.
        for item, old, new in zip(self._items, self._shown, rows):
            if old[2] != new[2]:
                item.setText(1, new[2])
                item.setToolTip(1, new[2])
        self._shown = rows

    def rows(self) -> dict[str, str]:
        """{label: value} of the rows on show (for checks)."""
        return {label: value for _section, label, value in self._shown or ()}
