"""The system's reduce-motion setting, each system's way, and each way of
failing to read it (motion stays on)."""
import ctypes
import subprocess
from types import SimpleNamespace

import pytest

from app.model.system_motion import (GNOME, MACOS, SPI_GETCLIENTAREAANIMATION,
                                     reduce_motion)


def answering(stdout, returncode=0, expect=None):
    def run(command, **kwargs):
        if expect is not None:
            assert command == expect
        assert kwargs["timeout"] > 0  # never waits for ever
        return SimpleNamespace(returncode=returncode, stdout=stdout)
    return run


def raising(error):
    def run(command, **kwargs):
        raise error
    return run


@pytest.mark.parametrize("stdout, reduced", [("false\n", True), ("true\n", False)])
def test_gnome_animations_off_means_reduce(stdout, reduced):
    assert reduce_motion("linux", answering(stdout, expect=GNOME)) is reduced


@pytest.mark.parametrize("stdout, reduced", [("1\n", True), ("0\n", False)])
def test_macos_reduce_motion(stdout, reduced):
    assert reduce_motion("darwin", answering(stdout, expect=MACOS)) is reduced


@pytest.mark.parametrize("platform", ["linux", "darwin"])
@pytest.mark.parametrize("run", [
    raising(FileNotFoundError("no gsettings")),
    raising(subprocess.TimeoutExpired("gsettings", 1.0)),
    raising(PermissionError("not allowed")),
    answering("", returncode=1),  # no such schema: another desktop
    answering("No such key \u201creduceMotion\u201d\n", returncode=1),
    answering("maybe\n"),
    answering(None),
], ids=["missing", "timeout", "denied", "failed", "no-key", "unknown", "no-output"])
def test_a_failed_read_leaves_motion_on(platform, run):
    assert reduce_motion(platform, run) is False


class User32:
    """SystemParametersInfoW as Windows answers it."""

    def __init__(self, animations: bool, ok: bool = True):
        self.animations, self.ok, self.asked = animations, ok, None

    def SystemParametersInfoW(self, action, param, pointer, flags):  # noqa: N802
        self.asked = action
        ctypes.cast(pointer, ctypes.POINTER(ctypes.c_int))[0] = int(self.animations)
        return int(self.ok)


def test_windows_client_area_animation_off_means_reduce():
    user32 = User32(animations=False)
    assert reduce_motion("win32", user32=user32) is True
    assert user32.asked == SPI_GETCLIENTAREAANIMATION
    assert reduce_motion("win32", user32=User32(animations=True)) is False


def test_windows_failures_leave_motion_on():
    assert reduce_motion("win32", user32=User32(animations=False, ok=False)) is False

    class Broken:
        def SystemParametersInfoW(self, *args):  # noqa: N802
            raise OSError("access denied")
    assert reduce_motion("win32", user32=Broken()) is False
    assert reduce_motion("win32", user32=object()) is False  # no such function


def test_windows_without_windll_leaves_motion_on(monkeypatch):
    monkeypatch.delattr(ctypes, "windll", raising=False)  # as on Linux and macOS
    assert reduce_motion("win32") is False


def test_other_systems_are_not_asked():
    assert reduce_motion("freebsd13", raising(AssertionError("asked"))) is False
