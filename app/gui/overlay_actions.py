"""View > Overlays: the geometry of a triangle run's step drawn over the grid
(half-planes, sub-triangles, distances, basis; see app/render/overlays.py,
which export draws from too, so window and file show the same)."""
from __future__ import annotations

from PySide6.QtGui import QAction

from widgets.overlay_layer import OverlayLayer

from app.render.overlays import OVERLAYS, overlay_strokes

TIPS = {"half-planes": "Hatch the side of each edge where its edge function is >= 0 "
                       "(red e0, green e1, magenta e2)",
        "sub-triangles": "The three triangles the step's pixel centre makes with the edges: "
                         "their areas over the whole are alpha, beta, gamma",
        "distances": "The perpendiculars from the pixel centre to the three edges",
        "basis": "The vectors P1 - P0 and P2 - P0 of the barycentric frame"}


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

    def shown(self) -> tuple[str, ...]:
        return tuple(name for name, act in self.actions.items() if act.isChecked())

    def refresh(self, *_args) -> None:
        player = self.window.player
        state = player.state()
        trace = player.trace
        strokes = [] if state is None or trace is None else \
            overlay_strokes(trace, state.index, self.shown())
        self.layer.set_strokes(strokes)
