"""Start-up leaves the collector little to do: launch() turns automatic
collection off before the window's modules load, and freezes what is
loaded once the window is built, so that neither start-up nor any later
collection walks it."""
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]

# Counts the collections from the call of launch() until the window is
# shown (automatic ones: no timer runs before the event loop).
PROBE = """
import gc
from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QApplication, QMainWindow
app = QApplication([])
collections = []
gc.callbacks.append(lambda phase, info: phase == "start" and collections.append(info))


class Shown(QObject):
    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Show and isinstance(watched, QMainWindow):
            print("BEFORE_SHOWN", len(collections))
            app.removeEventFilter(self)
        return False


def look():
    print("FROZEN", gc.get_freeze_count(), "AUTOMATIC", gc.isenabled(), "YOUNG", gc.get_count()[0])
    app.quit()


shown = Shown()
app.installEventFilter(shown)
QTimer.singleShot(0, look)
from app.gui import launch
launch()
"""


def test_the_window_starts_without_collections_and_with_what_is_loaded_frozen(tmp_path):
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "QT_QPA_PLATFORM": "offscreen",
           "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path), "XDG_DATA_HOME": str(tmp_path)}
    out = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, capture_output=True, text=True,
                         env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    words = out.stdout.split()
    before_shown = int(words[words.index("BEFORE_SHOWN") + 1])
    frozen = int(words[words.index("FROZEN") + 1])
    automatic = words[words.index("AUTOMATIC") + 1]
    young = int(words[words.index("YOUNG") + 1])
    # Importing the window's modules and building it: over a hundred
    # automatic collections while collection is on.
    assert before_shown == 0
    assert automatic == "False"
    # The modules, classes and functions of numpy, Qt, pyqtgraph and the
    # program: far more than the window itself makes afterwards.
    assert frozen > 50_000 and young < frozen // 2
