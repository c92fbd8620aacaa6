"""Editors for the scene: the algorithm picker, option editors generated
from an algorithm's option list, the points, and the grid."""
from __future__ import annotations

import colorsys
import math

from PySide6.QtCore import QRect, QSize, Qt, Signal
from PySide6.QtGui import QColor, QFont, QIcon, QPainter, QPalette, QPixmap
from PySide6.QtWidgets import (QAbstractItemView, QCheckBox, QColorDialog, QComboBox,
                               QFormLayout, QHBoxLayout, QLabel, QLineEdit, QSpinBox, QStyle,
                               QStyledItemDelegate, QToolButton, QTreeWidget, QTreeWidgetItem,
                               QWidget)

from algorithms.core.registry import InputError

NAME_ROLE = Qt.ItemDataRole.UserRole
SUMMARY_ROLE = Qt.ItemDataRole.UserRole + 1
ERROR_STYLE = "color: #c92a2a;"
INT_LIMIT = 2 ** 31 - 1
DEFAULT_COLORS = ("#e8452c", "#2563a8", "#23a55a", "#f08c00", "#7048e8", "#0c8599")


# ------------------------------------------------------------------ picker
class _AlgorithmDelegate(QStyledItemDelegate):
    """Draws an algorithm as its title over a smaller, greyer summary."""

    def sizeHint(self, option, index):  # noqa: N802
        size = super().sizeHint(option, index)
        if index.data(NAME_ROLE):
            height = option.fontMetrics.height()
            return QSize(size.width(), int(height * 2.35) + 6)
        return QSize(size.width(), size.height() + 6)

    def paint(self, painter, option, index):
        summary = index.data(SUMMARY_ROLE)
        if not index.data(NAME_ROLE):
            super().paint(painter, option, index)
            return
        self.initStyleOption(option, index)
        title = option.text
        option.text = ""
        widget = option.widget
        style = widget.style() if widget else None
        if style:
            style.drawControl(QStyle.ControlElement.CE_ItemViewItem, option, painter, widget)
        selected = bool(option.state & QStyle.StateFlag.State_Selected)
        rect = option.rect.adjusted(4, 3, -4, -3)
        painter.save()
        text_color = option.palette.color(QPalette.ColorRole.HighlightedText if selected
                                          else QPalette.ColorRole.Text)
        bold = QFont(option.font)
        bold.setBold(True)
        painter.setFont(bold)
        painter.setPen(text_color)
        line = option.fontMetrics.height()
        painter.drawText(QRect(rect.left(), rect.top(), rect.width(), line),
                         Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, title)
        small = QFont(option.font)
        if small.pointSizeF() > 0:
            small.setPointSizeF(small.pointSizeF() * 0.88)
        painter.setFont(small)
        grey = QColor(text_color)
        if not selected:
            grey = QColor("#66707c")
        painter.setPen(grey)
        metrics = painter.fontMetrics()
        elided = metrics.elidedText(summary or "", Qt.TextElideMode.ElideRight, rect.width())
        painter.drawText(QRect(rect.left(), rect.top() + line + 1, rect.width(), line),
                         Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, elided)
        painter.restore()


def _folded(text: str) -> str:
    """Lower case, letters and digits only: "Scan-line" and "scan line" read as "scanline"."""
    return "".join(c for c in text.lower() if c.isalnum())


