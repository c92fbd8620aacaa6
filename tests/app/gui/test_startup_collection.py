"""Start-up leaves the collector little to do: automatic collection is off
from the first import (app/launcher.py, app/window_preload.py), and what is
loaded before the window is built is frozen, so that neither the first
collection before the first paint nor any later one walks it."""
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]

PROBE = """
import gc
from app.window_preload import load_before_qt
load_before_qt()
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication
app = QApplication([])


def look():
    print("FROZEN", gc.get_freeze_count(), "AUTOMATIC", gc.isenabled(), "YOUNG", gc.get_count()[0])
    app.quit()


QTimer.singleShot(0, look)
from app.gui.window import launch
launch()
"""


def test_the_window_starts_with_what_is_loaded_frozen(tmp_path):
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "QT_QPA_PLATFORM": "offscreen",
           "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path), "XDG_DATA_HOME": str(tmp_path)}
    out = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, capture_output=True, text=True,
                         env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    words = out.stdout.split()
    frozen, automatic, young = int(words[1]), words[3], int(words[5])
    assert automatic == "False"
    # The modules, classes and functions of numpy, Qt, pyqtgraph and the
    # program: far more than the window itself makes afterwards.
    assert frozen > 50_000 and young < frozen // 2
