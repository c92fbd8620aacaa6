"""The vertex table: one row per point, its exact coordinates and, when the
algorithm takes them, its colour, depth z, clip-space w and attribute s.

Typed values are checked here (a number, inside the grid, a whole number
for whole-pixel algorithms, w > 0, #rrggbb); a bad one is refused with a
message and nothing is emitted. A good edit emits ``edited(points, breaks,
attributes)``: the whole input as it would be, for the window to apply.
The table never changes its own rows: it shows what ``set_points`` and
``set_attributes`` give it, so it stays in step with the grid.
"""
from __future__ import annotations

import bisect

from PySide6.QtCore import QAbstractTableModel, QEvent, QModelIndex, Qt, Signal
from PySide6.QtGui import QColor
from PySide6.QtWidgets import (QAbstractItemDelegate, QAbstractItemView, QColorDialog,
                               QHBoxLayout, QHeaderView, QLabel, QStyledItemDelegate, QTableView,
                               QToolButton, QVBoxLayout, QWidget)

from algorithms.core import registry
from algorithms.core.registry import format_value
from algorithms.core.errors import InputError

from .editors import DEFAULT_COLORS, default_color

ERROR_STYLE = "color: #c92a2a;"
GROUP_TINT = QColor("#eef2f7")  # every other contour or triangle

# Column titles and tooltips of the attribute columns, by option name.
ATTRIBUTES = {
    "colors": ("colour", "The vertex colour: type #rrggbb, or double-click to pick one"),
    "z": ("z", "The vertex depth z (any finite number)"),
    "w": ("w", "The vertex's clip-space w (greater than 0)"),
    "s": ("s", "A scalar attribute of the vertex (a texture coordinate, say)"),
}
# A value for the other vertices when an attribute is first given to one.
DEFAULTS = {"z": 0.0, "w": 1.0, "s": 0.0}


class Refused(ValueError):
    """A typed value the table does not take; the text says why."""


def parse_number(text: str, what: str, integer: bool = False):
    """A typed finite number (whole when ``integer``); Refused says why not."""
    try:
        return registry.parse_number(text.strip(), what, integer=integer)
    except InputError as error:
        raise Refused(str(error)) from None


def per_vertex(values, name: str, count: int) -> list:
    """An attribute option stretched to one entry per point: a list of
    three is shared by every triangle; none gives the defaults."""
    values = list(values or ())
    if len(values) == count:
        return values
    if len(values) == 3:
        return [values[k % 3] for k in range(count)]
    fill = [default_color(k, count) if name == "colors" else DEFAULTS.get(name, 0.0)
            for k in range(count)]
    return values[:count] + fill[len(values):]


