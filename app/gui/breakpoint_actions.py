"""Breakpoints, step units and bookmarks in the main window.

``Breakpoints(window)`` adds two docks to a ``MainWindow``:

* Breakpoints: the step unit (frame, decision, scanline, primitive) that
  the step buttons and Left/Right move by, the breakpoint conditions, and
  Run to breakpoint (F5) / Run back to breakpoint (Shift+F5), also in the
  Run menu. Play stops at a ticked condition too. The status bar says
  which condition stopped it, or that there is no further stop.
* Bookmarks: named frames of the scene. Add at the step on show (Ctrl+B),
  rename in place, delete, double-click to go there. They are the scene's
  ``bookmarks`` (saved and loaded with it by app/gui/file_actions.py, used as
  export range ends); without file actions they are kept on the window.

What the conditions and units mean is in app/model/breakpoints.py.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtWidgets import QDockWidget, QInputDialog, QLineEdit

from widgets.docks import panel_dock
from widgets.breakpoints_panel import BookmarksPanel, BreakpointsPanel

from app.model import breakpoints as bp

UNIT_TIPS = {
    bp.FRAME: "Every frame of the run",
    bp.DECISION: "Frames that take a branch (Bresenham's E or NE, the z-buffer's pass or fail)",
    bp.SCANLINE: "The first frame of each new row",
    bp.PRIMITIVE: "The first frame of each triangle",
}
CONDITION_TIPS = {
    bp.SIGN: "Stop where the decision variable (Bresenham's d) has another sign "
             "(-, 0, +) than at the decision before",
    bp.BRANCH: "Stop where the branch taken (E or NE, ...) differs from the one before",
    bp.AET: "Stop where an edge enters or leaves the active edge table (or two swap)",
    bp.SCANLINE: "Stop at the first frame of each new row",
    bp.PIXEL: "Stop at frames that visit or plot this pixel",
    bp.DEPTH: "Stop at fragments that fail the depth test (z-buffer)",
}
TITLES = {bp.SIGN: "Decision changes sign", bp.BRANCH: "Branch changes",
          bp.AET: "AET changes", bp.SCANLINE: "New scanline", bp.PIXEL: "Pixel reached",
          bp.DEPTH: "Depth test fails"}
MESSAGE_MS = 8000


def bookmark_list(window) -> list:
    """The scene's bookmarks ({"name", "step"}): the file actions' list when
    they are installed, else one kept on the window."""
    files = window.file_actions
    return files.bookmarks if files is not None else window.bookmarks


class Breakpoints(QObject):
    """Step units, breakpoints and bookmarks for one window."""

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.player = window.player
        self._files = None  # the file actions whose bookmark changes we follow
        self._build_docks()
        self._build_actions()
        self.player.stepper = self.step_target
        self.player.stop_finder = self.play_stop
        self.player.traceChanged.connect(self._trace_changed)
        self.panel.unitChanged.connect(self._unit_changed)
        self.panel.conditionsChanged.connect(self._update_note)
        self.panel.runRequested.connect(self.run_to)
        self.panel.pickToggled.connect(self._pick_toggled)
        self.marks.addRequested.connect(self.add_bookmark)
        self.marks.deleteRequested.connect(self.delete_bookmark)
        self.marks.renameRequested.connect(self.rename_bookmark)
        self.marks.jumpRequested.connect(self.jump_to_bookmark)
        window.grid.viewport().installEventFilter(self)
        self._trace_changed()

    # ------------------------------------------------------------ building
    def _build_docks(self) -> None:
        window = self.window
        units = [(unit, bp.UNIT_TITLES[unit].capitalize(), UNIT_TIPS[unit]) for unit in bp.UNITS]
        conditions = [(kind, TITLES[kind], CONDITION_TIPS[kind]) for kind in bp.CONDITIONS]
        self.panel = BreakpointsPanel(units, conditions, bp.PIXEL, window)
        self.marks = BookmarksPanel(window)
        self.breakpoints_dock = self._dock("Breakpoints", "breakpointsDock", self.panel)
        self.bookmarks_dock = self._dock("Bookmarks", "bookmarksDock", self.marks)
        # Tabs beside the scene panel: at 1280 x 800 there is no height to
        # spare under it, and the scene's editors matter more while drawing.
        left = Qt.DockWidgetArea.LeftDockWidgetArea
        window.addDockWidget(left, self.breakpoints_dock)
        window.addDockWidget(left, self.bookmarks_dock)
        window.tabifyDockWidget(window.scene_dock, self.breakpoints_dock)
        window.tabifyDockWidget(self.breakpoints_dock, self.bookmarks_dock)
        window.scene_dock.raise_()
        for dock in (self.breakpoints_dock, self.bookmarks_dock):
            window.menus["view"].addAction(dock.toggleViewAction())

    def _dock(self, title: str, name: str, widget) -> QDockWidget:
        dock = panel_dock(title, name, widget, self.window, scrolls=True)
        dock.visibilityChanged.connect(lambda shown: shown and self._refresh_panel())
        return dock

    def _build_actions(self) -> None:
        window = self.window
        run_menu = window.menus["run"]
        run_menu.addSeparator()
        self.run_action = window.add_action(run_menu, "run-to-breakpoint", "Run to &breakpoint",
                                         "F5", lambda: self.run_to(+1))
        self.run_back_action = window.add_action(run_menu, "run-back-to-breakpoint",
                                              "Run &back to breakpoint", "Shift+F5",
                                              lambda: self.run_to(-1))
        run_menu.addSeparator()
        self.bookmark_action = window.add_action(run_menu, "add-bookmark",
                                              "Book&mark this step\u2026", "Ctrl+B",
                                              self.add_bookmark)

    # -------------------------------------------------------------- state
    @property
    def trace(self):
        return self.player.trace

    def conditions(self) -> list[bp.Condition]:
        """The ticked conditions."""
        return [bp.Condition(kind, self.panel.pixel() if kind == bp.PIXEL else None)
                for kind in self.panel.enabled()]

    def unit(self) -> str:
        """The step unit in force: the one chosen, or frame when the run has none of it."""
        unit = self.panel.unit_key()
        if self.trace is None or bp.unavailable(self.trace, unit):
            return bp.FRAME
        return unit

    def set_unit(self, unit: str) -> None:
        self.panel.set_unit(unit)

    def _trace_changed(self) -> None:
        self._follow_files()
        self._show_bookmarks()
        self.panel.set_grid(*self.player.grid)
        self._panel_stale = True
        # Which conditions a run offers takes a pass over a long trace: it
        # waits until the Breakpoints tab is on show, or a step asks for it.
        # (A dock in a tab behind another counts as visible: ask what shows.)
        if not self.breakpoints_dock.visibleRegion().isEmpty():
            self._refresh_panel()

    def _refresh_panel(self) -> None:
        if not getattr(self, "_panel_stale", True):
            return
        self._panel_stale = False
        trace = self.trace
        reasons = {}
        if trace is not None:
            reasons = {key: bp.unavailable(trace, key) for key in (*bp.CONDITIONS, *bp.UNITS)}
        self.panel.set_available(reasons)
        self._unit_changed()

    def _unit_changed(self, _unit=None) -> None:
        """The step buttons and the Run menu name the unit they move by."""
        unit = self.unit()
        what = "" if unit == bp.FRAME else f" one {bp.UNIT_TITLES[unit]}"
        transport = self.window.transport
        transport.forward_button.setToolTip(f"Step forward{what} (Right)")
        transport.back_button.setToolTip(f"Step back{what} (Left)")
        actions = self.window.actions_
        for key, text in (("forward", "Step forward"), ("back", "Step back")):
            actions[key].setText(text + (f" ({bp.UNIT_TITLES[unit]})" if what else ""))
        self._update_note()

    def _update_note(self) -> None:
        """Say which chosen unit or ticked condition this run cannot use."""
        trace = self.trace
        if trace is None:
            self.panel.set_note("")
            return
        notes = []
        chosen = self.panel.unit_key()
        reason = bp.unavailable(trace, chosen)
        if reason:
            notes.append(f"Step by {bp.UNIT_TITLES[chosen]}: not here ({reason}); "
                         "stepping by frame.")
        for condition in self.conditions():
            reason = bp.unavailable(trace, condition)
            if reason:
                notes.append(f"{TITLES[condition.kind]}: not here ({reason}).")
        self.panel.set_note("\n".join(notes))

    def _say(self, text: str) -> None:
        self.window.statusBar().showMessage(text, MESSAGE_MS)

    # ----------------------------------------------------------- stepping
    def step_target(self, index: int, delta: int) -> int | None:
        """Where a step of ``delta`` units goes (the player's stepper)."""
        trace, unit = self.trace, self.unit()
        if trace is None:
            return None
        target = bp.step_target(trace, index, unit, delta)
        if target is None and unit != bp.FRAME:
            way = "further" if delta > 0 else "earlier"
            self._say(f"No {way} {bp.UNIT_TITLES[unit]} in this run")
        return target

    def run_to(self, direction: int = +1) -> int | None:
        """Go to the nearest frame (after or before the one on show) where a
        ticked condition holds; the frame, or None with the reason said."""
        self._refresh_panel()
        self.player.pause()
        trace = self.trace
        if trace is None:
            self._say("No run: place the points first")
            return None
        conditions = self.conditions()
        if not conditions:
            self.breakpoints_dock.raise_()
            self._say("No breakpoint is set: tick a condition in the Breakpoints panel")
            return None
        usable = [c for c in conditions if not bp.unavailable(trace, c)]
        stop = bp.first_stop(trace, self.player.index, usable, direction)
        if stop is None:
            way = "further" if direction > 0 else "earlier"
            missing = [TITLES[c.kind] for c in conditions if c not in usable]
            extra = f" ({', '.join(missing)}: not available in this run)" if missing else ""
            self._say(f"No {way} stop{extra}")
            return None
        self.player.seek(stop.index)
        self._say(f"Stopped at step {stop.index:,}: {stop.condition.title}")
        return stop.index

    def play_stop(self, index: int, target: int) -> int | None:
        """The first frame in index+1 .. target where play must stop (the
        player's stop finder)."""
        trace = self.trace
        if trace is None or not self.panel.enabled():
            return None
        usable = [c for c in self.conditions() if not bp.unavailable(trace, c)]
        stop = bp.first_stop(trace, index, usable, +1, bound=target)
        if stop is None:
            return None
        self._say(f"Play stopped at step {stop.index:,}: {stop.condition.title}")
        return stop.index

    # ------------------------------------------------------ pixel picking
    def _pick_toggled(self, on: bool) -> None:
        viewport = self.window.grid.viewport()
        viewport.setCursor(Qt.CursorShape.CrossCursor if on else Qt.CursorShape.ArrowCursor)
        if on:
            self._say("Click a pixel on the grid to stop at it")

    def eventFilter(self, watched, event):  # noqa: N802
        picking = self.panel.pick.isChecked()
        kind = event.type()
        if picking and kind in (QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonRelease,
                                QEvent.Type.MouseButtonDblClick):
            if kind == QEvent.Type.MouseButtonPress \
                    and event.button() == Qt.MouseButton.LeftButton:
                grid = self.window.grid
                x, y = grid.pixel_at(grid.mapToScene(event.position().toPoint()))
                self.panel.set_pixel(x, y)
                self.panel.pick.setChecked(False)
                self._say(f"Breakpoint at pixel ({x}, {y})")
            return True  # the click picks; it does not place a point
        return super().eventFilter(watched, event)

    # ------------------------------------------------------------ bookmarks
    def bookmarks(self) -> list:
        self._follow_files()
        return bookmark_list(self.window)

    def _follow_files(self) -> None:
        files = self.window.file_actions
        if files is not None and files is not self._files:
            self._files = files
            files.bookmarksChanged.connect(self._show_bookmarks)

    def _show_bookmarks(self) -> None:
        last = self.player.last if self.trace is not None else -1
        rows = [(mark["name"], mark["step"],
                 f"step {mark['step']:,} is past the end of this run (step {last:,})"
                 if mark["step"] > last else "")
                for mark in self.bookmarks()]
        self.marks.set_bookmarks(rows)

    def _edited(self) -> None:
        self._show_bookmarks()
        recovery = self.window.recovery
        if recovery is not None:
            recovery.check()  # bookmarks are part of the unsaved work

    def default_name(self, step: int) -> str:
        """"Step N", or "Step N (2)" ... when that name is taken."""
        names = {mark["name"] for mark in self.bookmarks()}
        name, k = f"Step {step:,}", 2
        while name in names:
            name, k = f"Step {step:,} ({k})", k + 1
        return name

    def add_bookmark(self, name: str | None = None) -> dict | None:
        """Bookmark the step on show; without a name, ask for one."""
        if self.trace is None:
            self._say("No run to bookmark: place the points first")
            return None
        step = int(self.player.index)
        default = self.default_name(step)
        if not isinstance(name, str):
            name, ok = QInputDialog.getText(self.window, "Bookmark",
                                            f"Name of the bookmark at step {step:,}:",
                                            QLineEdit.EchoMode.Normal, default)
            if not ok:
                return None
        name = self._checked_name(name, default)
        if name is None:
            return None
        marks = self.bookmarks()
        mark = {"name": name, "step": step}
        marks.append(mark)
        marks.sort(key=lambda m: m["step"])
        self._edited()
        self.marks.select(marks.index(mark))
        self.bookmarks_dock.raise_()  # its tab comes to the front to show the new mark
        self._say(f"Bookmarked step {step:,} as \u201c{name}\u201d")
        return mark

    def _checked_name(self, name: str, default: str, skip: int = -1) -> str | None:
        name = " ".join(name.split()) or default
        taken = {mark["name"] for k, mark in enumerate(self.bookmarks()) if k != skip}
        if name in taken:
            self._say(f"A bookmark named \u201c{name}\u201d already exists: choose another name")
            return None
        return name

    def rename_bookmark(self, row: int, name: str) -> bool:
        marks = self.bookmarks()
        if not 0 <= row < len(marks):
            return False
        checked = self._checked_name(name, marks[row]["name"], skip=row)
        if checked is not None:
            marks[row]["name"] = checked
        self._edited()  # shows the kept name when the new one was refused
        return checked is not None

    def delete_bookmark(self, row: int) -> bool:
        marks = self.bookmarks()
        if not 0 <= row < len(marks):
            return False
        mark = marks.pop(row)
        self._edited()
        self._say(f"Deleted the bookmark \u201c{mark['name']}\u201d")
        return True

    def jump_to_bookmark(self, row: int) -> bool:
        marks = self.bookmarks()
        if not 0 <= row < len(marks) or self.trace is None:
            return False
        step = marks[row]["step"]
        self.player.pause()
        if step > self.player.last:
            self._say(f"\u201c{marks[row]['name']}\u201d is step {step:,}, past the end of "
                      f"this run: showing the last step")
        self.player.seek(step)
        return True
