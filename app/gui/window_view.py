"""How the main window sits on the screen: a size that fits the screen it
opens on (a 1280 x 720 projector too), the dock layout kept between runs
and View > Reset layout, presentation mode (F11; Ctrl+Cmd+F on macOS), the
zoom of the whole window (Ctrl+= / Ctrl+- / Ctrl+0) and Edit > Copy view
as image.

``WindowView(window)`` adds them; ``remember(settings)`` (the running
program; tests with a settings file of their own) restores the layout and
zoom a previous run left and saves them when the window closes.
"""
from __future__ import annotations

import sys
from typing import NamedTuple

from PySide6.QtCore import QByteArray, QEvent, QObject, Qt, QTimer
from PySide6.QtGui import QKeySequence, QShortcut
from PySide6.QtWidgets import QApplication, QDockWidget, QToolBar

from app.gui.type_scale import apply_type_scale, base_font

PREFERRED_SIZE = (1280, 800)
MIN_SIZE = (900, 560)
GEOMETRY_KEY, STATE_KEY, ZOOM_KEY = "window/geometry", "window/state", "window/zoom"
ZOOMS = (0.8, 0.9, 1.0, 1.1, 1.25, 1.5, 1.75, 2.0)
PRESENTING = 1.6  # the type of presentation mode, on top of the zoom
SIDE_WIDTH = 395  # the pseudo-code column's width when there is room for it
SIDES = (Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.RightDockWidgetArea)
SIDE_MARGIN = 24  # the docks' separators and frames, beside the grid's minimum width


def standard_full_screen_keys() -> list[QKeySequence]:
    """Qt's full-screen keys of the running system (its platform theme's)."""
    return QKeySequence.keyBindings(QKeySequence.StandardKey.FullScreen)


def presentation_keys(standard=None, platform: str | None = None) -> list[QKeySequence]:
    """The keys of presentation mode: the system's standard full-screen keys
    (Ctrl+Cmd+F on macOS, where F11 shows the desktop), with F11 first on the
    other systems even where their standard is another (KDE's Ctrl+Shift+F)."""
    keys = list(standard_full_screen_keys() if standard is None else standard)
    mac = (platform or sys.platform) == "darwin"
    f11 = QKeySequence(Qt.Key.Key_F11)
    if not mac and f11 not in keys:
        keys.insert(0, f11)
    return keys or [f11]


class Before(NamedTuple):
    """What presentation mode changed, to put back on leaving it."""
    state: object  # the docks and bars (QMainWindow.saveState)
    geometry: object
    size: object  # restoreGeometry keeps a window within the screen: a larger one is resized
    maximized: bool
    shown: list  # the docks and the bars on show
    bars: list
    sizes: dict  # dock -> its size
    folded: bool  # the variables' constants


