"""The window by keyboard alone: the grid's cell cursor
(widgets/grid_cursor.py) with its place in the status bar and in the Edit
menu, F6 and Shift+F6 to go round the grid and the docks on show, and a ring
around the widget that has the focus (widgets/focus_ring.py).

F6 gives the focus to a dock's first list, table or tree, even one that Tab
passes by (the pseudo-code, the variables: they never take the focus from
Tab, so that the playback keys stay with the window), so that a screen
reader reads it and the ring shows where the keyboard is; the playback keys
keep working there. A dock without one gets its first widget Tab reaches.

A button that has the focus takes Enter, and Space when the keyboard moved
the focus to it (``ButtonKeys``): the window's Space (play) and Return (close
the contour) would otherwise take them, and a focused button could not be
pressed without a mouse. After a click Space still plays.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtWidgets import (QAbstractButton, QAbstractItemView, QApplication, QCheckBox,
                               QDockWidget, QLabel, QRadioButton, QWidget)

from widgets.focus_ring import FocusRing, clicked
from widgets.grid_cursor import GridCursor

GO_ROUND = Qt.FocusReason.ShortcutFocusReason
ENTER_KEYS = (Qt.Key.Key_Return, Qt.Key.Key_Enter)
KEYBOARD_REASONS = (Qt.FocusReason.TabFocusReason, Qt.FocusReason.BacktabFocusReason,
                    Qt.FocusReason.ShortcutFocusReason)


class KeyboardAccess(QObject):
    """Installs the cursor, the F6 keys and the focus ring on ``window``."""

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.cursor = GridCursor(window.grid)
        self.ring = FocusRing(window)
        # The grid takes the focus when a scene opens: a ring only when the keyboard moved it.
        self.ring.accepts = lambda widget: widget is not window.grid or self.cursor.by_keyboard
        # The window's dialogs and windows (export, preferences, compare,
        # gallery) get a ring of their own when the keyboard first moves in them.
        QApplication.instance().focusChanged.connect(self._ring_dialogs)
        self.button_keys = ButtonKeys(window)
        self.label = QLabel(window)
        self.label.setObjectName("keyCursor")
        self.label.hide()
        window.statusBar().addPermanentWidget(self.label)
        self.cursor.moved.connect(self._cursor_moved)
        window.player.traceChanged.connect(lambda: self._cursor_moved(
            self.cursor.cell if self.cursor.active else None))
        self.toggle = window.add_action(window.menus["edit"], "cursor", "&Keyboard cursor", "K",
                                        self.toggle_cursor)
        self.toggle.setToolTip("A cell cursor on the grid: the arrows move it, Enter places or "
                               "picks up a point, Esc puts a held point back (K)")
        view = window.menus["view"]
        view.addSeparator()
        window.add_action(window.menus["edit"], "find-algorithm", "&Find algorithm\u2026",
                          "Ctrl+F", self.find_algorithm)
        window.add_action(view, "next-panel", "Ne&xt panel", "F6", lambda: self.go_round(1))
        window.add_action(view, "previous-panel", "Pre&vious panel", "Shift+F6",
                          lambda: self.go_round(-1))

    def toggle_cursor(self) -> None:
        """K: the cursor on (the grid takes the focus) or off."""
        grid = self.window.grid
        on = not self.cursor.active
        if on:
            grid.setFocus(GO_ROUND)
            self.ring.follow(grid)  # a click may have given it the focus: no ring then
        self.cursor.set_enabled(on)

    def _ring_dialogs(self, _old, new) -> None:
        if new is None or clicked(new):
            return
        top = new.window()
        if top is self.window or top.findChild(FocusRing) is not None \
                or not _opened_from(top, self.window):
            return
        FocusRing(top).follow(new)

    def find_algorithm(self) -> None:
        """Ctrl+F: the keyboard to the algorithm search (Enter picks the first
        algorithm shown and gives the keys back to the grid)."""
        search = self.window.picker_search
        self.window.scene_dock.show()
        self.window.scene_dock.raise_()
        search.setFocus(GO_ROUND)
        search.selectAll()

    def _cursor_moved(self, cell) -> None:
        if cell is None:
            self.label.hide()
            return
        self.label.setText(f"cursor ({cell[0]}, {cell[1]}) \u00b7 {self.cursor.hint()}")
        self.label.show()

    # ------------------------------------------------------------ F6
    def regions(self) -> list[QWidget]:
        """The grid, then the docks on show (floating ones apart), left to right
        and top down."""
        # A dock behind another's tab counts as visible, but shows nothing.
        docks = [d for d in self.window.findChildren(QDockWidget)
                 if d.isVisible() and not d.visibleRegion().isEmpty()
                 and d.widget() is not None and d.window() is self.window]
        docks.sort(key=lambda d: (d.mapTo(self.window, d.rect().topLeft()).x(),
                                  d.mapTo(self.window, d.rect().topLeft()).y()))
        return [self.window.grid, *docks]

    def go_round(self, direction: int) -> None:
        """F6 (1) or Shift+F6 (-1): the focus to the next region."""
        regions = self.regions()
        focus = self.window.focusWidget()
        here = next((k for k, r in enumerate(regions)
                     if focus is not None and (r is focus or r.isAncestorOf(focus))), -1)
        if here < 0 and direction < 0:
            here = 0
        target = regions[(here + direction) % len(regions)]
        _focus_target(target).setFocus(GO_ROUND)


class ButtonKeys(QObject):
    """Enter presses the focused button. Space presses it too (or toggles a
    check box or a radio button) when the keyboard took the focus there (Tab,
    Shift+Tab, F6); after a click or a program's choice Space plays the run,
    as it does wherever the focus is."""

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self._watched: set[int] = set()
        self._by_keyboard = None  # the button Tab or F6 gave the focus to
        self._watch_new()
        QApplication.instance().focusChanged.connect(self._focus_changed)

    def _focus_changed(self, _old, new) -> None:
        if new is not None and new.window() is self.window:
            self._watch_new()  # buttons made since (an exercise's choices)

    def _watch_new(self) -> None:
        for button in self.window.findChildren(QAbstractButton):
            if id(button) not in self._watched:
                self._watched.add(id(button))
                button.installEventFilter(self)
                button.destroyed.connect(lambda *_a, key=id(button): self._watched.discard(key))

    def eventFilter(self, obj, event) -> bool:  # noqa: N802
        kind = event.type()
        if kind == QEvent.Type.FocusIn:
            self._by_keyboard = obj if event.reason() in KEYBOARD_REASONS else None
            return False
        if kind not in (QEvent.Type.ShortcutOverride, QEvent.Type.KeyPress) \
                or event.modifiers() & ~Qt.KeyboardModifier.KeypadModifier:
            return False
        key = event.key()
        if key == Qt.Key.Key_Space:
            takes = obj is self._by_keyboard
        else:
            takes = key in ENTER_KEYS and not isinstance(obj, (QCheckBox, QRadioButton))
        if not takes:
            return False
        if kind == QEvent.Type.ShortcutOverride:
            event.accept()  # the key comes to the button, not to the window's action
            return True
        if key != Qt.Key.Key_Space:  # Space the button handles itself
            obj.click()
            return True
        return False


def _opened_from(top: QWidget, window: QWidget) -> bool:
    """Whether the window ``top`` belongs to ``window`` (a dialog of it)."""
    parent = top.parentWidget()
    while parent is not None:
        if parent is window:
            return True
        parent = parent.parentWidget()
    return False


def _focus_target(region: QWidget) -> QWidget:
    """The widget in ``region`` the keyboard goes to."""
    if not isinstance(region, QDockWidget):
        return region
    start = widget = region.widget()
    views = [w for w in start.findChildren(QAbstractItemView) if w.isVisible()]
    if views:
        return views[0]
    for _ in range(500):  # the focus chain is a ring; a dock holds far fewer widgets
        widget = widget.nextInFocusChain()
        if widget is start or not region.isAncestorOf(widget):
            break
        if (widget.focusPolicy() & Qt.FocusPolicy.TabFocus) and widget.isVisible() \
                and widget.isEnabled():
            return widget
    return start
