"""The breakpoints and bookmarks panels: controls only.

``BreakpointsPanel`` holds the step unit, the breakpoint conditions (with
the pixel of "pixel reached") and the run buttons; ``BookmarksPanel`` lists
named frames. Both emit requests and show what they are told; what a
condition means is worked out elsewhere (app/model/breakpoints.py).
"""
from __future__ import annotations

from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QColor, QStandardItemModel
from PySide6.QtWidgets import (QAbstractItemView, QCheckBox, QComboBox, QGridLayout,
                               QHBoxLayout, QHeaderView, QLabel, QPushButton, QSizePolicy, QSpinBox,
                               QTableWidget, QTableWidgetItem, QToolButton, QVBoxLayout, QWidget)


def _no_focus(button):
    # Buttons never take the focus: Space and the arrows stay with playback.
    button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
    return button


class BreakpointsPanel(QWidget):
    """Step unit, breakpoint conditions and the run buttons."""

    unitChanged = Signal(str)
    conditionsChanged = Signal()
    runRequested = Signal(int)  # +1 forward, -1 back
    pickToggled = Signal(bool)

    def __init__(self, units, conditions, pixel_kind: str, parent=None):
        """``units``: (key, title, tip) rows; ``conditions``: (key, title, tip)
        rows; ``pixel_kind``: the condition that takes the pixel fields."""
        super().__init__(parent)
        self.setObjectName("breakpoints")
        self._pixel_kind = pixel_kind
        self.unit = QComboBox(self)
        self.unit.setObjectName("stepUnit")
        self.unit.setToolTip("How far a step goes: the step buttons, Left and Right "
                             "(Shift: ten of them) move by this unit")
        for key, title, tip in units:
            self.unit.addItem(title, key)
            self.unit.setItemData(self.unit.count() - 1, tip, Qt.ItemDataRole.ToolTipRole)
        self.unit.currentIndexChanged.connect(lambda _i: self.unitChanged.emit(self.unit_key()))
        conditions_grid = self._conditions_grid(conditions, pixel_kind)

        self.run_back = _no_focus(QPushButton("\u25c0 Run back", self))
        self.run_back.setToolTip("Go back to the nearest earlier frame where a ticked "
                                 "condition holds (Shift+F5)")
        self.run_forward = _no_focus(QPushButton("Run to breakpoint \u25b6", self))
        self.run_forward.setToolTip("Go on to the next frame where a ticked condition holds "
                                    "(F5); play also stops there")
        self.run_back.clicked.connect(lambda: self.runRequested.emit(-1))
        self.run_forward.clicked.connect(lambda: self.runRequested.emit(+1))
        self.note = QLabel(self)
        self.note.setObjectName("summary")
        self.note.setWordWrap(True)

        unit_row = QHBoxLayout()
        unit_row.addWidget(QLabel("Step by", self))
        unit_row.addWidget(self.unit, 1)
        runs = QHBoxLayout()
        runs.addWidget(self.run_back)
        runs.addWidget(self.run_forward, 1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 4, 8, 6)
        layout.setSpacing(4)
        layout.addLayout(unit_row)
        stop_label = QLabel("Stop when", self)
        stop_label.setObjectName("section")
        layout.addWidget(stop_label)
        layout.addLayout(conditions_grid)
        layout.addLayout(runs)
        layout.addWidget(self.note)
        layout.addStretch(1)
        # The dock takes no more height than the controls need.
        self.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Maximum)

    def _conditions_grid(self, conditions, pixel_kind: str) -> QGridLayout:
        """A check box per stop condition; the pixel fields beside the pixel's."""
        self.boxes: dict[str, QCheckBox] = {}
        self._tips: dict[str, str] = {}
        conditions_grid = QGridLayout()
        conditions_grid.setContentsMargins(0, 0, 0, 0)
        conditions_grid.setVerticalSpacing(2)
        for row, (key, title, tip) in enumerate(conditions):
            box = QCheckBox(title, self)
            box.setToolTip(tip)
            box.toggled.connect(lambda _on: self.conditionsChanged.emit())
            self.boxes[key] = box
            self._tips[key] = tip
            conditions_grid.addWidget(box, row, 0)
            if key == pixel_kind:
                conditions_grid.addWidget(self._pixel_fields(), row, 1)
        conditions_grid.setColumnStretch(2, 1)
        return conditions_grid

    def _pixel_fields(self) -> QWidget:
        fields = QWidget(self)
        row = QHBoxLayout(fields)
        row.setContentsMargins(0, 0, 0, 0)
        row.setSpacing(2)
        self.pixel_x = QSpinBox(fields)
        self.pixel_y = QSpinBox(fields)
        for box, axis in ((self.pixel_x, "x"), (self.pixel_y, "y")):
            box.setPrefix(f"{axis} ")
            box.setKeyboardTracking(False)
            box.setToolTip(f"The {axis} of the pixel to stop at")
            box.valueChanged.connect(self._pixel_edited)
            row.addWidget(box)
        self.pick = _no_focus(QToolButton(fields))
        self.pick.setText("Pick")
        self.pick.setCheckable(True)
        self.pick.setToolTip("Then click a pixel on the grid to stop at it")
        self.pick.toggled.connect(self.pickToggled.emit)
        row.addWidget(self.pick)
        return fields

    # ------------------------------------------------------------ values
    def unit_key(self) -> str:
        return self.unit.currentData()

    def set_unit(self, key: str) -> None:
        index = self.unit.findData(key)
        if index >= 0:
            self.unit.setCurrentIndex(index)

    def enabled(self) -> list[str]:
        """The ticked conditions, in the panel's order."""
        return [key for key, box in self.boxes.items() if box.isChecked()]

    def pixel(self) -> tuple[int, int]:
        return (self.pixel_x.value(), self.pixel_y.value())

    def set_pixel(self, x: int, y: int) -> None:
        for box, value in ((self.pixel_x, x), (self.pixel_y, y)):
            box.blockSignals(True)
            box.setValue(int(value))
            box.blockSignals(False)
        self._pixel_edited()

    def set_grid(self, width: int, height: int) -> None:
        """The pixel fields' ranges (a new grid does not tick the condition)."""
        for box, size in ((self.pixel_x, width), (self.pixel_y, height)):
            box.blockSignals(True)
            box.setRange(0, max(0, size - 1))
            box.blockSignals(False)

    def set_available(self, reasons: dict) -> None:
        """Per condition or unit key, why the run cannot use it ("" when it can).
        Unavailable conditions stay ticked but greyed; unavailable units
        cannot be chosen."""
        for key, box in self.boxes.items():
            reason = reasons.get(key, "")
            box.setEnabled(not reason)
            box.setToolTip(self._tips[key] + (f"\nNot available: {reason}." if reason else ""))
        model = self.unit.model()
        if isinstance(model, QStandardItemModel):
            for row in range(self.unit.count()):
                item = model.item(row)
                item.setEnabled(not reasons.get(self.unit.itemData(row), ""))

    def set_note(self, text: str) -> None:
        self.note.setText(text)
        self.note.setVisible(bool(text))

    def _pixel_edited(self, *_args) -> None:
        if self.boxes.get(self._pixel_kind) is not None:
            self.boxes[self._pixel_kind].setChecked(True)
        self.conditionsChanged.emit()


