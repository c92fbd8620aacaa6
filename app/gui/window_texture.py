"""The texture panel of the step on show (a part of ``MainWindow``): for runs that look a
texture up, the texture level in use with the pixel's footprint and fetched texels, and the
grid coloured by mip level; for the pipeline, the scene seen from outside with the frustum."""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFileDialog

from app.model.geometry import projected_paths
from app.render.compose import PALETTE
from app.render.outside_view import outside_view
from app.render.texture_frame import LEVEL_COLOURS, level_map, texture_picture
from widgets.docks import panel_dock
from widgets.outside_view import OutsideView
from widgets.texture_view import TextureView


def level_legend(count: int) -> str:
    swatches = " ".join(
        f'<span style="color: rgb{tuple(int(c) for c in LEVEL_COLOURS[k % len(LEVEL_COLOURS)])}">'
        f'\u25a0</span>&nbsp;{k}' for k in range(count))
    return f"Mip level read per pixel (the finer of two): {swatches}"


class TextureDisplay:
    """The texture dock: made on first need, shown for runs with a texture."""

    texture_dock = None
    outside_dock = None

    def _prepare_texture(self) -> None:
        self._prepare_outside()
        trace = self.player.trace
        wanted = trace is not None and "level" in trace.value_names
        if wanted and self.texture_dock is None:
            self.texture_view = TextureView(PALETTE, self)
            self.texture_view.open_requested.connect(self.open_texture)
            self.texture_dock = panel_dock("Texture", "textureDock", self.texture_view, self)
            self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.texture_dock)
            self.texture_dock.show()
            # Room for the pictures: the texture wants about a third of the height.
            self.resizeDocks([self.texture_dock], [max(300, self.height() // 3)],
                             Qt.Orientation.Vertical)
        if self.texture_dock is not None and wanted != self.texture_dock.isVisibleTo(self):
            self.texture_dock.setVisible(wanted)

    def _show_texture(self, state) -> None:
        if self.texture_dock is None or not self.texture_dock.isVisibleTo(self):
            return
        trace = self.player.trace
        picture = texture_picture(trace, state.index, self.player.options)
        self.texture_view.set_picture(picture)
        # The legend names the levels of the texture on show (one when there is none).
        levels = 1 if picture is None else picture.levels
        self.texture_view.set_y_down(self.grid.y_down)
        self.texture_view.set_levels(level_map(trace, state.index), level_legend(levels))

    def open_texture(self, path: str | None = None) -> None:
        """Use a PNG as the texture; a file that is no usable texture is a message."""
        if path is None:
            path, _ = QFileDialog.getOpenFileName(self, "Open texture", "",
                                                  "PNG images (*.png);;All files (*)")
            if not path:
                return
        self.set_option("texture", path)

    def _prepare_outside(self) -> None:
        player = self.player
        wanted = player.spec.name == "pipeline" and player.trace is not None
        if wanted and self.outside_dock is None:
            self.outside_view = OutsideView(PALETTE, self)
            self.outside_dock = panel_dock("Scene from outside", "outsideDock", self.outside_view,
                                           self)
            self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.outside_dock)
            self.outside_dock.show()
            self.resizeDocks([self.outside_dock], [max(260, self.height() // 3)],
                             Qt.Orientation.Vertical)
        if self.outside_dock is None:
            return
        if wanted != self.outside_dock.isVisibleTo(self):
            self.outside_dock.setVisible(wanted)
        if wanted:
            self.outside_view.set_view(outside_view(player.points, player.options, player.grid))
            self.grid.set_shape(projected_paths(player.trace))
