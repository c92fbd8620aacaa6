"""The "Pixel inspector" dock: what is known about one pixel at the step on show.

``InspectorDock(window)`` adds the dock (hidden until asked for, from
View > Pixel inspector, Ctrl+I), and wires it to the grid and the player:

* hovering a pixel inspects it;
* Alt+click, "Inspect pixel" in the grid's menu, or I over a pixel pins it:
  it stays inspected while stepping, outlined on the grid; Esc or the
  dock's Unpin button lets go;
* stepping re-inspects the same pixel at the new step.

The rows come from ``app.inspector``; only the inspected pixel at the
step on show is worked out, and only while the dock is on show.
"""
from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QKeySequence, QShortcut

from widgets.docks import panel_dock
from widgets.inspector_panel import InspectorPanel

from app.model.inspector import PixelInspector

# Violet: apart from every highlight colour of the grid (the compared run's
# differences are pink) in both themes.
PIN_COLOUR = "#7950f2"


class InspectorDock:
    """The dock, its View action, its shortcuts and the pin's outline."""

    def __init__(self, window):
        self.window = window
        self.pinned = None
        self.hovered = None
        self._inspector = None
        self.panel = InspectorPanel(window)
        self.dock = panel_dock("Pixel inspector", "inspectorDock", self.panel, window)
        window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.dock)
        self.dock.hide()
        self.action = self.dock.toggleViewAction()
        self.action.setText("Pixel inspector")
        self.action.setShortcut(QKeySequence("Ctrl+I"))
        self.action.setToolTip("Everything known about the pixel under the pointer, or a "
                               "pinned one, at the step on show (Ctrl+I)")
        window.addAction(self.action)
        window.menus["view"].addAction(self.action)
        self.pin_action = QAction("Pin the pixel under the pointer", window)
        self.pin_action.setShortcut(QKeySequence("I"))
        self.pin_action.setToolTip("Inspect the pixel under the pointer and keep it while "
                                   "stepping (I)")
        self.pin_action.triggered.connect(lambda: self.pin(self.hovered))
        window.addAction(self.pin_action)
        self.unpin_shortcut = QShortcut(QKeySequence("Esc"), window)
        self.unpin_shortcut.activated.connect(self.unpin)
        self.unpin_shortcut.activatedAmbiguously.connect(self.unpin)
        self.unpin_shortcut.setEnabled(False)
        self.outline = pg.PlotCurveItem(pen=pg.mkPen(PIN_COLOUR, width=3))
        self.outline.setZValue(5)
        self.outline.setVisible(False)
        window.grid.view_box.addItem(self.outline)

        window.grid.hoverChanged.connect(self._hovered)
        window.grid.inspectRequested.connect(self.pin)
        window.player.frameChanged.connect(lambda _index: self.refresh())
        window.player.traceChanged.connect(self._trace_changed)
        self.panel.unpinRequested.connect(self.unpin)
        self.dock.visibilityChanged.connect(self._shown)
        self._sized = False

    # ---------------------------------------------------------- pinning
    def pin(self, pixel) -> None:
        if pixel is None:
            return
        self.pinned = (int(pixel[0]), int(pixel[1]))
        x, y = self.pinned
        self.outline.setData([x, x + 1, x + 1, x, x], [y, y, y + 1, y + 1, y])
        self.outline.setVisible(True)
        self.unpin_shortcut.setEnabled(True)
        if not self.dock.isVisible():
            self.dock.show()  # refreshes through visibilityChanged
        self.refresh()

    def unpin(self) -> None:
        self.pinned = None
        self.outline.setVisible(False)
        self.unpin_shortcut.setEnabled(False)
        self.refresh()

    def _shown(self, visible: bool) -> None:
        if visible and not self._sized:
            # The first time, room for a triangle's rows; the others give up height.
            self._sized = True
            self.window.resizeDocks([self.dock], [max(320, self.window.height() // 2)],
                                    Qt.Orientation.Vertical)
        self.refresh()

    def _hovered(self, pixel) -> None:
        self.hovered = pixel
        if self.pinned is None:
            self.refresh()

    def _trace_changed(self) -> None:
        self._inspector = None
        width, height = self.window.player.grid
        if self.pinned is not None and not (self.pinned[0] < width and self.pinned[1] < height):
            self.unpin()
        self.refresh()

    # ---------------------------------------------------------- showing
    def refresh(self) -> None:
        """Inspect the pinned pixel, else the hovered one, at the step on show."""
        if not self.dock.isVisible():
            return
        pixel = self.pinned or self.hovered
        player = self.window.player
        if pixel is None or player.trace is None:
            why = "" if player.trace is not None else "No run: place the points first."
            self.panel.set_rows([], why, self.pinned is not None)
            return
        rows = self._inspector_for(player).rows(player.index, pixel)
        what = "Pinned" if self.pinned is not None else "Under the pointer"
        title = (f"<b>{what}: pixel ({pixel[0]}, {pixel[1]})</b> at step {player.index:,}")
        self.panel.set_rows(rows, title, self.pinned is not None)

    def _inspector_for(self, player) -> PixelInspector:
        if self._inspector is None or self._inspector.trace is not player.trace:
            trace = player.trace

            def raster_at(index):
                # The player replays the step on show once; reuse it.
                state = player.state() if index == player.index else None
                return state.raster if state is not None else trace.raster_at(index)

            shown = player.shown_scene  # the trace's own scene, even mid-recording
            self._inspector = PixelInspector(trace, shown.spec, shown.flat, shown.options,
                                             shown.grid, raster_at)
        return self._inspector


