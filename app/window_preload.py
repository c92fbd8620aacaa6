"""Load the window's Qt-free modules before Qt is imported.

Once PySide6 is imported, its import hook reads the source of every later
module to look for `from __feature__`; modules already loaded skip it. The
window needs the algorithm families, the model and the frame renderer, none
of which needs Qt, so the command line loads them first (measured: about
40-50 ms less start-up). `rasterlab list` and `run` never call this.
"""
from __future__ import annotations

import gc
import importlib

from algorithms.core import registry

# The Qt-free modules the first window imports, at import or while it is
# built (their own imports follow).
# The export writers, the report and the worksheets stay deferred.
WINDOW_MODULES = (
    "app.model.session", "app.model.examples", "app.model.compare", "app.model.tools",
    "app.model.insight", "app.model.notes", "app.model.tables", "app.model.breakpoints",
    "app.model.derivation", "app.teaching.exercise", "app.model.inspector", "app.model.steptable",
    "app.render.frame", "app.render.incremental", "app.render.compose",
    "app.render.outside_view", "app.render.reasoning", "app.render.texture_frame",
    "app.render.overlays", "logging",
)


def load_before_qt() -> None:
    """Import the families (and register them) and the window's Qt-free
    modules, with automatic collection off: app/launcher.py turns it off
    before the first import, and a window started another way gets it here."""
    gc.disable()
    registry.all_specs()
    for name in WINDOW_MODULES:
        importlib.import_module(name)
