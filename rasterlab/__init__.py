"""RasterLab: watch the classic rasterization algorithms work, step by step.

This package is the one name RasterLab installs. The program itself is the
packages ``algorithms``, ``app`` and ``widgets`` (with the data in
``resources``); an installed wheel keeps them in ``rasterlab/_lib``, out of
site-packages' top level, so an unrelated distribution called
``algorithms`` or ``app`` can be installed beside RasterLab without either
overwriting the other. Importing this package puts that folder first on
``sys.path`` (in a checkout, the checkout itself), so the program finds its
own packages before a same-named folder in the current directory. The
price, stated in the docs: in a process that imported ``rasterlab``,
``import algorithms`` means RasterLab's.

``rasterlab.run``, ``open_scene``, ``export``, ``check``, ``question``, ``Run`` and
``CheckResult`` are the Python API (app/api.py, docs/reference/api.md).
"""
from __future__ import annotations

import sys
from pathlib import Path

_HERE = Path(__file__).resolve().parent


def _program_folder() -> Path:
    """The folder holding app/, algorithms/, widgets/ and resources/: _lib
    in a wheel, the checkout in a source tree or an editable install."""
    for folder in (_HERE / "_lib", _HERE.parent):
        if (folder / "app" / "__init__.py").is_file():
            return folder
    raise ImportError(f"RasterLab's packages are missing beside {_HERE}; reinstall RasterLab")


PROGRAM = _program_folder()
if str(PROGRAM) in sys.path:
    sys.path.remove(str(PROGRAM))
sys.path.insert(0, str(PROGRAM))


def main(argv: list[str] | None = None) -> int:
    """The `rasterlab` command."""
    from app.cli import main as command_line
    return command_line(argv)


# The Python API (app/api.py), loaded on first use (PEP 562) so that the
# command's start-up does not import it.
_API = ("run", "open_scene", "export", "check", "question", "Run", "CheckResult")
__all__ = ["main", *_API]


def __getattr__(name: str):
    if name in _API:
        from app import api
        return getattr(api, name)
    raise AttributeError(f"module 'rasterlab' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_API))
