"""One way to make the window's panels: a movable, closable dock."""
from __future__ import annotations

from PySide6.QtWidgets import QDockWidget

FEATURES = (QDockWidget.DockWidgetFeature.DockWidgetMovable
            | QDockWidget.DockWidgetFeature.DockWidgetClosable)


def panel_dock(title: str, name: str, widget, parent) -> QDockWidget:
    """A dock holding ``widget``; ``name`` is its object name, which Qt uses
    to find it (and tests to look it up)."""
    dock = QDockWidget(title, parent)
    dock.setObjectName(name)
    dock.setWidget(widget)
    dock.setFeatures(FEATURES)
    return dock
