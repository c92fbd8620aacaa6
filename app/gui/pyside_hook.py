"""A quicker answer to the question PySide6's import hook asks of each module.

Once PySide6 is imported, every module imported after it is searched for the
text "PySide6" (modules that use PySide may select its ``__feature__``
options). PySide6 reads the source with ``inspect.getsource``, which goes
through the line cache and the source's encoding: about 0.13 ms a module,
28 ms of pyqtgraph's import (223 modules) and some 8 ms more for the
window's own. Searching the file's bytes for the same text gives the same
answer for a source file in a fraction of that; anything else is still
asked of PySide6's own function.
"""
from __future__ import annotations

import importlib
import sys


def quicken() -> bool:
    """Replace the hook's source search; False if there is none to replace
    (another PySide6 version) or it is replaced already."""
    importlib.import_module("PySide6")  # loads the hook's module, shibokensupport.feature
    feature = sys.modules.get("shibokensupport.feature")
    original = getattr(feature, "_mod_uses_pyside", None)
    if not callable(original) or hasattr(original, "original"):
        return False

    def uses_pyside(module) -> bool:
        path = getattr(module, "__file__", None)
        if not isinstance(path, str) or not path.endswith(".py"):
            return original(module)
        try:
            with open(path, "rb") as source:
                return b"PySide6" in source.read()
        except OSError:
            return original(module)

    uses_pyside.original = original
    feature._mod_uses_pyside = uses_pyside
    return True
