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

from PySide6.QtCore import QByteArray, QEvent, QObject, Qt
from PySide6.QtGui import QFont, QKeySequence, QShortcut
from PySide6.QtWidgets import QApplication, QDockWidget, QToolBar, QWidget

PREFERRED_SIZE = (1280, 800)
MIN_SIZE = (900, 560)
GEOMETRY_KEY, STATE_KEY, ZOOM_KEY = "window/geometry", "window/state", "window/zoom"
ZOOMS = (0.8, 0.9, 1.0, 1.1, 1.25, 1.5, 1.75, 2.0)
PRESENTING = 1.6  # the pseudo-code and variables in presentation mode, on top of the zoom
SIDE_WIDTH = 395  # the pseudo-code column's width when there is room for it


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
        self._fonts: dict = {}  # widget -> its own font at zoom 1
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
        self.zoom = float(min(max(zoom, ZOOMS[0]), ZOOMS[-1]))
        self._apply_fonts()
        if self.settings is not None:
            self.settings.setValue(ZOOM_KEY, self.zoom)
        self.window.statusBar().showMessage(f"Zoom {round(self.zoom * 100)} %", 2000)

    def _new_editors(self) -> None:
        """Editors made for a new run take the zoom too (nothing to do at 1)."""
        if self.zoom != 1.0 or self.presenting:
            self._apply_fonts(redraw=False)

    def _apply_fonts(self, redraw: bool = True) -> None:
        """Every widget's font at the zoom (larger still beside the grid
        while presenting); each widget's own font is kept to scale from."""
        w = self.window
        large = {id(x) for dock in (w.code_dock, w.variables_dock)
                 for x in dock.findChildren(QWidget)}
        for widget in [w, *w.findChildren(QWidget)]:
            key = id(widget)
            if key not in self._fonts:
                self._fonts[key] = widget.font()
                widget.destroyed.connect(lambda _o=None, k=key: self._fonts.pop(k, None))
            factor = self.zoom * (PRESENTING if self.presenting and key in large else 1.0)
            font = QFont(self._fonts[key])
            if font.pointSizeF() > 0:
                font.setPointSizeF(font.pointSizeF() * factor)
            if widget.font() != font:
                widget.setFont(font)
        w.variables.set_type_scale(self.zoom * (PRESENTING if self.presenting else 1.0))
        for name in ("bottom", "left"):  # the grid's coordinates, read from the back row too
            axis = w.grid.axes[name]
            tick = QFont(self._fonts[id(w)])
            if tick.pointSizeF() > 0:
                tick.setPointSizeF(tick.pointSizeF() * self.zoom * (1.4 if self.presenting else 1))
            axis.setStyle(tickFont=tick)
        # The words on the grid (M's side, the scan line) grow as the axes do.
        w.guides.item.set_text_scale(self.zoom * (1.4 if self.presenting else 1))
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

    def present(self) -> None:
        """Full screen: the grid and the transport, the pseudo-code and the
        variables beside them in large type; everything else hidden."""
        w = self.window
        if self.presenting:
            return
        shown = [d for d in w.findChildren(QDockWidget) if d.isVisibleTo(w)]
        bars = [b for b in w.findChildren(QToolBar) if b.isVisibleTo(w)]
        self._before = (w.saveState(), w.saveGeometry(), w.isMaximized(), shown, bars)
        self.presenting = True
        for widget in (*shown, *bars, w.menuBar(), w.statusBar()):
            widget.hide()
        for dock in (w.code_dock, w.variables_dock):
            dock.show()
        # The notes and the plot over the run give their room to the code and values.
        self._extras = [x for x in (w.code.notes_area, w.variables.plot, w.variables.plot_title)
                        if x.isVisibleTo(w)]
        for extra in self._extras:
            extra.hide()
        w.showFullScreen()
        if w.screen() is not None:  # without a window manager to do it
            w.setGeometry(w.screen().geometry())
        self._apply_fonts()
        third = max(320, w.width() // 3)
        w.resizeDocks([w.code_dock], [third], Qt.Orientation.Horizontal)
        self.leave.setEnabled(True)
        self.present_action.setChecked(True)
        w.grid.fit()

    def leave_presentation(self) -> None:
        w = self.window
        if not self.presenting:
            return
        state, geometry, maximized, shown, bars = self._before
        self.presenting = False
        self.leave.setEnabled(False)
        for extra in self._extras:
            extra.show()
        self._apply_fonts()
        w.menuBar().show()
        w.statusBar().show()
        if maximized:
            w.showMaximized()
        else:
            w.showNormal()
            w.restoreGeometry(geometry)
        w.restoreState(state)
        for widget in (*shown, *bars):
            widget.show()
        self.present_action.setChecked(False)
        w.grid.fit()

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
            elif event.type() == QEvent.Type.Resize and not self.presenting:
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