class BookmarksPanel(QWidget):
    """Named frames: add, rename in place, delete, double-click to jump."""

    addRequested = Signal()
    deleteRequested = Signal(int)         # row
    renameRequested = Signal(int, str)    # row, new name
    jumpRequested = Signal(int)           # row

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setObjectName("bookmarks")
        self.table = QTableWidget(0, 2, self)
        self.table.setAccessibleName("Bookmarks")
        self._ink = self.table.palette().text().color()
        self._muted = QColor("#8a939e")  # a bookmark past the end of the run
        self.table.setObjectName("bookmarkTable")
        self.table.setHorizontalHeaderLabels(["Name", "Step"])
        self.table.verticalHeader().setVisible(False)
        self.table.verticalHeader().setDefaultSectionSize(self.table.fontMetrics().height() + 8)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        # Double-click jumps; a click on the selected name (or F2) renames.
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.SelectedClicked
                                   | QAbstractItemView.EditTrigger.EditKeyPressed)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.ResizeToContents)
        self.table.setToolTip("Double-click a bookmark to go to its step; click the selected "
                              "name or press F2 to rename it")
        self.table.itemChanged.connect(self._item_changed)
        self.table.cellDoubleClicked.connect(lambda row, _column: self.jumpRequested.emit(row))
        self.add_button = _no_focus(QPushButton("Add", self))
        self.add_button.setToolTip("Bookmark the step on show (Ctrl+B)")
        self.add_button.clicked.connect(self.addRequested.emit)
        self.rename_button = _no_focus(QPushButton("Rename", self))
        self.rename_button.setToolTip("Rename the selected bookmark")
        self.rename_button.clicked.connect(self.edit_selected)
        self.delete_button = _no_focus(QPushButton("Delete", self))
        self.delete_button.setToolTip("Delete the selected bookmark")
        self.delete_button.clicked.connect(self._delete_clicked)
        self.go_button = _no_focus(QPushButton("Go", self))
        self.go_button.setToolTip("Go to the selected bookmark's step")
        self.go_button.clicked.connect(self._go_clicked)
        self.table.itemSelectionChanged.connect(self._update_buttons)
        buttons = QHBoxLayout()
        for button in (self.add_button, self.rename_button, self.delete_button, self.go_button):
            buttons.addWidget(button)
        buttons.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 4, 8, 6)
        layout.setSpacing(4)
        layout.addWidget(self.table, 1)
        layout.addLayout(buttons)
        self._update_buttons()

    def set_bookmarks(self, rows) -> None:
        """(name, step, note) per bookmark; the note (a step past the run's
        end, say) is shown as the row's tooltip."""
        selected = self.selected_row()
        self.table.blockSignals(True)
        self.table.setRowCount(len(rows))
        for row, (name, step, note) in enumerate(rows):
            # Items are updated in place, never replaced: this runs while
            # an edited name item reports its change.
            name_item, step_item = self._items(row)
            name_item.setText(str(name))
            step_item.setText(f"{int(step):,}")
            for item in (name_item, step_item):
                item.setToolTip(note or f"{name}: step {int(step):,}")
                item.setForeground(self._muted if note else self._ink)
        self.table.blockSignals(False)
        if 0 <= selected < len(rows):
            self.table.selectRow(selected)
        self._update_buttons()

    def _items(self, row: int):
        name_item, step_item = self.table.item(row, 0), self.table.item(row, 1)
        if name_item is None:
            name_item = QTableWidgetItem()
            self.table.setItem(row, 0, name_item)
        if step_item is None:
            step_item = QTableWidgetItem()
            step_item.setFlags(step_item.flags() & ~Qt.ItemFlag.ItemIsEditable)
            step_item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            self.table.setItem(row, 1, step_item)
        return name_item, step_item

    def selected_row(self) -> int:
        rows = self.table.selectionModel().selectedRows()
        return rows[0].row() if rows else -1

    def select(self, row: int) -> None:
        self.table.selectRow(row)

    def edit_selected(self) -> None:
        row = self.selected_row()
        if row >= 0:
            self.table.editItem(self.table.item(row, 0))

    def _item_changed(self, item) -> None:
        if item.column() == 0:
            self.renameRequested.emit(item.row(), item.text())

    def _delete_clicked(self) -> None:
        row = self.selected_row()
        if row >= 0:
            self.deleteRequested.emit(row)

    def _go_clicked(self) -> None:
        row = self.selected_row()
        if row >= 0:
            self.jumpRequested.emit(row)

    def _update_buttons(self) -> None:
        chosen = self.selected_row() >= 0
        for button in (self.rename_button, self.delete_button, self.go_button):
            button.setEnabled(chosen)
