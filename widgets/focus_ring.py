"""A ring drawn around the widget that has the keyboard focus, in a window
whose style draws a faint focus mark or none (Fusion marks a focused table
or text area only by a thin line in the highlight colour, and the panels
that never take the focus from Tab, such as the Variables table, draw none
when F6 gives it to them).

The ring is a child of the window laid over the focused widget; it takes no
clicks. It shows when the focus moved by the keyboard (not by a click on the
widget), so a click leaves the window as it was. A black line
under a white one stands out on any background, in either theme.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QRect, Qt
from PySide6.QtGui import QColor, QCursor, QGuiApplication, QPainter, QPen
from PySide6.QtWidgets import QApplication, QWidget
from shiboken6 import isValid

WIDTH = 4  # screen pixels: a 2 px black line and a 2 px white one inside it
OUTER, INNER = QColor("#000000"), QColor("#ffffff")


def clicked(widget: QWidget) -> bool:
    """Whether ``widget`` took the focus from a click: a button is down with
    the pointer over it."""
    if QGuiApplication.mouseButtons() == Qt.MouseButton.NoButton:
        return False
    under = QApplication.widgetAt(QCursor.pos())
    return under is not None and (under is widget or widget.isAncestorOf(under))


class FocusRing(QWidget):
    """Follows the keyboard focus among the widgets of ``window``."""

    def __init__(self, window):
        super().__init__(window)
        self.setObjectName("focusRing")
        self.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)
        self.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.target: QWidget | None = None
        #: Whether a widget that took the focus, not by a click, is ringed.
        self.accepts = lambda widget: True
        self.hide()
        QApplication.instance().focusChanged.connect(self._focus_changed)

    def _focus_changed(self, _old, new) -> None:
        self.follow(None if new is None or clicked(new) or new.window() is not self.window()
                    or not self.accepts(new) else new)

    def follow(self, widget: QWidget | None) -> None:
        """Ring ``widget`` (None: no ring)."""
        if self.target is not None and isValid(self.target):  # not deleted meanwhile
            self.target.removeEventFilter(self)
        self.target = widget
        if widget is not None:
            widget.installEventFilter(self)
        self._place()

    def _place(self) -> None:
        target = self.target
        if target is None or not isValid(target) or not target.isVisible():
            self.hide()
            return
        top_left = target.mapTo(self.window(), target.rect().topLeft())
        rect = QRect(top_left, target.size()).adjusted(-WIDTH, -WIDTH, WIDTH, WIDTH)
        self.setGeometry(rect.intersected(self.window().rect()))
        self.show()
        self.raise_()
        self.update()

    def eventFilter(self, obj, event) -> bool:  # noqa: N802
        if event.type() in (QEvent.Type.Move, QEvent.Type.Resize, QEvent.Type.Show,
                            QEvent.Type.Hide):
            self._place()
        return False

    def paintEvent(self, event):  # noqa: N802
        painter = QPainter(self)
        half = WIDTH // 4
        for colour, inset in ((OUTER, half), (INNER, WIDTH // 2 + half)):
            pen = QPen(colour, WIDTH // 2)
            pen.setJoinStyle(Qt.PenJoinStyle.MiterJoin)
            painter.setPen(pen)
            painter.drawRect(self.rect().adjusted(inset, inset, -inset - 1, -inset - 1))
        painter.end()
