"""The model's file and process calls on the systems this machine is not.

Each test fakes the one platform difference it is about: what the faked
function does is what that system's Python documents. What it cannot prove
is said where it matters: the real Windows calls run only on Windows.
"""
from __future__ import annotations

import ctypes
import os
import sys
import stat

import pytest

from app.model import files, processes


def test_an_atomic_write_needs_no_chmod_of_a_descriptor(tmp_path, monkeypatch):
    # Windows Pythons before 3.13 take only a path: os.chmod(fd, mode) is a TypeError.
    real_chmod = os.chmod
    calls = []

    def path_only(target, mode, *args, **kwargs):
        if isinstance(target, int):
            raise TypeError("chmod: path should be string, bytes or os.PathLike, not int")
        calls.append(mode)
        return real_chmod(target, mode, *args, **kwargs)

    monkeypatch.setattr(files.os, "chmod", path_only)
    target = tmp_path / "scene.json"
    target.write_bytes(b"old")
    real_chmod(target, 0o640)
    files.write_atomically(target, b"new")
    assert target.read_bytes() == b"new"
    assert stat.S_IMODE(os.stat(target).st_mode) == 0o640  # the old file's mode is kept
    assert calls == [0o640]
    assert [p.name for p in tmp_path.iterdir()] == ["scene.json"]  # no temporary left


class FakeKernel32:
    """OpenProcess, GetExitCodeProcess and CloseHandle as Windows answers them."""

    def __init__(self, handle: int, exit_code: int = processes.STILL_ACTIVE, readable=True):
        self.handle, self.exit_code, self.readable = handle, exit_code, readable
        self.opened, self.closed = [], []

    def OpenProcess(self, access, inherit, pid):  # noqa: N802 - the Windows name
        self.opened.append((access, inherit, pid))
        return self.handle

    def GetExitCodeProcess(self, handle, code):  # noqa: N802
        code._obj.value = self.exit_code
        return self.readable

    def CloseHandle(self, handle):  # noqa: N802
        self.closed.append(handle)
        return 1


@pytest.mark.parametrize("kernel32, error, alive", [
    (FakeKernel32(7), 0, True),                                    # running
    (FakeKernel32(7, exit_code=0), 0, False),                      # exited with code 0
    (FakeKernel32(7, readable=False), 0, True),                    # opened, so it exists
    (FakeKernel32(0), processes.ACCESS_DENIED, True),                # another user's process
    (FakeKernel32(0), 87, False),                                  # ERROR_INVALID_PARAMETER: none
])
def test_windows_liveness_reads_the_exit_code(kernel32, error, alive):
    assert processes._windows_process_alive(4242, kernel32, lambda: error) is alive
    assert kernel32.opened == [(processes.QUERY_LIMITED_INFORMATION, False, 4242)]
    assert kernel32.closed == ([kernel32.handle] if kernel32.handle else [])


def test_on_windows_no_signal_is_sent_to_probe_a_process(monkeypatch):
    # Signal 0 is CTRL_C_EVENT on Windows: os.kill would interrupt the process.
    monkeypatch.setattr(processes.sys, "platform", "win32")
    monkeypatch.setattr(processes.os, "kill", lambda *args: pytest.fail("os.kill was called"))
    asked = []
    monkeypatch.setattr(processes, "_windows_process_alive", lambda pid: asked.append(pid) or False)
    assert processes.process_alive(os.getpid()) is True  # ours, without asking
    assert processes.process_alive(4242) is False
    assert asked == [4242]


def test_elsewhere_a_process_that_ended_is_not_alive():
    import subprocess
    import sys
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    assert processes.process_alive(child.pid) is False
    assert processes.process_alive(os.getpid()) is True


def test_the_fake_exit_code_is_written_as_ctypes_would():
    # The fake writes through byref as the real call does; a check of the stand-in itself.
    code = ctypes.c_ulong()
    FakeKernel32(1, exit_code=259).GetExitCodeProcess(1, ctypes.byref(code))
    assert code.value == 259


def test_a_write_removes_what_a_killed_write_left_and_nothing_else(tmp_path):
    import subprocess
    child = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                           capture_output=True, text=True, check=True)
    gone = int(child.stdout)  # a process that has ended
    target = tmp_path / "scene.json"
    dead = tmp_path / f".scene.json.{gone}.abcd1234.tmp"
    older = tmp_path / ".scene.json.abcd1234.tmp"          # from before names held a pid
    running = tmp_path / f".scene.json.{os.getpid()}.abcd1234.tmp"  # a write still going
    other = tmp_path / f".notes.json.{gone}.abcd1234.tmp"   # another file's
    for path in (dead, older, running, other):
        path.write_text("half")
    files.write_atomically(target, b"{}")
    assert target.read_bytes() == b"{}"
    assert not dead.exists() and not older.exists()
    assert running.exists() and other.exists()
