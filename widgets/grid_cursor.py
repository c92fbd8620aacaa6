"""A cell cursor on the pixel grid: the keyboard's way to do what the
mouse does there, every drag included.

The cursor shows while the grid has the keyboard focus and the cursor is on
(the grid reached by Tab or F6 turns it on, a click turns it off, K toggles
it). While it is on:

* the arrow keys move it a cell (Shift: five cells);
* Enter on an empty cell places the next point there (the seed, with the
  seed tool); on a point's handle, the seed, or a circle's rim it picks that
  up: the arrows then move it, Enter drops it, Esc puts it back;
* Enter on the first vertex of a contour being drawn closes it; Shift+Enter
  starts a new contour, as Shift+click does.

The arrows belong to stepping elsewhere (Left/Right are the Run menu's), so
the cursor takes them only while it is on. It reports through the view's
own signals (``gestured``, ``radiusDragged``, ``markerPlaced``,
``editStarted``), so the window handles a key as it handles a drag.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QEvent, QObject, QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QPen, QColor
from PySide6.QtWidgets import QGraphicsRectItem

from app.model.drawing import CIRCLE, Move, Place, closes_at

from .grid_view import DRAW, MARKER

STEP, BIG_STEP = 1, 5  # cells an arrow moves the cursor; with Shift
ARROWS = {Qt.Key.Key_Left: (-1, 0), Qt.Key.Key_Right: (1, 0),
          Qt.Key.Key_Up: (0, 1), Qt.Key.Key_Down: (0, -1)}
ENTER = (Qt.Key.Key_Return, Qt.Key.Key_Enter)
KEYBOARD_REASONS = (Qt.FocusReason.TabFocusReason, Qt.FocusReason.BacktabFocusReason,
                    Qt.FocusReason.ShortcutFocusReason)
# Black under white: one of the two stands out on any cell, in either theme;
# the inner line turns amber while something is held.
OUTER, INNER, HOLDING = QColor("#000000"), QColor("#ffffff"), QColor("#ffb000")


def _ring(colour: QColor, width: float) -> QGraphicsRectItem:
    item = QGraphicsRectItem()
    pen = QPen(colour, width)
    pen.setCosmetic(True)  # screen pixels at every zoom
    pen.setJoinStyle(Qt.PenJoinStyle.MiterJoin)
    item.setPen(pen)
    item.setZValue(20)  # over the handles and labels
    item.setVisible(False)
    return item


class GridCursor(QObject):
    """The keyboard cursor of one ``PixelGridView``."""

    #: The cursor's cell (x, y) when it shows, None when it is hidden.
    moved = Signal(object)

    def __init__(self, view):
        super().__init__(view)
        self.view = view
        self.cell = None  # the grid's centre until it first shows
        self.enabled = False
        self.by_keyboard = False  # the grid's focus came from Tab, Shift+Tab or a shortcut
        self._held = None  # ("point", i, was) | ("marker", was) | ("rim", radii)
        self._rings = (_ring(OUTER, 5), _ring(INNER, 2))
        for ring in self._rings:
            view.view_box.addItem(ring)
        view.installEventFilter(self)

    # --------------------------------------------------------- state
    @property
    def active(self) -> bool:
        """The cursor shows and takes the arrows and Enter."""
        return self.enabled and self.view.hasFocus()

    @property
    def held(self) -> str | None:
        """What Enter picked up ("point", "marker", "rim"), or None."""
        return None if self._held is None else self._held[0]

    def set_enabled(self, on: bool) -> None:
        if not on:
            self.cancel()
        self.enabled = bool(on)
        self._show()

    def move_to(self, x: int, y: int) -> None:
        """Put the cursor on cell (x, y), clamped to the grid."""
        width, height = self.view.grid_size
        self.cell = (min(max(int(x), 0), width - 1), min(max(int(y), 0), height - 1))
        self._drag_held()
        self._show()

    def move_by(self, dx: int, dy: int) -> None:
        if self.view.y_down:
            dy = -dy  # Up goes up the screen in either frame
        self.move_to(self.cell[0] + dx, self.cell[1] + dy)

    def hint(self) -> str:
        """What Enter does on the cursor's cell, in a few words."""
        if self._held is not None:
            return f"moving the {self._held_name()}: Enter drops, Esc puts back"
        target = self._target()
        if target[0] == "place":
            return "Enter places the seed" if target[1] == MARKER else "Enter places a point"
        if target[0] == "close":
            return "Enter closes the contour"
        return f"Enter picks up the {self._held_name(target)}"

    # ------------------------------------------------------- actions
    def enter(self, new_contour: bool = False) -> None:
        """Enter: drop what is held, else act on the cursor's cell."""
        view = self.view
        if self._held is not None:
            self._held = None
            self._show()
            return
        target = self._target()
        if target[0] == "close":
            view.close_contour()
        elif target[0] == "place" and target[1] == MARKER:
            view.editStarted.emit()
            view.markerPlaced.emit(self.cell)
        elif target[0] == "place":
            view.editStarted.emit()
            view.gestured.emit(Place(self._point(), None, new_contour))
            if view.mode == CIRCLE and view._circle and len(view.points) == 1:
                # As a drag from an empty cell: the centre, then the radius.
                self._held = ("rim", view._radii)
        else:
            view.editStarted.emit()
            self._held = target
        self._show()

    def cancel(self) -> bool:
        """Esc: put what is held back where it was."""
        held, self._held = self._held, None
        if held is None:
            return False
        view = self.view
        if held[0] == "point":  # the point back, and the cursor with it
            view.gestured.emit(Move(held[1], held[2]))
            where = view.anchor(held[2])
            self.cell = (math.floor(where.x()), math.floor(where.y()))
        elif held[0] == "marker":
            view.markerPlaced.emit(held[1])
            self.cell = tuple(held[1])
        else:
            view.radiusDragged.emit(*held[1])
        self._show()
        return True

    # ---------------------------------------------------------- rules
    def _point(self):
        """The point the cursor's cell stands for: the cell, or its centre."""
        return self.view.snap(QPointF(self.cell[0] + 0.5, self.cell[1] + 0.5))

    def _in_cell(self, where: QPointF | None) -> bool:
        return where is not None and (math.floor(where.x()), math.floor(where.y())) == self.cell

    def _handle(self) -> int | None:
        view = self.view
        if view._places is not None:  # handles drawn elsewhere do not move the points
            return None
        found = [i for i, p in enumerate(view.points) if self._in_cell(view.anchor(p))]
        return found[-1] if found else None

    def _target(self):
        """What Enter on the cursor's cell does, as the mouse's drag rules
        have it (``PixelGridView._drag_target``)."""
        view = self.view
        handle = self._handle()
        on_marker = view.marker_point is not None and tuple(view.marker_point) == self.cell
        if on_marker and (handle is None or view.tool == MARKER):
            return ("marker", view.marker_point)
        if view.tool == MARKER and view._marker_name:
            return ("place", MARKER)
        if handle is not None and closes_at(view._rules, view._sketch, handle):
            return ("close",)
        if handle is not None:
            return ("point", handle, view.points[handle])
        if view._circle and view.points and self._in_cell(view._rim_position()):
            return ("rim", view._radii)
        return ("place", DRAW)

    def _held_name(self, target=None) -> str:
        kind = (target or self._held)[0]
        if kind == "point":
            names = self.view.labels()
            index = (target or self._held)[1]
            return f"point {names[index]}" if index < len(names) else "point"
        return {"marker": self.view._marker_name or "marker", "rim": "radius"}[kind]

    def _drag_held(self) -> None:
        held, view = self._held, self.view
        if held is None:
            return
        if held[0] == "point":
            point = self._point()
            if view.points[held[1]] != point:
                view.gestured.emit(Move(held[1], point))
        elif held[0] == "marker":
            if tuple(view.marker_point or ()) != self.cell:
                view.markerPlaced.emit(self.cell)
        elif view.points:
            centre = QPointF(self.cell[0] + 0.5, self.cell[1] + 0.5)
            view.radiusDragged.emit(*view._radii_to(centre, Qt.KeyboardModifier.NoModifier))

    # ---------------------------------------------------------- drawing
    def _show(self) -> None:
        view = self.view
        shown = self.active and view.grid_size[0] > 0
        if self.cell is None and shown:
            self.cell = (view.grid_size[0] // 2, view.grid_size[1] // 2)
        if self.cell is None:
            return
        if shown:  # the dashed preview runs to the cursor, as it does to the pointer
            view._cursor_at = QPointF(self.cell[0] + 0.5, self.cell[1] + 0.5)
            view._draw_preview()
        rect = QRectF(self.cell[0], self.cell[1], 1, 1)
        self._rings[1].setPen(self._pen(HOLDING if self._held else INNER))
        for ring in self._rings:
            ring.setRect(rect)
            ring.setVisible(shown)
        self.moved.emit(self.cell if shown else None)

    def _pen(self, colour: QColor) -> QPen:
        pen = QPen(self._rings[1].pen())
        pen.setColor(colour)
        return pen

    # ----------------------------------------------------------- events
    def eventFilter(self, obj, event) -> bool:  # noqa: N802
        kind = event.type()
        if kind == QEvent.Type.FocusIn:
            self.by_keyboard = event.reason() in KEYBOARD_REASONS
            if self.by_keyboard:
                self.enabled = True
            elif event.reason() == Qt.FocusReason.MouseFocusReason:
                self.set_enabled(False)
            self._show()
        elif kind == QEvent.Type.FocusOut:
            self.cancel()
            self._show()
        elif kind == QEvent.Type.ShortcutOverride and self._takes(event):
            event.accept()  # the key comes to the grid, not to the Run menu
            return True
        elif kind == QEvent.Type.KeyPress and self._takes(event):
            self._key(event)
            return True
        return False

    def _takes(self, event) -> bool:
        if not self.active:
            return False
        key = event.key()
        if key == Qt.Key.Key_Escape:
            return self._held is not None
        return key in ARROWS or key in ENTER

    def _key(self, event) -> None:
        key, shift = event.key(), bool(event.modifiers() & Qt.KeyboardModifier.ShiftModifier)
        if key in ARROWS:
            dx, dy = ARROWS[key]
            step = BIG_STEP if shift else STEP
            self.move_by(dx * step, dy * step)
        elif key in ENTER:
            self.enter(new_contour=shift)
        else:
            self.cancel()
