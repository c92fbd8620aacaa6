"""Whether the process that left a temporary file or folder still runs.

A writer names its temporaries with its process id (``owner_pid`` reads it
back), so the next writer removes only what a process that is gone left.
"""
from __future__ import annotations

import ctypes
import os
import re
import sys


def process_alive(pid: int) -> bool:
    """Whether a process with this id runs (ours counts as alive)."""
    if pid == os.getpid():
        return True
    if sys.platform == "win32":
        # os.kill(pid, 0) is no probe there: signal 0 is CTRL_C_EVENT.
        return _windows_process_alive(pid)
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return True
    return True


QUERY_LIMITED_INFORMATION = 0x1000  # the least access that reads an exit code
ACCESS_DENIED = 5
STILL_ACTIVE = 259


def _windows_process_alive(pid: int, kernel32=None, last_error=None) -> bool:
    """Whether a process runs, asked of Windows: a process we may not open
    exists; one we may open runs until it has an exit code. ``kernel32`` and
    ``last_error`` stand in for ctypes' in tests."""
    if kernel32 is None:
        kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
        last_error = ctypes.get_last_error
    if not 0 < pid < 2 ** 32:
        return False
    handle = kernel32.OpenProcess(QUERY_LIMITED_INFORMATION, False, pid)
    if not handle:
        return last_error() == ACCESS_DENIED
    try:
        code = ctypes.c_ulong()
        if not kernel32.GetExitCodeProcess(handle, ctypes.byref(code)):
            return True  # it could be opened, so it exists
        return code.value == STILL_ACTIVE
    finally:
        kernel32.CloseHandle(handle)


def owner_pid(name: str, prefix: str) -> int | None:
    """The process id in a leftover's name ``<prefix><pid>-...``; None for
    a name without one (written before names carried it: its writer is
    long gone)."""
    match = re.match(re.escape(prefix) + r"(\d+)[-.]", name)
    return int(match.group(1)) if match else None