class AlgorithmPicker(QTreeWidget):
    """Algorithms grouped by family: title, with the summary under it."""

    algorithmChosen = Signal(str)

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setObjectName("algorithmPicker")
        self.setHeaderHidden(True)
        self.setRootIsDecorated(True)
        self.setIndentation(14)
        self.setUniformRowHeights(False)
        self.setItemDelegate(_AlgorithmDelegate(self))
        self.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.currentItemChanged.connect(self._changed)
        self._items: dict[str, QTreeWidgetItem] = {}
        self._filter = ""
        self.nothing: QTreeWidgetItem | None = None  # the row that says no algorithm matches

    def set_specs(self, specs) -> None:
        """Fill the list from algorithm specs (name, title, family, summary)."""
        self.blockSignals(True)
        self.clear()
        self._items.clear()
        families: dict[str, QTreeWidgetItem] = {}
        for spec in specs:
            family = families.get(spec.family)
            if family is None:
                family = QTreeWidgetItem(self, [spec.family.replace("-", " ").capitalize()])
                family.setFlags(Qt.ItemFlag.ItemIsEnabled)
                font = family.font(0)
                font.setBold(True)
                family.setFont(0, font)
                family.setForeground(0, QColor("#3d4754"))
                families[spec.family] = family
            item = QTreeWidgetItem(family, [spec.title])
            item.setData(0, NAME_ROLE, spec.name)
            item.setData(0, SUMMARY_ROLE, spec.summary)
            item.setToolTip(0, f"{spec.title} ({spec.name})\n{spec.summary}")
            self._items[spec.name] = item
        self.nothing = QTreeWidgetItem(self, [""])
        self.nothing.setFlags(Qt.ItemFlag.NoItemFlags)
        self.expandAll()
        self.blockSignals(False)
        self.set_filter(self._filter)

    def names(self) -> list[str]:
        return list(self._items)

    def current_name(self) -> str | None:
        item = self.currentItem()
        return item.data(0, NAME_ROLE) if item is not None else None

    def set_current(self, name: str) -> None:
        item = self._items.get(name)
        if item is None or item is self.currentItem():
            return
        self.blockSignals(True)
        self.setCurrentItem(item)
        self.blockSignals(False)
        self.set_filter(self._filter)  # the algorithm on show is never hidden
        self.scrollToItem(item)

    def item_for(self, name: str) -> QTreeWidgetItem:
        return self._items[name]

    def set_filter(self, text: str) -> list[str]:
        """Show only the algorithms whose title, name, summary or family
        holds every word of ``text`` (any case; hyphens and spaces inside a
        word do not count, so "scan-line" finds "scanline"); returns their
        names. The algorithm on show stays listed whatever the filter, and
        a filter that leaves none says so."""
        self._filter = text
        words = [_folded(word) for word in text.split()]
        shown = []
        current = self.currentItem()
        for k in range(self.topLevelItemCount()):
            family = self.topLevelItem(k)
            if family is self.nothing:
                continue
            any_shown = False
            for j in range(family.childCount()):
                item = family.child(j)
                haystack = _folded(" ".join(str(v) for v in (
                    item.text(0), item.data(0, NAME_ROLE), item.data(0, SUMMARY_ROLE),
                    family.text(0))))
                hit = all(word in haystack for word in words)
                item.setHidden(not (hit or item is current))
                if hit:
                    shown.append(item.data(0, NAME_ROLE))
                any_shown = any_shown or not item.isHidden()
            family.setHidden(not any_shown)
        if self.nothing is not None:
            self.nothing.setText(0, f"No algorithm matches \u201c{text.strip()}\u201d")
            self.nothing.setHidden(bool(shown) or not words)
        return shown

    def choose_first_shown(self) -> None:
        """Enter in the search field: the first algorithm the filter found."""
        shown = self.set_filter(self._filter)
        if shown:
            self.setCurrentItem(self._items[shown[0]])

    def _changed(self, item, _previous) -> None:
        if item is None:
            return
        name = item.data(0, NAME_ROLE)
        if name:
            self.algorithmChosen.emit(name)


# ----------------------------------------------------------------- options
def _swatch(color: str) -> QIcon:
    pixmap = QPixmap(18, 18)
    pixmap.fill(Qt.GlobalColor.transparent)
    painter = QPainter(pixmap)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    painter.setPen(QColor("#505a66"))
    painter.setBrush(QColor(color))
    painter.drawRoundedRect(1, 1, 16, 16, 3, 3)
    painter.end()
    return QIcon(pixmap)


