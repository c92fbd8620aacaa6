"""A RasterLab program for the kill test: built as ``launch()`` builds it,
it opens the scene file given, makes one edit through the window's public
methods, waits until the recovery file holds the edit, prints
``READY <recovery file>`` and runs until it is killed.

usage: python recovery_child.py SCENE.json X1,Y1 X2,Y2
(the data folder comes from RASTERLAB_DATA_DIR)
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from PySide6.QtCore import QSettings  # noqa: E402
from PySide6.QtWidgets import QApplication  # noqa: E402

from app.gui.appdata import data_dir  # noqa: E402
from app.gui.window import APP_NAME, MainWindow  # noqa: E402


def main() -> None:
    scene_path, *points = sys.argv[1:]
    app = QApplication(sys.argv[:1])
    app.setApplicationName(APP_NAME)
    window = MainWindow()
    settings = QSettings(str(data_dir() / "settings.ini"), QSettings.Format.IniFormat)
    files = window.add_file_actions(settings)
    window.add_crash_handler()
    recovery = window.add_recovery(delay_ms=100)
    window.show()
    if not files.open_path(scene_path):
        sys.exit("cannot open the scene")
    recovery.autosaved.connect(lambda path: print(f"READY {path}", flush=True))
    window.set_points([tuple(int(v) for v in p.split(",")) for p in points])
    app.exec()


if __name__ == "__main__":
    main()
