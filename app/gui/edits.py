"""Every scene edit the person makes goes through here on its way to the
window, so that undo and redo cover them all: points drawn, dragged or
typed, contours, the algorithm, each option (per-vertex colour, z and w
among them), the grid size and the origin.

``SceneEdits(window)`` connects the scene editors to the window's
setters, each wrapped in ``SceneEdits.recording``: the scene before the
edit is kept in the session's history under the name of what changed, and the
Edit menu's Undo and Redo say that name.
"""
from __future__ import annotations

from contextlib import contextmanager

from PySide6.QtCore import QObject

from algorithms.core.registry import InputError

from app.model.history import MERGE_SECONDS

# Per-vertex options shown as columns of the vertex table. Lines take a
# colour per endpoint; triangles and the visibility runs take a colour,
# depth, w and s per vertex. (Fills and antialiasing have a "colors"
# option too, but per region or per shape, not per vertex.)
VERTEX_OPTIONS = ("colors", "z", "w", "s")
VERTEX_FAMILIES = ("lines", "triangles", "visibility")


def vertex_options(spec) -> list[str]:
    if spec.family not in VERTEX_FAMILIES:
        return []
    names = {option.name: option.kind for option in spec.options}
    return [name for name in VERTEX_OPTIONS if names.get(name) in ("colors", "numbers")]


class SceneEdits(QObject):
    """Records scene edits in the session's history and takes them back."""

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.session = window.player.session
        self.history = self.session.history
        self._gesture = 0  # one drag or click on the grid: its edits merge
        self._connect(window)
        self.refresh()

    def _connect(self, window) -> None:
        """Route every scene editor of ``window`` through the history."""
        g = window.grid
        g.editStarted.connect(self.start_gesture)
        g.gestured.connect(lambda gesture: self.gesture(lambda: window.draw(gesture)))
        g.radiusDragged.connect(lambda rx, ry: self.gesture(lambda: window.drag_radius(rx, ry)))
        g.markerPlaced.connect(lambda pixel: self.gesture(lambda: window.place_marker(pixel)))
        g.clearRequested.connect(window.clear_points)
        window.points.edited.connect(self.table_edited)
        window.points.refused.connect(window.say_error)
        window.picker.algorithmChosen.connect(lambda name: self.once(
            lambda: window.set_algorithm(name)))
        window.options.valueEdited.connect(lambda name, value: self.field(
            ("option", name), lambda: window.set_option(name, value)))
        window.grid_editor.gridChanged.connect(lambda width, height: self.field(
            ("grid",), lambda: window.set_grid(width, height)))
        window.grid_editor.originChanged.connect(lambda down: self.once(
            lambda: window.set_y_down(down)))
        window.y_down_action.toggled.connect(lambda down: self.once(
            lambda: window.set_y_down(down)))
        window.player.traceChanged.connect(self.sync_table)

    @contextmanager
    def recording(self, key=None, seconds: float | None = None):
        """Run an edit; if it changed the scene, remember the scene before it.
        Edits with the same ``key`` merge while the entry is open (for
        ``seconds`` after the last one; None: until another edit)."""
        try:
            with self.session.edit(key, seconds):
                yield
        finally:
            self.refresh()

    def start_gesture(self) -> None:
        self._gesture += 1
        self.history.seal()

    def gesture(self, edit) -> None:
        with self.recording(("gesture", self._gesture)):
            edit()

    def field(self, key, edit) -> None:
        """An edit from a typed or stepped field: merges for a moment."""
        with self.recording(key, MERGE_SECONDS):
            edit()

    def once(self, edit) -> None:
        with self.recording():
            edit()

    # ------------------------------------------------------- undo, redo
    def undo(self) -> None:
        self._go_to(self.session.undo)

    def redo(self) -> None:
        self._go_to(self.session.redo)

    def _go_to(self, move) -> None:
        """Put back a scene from the history (``move()`` returns it, None
        when there is none): the trace is recorded again and the step stays
        where it was, as a fraction of the run; the editors follow."""
        w, player = self.window, self.window.player
        algorithm = player.spec.name
        scene = move()
        if scene is not None:
            if scene.algorithm != algorithm:
                w.follow_scene()
            else:
                w.options.set_values(player.options)
                w.sync_grid()
            if scene.y_down != w.grid.y_down:
                w.set_y_down(scene.y_down)
        self.refresh()

    def refresh(self) -> None:
        """The Edit menu names the edit that Undo and Redo would take back."""
        actions = self.window.actions_
        for key, text, able in (("undo", self.history.undo_text, self.history.can_undo),
                                ("redo", self.history.redo_text, self.history.can_redo)):
            act = actions[key]
            title = "&Undo" if key == "undo" else "&Redo"
            act.setText(f"{title} {text}" if text else title)
            keys = act.shortcut().toString()
            act.setToolTip(f"{title[1:]} {text} ({keys})" if text else
                           f"Nothing to {key} ({keys})")
            act.setEnabled(able)

    # ------------------------------------------------------ vertex table
    def table_edited(self, points, breaks, attributes: dict) -> None:
        """Points, contours and per-vertex options typed into the table."""
        w, player = self.window, self.window.player
        options = dict(player.options, **attributes)
        with self.recording():
            try:
                player.restore(points, breaks, options)
            except InputError as error:
                w.say_error(str(error))
            w.options.set_values(player.options)
            w.sync_points()

    def sync_table(self) -> None:
        """The table's attribute columns follow the algorithm and options."""
        player = self.window.player
        if player.spec is not None:
            self.window.points.set_attributes(vertex_options(player.spec), player.options)
