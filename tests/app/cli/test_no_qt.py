"""`rasterlab list` and `rasterlab run` never load Qt: they work on machines without a display."""
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]

PROBE = """
import sys
from app import cli
cli.main(["list"])
cli.main(["run", "line-bresenham", "--points", "0,0", "5,2", "--json"])
cli.main(["run", "polygon-scanline", "--points", "2,2", "28,3", "20,20", "--ascii"])
loaded = sorted(m for m in sys.modules if m.split(".")[0] in ("PySide6", "shiboken6", "pyqtgraph"))
print("LOADED", loaded)
"""


def test_list_and_run_import_no_qt():
    out = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, capture_output=True, text=True,
                         env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "LOADED []"