class ColorListEditor(QWidget):
    """A checkbox to turn per-vertex colours on, and one button per vertex."""

    changed = Signal(object)  # tuple of '#rrggbb', or () when off

    def __init__(self, count: int, names=(), parent=None):
        super().__init__(parent)
        count = max(1, count)
        self.check = QCheckBox(self)
        self.check.setToolTip("One colour per vertex, interpolated along the primitive")
        self.check.toggled.connect(self._toggled)
        self.buttons: list[QToolButton] = []
        self._colors = [default_color(k, count) for k in range(count)]
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(4)
        layout.addWidget(self.check)
        for k in range(count):
            button = QToolButton(self)
            name = names[k] if k < len(names) else str(k + 1)
            if len(name) > 3:
                name = str(k + 1)
            button.setToolTip(f"Colour at {name}")
            button.setText(name)
            button.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextBesideIcon)
            button.clicked.connect(lambda _=False, k=k: self._pick(k))
            self.buttons.append(button)
            layout.addWidget(button)
        layout.addStretch(1)
        self._refresh()

    def value(self) -> tuple[str, ...]:
        return tuple(self._colors) if self.check.isChecked() else ()

    def set_value(self, colors) -> None:
        colors = tuple(colors or ())
        self.blockSignals(True)
        if colors and len(colors) == len(self._colors):
            self._colors = list(colors)
        self.check.setChecked(bool(colors))
        self.blockSignals(False)
        self._refresh()

    def set_color(self, k: int, color: str) -> None:
        """Set one vertex colour (as the dialog would)."""
        self._colors[k] = QColor(color).name()
        self._refresh()
        if self.check.isChecked():
            self.changed.emit(self.value())

    def _pick(self, k: int) -> None:
        color = QColorDialog.getColor(QColor(self._colors[k]), self, "Vertex colour")
        if color.isValid():
            self.set_color(k, color.name())

    def _toggled(self, _on: bool) -> None:
        self._refresh()
        self.changed.emit(self.value())

    def _refresh(self) -> None:
        for button, color in zip(self.buttons, self._colors):
            button.setIcon(_swatch(color))
            button.setEnabled(self.check.isChecked())


def default_color(k: int, count: int) -> str:
    """The colour vertex ``k`` of ``count`` starts with (red, green, blue for a triangle)."""
    if count == 3:
        return ("#e8452c", "#23a55a", "#2563a8")[k]
    if count <= len(DEFAULT_COLORS):
        return DEFAULT_COLORS[k]
    r, g, b = colorsys.hsv_to_rgb(k / count, 0.75, 0.85)
    return QColor.fromRgbF(r, g, b).name()


