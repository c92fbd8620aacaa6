"""Where a student's code runs: one case's child process, isolated as far
as this system allows, and ended whole with its case.

Each case gets a fresh private scratch folder holding a copy of the runner
(student_child.py) and of the student's file (or, for ``check --cmd``, the
submission's folder); nothing else of RasterLab is copied. A program the
command names (node, a JVM) is shown read-only as well (student_command.py). On Linux, when bubblewrap (``bwrap``) can start a sandbox here, the
child runs inside one: the scratch folder is the only writable place and,
besides it, only the Python interpreter, its standard library (without
site-packages) and the system's shared libraries are visible, read-only;
no network, no other process, no capability, a new session; the whole
sandbox is ended with the case. Elsewhere (no bwrap, user namespaces
disabled, macOS, Windows) the fallback runs the child with an empty
environment in the scratch folder and ends its process group (its process
tree on Windows): the code is then NOT isolated from the user's files and
network, and ``isolation()`` says so. Either way the runner sets its own
limits (CPU time, memory, file size, open files, processes) before it
reads the student's code.

``isolation()`` decides once per process (per value of RASTERLAB_BWRAP) by
starting the interpreter in a sandbox. RASTERLAB_BWRAP names the bwrap
program to use; a name that is not an installed program means the fallback.

What the child writes is read as it comes and capped: the runner's answer
(stdout) at ANSWER_LIMIT, the student's own prints (stderr, where the
runner sends stdout too) at OUTPUT_LIMIT, the rest counted and dropped, so
the grader's memory stays bounded whatever the child writes.
"""
from __future__ import annotations

import functools
import json
import os
import shutil
import signal
import stat
import subprocess
import sys
import sysconfig
import tempfile
import threading
from dataclasses import dataclass
from pathlib import Path

OUTPUT_LIMIT = 1 << 20   # the student's prints kept per case
ANSWER_LIMIT = 16 << 20  # the runner's answer: 100,000 steps with a few named values
RUNNER = "rasterlab-runner.py"
INSIDE = "/case"         # the scratch folder as the sandbox sees it
SANDBOX_UID = 65534      # "nobody" inside the sandbox
PROBE_SECONDS = 20


class SandboxFailure(Exception):
    """The child could not be started or gave no sign of life: RasterLab's
    failure (or the system's), never the student's."""


@dataclass(frozen=True)
class Isolation:
    """How a case's child runs: in a bubblewrap sandbox (``command`` is its
    start, up to the scratch folder's binding) or not (``reason`` says why)."""

    sandboxed: bool
    reason: str = ""
    command: tuple = ()

    def line(self) -> str:
        """The one line a report gives on the isolation in force."""
        if self.sandboxed:
            return ("isolation: bubblewrap sandbox (no network, no files but the case's own "
                    "scratch folder and a read-only Python, an empty environment, every "
                    "process ended with its case)")
        return (f"isolation: NONE ({self.reason}): the student's code is NOT isolated from "
                "your files and network; it runs with an empty environment in a private "
                "temporary folder, its process group ended with its case")


@dataclass(frozen=True)
class Ran:
    """What one child did: its status (None: ended at the wall clock; a
    signal as its negative number), the runner's answer and the student's
    prints, each as far as kept, and how much was dropped."""

    status: int | None
    answer: bytes
    answer_dropped: int
    output: bytes
    output_dropped: int


# ---------------------------------------------------------------- deciding
def isolation() -> Isolation:
    """The isolation this system gives, tried once per RASTERLAB_BWRAP value."""
    return _isolation(os.environ.get("RASTERLAB_BWRAP", "bwrap"))


@functools.lru_cache(maxsize=None)
def _isolation(bwrap: str) -> Isolation:
    if not sys.platform.startswith("linux"):
        return Isolation(False, f"bubblewrap runs on Linux only, this is {sys.platform}")
    program = shutil.which(bwrap)
    if program is None:
        return Isolation(False, f"no bubblewrap: {bwrap!r} not found (the bubblewrap package "
                                "installs it)")
    failure = ""
    # --disable-userns (bubblewrap 0.8) keeps the sandbox from making a
    # namespace of its own; an older bwrap sandboxes without it.
    for extra in (("--disable-userns",), ()):
        command = (program, *_sandbox_options(extra), *_python_view())
        failure = _probe(command)
        if not failure:
            return Isolation(True, command=command)
    return Isolation(False, f"{program} could not start a sandbox here: {failure}")


