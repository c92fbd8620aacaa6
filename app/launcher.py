"""The `rasterlab` command: the window when no command is given, the
command line (app/cli.py) otherwise."""
from __future__ import annotations

import gc
import sys


def main() -> int:
    if len(sys.argv) < 2:
        before_window()  # before the first import: most of start-up is imports
    from app.cli import main as command_line
    return command_line()


def before_window() -> None:
    """Automatic collection off for the window's start-up.

    The window hands collection to a timer in its main thread anyway
    (app/gui/main_thread_gc.py); off from the start, start-up does not walk
    the growing heap of modules, classes and Qt wrappers it is building
    again and again (measured: about 160 collections, 30-50 ms)."""
    gc.disable()