class OptionsEditor(QWidget):
    """One editor per option, made from the option's kind and range.

    Emits ``valueEdited(name, value)`` with a value the option's ``check``
    accepted. A value that is refused, here or later by the run, is shown
    under its editor by ``show_error`` and the editor goes back to the last
    good value.
    """

    valueEdited = Signal(str, object)

    def __init__(self, parent=None):
        super().__init__(parent)
        self._form = QFormLayout(self)
        self._form.setContentsMargins(0, 0, 0, 0)
        self._form.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.AllNonFixedFieldsGrow)
        self._form.setRowWrapPolicy(QFormLayout.RowWrapPolicy.DontWrapRows)
        self._form.setLabelAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter)
        self._editors: dict[str, QWidget] = {}
        self._errors: dict[str, QLabel] = {}
        self._options: dict = {}
        self._values: dict = {}

    # ------------------------------------------------------------ build
    def set_options(self, options, values: dict, vertex_count: int = 2, vertex_names=()) -> None:
        while self._form.rowCount():
            self._form.removeRow(0)
        self._editors.clear()
        self._errors.clear()
        self._options = {option.name: option for option in options}
        self._values = {}
        if not options:
            empty = QLabel("This algorithm has no options.", self)
            empty.setStyleSheet("color: #66707c;")
            self._form.addRow(empty)
        for option in options:
            editor = self._make(option, vertex_count, vertex_names)
            editor.setToolTip(option.help)
            editor.setObjectName(f"option-{option.name}")
            self._editors[option.name] = editor
            label = QLabel(option.name, self)
            label.setToolTip(option.help)
            self._form.addRow(label, editor)
            error = QLabel(self)
            error.setObjectName(f"error-{option.name}")
            error.setWordWrap(True)
            error.setStyleSheet(ERROR_STYLE)
            error.hide()
            self._errors[option.name] = error
            self._form.addRow(error)
        self.set_values(values)

    def _make(self, option, vertex_count, vertex_names) -> QWidget:
        kind = option.kind
        if kind == "bool":
            box = QCheckBox(self)
            box.toggled.connect(lambda on, n=option.name: self._edited(n, bool(on)))
            return box
        if kind == "int" and not option.choices:
            box = QSpinBox(self)
            low = -INT_LIMIT if option.minimum is None else max(-INT_LIMIT, math.ceil(option.minimum))
            high = INT_LIMIT if option.maximum is None else min(INT_LIMIT, math.floor(option.maximum))
            box.setRange(low, high)
            box.setKeyboardTracking(False)
            box.valueChanged.connect(lambda v, n=option.name: self._edited(n, int(v)))
            return box
        if kind == "choice":
            box = QComboBox(self)
            box.addItems(list(option.choices))
            box.currentTextChanged.connect(lambda text, n=option.name: self._edited(n, text))
            return box
        if kind == "colors":
            # One colour per vertex, unless the default says how many.
            count = len(option.default) if option.default else vertex_count
            box = ColorListEditor(count, vertex_names if count == vertex_count else (), self)
            box.changed.connect(lambda colors, n=option.name: self._edited(n, colors))
            return box
        if kind == "point" and not option.choices:
            box = PointOptionEditor(self)
            box.changed.connect(lambda point, n=option.name: self._edited(n, point))
            return box
        # Anything else (a float, a list of numbers, a point that may also
        # be a name such as "auto"): typed text goes through the option's
        # own parser, and the names are offered in a list.
        if option.choices:
            box = QComboBox(self)
            box.setEditable(True)
            box.setInsertPolicy(QComboBox.InsertPolicy.NoInsert)
            box.addItems(list(option.choices))
            box.lineEdit().editingFinished.connect(
                lambda n=option.name, b=box: self._typed(n, b.currentText()))
            box.activated.connect(lambda _i, n=option.name, b=box: self._typed(n, b.currentText()))
            return box
        edit = QLineEdit(self)
        edit.editingFinished.connect(lambda n=option.name, e=edit: self._typed(n, e.text()))
        return edit

    # ------------------------------------------------------------ values
    def editor(self, name: str) -> QWidget:
        return self._editors[name]

    def error_text(self, name: str) -> str:
        label = self._errors[name]
        return label.text() if not label.isHidden() else ""

    def set_values(self, values: dict) -> None:
        """Show these values (the last good ones) without emitting."""
        for name, value in values.items():
            editor = self._editors.get(name)
            if editor is None:
                continue
            self._values[name] = value
            editor.blockSignals(True)
            try:
                _show(editor, self._options[name], value)
            finally:
                editor.blockSignals(False)

    def show_error(self, name: str, message: str) -> None:
        label = self._errors.get(name)
        if label is None:
            return
        label.setText(message)
        label.show()
        # Back to the last good value.
        if name in self._values:
            self.set_values({name: self._values[name]})

    def clear_error(self, name: str) -> None:
        label = self._errors.get(name)
        if label is not None:
            label.clear()
            label.hide()

    def _typed(self, name: str, text: str) -> None:
        try:
            value = self._options[name].parse(text)
        except InputError as error:
            self.show_error(name, str(error))
            return
        if value == self._values.get(name):
            self.clear_error(name)
            self.set_values({name: value})
            return
        self._edited(name, value)

    def _edited(self, name: str, value) -> None:
        try:
            value = self._options[name].check(value)
        except InputError as error:
            self.show_error(name, str(error))
            return
        self.clear_error(name)
        self.valueEdited.emit(name, value)

    def accept(self, name: str, value) -> None:
        """The value was applied: it is the new last good value."""
        self._values[name] = value
        self.clear_error(name)


