"""One type scale for a whole window: the zoom (Ctrl+= / Ctrl+- / Ctrl+0)
times presentation mode's large type.

Every widget's font is set to its base font times the scale, so that a
table's header, its names and its values grow together. The base is the
font a widget had before any scaling, kept on the widget as a property and
read before anything changes: a child read after its parent grew would
take the grown type as its base and grow twice (the header of the
Variables panel did), and would keep it after the scale went back. A widget
made while the scale is not 1 (an option's editor for a new run) inherited
the scaled type, so its base is that divided by the scale; one with a font
of its own (set by the program) keeps it as its base.
"""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QFont
from PySide6.QtWidgets import QWidget

BASE = "typeScaleBase"  # the widget property holding its font at scale 1


def base_font(widget: QWidget) -> QFont:
    return QFont(widget.property(BASE))


def apply_type_scale(root: QWidget, scale: float, previous: float = 1.0) -> None:
    """Set ``root``'s and its children's fonts to their base times
    ``scale``; ``previous`` is the scale they are at now."""
    widgets = [root, *root.findChildren(QWidget)]
    for widget in widgets:  # every base first, before any font changes
        if widget.property(BASE) is None:
            widget.setProperty(BASE, _unscaled(widget, previous))
    for widget in widgets:
        font = base_font(widget)
        if font.pointSizeF() > 0:
            font.setPointSizeF(font.pointSizeF() * scale)
        if widget.font() != font:
            widget.setFont(font)


def _unscaled(widget: QWidget, previous: float) -> QFont:
    font = QFont(widget.font())
    own = widget.testAttribute(Qt.WidgetAttribute.WA_SetFont)
    if previous != 1.0 and not own and font.pointSizeF() > 0:
        font.setPointSizeF(font.pointSizeF() / previous)
    return font
