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
from app.gui import launch
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

