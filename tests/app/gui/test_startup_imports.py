"""The first window loads only what it shows: the export writers, Pillow,
the report's measurements, worksheets, compiled kernels and the error log's
file handler load when first used, so that start-up does not pay for them."""
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]

PROBE = """
import sys
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication
app = QApplication([])
QTimer.singleShot(0, app.quit)
from app.gui.window import launch
launch()
print("LOADED", sorted(m for m in sys.modules if m in DEFERRED or m.split(".")[0] in DEFERRED))
"""

DEFERRED = ("PIL", "numba", "av", "fpdf", "app.analysis", "app.render.export",
            "app.render.writers", "app.render.video", "app.render.html", "app.teaching.worksheet",
            "app.teaching.checking", "app.gui.worksheet_pdf", "logging.handlers",
            "app.gui.compare_window", "app.gui.gallery", "app.gui.report_window")


def test_the_first_window_loads_none_of_the_deferred_modules(tmp_path):
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "QT_QPA_PLATFORM": "offscreen",
           "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path), "XDG_DATA_HOME": str(tmp_path)}
    code = f"DEFERRED = {DEFERRED!r}\n" + PROBE
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "LOADED []"


PRELOAD_PROBE = """
import sys
from app.window_preload import load_before_qt
load_before_qt()
before = set(sys.modules)
print("QT", sorted(m for m in before if m.split(".")[0] in ("PySide6", "shiboken6", "pyqtgraph",
                                                             "widgets")))
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication
app = QApplication([])
QTimer.singleShot(0, app.quit)
from app.gui.window import launch
launch()
late = set(sys.modules) - before
print("LATE", sorted(m for m in late if m.split(".")[0] == "algorithms"
                     or m.startswith(("app.model", "app.render", "logging"))))
"""


def test_the_window_s_qt_free_modules_are_all_loaded_before_qt(tmp_path):
    # Modules loaded after PySide6 pass through its import hook, which reads
    # their source; the preload must cover every Qt-free module the window uses.
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "QT_QPA_PLATFORM": "offscreen",
           "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path), "XDG_DATA_HOME": str(tmp_path)}
    out = subprocess.run([sys.executable, "-c", PRELOAD_PROBE], cwd=ROOT, capture_output=True,
                         text=True, env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    lines = out.stdout.strip().splitlines()
    assert lines[-2] == "QT []"
    assert lines[-1] == "LATE []"
