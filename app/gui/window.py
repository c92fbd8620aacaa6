"""The main window: the pixel grid in the middle, the scene on the left,
pseudo-code and variables on the right, the transport bar at the bottom.

``app.gui.launch()`` opens it; ``MainWindow`` can also be built on its own
(tests, screenshots, benchmarks) and driven through ``window.player``.
"""
from __future__ import annotations

import numpy as np
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMainWindow, QMessageBox

from algorithms.core import registry
from algorithms.core.raster import Raster
from algorithms.core.registry import InputError
from algorithms.core.steps import Note
from widgets.grid_view import DRAW, MARKER

from app.gui.appdata import APP_NAME
from app.gui.look import ERROR_STYLE, app_icon, apply_look, coverage_rows, legend_rows, recolor
from app.gui.player import Player
from app.gui.shortcuts import GESTURES, ShortcutsDialog
from app.gui.coverage_display import CoverageDisplay
from app.gui.window_depth import DepthDisplay
from app.gui.window_texture import TextureDisplay
from app.gui.window_layout import build_layout
from app.gui.window_menus import add_action, build_menus
from app.model.drawing import CONTOURS, point_labels
from app.model.insight import PixelTally, has_insight, inside_chips, row_tones
from app.model.notation import colour_names, shown
from app.model.notes import note_at
from app.gui.window_guides import WindowGuides
from app.model.inputs import split_contours
from app.model.examples import default_scene
from app.model.inputs import group_size, open_ended
from app.model.exact import shown_rows
from app.model.tables import TableIndex
from app.model.variable_rows import RowOrder
from app.model.branches import decision_branches
from app.model.tools import (circle_kind, circle_options, clamp_option, drawing_mode,
                             marker_option, placing_message, shape_paths, tool_hint)
from app.render import frame as frame_view
from app.render.compose import PALETTE, compose
from app.render.incremental import StepImages
# What a frame shows is worked out in app/render/frame.py, shared with export.
from app.render.frame import step_cells as _step_cells
from app.render.frame import html_caption as _caption

PREFERRED_ALGORITHM = "line-bresenham"
# The demo segment: slope 5/12 has two exact ties (d = 0), where the
# textbook Bresenham and a rounding DDA may choose differently.
DEMO_POINTS = [(4, 5), (28, 15)]
DEMO_GRID = (32, 24)

def _is_pixel(value) -> bool:
    return isinstance(value, tuple) and len(value) == 2 and all(
        isinstance(v, int) and not isinstance(v, bool) for v in value)


