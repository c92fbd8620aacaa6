"""The DejaVu fonts RasterLab ships (resources/fonts/), made known to Qt.

Windows and macOS have no DejaVu of their own: without this, QFont("DejaVu
Sans") in the worksheet PDF would silently become another family, one
without every glyph the sheet uses. Qt keeps an application font for the
life of the process, so the files are added once, after the application
exists.
"""
from __future__ import annotations

from PySide6.QtGui import QFontDatabase

from app.model.shipped import FONTS

_families: list[str] = []


def register_shipped_fonts() -> list[str]:
    """Add every shipped .ttf to Qt's font database (the first call does;
    later ones return the same answer) and return the families they hold."""
    if not _families:
        for path in sorted(FONTS.glob("*.ttf")):
            font_id = QFontDatabase.addApplicationFont(str(path))
            if font_id == -1:  # no application yet, or a damaged install
                raise OSError(f"Qt cannot load the shipped font {path}; reinstall RasterLab")
            _families.extend(QFontDatabase.applicationFontFamilies(font_id))
    return sorted(set(_families))
