"""The program without numba (the ``fast`` extra not installed): the plain loops
run, and a process where numba cannot be imported prints and computes what
one with it does."""
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

from tests.support.kernel_cases import results

ROOT = Path(__file__).resolve().parents[3]
# A None in sys.modules makes `import numba` raise ImportError, as when it is not installed.
NO_NUMBA = "import sys; sys.modules['numba'] = None\n"
CLI = ("import runpy, sys\nsys.argv[0] = 'rasterlab'\n"
       "runpy.run_module('rasterlab', run_name='__main__')\n")


def python(code: str, *argv: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-c", code, *argv], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done


def test_run_without_numba_prints_the_same():
    for argv in (["run", "--scene", "triangle-mesh-1e6", "--json"],
                 ["run", "flood-fill", "--points", "1,1", "30,2", "28,20", "2,18", "--json"]):
        assert python(NO_NUMBA + CLI, *argv).stdout == python(CLI, *argv).stdout != ""


def test_kernels_without_numba_give_the_same_pixels(tmp_path):
    out = tmp_path / "plain.npz"
    code = (NO_NUMBA + "import numpy as np\nfrom algorithms.core.compiled import path\n"
            "from tests.support.kernel_cases import results\n"
            f"np.savez({str(out)!r}, **results())\nprint(path())\n")
    assert python(code).stdout.split() == ["python"]
    plain = np.load(out)
    here = results()  # compiled where numba is installed
    assert sorted(plain.files) == sorted(here)
    for name, array in here.items():
        assert plain[name].dtype == array.dtype and np.array_equal(plain[name], array), name
        assert array.any(), name  # each case draws something