class MainWindow(QMainWindow):
    """RasterLab's main window. Its layout and menus are built by functions
    of their own modules; the depth and texture displays are parts it owns."""

    def __init__(self, algorithm: str | None = None, points=None, options: dict | None = None,
                 grid=DEMO_GRID, parent=None):
        super().__init__(parent)
        self.setWindowTitle(APP_NAME)
        self.setWindowIcon(app_icon())
        self.dark = False  # the dark theme on show (set by the preferences)
        self.palette_ = PALETTE
        self.player = Player(self)
        self.history = self.player.session.history  # undo and redo of scene edits
        self._empty_image = None
        self._step_images = StepImages()  # patched cell by cell between nearby steps
        self._last_hover = None
        self._error = ""  # the last refusal, shown until the next good change
        self._tables = TableIndex(None)
        self._row_order = RowOrder()  # the Variables panel's: the step's rows first
        self._tally = None
        self._notes: list[int] = []
        self._tables_for = None  # the algorithm the tables dock was last shown for
        # Parts a running program adds (see add_file_actions and below).
        self.file_actions = self.report_entry = self.crash_handler = self.recovery = None
        self.bookmarks: list = []  # the scene's bookmarks while there are no file actions

        build_layout(self)  # app/gui/window_layout.py
        self.guides = WindowGuides(self.grid, PALETTE)
        build_menus(self)  # app/gui/window_menus.py
        self.depth_display = DepthDisplay(self)  # depth dock, samples, coverage error
        self.texture_display = TextureDisplay(self)  # texture, outside-view docks
        self.coverage_display = CoverageDisplay(self)  # overlaps' patterns, cracks
        self._connect()

        specs = registry.all_specs()
        self.picker.set_specs(specs)
        names = [spec.name for spec in specs]
        if algorithm is None:
            algorithm = PREFERRED_ALGORITHM if PREFERRED_ALGORITHM in names else names[0]
        breaks = ()
        if points is None and algorithm == PREFERRED_ALGORITHM:
            points = DEMO_POINTS
        elif points is None:
            points, breaks, _ = default_scene(registry.get(algorithm), grid)
        self.set_scene(algorithm, points, options, grid, breaks)
        self.resize(1280, 800)
        self.resizeDocks([self.scene_dock, self.code_dock], [255, 395], Qt.Orientation.Horizontal)
        self.resizeDocks([self.code_dock, self.variables_dock], [330, 430], Qt.Orientation.Vertical)
        if self._tables:
            self._make_room_for_tables()
        self._build_parts()
        apply_look(self, self.dark)

    def _build_parts(self) -> None:
        """The parts written in modules of their own, each given this window."""
        from app.gui.breakpoint_actions import Breakpoints
        from app.gui.entries import compare_entry, gallery_entry
        from app.gui.exercise_mode import ExerciseMode
        from app.gui.question_actions import QuestionActions
        from app.gui.student_actions import StudentActions
        from app.gui.inspector_dock import InspectorDock
        from app.gui.preferences import Preferences, PreferencesController
        from app.gui.recording import RecordingStatus
        from app.gui.derivation_overlay import DerivationOverlay
        from app.gui.steps_dock import StepsDock
        from app.gui.numbers_setting import NumbersSetting
        # Stored preferences, Edit > Preferences (Ctrl+,) and View > Grid lines.
        self.preferences = PreferencesController(self, Preferences())
        self.compare_entry = compare_entry(self)  # View > Compare… (Ctrl+K)
        self.gallery_entry = gallery_entry(self)  # Help > Examples and hard cases…
        self.breakpoints = Breakpoints(self)  # step units, breakpoints, bookmarks
        self.inspector = InspectorDock(self)  # View > Pixel inspector (Ctrl+I)
        self.steps = StepsDock(self)  # View > Steps table (Ctrl+T)
        self.numbers = NumbersSetting(self)  # View > Exact fractions
        if self.numbers.numbers != "decimal":  # the run on show was shown in decimals
            self.numbers_changed()
        self.derivation = DerivationOverlay(self)  # s and n of Bresenham's derivation
        self.recording_status = RecordingStatus(self)  # long runs: progress bar and Cancel
        self.exercise_mode = ExerciseMode(self)  # Run > Exercise
        self.student_actions = StudentActions(self)  # File > Open algorithm…, Run > First divergence
        self.question_actions = QuestionActions(self)  # File > Export questions…, practice
        from app.gui.overlay_actions import TriangleOverlays
        self.overlays = TriangleOverlays(self)  # View > Overlays (triangle and line geometry)
        from app.gui.input_guard import InputGuard
        self.input_guard = InputGuard(self)  # no wheel edits by accident; Ctrl+Z everywhere
        from app.gui.window_view import WindowView
        self.view = WindowView(self)  # screen fit, layout, presentation, zoom, Copy view
        from app.gui.presenter_keys import PresenterKeys
        self.presenter = PresenterKeys(self)  # PageUp/PageDown, B; the keys back to the grid
        from app.gui.keyboard import KeyboardAccess
        self.keyboard = KeyboardAccess(self)  # the grid's cursor (K), F6, the focus ring
        from app.gui.step_announcer import StepAnnouncer
        self.announcer = StepAnnouncer(self)  # steps said to a screen reader; View > Describe step

    def add_action(self, menu, key, text, shortcut, slot,
                   context=Qt.ShortcutContext.WindowShortcut, owner=None):
        """An action in ``menu`` and in ``actions_`` (app/gui/window_menus.py)."""
        return add_action(self, menu, key, text, shortcut, slot, context, owner)

    def open_texture(self, path: str | None = None) -> None:
        """Use a PNG as the texture (app/gui/window_texture.py)."""
        self.texture_display.open_texture(path)

    # The texture display's docks and views, under the window's names.
    texture_dock = property(lambda self: self.texture_display.dock)
    texture_view = property(lambda self: self.texture_display.view)
    outside_dock = property(lambda self: self.texture_display.outside_dock)
    outside_view = property(lambda self: self.texture_display.outside_view)

    # Parts a running program adds (``launch``); tests add them where they need them.
    def add_file_actions(self, settings=None):
        """Scene files and export in the File menu (app/gui/file_actions.py);
        ``settings`` keeps the recent files."""
        from app.gui.file_actions import FileActions
        self.file_actions = FileActions(self, settings)
        return self.file_actions

    def add_report_entry(self):
        """Run > Report… (app/gui/report_window.py)."""
        from app.gui.entries import report_entry
        self.report_entry = report_entry(self)
        return self.report_entry

    def add_crash_handler(self, folder=None):
        """Uncaught errors logged and shown, Help > Open log folder (app/gui/crash.py)."""
        from app.gui.crash import CrashHandler
        self.crash_handler = CrashHandler(self, folder).install()
        self.crash_handler.add_menu_entry(self.menus["help"])
        return self.crash_handler

    def add_recovery(self, folder=None, **timing):
        """Unsaved work kept and offered back after a crash (app/gui/recovery.py;
        needs the file actions). ``timing``: ``delay_ms``, ``poll_ms``."""
        from app.gui.recovery import Recovery
        self.recovery = Recovery(self, folder, **timing)
        return self.recovery

    # ----------------------------------------------------------- building
    def _connect(self) -> None:
        p = self.player
        p.traceChanged.connect(self._trace_changed)
        p.frameChanged.connect(self._frame_changed)
        p.playingChanged.connect(self.transport.set_playing)
        p.comparisonChanged.connect(self._comparison_changed)
        p.session.message.connect(self.say_error)
        p.speedCapped.connect(lambda line: self.statusBar().showMessage(line, 8000))

        t = self.transport
        t.firstRequested.connect(p.first)
        t.backRequested.connect(p.back)
        t.playRequested.connect(p.toggle)
        t.forwardRequested.connect(p.forward)
        t.lastRequested.connect(p.to_last)
        t.seekRequested.connect(self._scrub)
        t.speedChanged.connect(p.set_speed)
        p.set_speed(t.speed)

        g = self.grid
        g.hoverChanged.connect(self._hover)
        g.pointerMoved.connect(self._pointer_moved)
        # Scene edits (grid gestures, the vertex table, the algorithm, options,
        # grid size, origin) go through the undo history: app/gui/edits.py.
        from app.gui.edits import SceneEdits
        self.edits = SceneEdits(self)
        self.show_primitive.toggled.connect(g.set_show_primitive)
        self.compare.toggled.connect(p.set_compare)
        p.set_compare(self.compare.isChecked())
        self.coverage.toggled.connect(self._coverage_toggled)

    # ------------------------------------------------------- scene input
    def set_scene(self, algorithm: str, points, options=None, grid=DEMO_GRID, breaks=()) -> None:
        """Show a whole scene; raises InputError when it is bad. Contour
        inputs may come as a list of contours or flat with ``breaks``."""
        if breaks:
            points = split_contours(points, breaks)
        self.player.set_scene(algorithm, points, options, grid)
        self.history.clear()
        self.edits.refresh()
        self.follow_scene()
        if getattr(self, "presenter", None) is not None:  # a scene opened: the keys step it
            self.presenter.focus_grid()

    def set_algorithm(self, name: str) -> None:
        try:
            self.player.set_algorithm(name)
        except InputError as error:
            self.say_error(str(error))
            self.picker.set_current(self.player.spec.name)
            return
        self.follow_scene()
        if self.player.refusal:
            self.say_error(self.player.refusal)

    def set_option(self, name: str, value) -> None:
        try:
            self.player.set_option(name, value)
        except InputError as error:
            self.options.show_error(name, str(error))
            self.options.set_values({name: self.player.options[name]})
            self.say_error(str(error))
            return
        self.options.accept(name, self.player.options[name])
        if name == "shape":  # another grouping of the points
            self._set_grid_input()
            self.sync_points()

    def _set_grid_options(self, values: dict) -> None:
        """Options set by a gesture on the grid: the editors follow."""
        try:
            self.player.set_options(values)
        except InputError as error:
            self.say_error(str(error))
            for name in values:
                self.options.show_error(name, str(error))
            return
        for name in values:
            self.options.set_values({name: self.player.options[name]})
            self.options.accept(name, self.player.options[name])

    def set_points(self, points, breaks=None) -> None:
        try:
            self.player.set_points(points, breaks)
        except InputError as error:
            self.say_error(str(error))
        self.sync_points()

    def draw(self, gesture) -> None:
        """A gesture on the grid (app/model/drawing.py) applied to the points."""
        try:
            self.player.draw(gesture)
        except InputError as error:
            self.say_error(str(error))
        self.sync_points()

    def clear_points(self) -> None:
        self.edits.once(lambda: self.set_points([], ()))

    def sync_points(self) -> None:
        player = self.player
        sketch = player.sketch
        self.grid.set_points(sketch.points, sketch.breaks, sketch.open)
        self.points.set_points(player.points, self._labels(), player.breaks)
        self.edits.sync_table()

    def _labels(self) -> list[str]:
        spec, player = self.player.spec, self.player
        return point_labels(drawing_mode(spec), group_size(spec, player.options), len(player.points),
                            player.breaks, spec.inputs.names)

    def drag_radius(self, rx: float, ry: float) -> None:
        spec = self.player.spec
        names = circle_options(spec)
        self._set_grid_options({name: clamp_option(spec.option(name), value)
                                for name, value in zip(names, (rx, ry))})

    def place_marker(self, pixel) -> None:
        option = marker_option(self.player.spec)
        if option is not None:
            self._set_grid_options({option.name: (int(pixel[0]), int(pixel[1]))})

    def set_tool(self, tool: str) -> None:
        """``"draw"``: clicks place points; ``"marker"``: a click places the seed."""
        if tool == MARKER and marker_option(self.player.spec) is None:
            tool = DRAW
        self.grid.set_tool(tool)
        self.actions_["marker" if tool == MARKER else "draw"].setChecked(True)

    def set_grid(self, width: int, height: int) -> None:
        try:
            self.player.set_grid(width, height)
        except InputError as error:
            self.say_error(str(error))
        self.sync_grid()

    def sync_grid(self) -> None:
        """The grid's editors and view follow the player's grid and points."""
        self.grid_editor.set_grid(*self.player.grid)
        self.points.set_grid(*self.player.grid)
        self.grid.set_grid(*self.player.grid)
        self.sync_points()

    def set_palette(self, palette) -> None:
        """Draw the grid, the legends and new frames in ``palette``'s colours."""
        self.palette_ = palette
        self._empty_image = None  # composed with the old colours
        self.grid.set_palette(palette)
        self.guides.set_palette(palette)
        recolor(self.legend, legend_rows(palette))
        recolor(self.coverage_legend, coverage_rows(palette))

    def set_y_down(self, y_down: bool) -> None:
        """Origin top-left with y down (True), or bottom-left with y up."""
        self.player.session.set_origin(y_down)
        self.grid.set_y_down(y_down)
        self.depth_view.set_y_down(y_down)
        self.grid_editor.set_y_down(y_down)
        self.guides.show(self.player.trace, self.player.state())  # words such as "above" flip
        self.y_down_action.blockSignals(True)
        self.y_down_action.setChecked(y_down)
        self.y_down_action.blockSignals(False)
        self._hover(self._last_hover)

    # -------------------------------------------------------------- undo
    # The whole scene is remembered before each edit: app/gui/edits.py.
    def undo(self) -> None:
        self.edits.undo()

    def redo(self) -> None:
        self.edits.redo()

    def follow_scene(self) -> None:
        """Editors follow the player's scene (after an algorithm switch, say)."""
        spec, player = self.player.spec, self.player
        mode = drawing_mode(spec)
        self.picker.set_current(spec.name)
        self.setWindowTitle(f"{spec.title} \u2014 {APP_NAME}")
        self.options.set_options(spec.options, player.options, spec.inputs.count,
                                 spec.inputs.names)
        self.points.set_grid(*player.grid)
        self.grid_editor.set_grid(*player.grid)
        self.grid.set_grid(*player.grid)
        self._set_grid_input()
        marker = marker_option(spec)
        self.grid.set_marker_name(marker.name if marker else "")
        self.actions_["marker"].setVisible(marker is not None)
        if marker is not None:
            self.actions_["marker"].setText(f"Place the {marker.name}")
        else:
            self.set_tool(DRAW)
        self.actions_["close"].setVisible(mode == CONTOURS)
        self.hint.setText(tool_hint(spec))
        self.sync_points()
        self._show_inputs()

    def _set_grid_input(self) -> None:
        """The grid's drawing tool: its points come in groups the options name."""
        spec, mode = self.player.spec, drawing_mode(self.player.spec)
        size = group_size(spec, self.player.options)
        self.points.set_input(spec.inputs.count, spec.inputs.names, spec.inputs.integer,
                              open_ended(spec), size if spec.inputs.multiple else 0)
        self.grid.set_input(size, spec.inputs.integer,
                            spec.inputs.names, closed=mode == CONTOURS,
                            open_ended=open_ended(spec), mode=mode)

    def _show_inputs(self) -> None:
        """The circle's rim handle and the seed marker follow the options."""
        spec, options = self.player.spec, self.player.options
        names = circle_options(spec)
        radii = [float(options[name]) for name in names]
        self.grid.set_circle(circle_kind(spec), *(radii * 2)[:2])
        marker = marker_option(spec)
        if marker is None:
            return
        value = options.get(marker.name)
        trace = self.player.trace
        if isinstance(value, tuple):
            self.grid.set_marker(value)
        elif trace is not None and _is_pixel(trace.start.constants.get(marker.name)):
            # Chosen by the algorithm ("auto"): shown faint.
            self.grid.set_marker(trace.start.constants[marker.name], automatic=True)
        else:
            self.grid.set_marker(None)

    # ------------------------------------------------------------ display
    def _scrub(self, index: int) -> None:
        self.player.pause()
        self.player.seek(index)

    def _trace_changed(self) -> None:
        player, trace, spec = self.player, self.player.trace, self.player.spec
        self._error = ""
        self.grid.set_shape(shape_paths(spec, player.points, player.options, player.breaks))
        self.guides.run_changed(player)
        self._show_inputs()
        self._tables = TableIndex(trace, self.numbers_shown)
        self._row_order = RowOrder.of(trace)
        self.variables.set_constants(self._row_order.constants)
        self._tally = PixelTally(trace) if trace is not None and has_insight(
            trace.value_names) else None
        self._notes = [] if trace is None else trace.steps_of(Note).tolist()
        self._show_tables_dock()
        self.depth_display.prepare()
        self.texture_display.prepare()
        if trace is None:
            self.transport.set_range(-1)
            self.variables.set_series(None)
            self.variables.set_rows([])
            self.variables.set_chips([])
            self.tables.set_tables([])
            self.code.set_current(None)
            self._update_message()
            return
        self.code.set_code([shown(line.text) for line in trace.code], spec.notes)
        self.transport.set_range(len(trace) - 1)
        name = _series_name(trace)
        decision = name is not None and name == trace.start.decision
        self.variables.set_series(None if name is None else trace.series(name), name or "",
                                  decision, decision_branches(trace) if decision else None)

    def _show_tables_dock(self) -> None:
        """The tables dock appears for runs with tables and goes for runs
        without; a person who closes it keeps it closed for this algorithm."""
        name = self.player.spec.name
        if self.player.trace is None:
            return  # points being placed: the grid must not move under the pointer
        if not self._tables:
            if self.tables_dock.isVisibleTo(self):
                self.tables_dock.hide()
                self._tables_for = None  # hidden here, so shown again here
            return
        if self._tables_for != name:
            self.tables_dock.show()
            self._make_room_for_tables()
        self._tables_for = name

    def _make_room_for_tables(self) -> None:
        # Room for the tables' rows, up to eight; the grid gives up height.
        self.tables.set_tables(self._tables.at(self.player.index))
        self.resizeDocks([self.tables_dock], [self.tables.fitting_height()],
                         Qt.Orientation.Vertical)

    def _frame_changed(self, index: int) -> None:
        self.show_frame()

    @property
    def numbers_shown(self) -> str:
        """How the panels show numbers: View > Exact fractions (decimal until it is made)."""
        return self.numbers.numbers if hasattr(self, "numbers") else "decimal"

    def numbers_changed(self) -> None:
        """The numbers setting changed: every panel and the steps table anew."""
        self._tables = TableIndex(self.player.trace, self.numbers_shown)
        self.steps.refresh()
        self.show_frame()

    def show_frame(self) -> None:
        """Bring the grid and the panels to the player's current step."""
        player = self.player
        state = player.state()
        if state is None:
            self.grid.set_image(self._blank())
            self.grid.set_highlights((), ())
            self.guides.show(None, None)
            self.variables.set_caption("No run: place the points first.")
            self.coverage_display.show(None)
            self._update_message()
            return
        errors = None if self.coverage.isChecked() else self.depth_display.error_map()
        if errors is not None:
            self.grid.set_image(errors)
        else:
            image = self._step_images.image(player.trace, state, self.palette_,
                                            coverage=self.coverage.isChecked())
            self.grid.set_image(image, self._step_images.changed)
        self.depth_display.show(state)
        self.texture_display.show(state)
        cells, spans = _step_cells(state)
        self.grid.set_highlights(cells, state.candidates, spans)
        self.guides.show(player.trace, state)
        trace, index = player.trace, state.index
        self.transport.set_position(index)
        self.code.set_current(state.step.line)
        self.variables.set_caption(_caption(state, len(trace) - 1))
        self._show_values(state)
        if self._tables:
            self.tables.set_tables(self._tables.at(index))
        self.coverage_display.show(state)
        self._update_message()
        self._hover(self._last_hover)

    def _show_values(self, state) -> None:
        trace, index = self.player.trace, state.index
        colors = colour_names(trace.start)
        # The trace's own algorithm: a switch may still be recording.
        rows = shown_rows(self.player.trace_spec, trace, index, self.numbers_shown)
        rows += self.depth_display.accuracy_rows(state, rows)
        tones = row_tones(rows) if self._tally else None
        # Values as a person reads them: five significant figures, ≤, subscripts.
        rows = [(name, text if name in colors else shown(str(text))) for name, text in rows]
        self.variables.set_rows(self._row_order.arrange(rows), colors, tones)
        chips = []
        if self._tally is not None:
            chips = inside_chips(state.step.values, state.step.kind)
            tested, filled = self._tally.at(index)
            chips.append((f"{tested:,} tested \u00b7 {filled:,} filled", "info",
                          "pixels looked at, and pixels written, up to this step"))
        self.variables.set_chips(chips)
        self.variables.set_marker(index)

    def _coverage_toggled(self, on: bool) -> None:
        self.legend.setVisible(not on)
        self.coverage_legend.setVisible(on)
        self.show_frame()

    def _comparison_changed(self) -> None:
        player = self.player
        self.grid.set_differences(player.differences)
        if not player.compared:
            self.difference_label.setText("")
            return
        count = len(player.differences)
        other = player.previous_title
        if count == 0:
            self.difference_label.setText(f"Same pixels as {other}")
        else:
            self.difference_label.setText(
                f"{count} pixel{'s' if count != 1 else ''} differ{'s' if count == 1 else ''} "
                f"from {other}")

    def _blank(self) -> np.ndarray:
        width, height = self.player.grid
        if self._empty_image is None or self._empty_image.shape[:2] != (height, width):
            self._empty_image = compose(Raster(width, height), None, self.palette_)
        return self._empty_image

    def _pointer_moved(self, where) -> None:
        self._last_pointer = where
        self._hover(self._last_hover)

    def _hover(self, pixel) -> None:
        self._last_hover = pixel
        if pixel is None:
            self.cursor_label.setText("")
            return
        x, y = pixel
        text = f"pixel ({x}, {y})"
        where = getattr(self, "_last_pointer", None)
        if where is not None:  # the real coordinates, as the axes read them
            text += f" \u00b7 at ({where[0]:.2f}, {where[1]:.2f})"
        state = self.player.state()
        if state is not None and state.raster.inside(x, y):
            count = int(state.raster.counts[y, x])
            if count:
                text += " \u00b7 written" + (f" {count}\u00d7" if count > 1 else "")
                if state.raster.colors is not None and state.raster.colors[y, x] >= 0:
                    text += f" \u00b7 #{int(state.raster.colors[y, x]):06x}"
        self.cursor_label.setText(text)

    # ----------------------------------------------------------- messages
    def say_error(self, text: str) -> None:
        """A refusal: shown (in red) until the next change that works."""
        self._error = text
        self._update_message()

    def _update_message(self) -> None:
        """The status line: a refusal, else a cut-short run, else what to
        place next, else the algorithm's latest note at or before the step."""
        player = self.player
        trace = player.trace
        text, error = self._error, bool(self._error)
        if not text and trace is not None and trace.truncated:
            text = trace.message
        if not text:
            text = placing_message(player.spec, player.points, player.breaks, player.options)
        if not text and trace is not None and self._notes:
            step = note_at(trace, self._notes, player.index)
            if step is not None:
                text = f"Step {step:,}: {trace.record_at(step).text}"
        if not text:
            text = self.texture_display.handle_note
        self._say(text, error)

    def _say(self, text: str, error: bool = False) -> None:
        # Called on every step: only what changed is set (a style sheet
        # costs milliseconds even when it is the same).
        style = ERROR_STYLE if error else ""
        if self.message.text() != text:
            self.message.setText(text)
            self.message.setToolTip(text)
        if self.message.styleSheet() != style:
            self.message.setStyleSheet(style)

    # ------------------------------------------------------------ dialogs
    def show_shortcuts(self) -> None:
        from app.gui.about import shortcut_rows
        dialog = ShortcutsDialog(self, shortcut_rows(self, GESTURES))
        dialog.exec()

    def show_about(self) -> None:
        from app.gui.about import app_version, runtime_versions
        count = len(registry.all_specs())
        QMessageBox.about(
            self, f"About {APP_NAME}",
            f"<h3>{APP_NAME}</h3>"
            "<p>Step through the classic rasterization algorithms on a magnified pixel "
            "grid: every frame shows the pixel being decided, the candidates it was "
            "chosen from, the variables and the line of pseudo-code that ran.</p>"
            f"<p>{count} algorithm{'s' if count != 1 else ''} available. "
            "Pixel (i, j) is the square [i, i+1) \u00d7 [j, j+1) with its centre at "
            "(i + \u00bd, j + \u00bd).</p>"
            "<p>Built with Python, Qt (PySide6), pyqtgraph and numpy.</p>"
            f"<p>Version {app_version()} · {runtime_versions()}</p>")

    def closeEvent(self, event):  # noqa: N802
        self.player.pause()
        self.player.stop_recording()  # a background recording ends with the window
        super().closeEvent(event)


def _series_name(trace) -> str | None:
    """The value to plot over the run: the decision variable, else the first
    named value that has finite values."""
    start = trace.start
    if start.decision is not None and start.decision in trace.value_names:
        return start.decision
    colour = frame_view.colour_name(start)
    for name in trace.value_names:
        if name == colour:
            continue  # packed colours are not worth a plot
        if np.isfinite(trace.series(name)).any():
            return name
    return None
