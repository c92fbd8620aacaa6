"""The grid's view box: clicks and drags go to the grid's drawing tools;
anything else pans or zooms as in any pyqtgraph view."""
from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import Qt


class GridViewBox(pg.ViewBox):
    """A ViewBox that hands clicks and drags to the drawing tools, and pans
    or zooms otherwise."""

    def __init__(self, owner):
        super().__init__(lockAspect=True, enableMenu=False)
        self._owner = owner
        self._dragging = None

    def mouseClickEvent(self, ev):  # noqa: N802
        if ev.button() == Qt.MouseButton.LeftButton:
            ev.accept()
            self._owner._clicked(ev.scenePos(), ev.modifiers(), ev.double())
        elif ev.button() == Qt.MouseButton.RightButton:
            ev.accept()
            self._owner._context_menu(ev.scenePos(), ev.screenPos())
        else:
            super().mouseClickEvent(ev)

    def mouseDragEvent(self, ev, axis=None):  # noqa: N802
        if ev.button() == Qt.MouseButton.LeftButton:
            if ev.isStart():
                self._dragging = self._owner._drag_target(ev.buttonDownScenePos(), ev.modifiers())
                if self._dragging is not None:
                    self._owner.editStarted.emit()
            if self._dragging is not None:
                ev.accept()
                self._owner._dragged(self._dragging, ev.scenePos(), ev.modifiers(),
                                     ev.isFinish())
                if ev.isFinish():
                    self._dragging = None
                return
        # Anything else pans (left or middle button) or zooms (right button).
        super().mouseDragEvent(ev, axis)
