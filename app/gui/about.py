"""What the About box and the keyboard-shortcuts sheet show.

The version comes from the installed package's metadata, else from
pyproject.toml (a source checkout run without installing). The shortcuts
sheet lists the window's own actions, so that it cannot drift from the
keys that really work, then the pointer gestures, which no action holds.
"""
from __future__ import annotations

import platform
import re
from importlib import metadata
from pathlib import Path

import PySide6
from PySide6.QtCore import qVersion
from PySide6.QtGui import QKeySequence

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


def runtime_versions() -> str:
    return (f"Python {platform.python_version()}, Qt {qVersion()}, "
            f"PySide6 {PySide6.__version__}")


def shortcut_rows(window, gestures=()) -> list[tuple[str, str]]:
    """(keys, what they do) for every action of ``window`` that has a
    shortcut, in menu order, then the gesture rows of ``gestures``."""
    rows, seen = [], set()
    for action in _actions_in_menus(window.menuBar()) + list(window.actions()):
        if id(action) in seen or not action.shortcuts():
            continue
        seen.add(id(action))
        keys = ", ".join(key.toString(QKeySequence.SequenceFormat.NativeText)
                         for key in action.shortcuts())
        text = action.text().replace("&", "").replace("\u2026", "").strip()
        rows.append((keys, text))
    rows += list(gestures)
    return rows


def _actions_in_menus(widget) -> list:
    found = []
    for action in widget.actions():
        found.append(action)
        if action.menu() is not None:
            found += _actions_in_menus(action.menu())
    return found
