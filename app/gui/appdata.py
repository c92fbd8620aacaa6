"""Where RasterLab keeps its own files: the settings, the recovery copy of
the scene being edited and the error log.

The settings are the INI file named by ``$RASTERLAB_SETTINGS`` when that is
set, else the per-user QSettings of RasterLab.

The folder is ``$RASTERLAB_DATA_DIR`` when that is set (tests and portable
set-ups point it at a folder of their own), else Qt's per-user application
data folder (``QStandardPaths.AppLocalDataLocation``, for example
``~/.local/share/RasterLab`` on Linux).
"""
from __future__ import annotations

import os
from pathlib import Path

from PySide6.QtCore import QSettings, QStandardPaths

APP_NAME = "RasterLab"  # the window's title, and the settings' organisation and application
SETTINGS_ENV = "RASTERLAB_SETTINGS"
ENV_VAR = "RASTERLAB_DATA_DIR"
FALLBACK = Path.home() / ".rasterlab"


def data_dir() -> Path:
    """The folder, not yet created (see ``ensure``)."""
    chosen = os.environ.get(ENV_VAR, "").strip()
    if chosen:
        return Path(chosen).expanduser()
    location = QStandardPaths.writableLocation(
        QStandardPaths.StandardLocation.AppLocalDataLocation)
    # Without an application name Qt answers with a shared folder; use ours.
    if not location or Path(location).name.lower() != "rasterlab":
        return FALLBACK
    return Path(location)


def documents_dir() -> Path:
    """The user's documents folder (where saves and exports start), else the home folder."""
    location = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.DocumentsLocation)
    return Path(location) if location else Path.home()


def ensure(folder: Path) -> Path:
    """Create ``folder`` (and its parents) if needed; raises OSError."""
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def open_settings() -> QSettings:
    """The settings store: ``$RASTERLAB_SETTINGS`` (an INI file) or the user's."""
    path = os.environ.get(SETTINGS_ENV, "").strip()
    if path:
        return QSettings(str(Path(path).expanduser()), QSettings.Format.IniFormat)
    return QSettings(APP_NAME, APP_NAME)