class WindowView(QObject):
    """Screen fit, layout memory, presentation mode, zoom and Copy view."""

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.settings = None
        self.zoom = 1.0
        self.presenting = False
        self._before = None  # what presentation mode hid, to put back
        self._extras: list = []  # the notes and the plot, hidden while presenting
        self._scaled = 1.0  # the type scale the widgets are at
        self._widths: dict = {}  # side dock -> its width at zoom 100 %
        window.setMinimumSize(*MIN_SIZE)
        self.default_state = window.saveState()
        self._build_actions()
        window.installEventFilter(self)
        window.player.traceChanged.connect(self._new_editors)
        window.player.frameChanged.connect(lambda _index: self.follow_current())

    # ------------------------------------------------------------ actions
    def _build_actions(self) -> None:
        w, view = self.window, self.window.menus["view"]
        view.addSeparator()
        self.present_action = w.add_action(view, "present", "&Presentation", None, self.toggle)
        self.present_action.setShortcuts(presentation_keys())
        self.present_action.setCheckable(True)
        key = self.present_action.shortcut().toString(QKeySequence.SequenceFormat.NativeText)
        self.present_action.setToolTip("Full screen: the grid, the pseudo-code and the "
                                       f"variables in large type ({key}; Esc leaves)")
        self.leave = QShortcut(QKeySequence("Esc"), w)
        self.leave.activated.connect(self.toggle)
        self.leave.setEnabled(False)  # Esc is the grid's and the inspector's otherwise
        w.add_action(view, "zoom-in", "Zoom &in", "Ctrl+=", lambda: self.step_zoom(1)
                     ).setShortcuts([QKeySequence("Ctrl+="), QKeySequence("Ctrl++")])
        w.add_action(view, "zoom-out", "Zoom &out", "Ctrl+-", lambda: self.step_zoom(-1))
        w.add_action(view, "zoom-reset", "&Actual size", "Ctrl+0", lambda: self.set_zoom(1.0))
        w.add_action(view, "reset-layout", "&Reset layout", None, self.reset_layout).setToolTip(
            "Put the panels back where they were when RasterLab was first started")
        edit = w.menus["edit"]
        w.add_action(edit, "copy-view", "Copy view as &image", "Ctrl+Shift+C",
                     self.copy_view).setToolTip("The grid as shown, to the clipboard, for a "
                                                "slide or a document")

    # --------------------------------------------------- follow the step
    def follow_current(self) -> bool:
        """Zoomed in on a large grid, the view pans (keeping its zoom) to the
        pixel of the step when it is out of sight. True when it panned."""
        grid = self.window.grid
        cells = grid.outlines.layer("current")
        if not len(cells):
            return False
        x, y = (float(v) + 0.5 for v in cells[0])
        (x0, x1), (y0, y1) = grid.view_box.viewRange()
        margin_x, margin_y = min(1.0, (x1 - x0) / 4), min(1.0, (y1 - y0) / 4)
        if x0 + margin_x <= x <= x1 - margin_x and y0 + margin_y <= y <= y1 - margin_y:
            return False
        grid.view_box.translateBy(x=x - (x0 + x1) / 2, y=y - (y0 + y1) / 2)
        return True

    # ------------------------------------------------------- copy the view
    def copy_view(self):
        picture = self.window.grid.grab()
        QApplication.clipboard().setPixmap(picture)
        self.window.statusBar().showMessage(
            f"Copied the grid view ({picture.width()} \u00d7 {picture.height()} px)", 4000)
        return picture

    # --------------------------------------------------------------- zoom
    def step_zoom(self, direction: int) -> None:
        index = min(range(len(ZOOMS)), key=lambda k: abs(ZOOMS[k] - self.zoom))
        self.set_zoom(ZOOMS[max(0, min(len(ZOOMS) - 1, index + direction))])

    def set_zoom(self, zoom: float) -> None:
        zoom = float(min(max(zoom, ZOOMS[0]), ZOOMS[-1]))
        if self.zoom == 1.0 and zoom != 1.0 and not self.presenting:
            self._widths = {d: d.width() for d in self._side_docks()}
        self.zoom = zoom
        self._apply_fonts()
        if not self.presenting:
            self._fit_side_docks()
            # Again once the window has laid out the new type.
            QTimer.singleShot(0, self, self._fit_side_docks)
        if self.settings is not None:
            self.settings.setValue(ZOOM_KEY, self.zoom)
        self.window.statusBar().showMessage(f"Zoom {round(self.zoom * 100)} %", 2000)

    @property
    def scale(self) -> float:
        """The type scale of the whole window: the zoom, times
        presentation mode's large type while presenting."""
        return self.zoom * (PRESENTING if self.presenting else 1.0)

    def _side_docks(self) -> list:
        w = self.window
        return [d for d in w.findChildren(QDockWidget) if d.isVisibleTo(w) and not d.isFloating()
                and w.dockWidgetArea(d) in SIDES]

    def _fit_side_docks(self) -> None:
        """The side panels' widths at the zoom: those they had at 100 %
        times the zoom, all of them narrower if the grid and the transport
        bar would lack room (never past the window's edge); at 100 % the
        very widths they had."""
        w = self.window
        widths = {d: round(width * self.zoom) for d, width in self._widths.items()
                  if d.isVisibleTo(w) and w.dockWidgetArea(d) in SIDES}
        if not widths:
            return
        columns = {w.dockWidgetArea(d): 0 for d in widths}
        for d, width in widths.items():
            columns[w.dockWidgetArea(d)] = max(columns[w.dockWidgetArea(d)], width)
        room = w.width() - w.centralWidget().minimumSizeHint().width() - SIDE_MARGIN
        if self.zoom != 1.0 and sum(columns.values()) > room:
            shrink = max(room, 0) / sum(columns.values())
            widths = {d: max(1, int(width * shrink)) for d, width in widths.items()}
        docks = list(widths)
        w.resizeDocks(docks, [widths[d] for d in docks], Qt.Orientation.Horizontal)

    def _new_editors(self) -> None:
        """Editors made for a new run take the type scale too (nothing to do at 1)."""
        if self.scale != 1.0:
            self._apply_fonts(redraw=False)

    def _apply_fonts(self, redraw: bool = True) -> None:
        """Every widget's type at the window's scale (app/gui/type_scale.py);
        the grid's coordinates and words, drawn by pyqtgraph, follow."""
        w = self.window
        apply_type_scale(w, self.scale, self._scaled)
        self._scaled = self.scale
        w.variables.fit_type()
        for name in ("bottom", "left"):  # the grid's coordinates, read from the back row too
            tick = base_font(w)
            if tick.pointSizeF() > 0:
                tick.setPointSizeF(tick.pointSizeF() * self.scale)
            w.grid.axes[name].setStyle(tickFont=tick)
        # The words on the grid (M's side, the scan line) grow as the axes do.
        w.guides.item.set_text_scale(self.scale)
        if redraw:
            w.show_frame()
        w.code.restyle()
        w.code.lines.resizeRowsToContents()
        w.code.reveal()

    # ------------------------------------------------------- presentation
    def toggle(self) -> None:
        if self.presenting:
            self.leave_presentation()
        else:
            self.present()

    def presentation_docks(self) -> list:
        """The docks of presentation mode: the pseudo-code, the variables
        (unless an exercise has put them aside: they give its answers away)
        and whichever teaching panel is open."""
        w = self.window
        exercise = getattr(w, "exercise_mode", None)
        docks = [w.code_dock]
        if exercise is None or not exercise.active:
            docks.append(w.variables_dock)
        teaching = [w.depth_dock, w.texture_dock, w.outside_dock,
                    None if exercise is None else exercise.dock]
        return docks + [d for d in teaching if d is not None and d.isVisibleTo(w)]

    def present(self) -> None:
        """Full screen, a layout of its own: the grid and the transport, the
        pseudo-code, the step's rows of the variables (constants folded)
        and the teaching panel that is open, all in large type; everything
        else hidden until Esc, which puts back exactly what was there."""
        w = self.window
        if self.presenting:
            return
        keep = self.presentation_docks()
        shown = [d for d in w.findChildren(QDockWidget) if d.isVisibleTo(w)]
        bars = [b for b in w.findChildren(QToolBar) if b.isVisibleTo(w)]
        self._before = Before(w.saveState(), w.saveGeometry(), w.size(), w.isMaximized(),
                              shown, bars,
                              {d: d.size() for d in shown}, w.variables.folded)
        self.presenting = True
        for widget in (*shown, *bars, w.menuBar(), w.statusBar()):
            if widget not in keep:
                widget.hide()
        for dock in keep:
            dock.show()
        # The notes and the plot over the run give their room to the code and values.
        self._extras = [x for x in (w.code.notes_area,) if x.isVisibleTo(w)]
        for extra in self._extras:
            extra.hide()
        w.variables.set_plot_allowed(False)
        w.variables.set_folded(True)
        w.showFullScreen()
        if w.screen() is not None:  # without a window manager to do it
            w.setGeometry(w.screen().geometry())
        self._apply_fonts()
        self._fit_side()
        self.leave.setEnabled(True)
        self.present_action.setChecked(True)
        w.grid.fit()

    def _fit_side(self) -> None:
        """The panels' column a third of the screen: the size the screen
        gives the window comes after showFullScreen, and is fitted again then."""
        w = self.window
        w.resizeDocks([w.code_dock], [max(320, w.width() // 3)], Qt.Orientation.Horizontal)

    def leave_presentation(self) -> None:
        w = self.window
        if not self.presenting:
            return
        before = self._before
        self.presenting = False
        self.leave.setEnabled(False)
        for extra in self._extras:
            extra.show()
        w.variables.set_plot_allowed(True)
        w.variables.set_folded(before.folded)
        self._apply_fonts()
        w.menuBar().show()
        w.statusBar().show()
        if before.maximized:
            w.showMaximized()
        else:
            w.showNormal()
            w.restoreGeometry(before.geometry)
            w.resize(before.size)
        w.restoreState(before.state)
        for widget in (*before.shown, *before.bars):
            widget.show()
        self._restore_sizes(before.sizes)
        self.present_action.setChecked(False)
        w.grid.fit()

    def _restore_sizes(self, sizes: dict) -> None:
        """Each dock's width and height as before: restoreState shares the
        room out again, a pixel or two off after the window's size changed."""
        w = self.window
        docks = list(sizes)
        w.resizeDocks(docks, [sizes[d].width() for d in docks], Qt.Orientation.Horizontal)
        w.resizeDocks(docks, [sizes[d].height() for d in docks], Qt.Orientation.Vertical)

    # ------------------------------------------------------------ layout
    def reset_layout(self) -> None:
        w = self.window
        if self.presenting:
            self.leave_presentation()
        w.restoreState(self.default_state)
        w.resizeDocks([w.scene_dock, w.code_dock], [255, SIDE_WIDTH], Qt.Orientation.Horizontal)
        w.resizeDocks([w.code_dock, w.variables_dock], [330, 430], Qt.Orientation.Vertical)
        w.grid.fit()

    def remember(self, settings) -> None:
        """Fit the screen; restore the layout and zoom kept in ``settings``;
        keep them there on close."""
        self.settings = settings
        fit_to_screen(self.window)
        geometry, state = settings.value(GEOMETRY_KEY), settings.value(STATE_KEY)
        if isinstance(geometry, QByteArray):
            self.window.restoreGeometry(geometry)
            fit_to_screen(self.window, keep_size=True)
        if isinstance(state, QByteArray):
            self.window.restoreState(state)
        try:
            zoom = float(settings.value(ZOOM_KEY, 1.0))
        except (TypeError, ValueError):
            zoom = 1.0  # a hand-edited settings file: the usual size
        if zoom != 1.0:
            self.set_zoom(zoom)

    def save(self) -> None:
        if self.settings is None:
            return
        if self.presenting:
            self.leave_presentation()  # the layout to keep is the everyday one
        self.settings.setValue(GEOMETRY_KEY, self.window.saveGeometry())
        self.settings.setValue(STATE_KEY, self.window.saveState())
        self.settings.setValue(ZOOM_KEY, self.zoom)
        self.settings.sync()

    def eventFilter(self, obj, event) -> bool:  # noqa: N802
        if obj is self.window:
            if event.type() == QEvent.Type.Close:
                self.save()
            elif event.type() == QEvent.Type.Resize and self.presenting:
                self._fit_side()
            elif event.type() == QEvent.Type.Resize:
                self._give_back_width(event)
        return False

    def _give_back_width(self, event) -> None:
        """A window made small and then large again gives the pseudo-code
        column back the width it lost, not all to the grid."""
        w = self.window
        if event.size().width() <= event.oldSize().width() or not w.code_dock.isVisible():
            return
        wanted = min(SIDE_WIDTH, event.size().width() // 3)
        if w.code_dock.width() < wanted:
            w.resizeDocks([w.code_dock], [wanted], Qt.Orientation.Horizontal)


def fit_to_screen(window, keep_size: bool = False) -> None:
    """The preferred size (or the one kept), but never more than the
    screen's free area, so that the transport bar is always on screen."""
    screen = window.screen() or QApplication.primaryScreen()
    width, height = (window.width(), window.height()) if keep_size else PREFERRED_SIZE
    if screen is not None:
        room = screen.availableGeometry()
        # The frame (title bar, borders) takes some of the room too.
        width, height = min(width, room.width() - 16), min(height, room.height() - 48)
    window.resize(max(width, MIN_SIZE[0]), max(height, MIN_SIZE[1]))
