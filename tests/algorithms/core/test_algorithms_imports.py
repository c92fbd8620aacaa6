"""algorithms/ stands alone: importing it loads no Qt, no app, no widgets."""
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
FORBIDDEN = ("PySide6", "pyqtgraph", "app", "widgets", "shiboken6")

SCRIPT = f"""
import sys
import algorithms.lines, algorithms.core.trace, algorithms.core.registry, algorithms.exact.lines
algorithms.core.registry.all_specs()
loaded = sorted(name for name in sys.modules
                if name.split('.')[0] in {FORBIDDEN!r})
print(','.join(loaded))
"""


def test_no_gui_modules_are_loaded():
    result = subprocess.run([sys.executable, "-c", SCRIPT], cwd=ROOT, capture_output=True,
                            text=True, timeout=60, env={"PYTHONPATH": str(ROOT), "PATH": ""})
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == ""


def test_the_check_would_notice_a_gui_import():
    # The same script does see a forbidden module once one is imported.
    result = subprocess.run([sys.executable, "-c", "import widgets\n" + SCRIPT], cwd=ROOT,
                            capture_output=True, text=True, timeout=60,
                            env={"PYTHONPATH": str(ROOT), "PATH": ""})
    assert result.returncode == 0, result.stderr
    assert "widgets" in result.stdout.strip().split(",")
