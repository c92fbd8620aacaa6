"""The last line of defence: an exception nobody caught.

``CrashHandler(window).install()`` makes ``sys.excepthook`` (where PySide6
sends an exception raised in a slot or an event handler) and
``threading.excepthook`` write the traceback to a rotating log file in the
application data folder and show one message box saying so. The program
keeps running: Qt goes on with the next event, and the scene is whatever
the last completed change left (every edit checks and records before it
changes anything).

A burst of exceptions (a slot failing on every timer tick, say) shows one
message box, not one per exception. An exception while Qt is shutting down,
or with no application at all, prints one line on stderr instead.
"""
from __future__ import annotations

import logging
import sys
import threading
import traceback
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QObject, Qt, QUrl, Signal, Slot
from PySide6.QtGui import QDesktopServices
from PySide6.QtWidgets import QApplication, QMessageBox

from app.gui.appdata import data_dir, ensure
from app.model.scene import one_line

LOG_NAME = "rasterlab.log"
LOG_BYTES = 512 * 1024
LOG_BACKUPS = 3
TITLE = "RasterLab: unexpected error"


def log_path(folder: Path | None = None) -> Path:
    return (folder if folder is not None else data_dir()) / LOG_NAME


def summary(exc_type, value) -> str:
    """The exception as one short line: ``ZeroDivisionError: division by zero``."""
    text = str(value)
    return one_line(f"{exc_type.__name__}: {text}" if text else exc_type.__name__, 200)


class CrashHandler(QObject):
    """Logs uncaught exceptions and shows them, one dialog per burst."""

    # Emitted from whatever thread raised; delivered in the GUI thread.
    _reported = Signal(str)

    def __init__(self, window=None, folder: Path | None = None):
        super().__init__()
        self.window = window
        self.log_file = log_path(folder)
        # Made at the first error, so start-up does not load logging.handlers.
        self._logger: logging.Logger | None | bool = None  # False: it cannot be made
        self._logger_lock = threading.Lock()
        self.count = 0  # exceptions handled since install
        self._pending: list[str] = []
        self._showing = False
        self._previous = None
        # Queued even from the GUI thread: the exceptions of one pass of the
        # event loop gather into one dialog, shown once the failing code
        # has unwound.
        self._reported.connect(self._queue, Qt.ConnectionType.QueuedConnection)

    # ----------------------------------------------------------- hooks
    def install(self) -> "CrashHandler":
        self._previous = (sys.excepthook, threading.excepthook)
        sys.excepthook = self.handle
        threading.excepthook = self._thread_hook
        return self

    def add_menu_entry(self, menu) -> None:
        """"Open log folder" in ``menu`` (the main window's Help menu)."""
        act = menu.addAction("Open &log folder")
        act.setToolTip(f"Show the folder of the error log ({self.log_file.parent})")
        act.setStatusTip(act.toolTip())
        act.triggered.connect(self.open_log_folder)

    def uninstall(self) -> None:
        if self._previous is not None and sys.excepthook == self.handle:
            sys.excepthook, threading.excepthook = self._previous
        self._previous = None

    def _thread_hook(self, args) -> None:
        if args.exc_type is SystemExit:
            return
        self.handle(args.exc_type, args.exc_value, args.exc_traceback)

    def handle(self, exc_type, value, tb) -> None:
        """The excepthook: never raises, whatever happens inside."""
        if issubclass(exc_type, KeyboardInterrupt):
            sys.__excepthook__(exc_type, value, tb)
            return
        self.count += 1
        line = summary(exc_type, value)
        logged = self._log(exc_type, value, tb)
        app = QApplication.instance()
        if app is None or QCoreApplication.closingDown() or self.window is None:
            where = f" (details in {self.log_file})" if logged else ""
            _stderr(f"RasterLab: unexpected error: {line}{where}")
            return
        try:
            self._reported.emit(line)
        except RuntimeError:  # the handler's Qt side is already gone
            _stderr(f"RasterLab: unexpected error: {line}")

    @property
    def logger(self) -> logging.Logger | None:
        """The error log's logger (made when first asked for), or None when
        its folder cannot be made."""
        with self._logger_lock:  # errors of two threads at once make one
            if self._logger is None:
                self._logger = _file_logger(self.log_file) or False
        return self._logger or None

    def _log(self, exc_type, value, tb) -> bool:
        logger = self.logger
        if logger is None:
            return False
        text = "".join(traceback.format_exception(exc_type, value, tb))
        try:
            logger.error("Uncaught exception\n%s", text.rstrip())
            return True
        except Exception:  # noqa: BLE001 - a full disk must not hide the error
            return False

    # ---------------------------------------------------------- dialog
    @Slot(str)
    def _queue(self, line: str) -> None:
        self._pending.append(line)
        if self._showing:
            return  # logged; the dialog on show stands for it
        self._showing = True
        try:
            QCoreApplication.processEvents()  # gather the rest of the burst
            lines, self._pending = self._pending, []
            self.show_message(self.message(lines))
        finally:
            self._showing = False
        # What failed while the dialog was open is in the log; a second
        # dialog would only trap a person in a loop of them.
        if self._pending:
            self._note(len(self._pending))
            self._pending = []

    def _note(self, count: int) -> None:
        if _alive(self.window):
            self.window.statusBar().showMessage(
                f"{count} more unexpected error{'s' if count != 1 else ''}: "
                f"see {self.log_file}", 10000)

    def message(self, lines: list[str]) -> str:
        more = len(lines) - 1
        text = f"Something went wrong: {lines[0]}"
        if more:
            text += f"\n(and {more} more error{'s' if more != 1 else ''} right after it)"
        return (f"{text}\n\nRasterLab keeps running and the scene is kept: you can go on or "
                f"save it. The details are in {self.log_file}.")

    def show_message(self, text: str) -> None:
        parent = self.window if _alive(self.window) else None
        QMessageBox.critical(parent, TITLE, text)

    def open_log_folder(self) -> bool:
        try:
            ensure(self.log_file.parent)
        except OSError:
            return False
        return QDesktopServices.openUrl(QUrl.fromLocalFile(str(self.log_file.parent)))


def _file_logger(path: Path) -> logging.Logger | None:
    """A logger writing to ``path`` only (never to the console), or None
    when the folder cannot be created."""
    import logging.handlers  # only once there is an error to log
    try:
        ensure(path.parent)
        handler = logging.handlers.RotatingFileHandler(
            path, maxBytes=LOG_BYTES, backupCount=LOG_BACKUPS, encoding="utf-8", delay=True)
    except OSError as error:
        _stderr(f"RasterLab: cannot keep an error log in {path.parent} ({error})")
        return None
    handler.setFormatter(logging.Formatter("%(asctime)s %(levelname)s %(message)s"))
    logger = logging.getLogger(f"rasterlab.crash.{path}")
    logger.handlers.clear()  # one handler per file, however often installed
    logger.addHandler(handler)
    logger.setLevel(logging.INFO)
    logger.propagate = False
    return logger


def _stderr(line: str) -> None:
    try:
        print(line, file=sys.stderr, flush=True)
    except (OSError, ValueError):
        pass  # no stderr left to tell


def _alive(widget) -> bool:
    if widget is None:
        return False
    try:
        widget.isVisible()
    except RuntimeError:  # the C++ side was deleted
        return False
    return True
