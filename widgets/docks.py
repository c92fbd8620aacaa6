"""One way to make the window's panels: a movable, closable dock."""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget, QFrame, QScrollArea

FEATURES = (QDockWidget.DockWidgetFeature.DockWidgetMovable
            | QDockWidget.DockWidgetFeature.DockWidgetClosable)


def panel_dock(title: str, name: str, widget, parent, scrolls: bool = False) -> QDockWidget:
    """A dock holding ``widget``; ``name`` is its object name, which Qt uses
    to find it (and tests to look it up). ``scrolls``: the widget sits in a
    scroll area, so that at a large zoom its width (a row of controls)
    does not set the dock's, nor push the window past the screen."""
    dock = QDockWidget(title, parent)
    dock.setObjectName(name)
    if scrolls:
        area = QScrollArea(dock)
        area.setWidget(widget)
        area.setWidgetResizable(True)
        area.setFrameShape(QFrame.Shape.NoFrame)
        area.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAsNeeded)
        widget = area
    dock.setWidget(widget)
    dock.setFeatures(FEATURES)
    return dock
