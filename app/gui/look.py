"""How the main window looks: its named widgets' style sheets, the section
titles and colour legends of the Scene dock, and the program's icon."""
from __future__ import annotations

from PySide6.QtCore import QRect, Qt
from PySide6.QtGui import QBrush, QColor, QIcon, QPainter, QPixmap
from PySide6.QtWidgets import QHBoxLayout, QLabel, QVBoxLayout, QWidget

from app.model.colours import COVERAGE_PATTERNS
from app.render.compose import COVERAGE_LEVELS, PALETTE

# Each named widget has a style sheet of its own (object name: light rules,
# and the dark theme's rules over them). One sheet on the window would send
# all of its ~380 widgets through Qt's style-sheet style: 17 to 25 ms more
# of the start-up, measured; a widget's own sheet reaches it and its
# children only.
LOOK = {
    "section": ("color: #55606d; font-weight: bold; padding-top: 8px;", "color: #9aa7b5;"),
    "summary": ("color: #55606d;", "color: #9aa7b5;"),
    "stepCaption": ("color: #1d2733;", "color: #e6edf3;"),
    "seriesTitle": ("color: #55606d;", "color: #9aa7b5;"),
    "codeNotes": ("color: #4b5563; background: #f3f5f8; border: 1px solid #dde2e8; "
                  "border-radius: 4px; padding: 6px;",
                  "color: #c9d1d9; background: #232a33; border: 1px solid #38414d;"),
    "stepCounter": ("font-weight: bold;", ""),
    "transport": ("background: #f3f5f8; border-top: 1px solid #d5dbe2;",
                  "background: #232a33; border-top: 1px solid #38414d;"),
    "legend": ("color: #3d4754;", "color: #c9d1d9;"),
    "differences": ("color: #b0245f; padding: 0 10px;", ""),
    "cursor": ("color: #3d4754; padding: 0 6px 0 10px; border-left: 1px solid #cfd5dc;",
               "color: #c9d1d9; border-left: 1px solid #38414d;"),
    "coverage": ("color: #c2255c; padding: 0 10px;", ""),
    "drawingTools": ("spacing: 2px; padding: 1px 4px;", ""),
}
ERROR_STYLE = "color: #c92a2a;"
# A chip's pattern (app/model/colours.py names) as Qt draws it at chip size.
CHIP_BRUSHES = {"stripes /": Qt.BrushStyle.BDiagPattern, "cross": Qt.BrushStyle.DiagCrossPattern}


def look_sheet(name: str, dark: bool) -> str:
    """The style sheet of the widget named ``name``: its rules by its name
    only, so that they do not pass to its children (the transport bar's
    buttons)."""
    light, over = LOOK[name]
    sheet = f"#{name} {{ {light} }}"
    return sheet + f" #{name} {{ {over} }}" if dark and over else sheet


def apply_look(root: QWidget, dark: bool) -> None:
    """Give the named widgets in ``root`` (and ``root``) their look."""
    for name in LOOK:
        found = root.findChildren(QWidget, name)
        if root.objectName() == name:
            found.append(root)
        sheet = look_sheet(name, dark)
        for widget in found:
            widget.setStyleSheet(sheet)


def section(text: str, parent=None) -> QLabel:
    label = QLabel(text.upper(), parent)
    label.setObjectName("section")
    font = label.font()
    if font.pointSizeF() > 0:
        font.setPointSizeF(font.pointSizeF() * 0.85)
    font.setLetterSpacing(font.SpacingType.PercentageSpacing, 108)
    label.setFont(font)
    return label


def legend_chip(color: str, fill: bool, marks=None) -> QLabel:
    label = QLabel()
    label.setPixmap(chip_pixmap(color, fill, marks))
    return label


def chip_pixmap(color: str, fill: bool, marks=None) -> QPixmap:
    """A filled or outlined chip; ``marks`` (pattern, colour) draws the
    pattern a filled cell of this meaning carries on the grid."""
    pixmap = QPixmap(14, 14)
    pixmap.fill(Qt.GlobalColor.transparent)
    painter = QPainter(pixmap)
    if fill:
        painter.fillRect(1, 1, 12, 12, QColor(color))
        if marks is not None and marks[0] in CHIP_BRUSHES:
            painter.fillRect(1, 1, 12, 12, QBrush(QColor(marks[1]), CHIP_BRUSHES[marks[0]]))
    else:
        pen = painter.pen()
        pen.setColor(QColor(color))
        pen.setWidth(3)
        painter.setPen(pen)
        painter.drawRect(2, 2, 10, 10)
    painter.end()
    return pixmap


def legend(rows) -> QWidget:
    """Chips with their meaning: (colour, filled?, text, marks) per row
    (marks: see ``chip_pixmap``); ``widget.chips`` keeps (chip, filled?) to
    recolour them."""
    widget = QWidget()
    widget.chips = []
    box = QVBoxLayout(widget)
    box.setSpacing(2)
    box.setContentsMargins(0, 4, 0, 0)
    for color, fill, text, marks in rows:
        row = QHBoxLayout()
        row.setSpacing(6)
        chip = legend_chip(color, fill, marks)
        widget.chips.append((chip, fill))
        row.addWidget(chip)
        label = QLabel(text)
        label.setObjectName("legend")
        row.addWidget(label, 1)
        box.addLayout(row)
    return widget


# The highlight legend: (Palette field, filled chip?, meaning).
LEGEND = (("current", False, "pixel or span of this step"),
          ("candidate", False, "candidates of the decision"),
          ("difference", False, "differs from previous algorithm"),
          ("overdraw", True, "written more than once"))


def legend_rows(palette) -> list:
    return [(getattr(palette, field), fill, text, None) for field, fill, text in LEGEND]


def coverage_rows(palette) -> list:
    """The coverage levels' chips, patterned as on the grid (app/render/compose.py)."""
    ground = palette.coverage[0]
    return [(color, True, text, (pattern, ground)) for color, text, pattern
            in zip(palette.coverage, COVERAGE_LEVELS, COVERAGE_PATTERNS)]


def recolor(legend, rows) -> None:
    for (chip, fill), (color, _fill, _text, marks) in zip(legend.chips, rows):
        chip.setPixmap(chip_pixmap(color, fill, marks))


def app_icon() -> QIcon:
    """A staircase of pixels under a thin ideal line."""
    icon = QIcon()
    for size in (16, 32, 64, 128):
        pixmap = QPixmap(size, size)
        pixmap.fill(QColor(PALETTE.background))
        painter = QPainter(pixmap)
        cell = size / 8
        ink = QColor(PALETTE.ink)
        for k in range(8):
            y = round(k * 5 / 8)
            painter.fillRect(QRect(round(k * cell), round(size - (y + 2) * cell - cell),
                                   max(1, round(cell)), max(1, round(cell))), ink)
        pen = painter.pen()
        pen.setColor(QColor(PALETTE.primitive))
        pen.setWidthF(max(1.0, size / 24))
        painter.setPen(pen)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.drawLine(round(cell / 2), round(size - 2.5 * cell),
                         round(size - cell / 2), round(size - 2.5 * cell - 7 * cell * 5 / 8))
        painter.end()
        icon.addPixmap(pixmap)
    return icon