def _show(editor, option, value) -> None:
    if isinstance(editor, QCheckBox):
        editor.setChecked(bool(value))
    elif isinstance(editor, QSpinBox):
        editor.setValue(int(value))
    elif isinstance(editor, (ColorListEditor, PointOptionEditor)):
        editor.set_value(value)
    elif isinstance(editor, QComboBox) and not editor.isEditable():
        editor.setCurrentText(str(value))
    elif isinstance(editor, QComboBox):
        editor.setEditText(_text(value))
    elif isinstance(editor, QLineEdit):
        editor.setText(_text(value))


def _text(value) -> str:
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, (tuple, list)):
        return ",".join(_text(v) for v in value)
    return str(value)


class PointOptionEditor(QWidget):
    """A pixel given as an option (a seed, say): two whole numbers."""

    changed = Signal(object)

    def __init__(self, parent=None):
        super().__init__(parent)
        self.x_box, self.y_box = QSpinBox(self), QSpinBox(self)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(4)
        for box, axis in ((self.x_box, "x"), (self.y_box, "y")):
            box.setRange(-INT_LIMIT, INT_LIMIT)
            box.setPrefix(f"{axis} ")
            box.setKeyboardTracking(False)
            box.valueChanged.connect(self._edited)
            layout.addWidget(box, 1)

    def value(self) -> tuple[int, int]:
        return (self.x_box.value(), self.y_box.value())

    def set_value(self, point) -> None:
        for box, v in zip((self.x_box, self.y_box), point or (0, 0)):
            box.blockSignals(True)
            box.setValue(int(v))
            box.blockSignals(False)

    def _edited(self, _value) -> None:
        self.changed.emit(self.value())


# -------------------------------------------------------------------- grid
class GridEditor(QWidget):
    """Grid width and height, and where the origin is."""

    gridChanged = Signal(int, int)
    originChanged = Signal(bool)  # True: origin top-left, y down

    ORIGINS = ("Bottom-left, y up", "Top-left, y down")

    def __init__(self, maximum: int = 4096, parent=None):
        super().__init__(parent)
        self.width_box = QSpinBox(self)
        self.height_box = QSpinBox(self)
        for box, name in ((self.width_box, "width"), (self.height_box, "height")):
            box.setKeyboardTracking(False)
            box.setObjectName(f"grid-{name}")
            box.valueChanged.connect(self._resized)
        self.set_maximum(maximum)
        self.origin = QComboBox(self)
        self.origin.addItems(list(self.ORIGINS))
        self.origin.setToolTip("Where pixel (0, 0) is and which way y grows. The algorithms "
                               "run on the coordinates as shown.")
        self.origin.currentIndexChanged.connect(lambda i: self.originChanged.emit(i == 1))
        size = QHBoxLayout()
        size.setSpacing(4)
        size.addWidget(self.width_box, 1)
        times = QLabel("\u00d7", self)
        size.addWidget(times)
        size.addWidget(self.height_box, 1)
        form = QFormLayout(self)
        form.setContentsMargins(0, 0, 0, 0)
        form.addRow("Size", size)
        form.addRow("Origin", self.origin)

    def set_maximum(self, maximum: int) -> None:
        """The largest width and height the boxes accept (no signal)."""
        self.maximum = int(maximum)
        for box, name in ((self.width_box, "width"), (self.height_box, "height")):
            box.blockSignals(True)
            box.setRange(1, self.maximum)
            box.blockSignals(False)
            box.setToolTip(f"Grid {name} in pixels (1 to {self.maximum}; the maximum is "
                           "\"Maximum grid size\" in Edit > Preferences)")

    def set_grid(self, width: int, height: int) -> None:
        for box, value in ((self.width_box, width), (self.height_box, height)):
            box.blockSignals(True)
            box.setValue(value)
            box.blockSignals(False)

    def set_y_down(self, y_down: bool) -> None:
        self.origin.blockSignals(True)
        self.origin.setCurrentIndex(1 if y_down else 0)
        self.origin.blockSignals(False)

    def _resized(self, _value) -> None:
        self.gridChanged.emit(self.width_box.value(), self.height_box.value())


__all__ = ["AlgorithmPicker", "ColorListEditor", "OptionsEditor", "GridEditor"]
