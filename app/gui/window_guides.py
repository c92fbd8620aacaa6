"""The step's reasoning on the window's grid: the frame model's guides
(app/render/reasoning.py), the same ones an exported frame draws."""
from __future__ import annotations

from app.model.tools import shape_paths
from app.render.reasoning import step_guides
from widgets.guide_items import GuidesItem


class WindowGuides:
    """Keeps the grid's guides item at the player's step."""

    def __init__(self, grid, palette):
        self.item = GuidesItem(palette)
        self.grid = grid
        grid.view_box.addItem(self.item)
        self.paths: list = []

    def set_palette(self, palette) -> None:
        self.item.set_palette(palette)

    def run_changed(self, player) -> None:
        """The ideal primitive the guides point at (M's drop), for a new run."""
        self.paths = shape_paths(player.spec, player.points, player.options, player.breaks) \
            if player.trace is not None else []

    def show(self, trace, state) -> None:
        if trace is None or state is None:
            self.item.set_guides(None)
            return
        self.item.set_size(trace.width, trace.height)
        self.item.set_guides(step_guides(trace, state, self.paths, self.grid.y_down) or None)
