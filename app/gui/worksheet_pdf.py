"""A worksheet (app/teaching/worksheet.py) as a PDF, drawn with Qt's QPdfWriter.

A4 pages in DejaVu Sans and Sans Mono (the shipped files, app/gui/fonts.py):
the title, the pseudo-code and the constants, then the step table
(ROWS_PER_PAGE rows a page, headings repeated), then one page with the grid
and the ideal shape (shaded where the run plots, on the answer key). The
command line imports this module only when it writes a PDF.
"""
from __future__ import annotations

import os
from pathlib import Path

from PySide6.QtCore import QBuffer, QIODevice, QMarginsF, QPointF, QRectF, Qt
from PySide6.QtGui import (QColor, QFont, QPageLayout, QPageSize, QPainter,
                           QPdfWriter, QPen)
from PySide6.QtWidgets import QApplication

from app.gui.fonts import register_shipped_fonts
from app.model.files import write_atomically

ROWS_PER_PAGE = 30
DPI = 150


def application():
    """Qt needs an application to lay out text; without a display, an offscreen one.
    A full QApplication, not a QGuiApplication: the process (the window's, or
    a test run's) may make widgets afterwards, which a QGuiApplication forbids."""
    app = QApplication.instance()
    if app is None:
        if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
            os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
        app = QApplication([])
    return app


def page_count(sheet) -> int:
    return max(1, -(-len(sheet.rows) // ROWS_PER_PAGE)) + 1


def write_pdf(sheet, path, answers: bool) -> None:
    """Draw the PDF into memory, then write it atomically
    (``write_atomically``): Qt never opens the file, so a folder that cannot
    be written gives one line (OSError) instead of QPainter's warnings."""
    application()
    register_shipped_fonts()  # the window's launch() has, but the command line has not
    buffer = QBuffer()
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    writer = QPdfWriter(buffer)
    writer.setResolution(DPI)
    writer.setPageLayout(QPageLayout(QPageSize(QPageSize.PageSizeId.A4),
                                     QPageLayout.Orientation.Portrait, QMarginsF(15, 15, 15, 15)))
    writer.setTitle(f"{'Answer key' if answers else 'Worksheet'}: {sheet.title}")
    painter = QPainter(writer)
    if not painter.isActive():
        raise OSError(f"{path}: Qt cannot draw the PDF")
    try:
        area = QRectF(writer.pageLayout().paintRectPixels(DPI))
        area.moveTo(0, 0)
        chunks = [sheet.cells(answers)[k:k + ROWS_PER_PAGE]
                  for k in range(0, max(len(sheet.rows), 1), ROWS_PER_PAGE)]
        for n, rows in enumerate(chunks):
            top = _heading(painter, sheet, answers, area) if n == 0 else 0.0
            _table(painter, sheet, rows, area, top)
            writer.newPage()
        _grid(painter, sheet, answers, area)
    finally:
        painter.end()
    write_atomically(Path(path), bytes(buffer.data()), OSError)


def _font(painter, size: float, bold: bool = False, mono: bool = False) -> float:
    font = QFont("DejaVu Sans Mono" if mono else "DejaVu Sans")
    font.setPointSizeF(size)
    font.setBold(bold)
    painter.setFont(font)
    return painter.fontMetrics().height()


def _heading(painter, sheet, answers: bool, area: QRectF) -> float:
    y = 0.0
    height = _font(painter, 14, bold=True)
    kind = "Answer key" if answers else "Worksheet"
    painter.drawText(QPointF(0, y + height), f"{kind}: {sheet.title} ({sheet.algorithm})")
    y += height * 1.6
    height = _font(painter, 8, mono=True)
    for line in sheet.code:
        painter.drawText(QRectF(0, y, area.width(), height), Qt.TextFlag.TextSingleLine, line)
        y += height
    _font(painter, 9)
    lines = []
    if sheet.constants:
        lines.append("Constants: " + ", ".join(f"{n} = {v}" for n, v in sheet.constants))
    if not answers:
        lines.append(f"Fill in the columns {', '.join(sorted(sheet.blank))}, and shade the "
                     "pixels on the grid of the last page.")
    if sheet.note:
        lines.append(sheet.note)
    for line in lines:
        y += painter.fontMetrics().height() * 1.3
        painter.drawText(QPointF(0, y), line)
    return y + painter.fontMetrics().height()


def _table(painter, sheet, rows, area: QRectF, top: float) -> None:
    height = _font(painter, 9) * 1.5
    widths = [max(len(c), *(len(r[k]) for r in sheet.rows), 4) + 2
              for k, c in enumerate(sheet.columns)] if sheet.rows else [8] * len(sheet.columns)
    scale = area.width() / sum(widths)
    xs = [sum(widths[:k]) * scale for k in range(len(widths) + 1)]
    painter.setPen(QPen(QColor("#000000"), 1))
    for r, row in enumerate([list(sheet.columns)] + rows):
        y = top + r * height
        if r == 0:
            painter.fillRect(QRectF(0, y, area.width(), height), QColor("#e8e8e8"))
        for k, text in enumerate(row):
            cell = QRectF(xs[k], y, xs[k + 1] - xs[k], height)
            painter.drawRect(cell)
            painter.drawText(cell.adjusted(4, 0, -2, 0), Qt.AlignmentFlag.AlignVCenter, text)


def _grid(painter, sheet, answers: bool, area: QRectF) -> None:
    width, height = sheet.grid
    title = _font(painter, 11, bold=True) * 1.5
    painter.drawText(QPointF(0, title * 0.7),
                     "The pixels plotted" if answers else "Shade the pixels the algorithm plots")
    label = _font(painter, 7)
    left = painter.fontMetrics().horizontalAdvance("0000")
    cell = min((area.width() - left) / width, (area.height() - title - 2 * label) / height)
    top = title

    def at(x, y):
        return QPointF(left + x * cell, top + (height - y) * cell)
    if answers:
        for x, y in sheet.pixels:
            if 0 <= x < width and 0 <= y < height:
                painter.fillRect(QRectF(at(x, y + 1), at(x + 1, y)), QColor("#8fa8d8"))
    painter.setPen(QPen(QColor("#b0b0b0"), 1))
    for k in range(width + 1):
        painter.drawLine(at(k, 0), at(k, height))
    for k in range(height + 1):
        painter.drawLine(at(0, k), at(width, k))
    painter.setPen(QPen(QColor("#000000"), 1))
    # Pixel numbers every 5 cells, under and beside the cells they name.
    for x in range(0, width, 5):
        corner = at(x, 0)
        painter.drawText(QRectF(corner.x(), corner.y(), cell, label * 1.5),
                         Qt.AlignmentFlag.AlignCenter, str(x))
    for y in range(0, height, 5):
        corner = at(0, y + 1)
        painter.drawText(QRectF(0, corner.y(), left - 4, cell),
                         Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter, str(y))
    painter.setPen(QPen(QColor("#d9480f"), 3))
    for points, closed in sheet.paths:
        xy = [at(x, y) for x, y in points] + ([at(*points[0])] if closed and points else [])
        for a, b in zip(xy, xy[1:]):
            painter.drawLine(a, b)