class VertexModel(QAbstractTableModel):
    """Rows: the points; columns: x, y, then the attributes."""

    edited = Signal(list, object, object)
    refused = Signal(str)

    def __init__(self, parent=None):
        super().__init__(parent)
        self.points: list[tuple] = []
        self.breaks: tuple = ()
        self.labels: list[str] = []
        self.names: tuple = ()
        self.count = 0
        self.integer = True
        self.open_ended = False
        self.size = (32, 24)
        self.attributes: list[str] = []  # option names shown as columns
        self.values: dict = {}  # option name -> its value (a tuple)
        self.group_size = 0  # triangles: rows per group, when not contours
        self._shape = (0, 0)  # rows and columns the view last took in
        self._entries: dict = {}  # option name -> one value per point

    # ------------------------------------------------------------ shape
    def rowCount(self, parent=QModelIndex()):  # noqa: N802
        if parent.isValid():
            return 0
        return len(self.points) if self.open_ended else max(self.count, len(self.points))

    def columnCount(self, parent=QModelIndex()):  # noqa: N802
        return 0 if parent.isValid() else 2 + len(self.attributes)

    def column_name(self, column: int) -> str:
        return ("x", "y")[column] if column < 2 else self.attributes[column - 2]

    def refresh(self) -> None:
        """Show the new state: in place when the shape is the same (a cell
        being edited or moved to stays open), else by a reset."""
        self._entries.clear()
        rows, columns = self.rowCount(), self.columnCount()
        if (rows, columns) == self._shape and rows and columns:
            self.dataChanged.emit(self.index(0, 0), self.index(rows - 1, columns - 1))
            self.headerDataChanged.emit(Qt.Orientation.Vertical, 0, rows - 1)
            self.headerDataChanged.emit(Qt.Orientation.Horizontal, 0, columns - 1)
            return
        self.beginResetModel()
        self._shape = (rows, columns)
        self.endResetModel()

    # ------------------------------------------------------------- data
    def label(self, row: int) -> str:
        if row < len(self.labels):
            return self.labels[row]
        return self.names[row] if row < len(self.names) else f"P{row + 1}"

    def group(self, row: int) -> int:
        if self.breaks:
            return bisect.bisect_right(self.breaks, row)
        return row // self.group_size if self.group_size else 0

    def headerData(self, section, orientation, role=Qt.ItemDataRole.DisplayRole):  # noqa: N802
        horizontal = orientation == Qt.Orientation.Horizontal
        if role == Qt.ItemDataRole.DisplayRole:
            if horizontal:
                name = self.column_name(section)
                return ATTRIBUTES[name][0] if name in ATTRIBUTES else name
            return self.label(section)
        if role == Qt.ItemDataRole.ToolTipRole:
            if not horizontal:
                return f"Vertex {self.label(section)}"
            name = self.column_name(section)
            if name in ATTRIBUTES:
                return ATTRIBUTES[name][1]
            return (f"The point's {name} in pixel units, exactly as typed"
                    + (" (whole numbers)" if self.integer else
                       " (the run snaps it to its sub-pixel grid, 1/256 px by default)"))
        return None

    def data(self, index, role=Qt.ItemDataRole.DisplayRole):
        row, name = index.row(), self.column_name(index.column())
        placed = row < len(self.points)
        if role in (Qt.ItemDataRole.DisplayRole, Qt.ItemDataRole.EditRole):
            if not placed:
                return "\u2013" if role == Qt.ItemDataRole.DisplayRole else ""
            if name == "colors" and role == Qt.ItemDataRole.DisplayRole and self.values.get(name):
                return ""  # the swatch says it; the tooltip and the editor give #rrggbb
            return self.text(row, name)
        if role == Qt.ItemDataRole.BackgroundRole:
            if name == "colors" and placed and self.values.get(name):
                return QColor(self.text(row, name))
            return GROUP_TINT if self.group(row) % 2 else None
        if role == Qt.ItemDataRole.ForegroundRole and name == "colors" and placed \
                and self.values.get(name):
            return QColor("#ffffff" if QColor(self.text(row, name)).lightness() < 140
                          else "#1d2733")
        if role == Qt.ItemDataRole.ToolTipRole:
            tip = self.headerData(index.column(), Qt.Orientation.Horizontal, role)
            return f"{self.text(row, name)}: {tip}" if name == "colors" and placed \
                and self.values.get(name) else tip
        if role == Qt.ItemDataRole.TextAlignmentRole and name != "colors":
            return int(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        return None

    def text(self, row: int, name: str) -> str:
        if name in ("x", "y"):
            return format_value(self.points[row][0 if name == "x" else 1])
        if not self.values.get(name):
            return ""  # not given: the run goes without it
        value = self.entries(name)[row]
        return value if name == "colors" else format_value(value)

    def entries(self, name: str) -> list:
        """One value per point (worked out once per change: tables can be long)."""
        cached = self._entries.get(name)
        if cached is None:
            cached = self._entries[name] = per_vertex(self.values.get(name), name,
                                                      len(self.points))
        return cached

    def flags(self, index):
        flags = Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
        if index.row() < len(self.points):
            flags |= Qt.ItemFlag.ItemIsEditable
        return flags

    def setData(self, index, value, role=Qt.ItemDataRole.EditRole):  # noqa: N802
        if role != Qt.ItemDataRole.EditRole or index.row() >= len(self.points):
            return False
        row, name = index.row(), self.column_name(index.column())
        try:
            self.put(row, name, str(value))
        except Refused as error:
            self.refused.emit(str(error))
            return False
        return True

    # ------------------------------------------------------------ edits
    def put(self, row: int, name: str, text: str) -> None:
        """Emit the input with ``text`` typed into (row, name); raises Refused."""
        what = f"{self.label(row)} {ATTRIBUTES.get(name, (name,))[0]}"
        points, values = list(self.points), dict(self.values)
        if name in ("x", "y"):
            axis = 0 if name == "x" else 1
            value = parse_number(text, what, self.integer)
            limit = self.size[axis] - 1 if self.integer else self.size[axis]
            if not 0 <= value <= limit:
                raise Refused(f"{what}: {text.strip()} is outside the grid (0 to {limit})")
            point = list(points[row])
            point[axis] = value
            points[row] = tuple(point)
        else:
            entries = list(self.entries(name))
            entries[row] = self._attribute(name, text, what)
            values[name] = tuple(entries)
        if points != self.points or values != self.values:
            self.edited.emit(points, tuple(self.breaks), values)

    @staticmethod
    def _attribute(name: str, text: str, what: str):
        if name == "colors":
            color = text.strip().lower()
            if len(color) != 7 or not QColor.isValidColorName(color) or color[0] != "#":
                raise Refused(f"{what}: {text.strip()!r} is not a colour #rrggbb")
            return color
        value = parse_number(text, what)
        if name == "w" and not value > 0:
            raise Refused(f"{what}: w must be greater than 0, got {text.strip()}")
        return value

    def insert_after(self, row: int) -> None:
        """A new vertex after ``row`` (at the end when -1), in its contour."""
        points = list(self.points)
        if points:
            row = len(points) - 1 if row < 0 else min(row, len(points) - 1)
            x, y = points[row]
            step = 1 if self.integer else 0.5
            point = (min(x + step, self.size[0] - (1 if self.integer else 0)),
                     min(y + step, self.size[1] - (1 if self.integer else 0)))
        else:
            row = -1
            point = (self.size[0] // 2, self.size[1] // 2)
            point = point if self.integer else (float(point[0]), float(point[1]))
        points.insert(row + 1, point)
        breaks = tuple(b + 1 if b > row else b for b in self.breaks)
        values = self._resized(lambda entries, fill: entries.insert(row + 1, fill))
        self.edited.emit(points, breaks, values)

    def remove(self, row: int) -> None:
        if not 0 <= row < len(self.points):
            return
        points = list(self.points)
        del points[row]
        breaks = tuple(sorted({b - 1 if b > row else b for b in self.breaks} - {0}))
        values = self._resized(lambda entries, _fill: entries.pop(row))
        self.edited.emit(points, breaks, values)

    def _resized(self, change) -> dict:
        """Attributes given one per vertex follow an added or removed vertex."""
        values = dict(self.values)
        n = len(self.points)
        for name, entries in self.values.items():
            if entries and len(entries) == n and n != 3:
                entries = list(entries)
                fill = default_color(n % len(DEFAULT_COLORS), n + 1) if name == "colors" \
                    else DEFAULTS.get(name, 0.0)
                change(entries, fill)
                values[name] = tuple(entries)
        return values


class _Delegate(QStyledItemDelegate):
    """Enter commits the cell and moves on to the next one, as Tab does."""

    def eventFilter(self, editor, event):  # noqa: N802
        if event.type() == QEvent.Type.KeyPress and event.key() in (Qt.Key.Key_Return,
                                                                    Qt.Key.Key_Enter):
            self.commitData.emit(editor)
            self.closeEditor.emit(editor, QAbstractItemDelegate.EndEditHint.EditNextItem)
            return True
        return super().eventFilter(editor, event)


class _View(QTableView):
    # Keys the table uses while it has the focus; the window's playback
    # shortcuts (Space, arrows, Home, End) must not take them away.
    OWN_KEYS = {Qt.Key.Key_Left, Qt.Key.Key_Right, Qt.Key.Key_Up, Qt.Key.Key_Down,
                Qt.Key.Key_Home, Qt.Key.Key_End, Qt.Key.Key_Space, Qt.Key.Key_Return,
                Qt.Key.Key_Enter, Qt.Key.Key_Delete, Qt.Key.Key_Insert, Qt.Key.Key_Backspace,
                Qt.Key.Key_Tab, Qt.Key.Key_Backtab, Qt.Key.Key_F2}

    def __init__(self, owner):
        super().__init__(owner)
        self.owner = owner

    def event(self, event):
        if event.type() == QEvent.Type.ShortcutOverride and event.key() in self.OWN_KEYS \
                and not event.modifiers() & ~Qt.KeyboardModifier.ShiftModifier \
                & ~Qt.KeyboardModifier.KeypadModifier:
            event.accept()
            return True
        return super().event(event)

    def keyPressEvent(self, event):  # noqa: N802
        key = event.key()
        current = self.currentIndex()
        if key == Qt.Key.Key_Insert and self.owner.add_button.isEnabled():
            self.owner.add_row()
        elif key == Qt.Key.Key_Delete and self.owner.remove_button.isEnabled():
            self.owner.remove_row()
        elif key in (Qt.Key.Key_Return, Qt.Key.Key_Enter) and current.isValid():
            self.edit(current)
        else:
            super().keyPressEvent(event)

    def edit(self, index, trigger=QAbstractItemView.EditTrigger.AllEditTriggers, event=None):
        # A double-click on a colour opens the colour dialog instead.
        if (trigger == QAbstractItemView.EditTrigger.DoubleClicked and index.isValid()
                and self.model().column_name(index.column()) == "colors"):
            self.owner.pick_color(index.row())
            return False
        return super().edit(index, trigger, event)


class VertexTable(QWidget):
    """The points (and per-vertex attributes) as an editable table."""

    edited = Signal(list, object, object)  # points, breaks, attribute options
    refused = Signal(str)

    MAX_VISIBLE_ROWS = 9

    def __init__(self, parent=None):
        super().__init__(parent)
        self.model = VertexModel(self)
        self.view = _View(self)
        self.view.setObjectName("vertexTable")
        self.view.setModel(self.model)
        self.view.setItemDelegate(_Delegate(self.view))
        self.view.setEditTriggers(QAbstractItemView.EditTrigger.DoubleClicked
                                  | QAbstractItemView.EditTrigger.EditKeyPressed
                                  | QAbstractItemView.EditTrigger.AnyKeyPressed)
        self.view.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.view.setTabKeyNavigation(True)
        self.view.setToolTip("The points as numbers: type to replace a value, Tab or Enter "
                             "moves on; Insert adds a vertex, Delete removes one")
        self.view.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
        self.view.horizontalHeader().setMinimumSectionSize(40)
        self.view.verticalHeader().setDefaultSectionSize(22)
        self.view.verticalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Fixed)
        self.empty = QLabel("No points yet.", self)
        self.empty.setStyleSheet("color: #66707c;")
        self.message = QLabel(self)
        self.message.setObjectName("vertexMessage")
        self.message.setWordWrap(True)
        self.message.setStyleSheet(ERROR_STYLE)
        self.message.hide()
        self.add_button = self._button("Add", "Add a vertex after the selected one (Insert)",
                                       self.add_row)
        self.remove_button = self._button("Remove", "Remove the selected vertex (Delete)",
                                          self.remove_row)
        buttons = QHBoxLayout()
        buttons.setContentsMargins(0, 0, 0, 0)
        buttons.addWidget(self.add_button)
        buttons.addWidget(self.remove_button)
        buttons.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(3)
        layout.addWidget(self.view)
        layout.addWidget(self.empty)
        layout.addLayout(buttons)
        layout.addWidget(self.message)
        self.model.edited.connect(self._edited)
        self.model.refused.connect(self.show_error)
        self._apply()

    def _button(self, text, tip, slot) -> QToolButton:
        button = QToolButton(self)
        button.setText(text)
        button.setToolTip(tip)
        button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        button.clicked.connect(slot)
        return button

    # --------------------------------------------------------- showing
    def set_input(self, count: int, names, integer: bool, open_ended: bool = False,
                  group_size: int = 0) -> None:
        m = self.model
        m.count, m.names, m.integer, m.open_ended = count, tuple(names), integer, bool(open_ended)
        m.group_size = group_size
        self._apply()

    def set_grid(self, width: int, height: int) -> None:
        self.model.size = (width, height)

    def set_points(self, points, labels=None, breaks=()) -> None:
        self.model.points = [tuple(p) for p in points]
        self.model.labels = list(labels) if labels is not None else []
        self.model.breaks = tuple(breaks)
        self._apply()

    def set_attributes(self, names, options: dict) -> None:
        """Columns for these per-vertex options, showing their values."""
        names = list(names)
        values = {name: tuple(options.get(name) or ()) for name in names}
        if names == self.model.attributes and values == self.model.values:
            return  # asked again after every run and drag: nothing to redraw
        self.model.attributes, self.model.values = names, values
        self._apply()

    def _apply(self) -> None:
        current = self.view.currentIndex()
        self.model.refresh()
        if current.isValid() and current.row() < self.model.rowCount() \
                and current.column() < self.model.columnCount() \
                and not self.view.currentIndex().isValid():
            self.view.setCurrentIndex(self.model.index(current.row(), current.column()))
        n = self.model.rowCount()
        self.view.setVisible(n > 0)
        self.empty.setVisible(n == 0)
        self.add_button.setVisible(self.model.open_ended)
        self.remove_button.setVisible(self.model.open_ended)
        self.remove_button.setEnabled(bool(self.model.points))
        header = self.view.horizontalHeader().sizeHint().height()
        rows = min(max(n, 1), self.MAX_VISIBLE_ROWS)
        self.view.setFixedHeight(header + rows * self.view.verticalHeader().defaultSectionSize()
                                 + 2 * self.view.frameWidth())

    # ---------------------------------------------------------- reading
    def row_count(self) -> int:
        return self.model.rowCount()

    def label_text(self, k: int) -> str:
        return self.model.label(k)

    def cell_text(self, row: int, column: str) -> str:
        """The value as the cell's editor starts with it ("" when not given)."""
        col = self.column_names().index(column)
        return self.model.data(self.model.index(row, col), Qt.ItemDataRole.EditRole)

    def column_names(self) -> list[str]:
        return ["x", "y", *self.model.attributes]

    # ----------------------------------------------------------- edits
    def type_value(self, row: int, column: str, text: str) -> bool:
        """Put ``text`` into a cell as typing would; False when refused."""
        col = self.column_names().index(column)
        return self.model.setData(self.model.index(row, col), text)

    def add_row(self) -> None:
        self.model.insert_after(self.view.currentIndex().row()
                                if self.view.currentIndex().isValid() else -1)

    def remove_row(self) -> None:
        index = self.view.currentIndex()
        self.model.remove(index.row() if index.isValid() else len(self.model.points) - 1)

    def pick_color(self, row: int) -> None:
        name = "colors"
        start = QColor(self.model.text(row, name) or default_color(row, len(self.model.points)))
        color = QColorDialog.getColor(start, self, f"Colour of {self.model.label(row)}")
        if color.isValid():
            self.type_value(row, name, color.name())

    def show_error(self, text: str) -> None:
        self.message.setText(text)
        self.message.setToolTip(text)
        self.message.setVisible(bool(text))
        self.refused.emit(text)

    def _edited(self, points, breaks, values) -> None:
        self.message.hide()
        self.edited.emit(points, breaks, values)


__all__ = ["VertexTable", "VertexModel", "per_vertex"]
