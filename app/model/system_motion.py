"""Whether the person asked their system for less motion on screen: the
default of Preferences > Reduce motion.

Qt exposes no such setting, so each system is asked its own way:

* Linux (GNOME and the desktops that share its settings):
  ``gsettings get org.gnome.desktop.interface enable-animations`` says false;
* Windows: ``SystemParametersInfo(SPI_GETCLIENTAREAANIMATION)`` says the
  animations inside windows are off (Settings > Accessibility > Visual
  effects > Animation effects);
* macOS: ``defaults read com.apple.universalaccess reduceMotion`` says 1.

Any failure to ask (no such program, a timeout, another desktop, an answer
not understood) counts as "not asked for": motion stays on, nothing raises.
"""
from __future__ import annotations

import subprocess
import sys

TIMEOUT_S = 1.0  # a settings daemon that does not answer must not hold up the start
SPI_GETCLIENTAREAANIMATION = 0x1042
GNOME = ["gsettings", "get", "org.gnome.desktop.interface", "enable-animations"]
MACOS = ["defaults", "read", "com.apple.universalaccess", "reduceMotion"]


def reduce_motion(platform: str | None = None, run=subprocess.run, user32=None) -> bool:
    """True when the system asks for reduced motion; False when it does not
    or cannot be asked. ``run`` and ``user32`` stand in for the system in tests."""
    platform = platform or sys.platform
    if platform.startswith("linux"):
        return _answer(run, GNOME) == "false"
    if platform == "darwin":
        return _answer(run, MACOS) == "1"
    if platform == "win32":
        return _windows_animations_off(user32)
    return False


def _answer(run, command: list[str]) -> str | None:
    """The command's one-line answer, or None when it failed in any way."""
    try:
        done = run(command, capture_output=True, text=True, timeout=TIMEOUT_S, check=False)
    except (OSError, subprocess.SubprocessError, ValueError):
        return None
    if done.returncode != 0 or not isinstance(done.stdout, str):
        return None
    return done.stdout.strip().lower()


def _windows_animations_off(user32=None) -> bool:
    try:
        import ctypes
        if user32 is None:
            user32 = ctypes.windll.user32  # only on Windows
        enabled = ctypes.c_int(1)  # a Win32 BOOL
        ok = user32.SystemParametersInfoW(SPI_GETCLIENTAREAANIMATION, 0, ctypes.byref(enabled), 0)
    except (AttributeError, ImportError, OSError, TypeError, ValueError):
        return False
    return bool(ok) and not enabled.value
