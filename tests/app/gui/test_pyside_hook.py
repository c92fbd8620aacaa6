"""PySide6's import hook gets its answer (does a module's source mention
PySide6?) from the file's bytes, installed before pyqtgraph and the
window's modules are imported, and the answer is PySide6's own."""
import subprocess
import sys
from pathlib import Path

from app.gui import pyside_hook

ROOT = Path(__file__).resolve().parents[3]

# PySide6's own search counted from its first import: every module it is
# asked about after that goes through it, unless the quick one answers.
PROBE = """
import sys
import PySide6
feature = sys.modules["shibokensupport.feature"]
original, asked = feature._mod_uses_pyside, []


def counting(module):
    asked.append(module.__name__)
    return original(module)


feature._mod_uses_pyside = counting
import app.gui.window
print("ASKED", sum(name.split(".")[0] in ("pyqtgraph", "widgets") for name in asked),
      "OF", sum(name.split(".")[0] in ("pyqtgraph", "widgets") for name in sys.modules))
"""


def test_the_window_imports_pyqtgraph_and_its_widgets_after_the_quick_search():
    out = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, check=True,
                         capture_output=True, text=True,
                         env={"QT_QPA_PLATFORM": "offscreen", "PATH": "/usr/bin:/bin",
                              "PYTHONPATH": str(ROOT)}).stdout
    asked, loaded = (int(n) for n in out.split("ASKED")[1].split("OF"))
    assert loaded > 100  # pyqtgraph and the widgets were imported...
    assert asked == 0  # ...and none of them read through inspect


def test_the_quick_search_answers_as_pyside_does_for_every_loaded_module():
    import app.gui.window  # noqa: F401 (loads pyqtgraph, Qt and the window's modules)
    quick = sys.modules["shibokensupport.feature"]._mod_uses_pyside
    assert hasattr(quick, "original")
    modules = [module for module in list(sys.modules.values()) if module is not None]
    uses = [module.__name__ for module in modules if quick(module)]
    assert uses == [module.__name__ for module in modules if quick.original(module)]
    assert "widgets.grid_view" in uses and "pyqtgraph.Qt" in uses
    assert "algorithms.core.trace" not in uses and "sys" not in uses


def test_it_is_installed_once():
    assert pyside_hook.quicken() is False
