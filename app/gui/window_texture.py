"""The texture panel of the step on show (``MainWindow.texture_display``): for runs that look a
texture up, the texture level in use with the pixel's footprint and fetched texels, and the
grid coloured by mip level; for the pipeline, the picture of the stage at the step (the world
from above with the frustum, eye space, clip space, NDC, the window)."""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFileDialog

from app.model.geometry import projected_paths
from app.render.compose import PALETTE
from app.render.outside_view import handle_places
from app.render.stage_view import StagePictures
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
    """The texture and outside-view docks: made on first need, shown for
    runs with a texture (the pipeline's, for the outside view)."""

    def __init__(self, window):
        self.window = window
        self.dock = self.view = None  # the texture dock and its view
        self.outside_dock = self.outside_view = None
        self.handle_note = ""  # why the handles sit where they do, for the status line
        self.stages = None  # the pipeline run's StagePictures
        self._shown_stage = None

    def prepare(self) -> None:
        """Per run: each dock shown, made first if need be, or hidden."""
        self._prepare_outside()
        w = self.window
        trace = w.player.trace
        wanted = trace is not None and "level" in trace.value_names
        if wanted and self.dock is None:
            self.view = TextureView(PALETTE, w)
            self.view.open_requested.connect(self.open_texture)
            self.dock = panel_dock("Texture", "textureDock", self.view, w)
            w.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.dock)
            self.dock.show()
            # Room for the pictures: the texture wants about a third of the height.
            w.resizeDocks([self.dock], [max(300, w.height() // 3)], Qt.Orientation.Vertical)
        if self.dock is not None and wanted != self.dock.isVisibleTo(w):
            self.dock.setVisible(wanted)

    def show(self, state) -> None:
        """The texture level in use at the step, with the pixel's footprint; the pipeline's
        stage picture."""
        self._show_stage(state.index)
        w = self.window
        if self.dock is None or not self.dock.isVisibleTo(w):
            return
        trace = w.player.trace
        picture = texture_picture(trace, state.index, w.player.options)
        self.view.set_picture(picture)
        # The legend names the levels of the texture on show (one when there is none).
        levels = 1 if picture is None else picture.levels
        self.view.set_y_down(w.grid.y_down)
        self.view.set_levels(level_map(trace, state.index), level_legend(levels))

    def open_texture(self, path: str | None = None) -> None:
        """Use a PNG as the texture; a file that is no usable texture is a message."""
        if path is None:
            path, _ = QFileDialog.getOpenFileName(self.window, "Open texture", "",
                                                  "PNG images (*.png);;All files (*)")
            if not path:
                return
        self.window.set_option("texture", path)

    def _prepare_outside(self) -> None:
        w = self.window
        player = w.player
        wanted = player.spec.name == "pipeline" and player.trace is not None
        if wanted and self.outside_dock is None:
            self._make_outside_dock()
        self._place_handles(wanted)
        if self.outside_dock is None:
            return
        if wanted != self.outside_dock.isVisibleTo(w):
            self.outside_dock.setVisible(wanted)
        self.stages = None
        if wanted:
            self.stages = StagePictures(player.trace, player.points, player.options, player.grid)
            self._shown_stage = None
            self._show_stage(player.index)
            w.grid.set_shape(projected_paths(player.trace))

    def _show_stage(self, index: int) -> None:
        if self.stages is None or not self.outside_dock.isVisibleTo(self.window):
            return
        view = self.stages.at(index)
        if view is self._shown_stage:
            return
        self._shown_stage = view
        self.outside_view.set_view(view)
        self.outside_dock.setWindowTitle(view.title if view is not None else "Pipeline stage")

    def _make_outside_dock(self) -> None:
        # Under the Scene dock, which scrolls: the right-hand column holds the pseudo-code,
        # variables and depth buffer already and would leave the picture a strip.
        w = self.window
        self.outside_view = OutsideView(PALETTE, w)
        self.outside_dock = panel_dock("Pipeline stage", "outsideDock", self.outside_view, w)
        w.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, self.outside_dock,
                        Qt.Orientation.Vertical)
        self.outside_dock.show()
        share = w.height() * 2 // 5
        w.resizeDocks([w.scene_dock, self.outside_dock], [w.height() - share, share],
                      Qt.Orientation.Vertical)

    def _place_handles(self, pipeline: bool) -> None:
        """The pipeline's grid is window space: its handles sit where the viewport puts each
        vertex, and they do not drag (a window position does not say the world x, y, z)."""
        w = self.window
        places = handle_places(w.player.points, w.player.options, w.player.grid) \
            if pipeline else None
        w.grid.set_handle_places(places)
        self.handle_note = "" if places is None else (
            "The grid is window space: each handle sits where the viewport puts its vertex "
            "and does not drag; change the world x, y, z in the Points table"
            + (" (a vertex at or behind the eye has no place on the screen)"
               if None in places else "") + ".")
