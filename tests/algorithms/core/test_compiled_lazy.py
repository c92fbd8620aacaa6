"""The compiled kernels load numba on their first call only: listing and
running algorithms (the generators) never import it."""
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]

PROBE = """
import sys
from app import cli
cli.main(["list"])
cli.main(["run", "flood-fill", "--points", "1,1", "20,1", "20,15", "1,15", "--json"])
cli.main(["run", "line-wu", "--points", "0,0", "9,4", "--json"])
print("BEFORE", "numba" in sys.modules)
from algorithms.core.registry import get
spec = get("flood-fill")
spec.kernel([[(1, 1), (20, 1), (20, 15), (1, 15)]], spec.resolve({}), (24, 18))
print("AFTER", "numba" in sys.modules)
"""


def test_numba_is_imported_by_a_compiled_kernel_only():
    pytest.importorskip("numba")  # the optional extra rasterlab[fast]
    out = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, capture_output=True, text=True,
                         env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-2:] == ["BEFORE False", "AFTER True"]