def _sandbox_options(extra: tuple) -> tuple:
    return ("--unshare-all", "--unshare-user", *extra, "--cap-drop", "ALL",
            "--uid", str(SANDBOX_UID), "--gid", str(SANDBOX_UID),
            "--die-with-parent", "--new-session", "--dev", "/dev", "--proc", "/proc")


def _probe(command: tuple) -> str:
    """"" when ``command`` starts the interpreter in a sandbox, else why not."""
    scratch = tempfile.mkdtemp(prefix="rasterlab-probe-")
    try:
        done = subprocess.run([*command, "--bind", scratch, INSIDE, "--chdir", INSIDE,
                               interpreter(), "-I", "-S", "-c", "print('ok')"],
                              env=environment(INSIDE), capture_output=True,
                              timeout=PROBE_SECONDS)
    except (OSError, subprocess.TimeoutExpired) as error:
        return str(error)
    finally:
        remove(scratch)
    if done.returncode == 0 and done.stdout.strip() == b"ok":
        return ""
    said = done.stderr.decode("utf-8", "replace").strip().splitlines()
    return said[-1] if said else f"status {done.returncode}"


def interpreter() -> str:
    """The Python the runner runs on: the real one behind a virtual environment."""
    return os.path.realpath(getattr(sys, "_base_executable", None) or sys.executable)


def _python_view() -> tuple:
    """The read-only bindings that let the interpreter run: its executable,
    its shared library, its standard library with site-packages hidden
    (an empty tmpfs over them) and the system's shared libraries."""
    exe = interpreter()
    stdlib = {sysconfig.get_path(name, vars={"base": sys.base_prefix,
                                             "platbase": sys.base_exec_prefix,
                                             "installed_base": sys.base_prefix,
                                             "installed_platbase": sys.base_exec_prefix})
              for name in ("stdlib", "platstdlib")}
    shown = [exe, *sorted(stdlib)]
    library = sysconfig.get_config_var("INSTSONAME")
    if library and sysconfig.get_config_var("Py_ENABLE_SHARED"):
        shown.append(os.path.join(sysconfig.get_config_var("LIBDIR") or "", library))
    arch = sysconfig.get_config_var("MULTIARCH") or ""
    system = ["/lib", "/lib64", "/usr/lib64", "/lib32"]
    if arch:
        system += [f"/usr/lib/{arch}", f"/lib/{arch}"]
    args = []
    for path in system:
        if os.path.islink(path):
            args += ["--symlink", os.readlink(path), path]  # /lib -> usr/lib: the name only
        elif os.path.isdir(path):
            shown.append(path)
    bound = []
    for path in shown:
        if os.path.exists(path) and path not in bound:
            bound.append(path)
            args += ["--ro-bind", os.path.realpath(path), path]
    hidden = [os.path.join(folder, name) for folder in bound for name in
              ("site-packages", "dist-packages", "python3/dist-packages")]
    for path in hidden:
        if os.path.isdir(path):
            args += ["--tmpfs", path]
    return tuple(args)


def environment(home: str) -> dict:
    """The child's whole environment: UTF-8, a home and a temporary folder
    in its scratch folder, and what Windows needs to start Python at all."""
    env = {"LC_ALL": "C.UTF-8", "HOME": home, "TMPDIR": home, "TMP": home, "TEMP": home}
    if "SYSTEMROOT" in os.environ:
        env["SYSTEMROOT"] = os.environ["SYSTEMROOT"]
    return env


# ----------------------------------------------------------------- running
def run_case(files: dict, request: bytes, wall_seconds: float, where: Isolation,
             tree: Path | None = None, shown: tuple = ()) -> Ran:
    """Run the runner (``files[RUNNER]``) on ``request`` (its stdin) in a
    fresh scratch folder holding a copy of the folder ``tree`` (a compiled
    submission, with its files' modes) and of each of ``files`` ({name in
    the folder: path}); end it after ``wall_seconds``. ``shown`` are the
    system's paths the case also needs, shown read-only in the sandbox (a
    program such as node and its installation). Nothing of the case (no
    process, no file) is left when this returns."""
    try:
        scratch = tempfile.mkdtemp(prefix="rasterlab-case-")
    except OSError as error:
        raise SandboxFailure(f"no scratch folder for the case: {error}") from None
    try:
        if tree is not None:
            shutil.copytree(tree, scratch, symlinks=True, dirs_exist_ok=True)
        for name, path in files.items():
            shutil.copy(path, os.path.join(scratch, name))  # with its mode: a program runs
        return _run(scratch, request, wall_seconds, where, shown)
    except OSError as error:
        raise SandboxFailure(f"the case's process could not run: {error}") from None
    finally:
        remove(scratch)


