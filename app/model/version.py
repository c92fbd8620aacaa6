"""RasterLab's version, as `rasterlab --version` and the About box say it.

It comes from the installed package's metadata, else from pyproject.toml (a
source checkout run without installing).
"""
from __future__ import annotations

import re
from importlib import metadata
from pathlib import Path

PACKAGE = "rasterlab"
PYPROJECT = Path(__file__).resolve().parents[2] / "pyproject.toml"


def app_version() -> str:
    try:
        return metadata.version(PACKAGE)
    except metadata.PackageNotFoundError:
        pass
    try:
        return declared_version(PYPROJECT.read_text(encoding="utf-8")) or "unknown"
    except OSError:
        return "unknown"


def declared_version(text: str) -> str:
    """The [project] version pyproject.toml's text declares ("" for none)."""
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10: the table's one version line
        project = re.search(r"^\[project\]$(.*?)(?=^\[|\Z)", text, re.M | re.S)
        found = project and re.search(r'^version\s*=\s*"([^"]*)"', project.group(1), re.M)
        return found.group(1) if found else ""
    try:
        return str(tomllib.loads(text)["project"]["version"])
    except (KeyError, tomllib.TOMLDecodeError):
        return ""
