"""Two guards against edits nobody meant, for every control of a window.

* The mouse wheel changes a spin box or a combo box only while it has the
  focus; over an unfocused one it scrolls the panel underneath instead (a
  scroll through the Scene panel must not shrink the grid on its way).
* Ctrl+Z and Ctrl+Shift+Z (Ctrl+Y) reach the window's undo and redo even
  when a spin box or a combo box has the focus: their values are scene
  edits already made, which the window's history holds. A text field (a
  spin box's too) keeps them while it has typing of its own to take back.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import (QAbstractScrollArea, QAbstractSpinBox, QComboBox, QLineEdit,
                               QWidget)

VALUE_CONTROLS = (QAbstractSpinBox, QComboBox)
UNDO_KEYS = (QKeySequence.StandardKey.Undo, QKeySequence.StandardKey.Redo)


def value_control(obj) -> QWidget | None:
    """The spin box or combo box ``obj`` is, or is the text field of."""
    for widget in (obj, obj.parent() if isinstance(obj, QLineEdit) else None):
        if isinstance(widget, VALUE_CONTROLS):
            return widget
    return None


class InputGuard(QObject):
    """Watches the spin boxes, combo boxes and text fields of ``window``.

    It is installed on each of them, not on the application: a filter there
    would call Python for every event of the program. Editors made later
    (an algorithm's options) are picked up after each new run."""

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self._guarded: set[int] = set()
        self.scan()
        window.player.traceChanged.connect(self.scan)
        # An algorithm's option editors are made as it is chosen: each is
        # guarded as it first shows (its parent hears of it).
        window.options.installEventFilter(self)

    def scan(self) -> None:
        """Guard the window's controls not guarded yet."""
        self._guard_inside(self.window)

    def _guard_inside(self, widget: QWidget) -> None:
        """Found by kind in Qt, so that the window's other ~380 widgets are
        not wrapped for Python (a wrapper costs a property and its event)."""
        for kind in (*VALUE_CONTROLS, QLineEdit):
            for control in widget.findChildren(kind):
                self._guard(control)

    def _guard(self, widget) -> None:
        if isinstance(widget, (*VALUE_CONTROLS, QLineEdit)) and id(widget) not in self._guarded:
            self._guarded.add(id(widget))
            widget.destroyed.connect(lambda _obj=None, key=id(widget):
                                     self._guarded.discard(key))
            widget.installEventFilter(self)
            if isinstance(widget, VALUE_CONTROLS):
                # A wheel would otherwise give it the focus, then the value.
                widget.setFocusPolicy(Qt.FocusPolicy.StrongFocus)

    def eventFilter(self, obj, event) -> bool:  # noqa: N802
        kind = event.type()
        if kind in (QEvent.Type.ChildAdded, QEvent.Type.ChildPolished):
            child = event.child()
            if isinstance(child, QWidget):
                self._guard(child)
                self._guard_inside(child)
        elif kind == QEvent.Type.Wheel:
            control = value_control(obj)
            if control is not None and not control.hasFocus():
                scroll_instead(control, event)
                return True
        elif kind == QEvent.Type.ShortcutOverride:
            if any(event.matches(key) for key in UNDO_KEYS) and not _keeps_undo(obj):
                event.ignore()  # not overridden: the window's shortcut runs
                return True
        return False


def _keeps_undo(obj) -> bool:
    """A text field (a spin box's too) keeps Ctrl+Z while it holds typing
    of its own not yet taken back or committed."""
    control = value_control(obj)
    if isinstance(control, QAbstractSpinBox):
        obj = control.lineEdit()
    elif control is not None:
        obj = control.lineEdit() if control.isEditable() else None
    return isinstance(obj, QLineEdit) and obj.isUndoAvailable()


def scroll_instead(control, event) -> None:
    """Hand the wheel to the scroll area the control sits in, if any."""
    widget = control.parentWidget()
    while widget is not None and not isinstance(widget, QAbstractScrollArea):
        widget = widget.parentWidget()
    if widget is not None:
        bar = widget.verticalScrollBar()
        steps = event.angleDelta().y() / 120
        bar.setValue(bar.value() - round(steps * bar.singleStep() * 3))