def _run(scratch: str, request: bytes, wall_seconds: float, where: Isolation,
         shown: tuple = ()) -> Ran:
    python = [interpreter(), "-I", "-S", "-X", "utf8", RUNNER]
    info = None
    if where.sandboxed:
        info, info_write = os.pipe()
        extra = [word for path in shown for word in ("--ro-bind", path, path)]
        command = [*where.command, *extra, "--bind", scratch, INSIDE, "--chdir", INSIDE,
                   "--info-fd", str(info_write), *python]
        home, fds = INSIDE, (info_write,)
    else:
        command, home, fds = python, scratch, ()
    flags = subprocess.CREATE_NEW_PROCESS_GROUP if sys.platform == "win32" else 0
    try:
        child = subprocess.Popen(command, cwd=scratch, env=environment(home),
                                 stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, pass_fds=fds,
                                 start_new_session=sys.platform != "win32",
                                 creationflags=flags)
    finally:
        if info is not None:
            os.close(fds[0])
    sandbox_pid = _sandbox_pid(info) if info is not None else None
    answer, output = _Capped(child.stdout, ANSWER_LIMIT), _Capped(child.stderr, OUTPUT_LIMIT)
    try:
        _send(child, request)
        try:
            status = child.wait(timeout=wall_seconds)
        except subprocess.TimeoutExpired:
            status = None
    finally:
        _end(child, sandbox_pid)
        answer.join()
        output.join()
    if where.sandboxed and status is not None and status > 128:
        status = 128 - status  # bwrap passes on a signal's end as 128 + its number
    return Ran(status, bytes(answer.kept), answer.dropped, bytes(output.kept), output.dropped)


def _sandbox_pid(info: int) -> int | None:
    """The process id of the sandbox's first process, as bwrap reports it:
    ending it ends every process of the sandbox (it is their pid namespace's init)."""
    data = b""
    try:
        while len(data) < 65536:
            chunk = os.read(info, 4096)
            if not chunk:
                break
            data += chunk
    finally:
        os.close(info)
    try:
        return int(json.loads(data)["child-pid"])
    except (ValueError, KeyError, TypeError):
        return None


def _send(child: subprocess.Popen, request: bytes) -> None:
    try:
        child.stdin.write(request)
        child.stdin.close()
    except OSError:  # the child ended before it read its request
        pass


def _end(child: subprocess.Popen, sandbox_pid: int | None) -> None:
    """End every process of the case: the sandbox's init (the kernel then
    ends its whole pid namespace, and bwrap exits once it is gone), the
    process group, and wait for the child."""
    if sandbox_pid is not None:
        _kill(lambda: os.kill(sandbox_pid, signal.SIGKILL))
    if sys.platform == "win32":
        subprocess.run(["taskkill", "/F", "/T", "/PID", str(child.pid)],
                       capture_output=True, check=False)
    else:
        _kill(lambda: os.killpg(child.pid, signal.SIGKILL))
    child.kill()
    child.wait()


def _kill(kill) -> None:
    try:
        kill()
    except (ProcessLookupError, PermissionError):  # gone already
        pass


class _Capped(threading.Thread):
    """Reads a pipe to its end, keeping its first ``limit`` bytes and
    counting the rest."""

    def __init__(self, stream, limit: int):
        super().__init__(daemon=True)
        self.stream, self.limit = stream, limit
        self.kept, self.dropped = bytearray(), 0
        self.start()

    def run(self) -> None:
        with self.stream:
            while chunk := self.stream.read(65536):
                room = self.limit - len(self.kept)
                self.kept += chunk[:room]
                self.dropped += max(0, len(chunk) - room)

    def join(self, timeout: float | None = 5.0) -> None:
        # A process outside a sandbox may have kept the pipe open in a child
        # of its own that left the process group; its output is not awaited.
        super().join(timeout)


def remove(folder: str) -> None:
    """Remove a scratch folder, also what the student's code made unreadable."""
    def writable(function, path, _):
        try:
            os.chmod(os.path.dirname(path), stat.S_IRWXU)
            os.chmod(path, stat.S_IRWXU)
            function(path)
        except OSError:
            pass
    if sys.version_info >= (3, 12):
        shutil.rmtree(folder, onexc=writable)
    else:
        shutil.rmtree(folder, onerror=writable)
