"""View > Overlays: the geometry of a triangle run's step drawn over the grid
(half-planes, sub-triangles, distances, basis) and a line run's octant
diagram (octants); see app/render/overlays.py, which export draws from too,
so window and file show the same."""
from __future__ import annotations

from PySide6.QtGui import QAction

from widgets.overlay_layer import OverlayLayer

from algorithms.lines.common import octant_map
from app.render.octant_overlay import line_on_grid
from app.render.overlays import OVERLAYS, Shapes, overlay_shapes

TIPS = {"half-planes": "Tint the side of each edge where its edge function is >= 0 "
                       "(edges: red e0, green e1, magenta e2); the tints overlap darkest "
                       "inside the triangle",
        "sub-triangles": "The three triangles the step's pixel centre makes with the edges: "
                         "their areas over the whole are the weights \u03b1, \u03b2, \u03b3 "
                         "of the opposite vertices P0, P1, P2",
        "distances": "The perpendiculars from the pixel centre to the three edges",
        "basis": "The vectors P1 - P0 and P2 - P0 of the barycentric frame",
        "octants": "Lines: the eight octants around P, the line's (green), the mirrors "
                   "that take it to the first octant (dashed) and its image there"}


class TriangleOverlays:
    """The overlay toggles of a window and the layer that draws them."""

    def __init__(self, window):
        self.window = window
        self.layer = OverlayLayer(window.grid.view_box)
        self.actions: dict[str, QAction] = {}
        menu = window.menus["view"].addMenu("&Overlays")
        menu.setToolTipsVisible(True)
        for name in OVERLAYS:
            act = menu.addAction(name.replace("-", " ").capitalize())
            act.setCheckable(True)
            act.setToolTip(TIPS[name])
            act.toggled.connect(self.refresh)
            self.actions[name] = act
            window.actions_[f"overlay-{name}"] = act
        window.player.frameChanged.connect(self.refresh)
        window.player.traceChanged.connect(self.refresh)
        window.player.traceChanged.connect(self.show_octant_text)
        self.actions["octants"].toggled.connect(self.show_octant_text)

    def shown(self) -> tuple[str, ...]:
        return tuple(name for name, act in self.actions.items() if act.isChecked())

    def line(self):
        """The run's segment P -> Q in grid units, or None when it draws no line."""
        player = self.window.player
        return line_on_grid(player.spec, player.points) if player.trace is not None else None

    def refresh(self, *_args) -> None:
        player = self.window.player
        state = player.state()
        trace = player.trace
        shapes = Shapes() if state is None or trace is None else \
            overlay_shapes(trace, state.index, self.shown(), self.line())
        self.layer.set_shapes(shapes)

    def octant_text(self) -> str:
        """What the octant diagram says in words, or "" when it shows nothing."""
        line = self.line()
        if line is None or not self.actions["octants"].isChecked():
            return ""
        (x0, y0), (x1, y1) = line
        return octant_map(x1 - x0, y1 - y0).text()

    def show_octant_text(self, *_args) -> None:
        text = self.octant_text()
        if text:
            self.window.statusBar().showMessage(text)

    def switch_on(self, names) -> None:
        """Check the overlays a scene names (unknown names skipped)."""
        for name in names:
            if name in self.actions:
                self.actions[name].setChecked(True)
