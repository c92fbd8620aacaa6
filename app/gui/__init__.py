"""The window: Qt widgets and actions over the Qt-free model (app/model).
``launch()`` opens it."""
from __future__ import annotations

import gc
import sys


def launch(argv=None) -> int:
    """Open the window on the demo scene (or the last scene) and run until
    it is closed.

    Automatic collection goes off before the window's modules load: the
    window's main-thread timer collects instead (app/gui/main_thread_gc.py),
    and start-up does not walk the growing heap of modules, classes and Qt
    wrappers again and again (some 110 collections otherwise). Once the
    window is built, what is loaded lives as long as the program: frozen,
    no collection walks it again (some 120,000 objects; the build leaves a
    few dozen of garbage)."""
    gc.disable()
    from PySide6.QtWidgets import QApplication

    from app.gui.appdata import APP_NAME, open_settings
    from app.gui.fonts import register_shipped_fonts
    from app.gui.look import app_icon
    from app.gui.preferences import reopen_last_scene
    from app.gui.window import MainWindow

    app = QApplication.instance()
    if app is None:
        app = QApplication(list(argv) if argv is not None else sys.argv[:1])
        app.setApplicationName(APP_NAME)
        app.setStyle("Fusion")
    register_shipped_fonts()
    app.setWindowIcon(app_icon())
    window = MainWindow()
    window.add_file_actions()
    window.add_report_entry()
    window.view.remember(open_settings())  # the layout and zoom of the last run
    reopen_last_scene(window)
    window.add_crash_handler()
    recovery = window.add_recovery()
    gc.freeze()
    window.show()
    recovery.offer()
    return app.exec()
