"""A worksheet (app/teaching/worksheet.py) as a PDF, drawn with Qt's QPdfWriter.

A4 pages in DejaVu Sans and Sans Mono (the shipped files, app/gui/fonts.py):
the title, the name and date fields (on the student's sheet), the inputs,
the pseudo-code (long lines wrapped, never cut) and the constants, then the
step table and the tables to fill in by hand (as many rows a page as fit,
headings repeated), then one page with the grid and the ideal shape (shaded
where the run plots, on the answer key). The command line imports this
module only when it writes a PDF.

What a reader of the PDF is told (what QPdfWriter can say): the title in
the document information (setTitle), RasterLab as its creator, and an XMP
metadata stream (setDocumentXmpMetadata) with the title, the subject and
the language (dc:title, dc:description, dc:language). The text is real text
in embedded fonts, which readers can select, search and read aloud. Qt
writes no structure tree (an untagged PDF) and no /Lang entry in the
document catalog: those need another PDF library.
"""
from __future__ import annotations

import os
from pathlib import Path

from PySide6.QtCore import QBuffer, QIODevice, QMarginsF, QPointF, QRectF, Qt
from PySide6.QtGui import (QColor, QFont, QPageLayout, QPageSize, QPainter,
                           QPdfWriter, QPen)
from PySide6.QtWidgets import QApplication

from app.gui.fonts import register_shipped_fonts
from app.model.escape import xml_text
from app.model.files import write_atomically
from app.teaching.worksheet import FIELDS

DPI = 150
LANGUAGE = "en"   # the sheets are written in English
ROW_HEIGHT = 1.5  # a table row, in lines of its 9 pt text


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
    title = f"{'Answer key' if answers else 'Worksheet'}: {sheet.title}"
    writer.setTitle(title)
    writer.setCreator("RasterLab")
    writer.setDocumentXmpMetadata(xmp(title, subject(sheet, answers), LANGUAGE))
    painter = QPainter(writer)
    if not painter.isActive():
        raise OSError(f"{path}: Qt cannot draw the PDF")
    try:
        area = QRectF(writer.pageLayout().paintRectPixels(DPI))
        area.moveTo(0, 0)
        top = _heading(painter, sheet, answers, area)
        tables = [("", sheet.columns, sheet.cells(answers))] + [
            (table.name, table.columns, table.cells(answers)) for table in sheet.tables]
        for name, columns, rows in tables:
            top = _paged_table(writer, painter, name, columns, rows, area, top)
        writer.newPage()
        _grid(painter, sheet, answers, area)
    finally:
        painter.end()
    write_atomically(Path(path), bytes(buffer.data()), OSError)


def subject(sheet, answers: bool) -> str:
    """What the sheet asks, in one line: the PDF's subject."""
    task = "the steps and pixels, filled in" if answers else \
        "fill in the step table and shade the pixels it plots"
    return f"{sheet.algorithm} on {sheet.inputs}: {task}"


def xmp(title: str, subject: str, language: str) -> bytes:
    """An XMP packet naming the document's title, subject and language."""
    alt = '<rdf:Alt><rdf:li xml:lang="x-default">{}</rdf:li></rdf:Alt>'
    return (
        '<?xpacket begin="\ufeff" id="W5M0MpCehiHzreSzNTczkc9d"?>'
        '<x:xmpmeta xmlns:x="adobe:ns:meta/"><rdf:RDF '
        'xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#">'
        '<rdf:Description rdf:about="" xmlns:dc="http://purl.org/dc/elements/1.1/" '
        'xmlns:xmp="http://ns.adobe.com/xap/1.0/">'
        f'<dc:title>{alt.format(xml_text(title))}</dc:title>'
        f'<dc:description>{alt.format(xml_text(subject))}</dc:description>'
        f'<dc:language><rdf:Bag><rdf:li>{xml_text(language)}</rdf:li></rdf:Bag></dc:language>'
        '<dc:format>application/pdf</dc:format><xmp:CreatorTool>RasterLab</xmp:CreatorTool>'
        '</rdf:Description></rdf:RDF></x:xmpmeta><?xpacket end="w"?>').encode("utf-8")


def _font(painter, size: float, bold: bool = False, mono: bool = False) -> float:
    font = QFont("DejaVu Sans Mono" if mono else "DejaVu Sans")
    font.setPointSizeF(size)
    font.setBold(bold)
    painter.setFont(font)
    return painter.fontMetrics().height()


def _wrapped(painter, text: str, y: float, width: float) -> float:
    """Draw ``text`` wrapped to ``width`` from ``y``; the y below it."""
    flags = int(Qt.TextFlag.TextWordWrap)
    rect = painter.boundingRect(QRectF(0, y, width, 10_000), flags, text)
    painter.drawText(QRectF(0, y, width, rect.height()), flags, text)
    return y + rect.height()


def _heading(painter, sheet, answers: bool, area: QRectF) -> float:
    _font(painter, 14, bold=True)
    kind = "Answer key" if answers else "Worksheet"
    y = _wrapped(painter, f"{kind}: {sheet.title} ({sheet.algorithm})", 0.0, area.width())
    height = _font(painter, 10)
    if not answers:
        y = _wrapped(painter, FIELDS, y + height * 0.4, area.width())
    y = _wrapped(painter, f"Inputs: {sheet.inputs}", y + height * 0.4, area.width())
    y += height * 0.5
    _font(painter, 8, mono=True)
    for line in sheet.code:
        y = _wrapped(painter, line, y, area.width())
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
        y = _wrapped(painter, line, y + painter.fontMetrics().height() * 0.3, area.width())
    return y + painter.fontMetrics().height()


def _paged_table(writer, painter, name: str, columns, rows, area: QRectF, top: float) -> float:
    """A table from ``top``, on as many pages as it needs (headings repeated);
    the y below it."""
    height = _font(painter, 9) * ROW_HEIGHT
    widths = [max(len(c), *(len(r[k]) for r in rows), 4) + 2
              for k, c in enumerate(columns)] if rows else [8] * len(columns)
    if name:
        top += height * 0.5
        if top + 3 * height > area.height():
            writer.newPage()
            top = 0.0
        _font(painter, 11, bold=True)
        top = _wrapped(painter, name, top, area.width())
    rows = list(rows)
    while True:
        fit = max(1, int((area.height() - top) / height) - 1)
        _table(painter, columns, widths, rows[:fit], area, top)
        top += (1 + min(fit, len(rows))) * height
        rows = rows[fit:]
        if not rows:
            return top
        writer.newPage()
        top = 0.0


def _table(painter, columns, widths, rows, area: QRectF, top: float) -> None:
    height = _font(painter, 9) * ROW_HEIGHT
    scale = area.width() / sum(widths)
    xs = [sum(widths[:k]) * scale for k in range(len(widths) + 1)]
    painter.setPen(QPen(QColor("#000000"), 1))
    for r, row in enumerate([list(columns)] + rows):
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
