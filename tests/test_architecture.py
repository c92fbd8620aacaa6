"""The import contracts of pyproject.toml ([tool.importlinter]) hold, and the
check really fails when a layer imports what it must not."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("algorithms", "app", "widgets")
# Run in a child process: the packages this process has already imported
# would otherwise be found in place of a copy's.
LINT = ("import sys; from importlinter.cli import lint_imports; "
        "sys.exit(lint_imports(config_filename='pyproject.toml', no_cache=True, no_logo=True))")


def lint(folder: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", LINT], cwd=folder, capture_output=True,
                          text=True, env=dict(os.environ, PYTHONPATH=str(folder)), timeout=120)


def test_the_import_contracts_are_kept():
    result = lint(ROOT)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "0 broken" in result.stdout


@pytest.fixture
def copy(tmp_path):
    """The packages and the contracts, copied where a test may break them."""
    for name in PACKAGES:
        shutil.copytree(ROOT / name, tmp_path / name,
                        ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(ROOT / "pyproject.toml", tmp_path)
    return tmp_path


@pytest.mark.parametrize("contract, plants", [
    ("algorithms are pure", [("algorithms/lines.py", "import PySide6.QtGui")]),
    ("algorithms are pure", [("algorithms/lines.py", "from widgets import grid_view")]),
    ("load no Qt and no widgets", [("app/model/scene.py", "import pyqtgraph")]),
    ("load no Qt and no widgets", [("app/analysis/report.py", "from widgets import panels")]),
    ("widgets use nothing of app", [("widgets/panels.py", "from app.gui import window")]),
    ("layers", [("app/render/frame.py", "from app.gui import window")]),
    ("layers", [("app/model/scene.py", "from app.render import compose")]),
    ("no cycles", [("algorithms/exact/planted.py", "from algorithms import lines"),
                   ("algorithms/lines/__init__.py", "from algorithms.exact import planted")]),
], ids=["algorithms-qt", "algorithms-widgets", "model-qt", "analysis-widgets", "widgets-gui",
        "render-gui", "model-render", "cycle"])
def test_a_planted_forbidden_import_breaks_its_contract(copy, contract, plants):
    assert lint(copy).returncode == 0
    for module, line in plants:
        with open(copy / module, "a") as file:
            file.write(f"\n{line}\n")
    result = lint(copy)
    assert result.returncode == 1, result.stdout
    broken = [row for row in result.stdout.splitlines() if " BROKEN" in row]
    assert any(contract in row for row in broken), result.stdout


@pytest.mark.parametrize("module", ["algorithms.visibility.zbuffer_painter",
                                    "algorithms.visibility.painter_split", "algorithms.pipeline",
                                    "algorithms.textures", "algorithms.antialias",
                                    "algorithms.triangles", "algorithms.circles.curves",
                                    "algorithms.fill.kernel"])
def test_each_family_module_imports_on_its_own_and_lists_in_one_order(module):
    # A fresh interpreter that imports this module first: no import cycle,
    # and the algorithms listed in the same order as after any other first import.
    code = (f"import {module}\nfrom algorithms.core import registry\n"
            "print(' '.join(s.name for s in registry.all_specs()))")
    first = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                           timeout=120)
    plain = subprocess.run([sys.executable, "-c", code.replace(f"import {module}\n", "")],
                           cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert first.returncode == 0, first.stderr[-500:]
    assert first.stdout == plain.stdout
