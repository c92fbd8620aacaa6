"""What the About box and the keyboard-shortcuts sheet show.

The version is app.model.version's. The shortcuts sheet lists the window's own actions, so that it cannot drift from the
keys that really work, then the pointer gestures, which no action holds.
"""
from __future__ import annotations

import platform

import PySide6
from PySide6.QtCore import qVersion
from PySide6.QtGui import QKeySequence

from app.model.version import app_version, declared_version  # noqa: F401 (the About box)


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
