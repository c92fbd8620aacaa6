"""The transport's icons, drawn in the text colour of the widget's palette,
so that they read on a light and on a dark background alike (the style's
own media icons are dark grey glyphs, lost on a dark theme)."""
from __future__ import annotations

from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QColor, QIcon, QPainter, QPainterPath, QPalette, QPixmap

KINDS = ("first", "back", "play", "pause", "forward", "last")


def _triangle(path: QPainterPath, left: float, right: float, top: float, bottom: float) -> None:
    """A triangle pointing right when left < right, left otherwise."""
    path.moveTo(left, top)
    path.lineTo(right, (top + bottom) / 2)
    path.lineTo(left, bottom)
    path.closeSubpath()


def _shape(kind: str) -> QPainterPath:
    """The glyph in a 24 x 24 box."""
    path = QPainterPath()
    top, bottom = 5.0, 19.0
    if kind == "play":
        _triangle(path, 7, 19, top - 1, bottom + 1)
    elif kind == "pause":
        path.addRect(QRectF(6.5, top, 4, bottom - top))
        path.addRect(QRectF(13.5, top, 4, bottom - top))
    elif kind == "forward":
        _triangle(path, 3.5, 12, top, bottom)
        _triangle(path, 12, 20.5, top, bottom)
    elif kind == "back":
        _triangle(path, 20.5, 12, top, bottom)
        _triangle(path, 12, 3.5, top, bottom)
    elif kind == "last":
        _triangle(path, 5, 16, top, bottom)
        path.addRect(QRectF(16, top, 3, bottom - top))
    elif kind == "first":
        _triangle(path, 19, 8, top, bottom)
        path.addRect(QRectF(5, top, 3, bottom - top))
    else:
        raise ValueError(f"no icon {kind!r}")
    return path


def media_icon(kind: str, palette: QPalette, size: int = 48) -> QIcon:
    """The icon in ``palette``'s button-text colour (dimmed when disabled)."""
    icon = QIcon()
    for mode, group in ((QIcon.Mode.Normal, QPalette.ColorGroup.Active),
                        (QIcon.Mode.Disabled, QPalette.ColorGroup.Disabled)):
        icon.addPixmap(_pixmap(kind, palette.color(group, QPalette.ColorRole.ButtonText), size),
                       mode)
    return icon


def _pixmap(kind: str, color: QColor, size: int) -> QPixmap:
    pixmap = QPixmap(size, size)
    pixmap.fill(Qt.GlobalColor.transparent)
    painter = QPainter(pixmap)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    painter.scale(size / 24, size / 24)
    painter.setPen(Qt.PenStyle.NoPen)
    painter.setBrush(color)
    painter.drawPath(_shape(kind))
    painter.end()
    return pixmap


__all__ = ["KINDS", "media_icon"]
