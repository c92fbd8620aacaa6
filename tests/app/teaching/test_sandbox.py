"""`rasterlab check` against hostile submissions: each attack is contained by
the sandbox, fails its case (exit 1, never 3), leaves valid JSON and JUnit
XML and nothing behind; the fallback says it is not isolated, and
--require-sandbox refuses to run without a sandbox (exit 2)."""
from __future__ import annotations

import ast
import json
import os
import secrets
import socket
import subprocess
import sys
import tempfile
import textwrap
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from app.teaching import sandbox, student
from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
SANDBOXED = sandbox.isolation().sandboxed
needs_sandbox = pytest.mark.skipif(not SANDBOXED, reason="bubblewrap cannot start a sandbox "
                                   f"here: {sandbox.isolation().reason}")
MISSING_BWRAP = "/nonexistent/bwrap"


@pytest.fixture
def scratch_root(tmp_path, monkeypatch):
    """The folder the cases' scratch folders are made in; empty after each check."""
    root = tmp_path / "temporary"
    root.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(root))
    return root


def hostile(run_cli, tmp_path, body: str, *options) -> tuple[dict, str]:
    """Check a submission whose draw() runs ``body`` (its last line raises,
    so the case fails): the case's JSON record and stderr, once the exit
    status, the JSON, the JUnit XML and the scratch folders are checked."""
    path = tmp_path / "hostile.py"
    path.write_text("def draw(x0, y0, x1, y1):\n" + textwrap.indent(textwrap.dedent(body), "    ")
                    + "    yield x0, y0\n", encoding="utf-8")
    junit = tmp_path / "report.xml"
    status, out, err = run_cli("check", path, "--against", "line-bresenham", "--cases",
                               "random", "1", "--json", "--junit", junit, *options)
    assert status == 1, err
    report = json.loads(out)
    assert report["isolation"].startswith("isolation: bubblewrap sandbox")
    suite = ET.parse(junit).getroot()
    assert suite.attrib["tests"] == "1"
    assert os.listdir(tempfile.tempdir) == []  # no scratch folder left
    (case,) = report["cases"]
    assert not case["passed"]
    return case, err


def alive(marker: str) -> list[int]:
    """The processes whose command line holds ``marker``."""
    found = []
    for entry in Path("/proc").iterdir():
        try:
            if entry.name.isdigit() and marker.encode() in (entry / "cmdline").read_bytes():
                found.append(int(entry.name))
        except OSError:  # ended meanwhile
            pass
    return found


@needs_sandbox
def test_files_of_the_home_and_outside_the_scratch_folder_cannot_be_read(
        run_cli, tmp_path, scratch_root, monkeypatch):
    token = secrets.token_hex(8)
    home = tmp_path / "home"
    home.mkdir()
    (home / ".bashrc").write_text(f"export SECRET={token}\n")
    monkeypatch.setenv("HOME", str(home))
    outside = Path(tempfile.gettempdir()).parent / "outside.txt"  # in tmp_path, under /tmp
    outside.write_text(token)
    case, _ = hostile(run_cli, tmp_path, f"""
        import os
        for name in ({str(home / '.bashrc')!r}, {str(outside)!r}, os.path.expanduser("~/.bashrc")):
            try:
                print("ESCAPED", open(name).read())
            except OSError as error:
                print("refused:", error)
        print(sorted(os.listdir("/")))
        raise ValueError("contained")
    """)
    assert case["message"] == "ValueError: contained"
    assert token not in json.dumps(case) and "ESCAPED" not in case["output"]
    assert "refused: [Errno 2]" in case["output"]


@needs_sandbox
def test_nothing_outside_the_scratch_folder_can_be_written(run_cli, tmp_path, scratch_root):
    targets = [tmp_path / "written.txt", Path("/tmp") / f"rasterlab-{secrets.token_hex(8)}",
               ROOT / f"written-{secrets.token_hex(4)}.txt"]
    case, _ = hostile(run_cli, tmp_path, f"""
        import os
        open("mine.txt", "w").write("the scratch folder is writable")
        for name in {[str(target) for target in targets]!r} + [os.path.abspath(__file__)]:
            try:
                open(name, "a").write("x")
                print("ESCAPED", name) if not name.endswith(__file__) else None
            except OSError as error:
                print("refused:", error)
        raise ValueError("contained")
    """)
    assert case["message"] == "ValueError: contained" and "ESCAPED" not in case["output"]
    assert not any(target.exists() for target in targets)
    assert (tmp_path / "hostile.py").read_text().count("contained") == 1  # its own file untouched


@needs_sandbox
def test_the_graders_environment_is_not_visible(run_cli, tmp_path, scratch_root, monkeypatch):
    token = secrets.token_hex(8)
    monkeypatch.setenv("RASTERLAB_TEST_SECRET", token)
    case, _ = hostile(run_cli, tmp_path, """
        import os
        print(sorted(os.environ))
        for pid in range(1, 5):
            try:
                print(open(f"/proc/{pid}/environ", "rb").read())
            except OSError:
                pass
        raise ValueError("contained")
    """)
    assert token not in json.dumps(case)
    names = ast.literal_eval(case["output"].splitlines()[0])  # the list the child printed
    assert set(names) <= {"LC_ALL", "HOME", "TMPDIR", "TMP", "TEMP", "PWD"}


@needs_sandbox
def test_no_socket_reaches_a_listener_of_the_grader(run_cli, tmp_path, scratch_root):
    with socket.create_server(("127.0.0.1", 0)) as listener:
        listener.setblocking(False)
        port = listener.getsockname()[1]
        case, _ = hostile(run_cli, tmp_path, f"""
            import socket
            try:
                socket.create_connection(("127.0.0.1", {port}), timeout=1)
                print("ESCAPED")
            except OSError as error:
                print("refused:", error)
            raise ValueError("contained")
        """)
        with pytest.raises(BlockingIOError):
            listener.accept()  # nobody connected
    assert "ESCAPED" not in case["output"] and "refused" in case["output"]


SLEEPER = "import time; time.sleep(100000)"


@needs_sandbox
def test_fifty_processes_end_with_their_case(run_cli, tmp_path, scratch_root):
    marker = f"rasterlab-test-{secrets.token_hex(8)}"
    case, _ = hostile(run_cli, tmp_path, f"""
        import subprocess, sys
        started = 0
        for _ in range(50):
            try:
                subprocess.Popen([sys.executable, "-c", {SLEEPER!r}, {marker!r}])
                started += 1
            except OSError as error:
                print("refused:", error)
        raise ValueError(f"started {{started}}")
    """)
    assert case["message"].startswith("ValueError: started")
    assert alive(marker) == []


@needs_sandbox
def test_a_detached_child_does_not_outlive_its_case(run_cli, tmp_path, scratch_root):
    marker = f"rasterlab-test-{secrets.token_hex(8)}"
    case, _ = hostile(run_cli, tmp_path, f"""
        import os, sys
        if os.fork() == 0:
            os.setsid()
            if os.fork() == 0:
                os.execv(sys.executable, [sys.executable, "-c", {SLEEPER!r}, {marker!r}])
            os._exit(0)
        os.wait()
        raise ValueError("contained")
    """)
    assert case["message"] == "ValueError: contained"
    assert alive(marker) == []


@needs_sandbox
def test_rasterlab_is_out_of_reach(run_cli, tmp_path, scratch_root):
    case, _ = hostile(run_cli, tmp_path, f"""
        import os, shutil, subprocess, sys
        reached = []
        for name in ("app", "algorithms", "rasterlab", "numpy"):
            try:
                __import__(name)
                reached.append(name)
            except ImportError:
                pass
        for path in ({str(ROOT)!r}, {sys.executable!r}, {str(student.CHILD)!r}):
            if os.path.exists(path):
                reached.append(path)
        if shutil.which("rasterlab"):
            reached.append(shutil.which("rasterlab"))
        try:
            subprocess.run(["rasterlab", "run", "--help"], check=True)
            reached.append("the rasterlab command")
        except OSError:
            pass
        raise ValueError(f"reached {{reached}}")
    """)
    assert case["message"] == "ValueError: reached []"


@needs_sandbox
def test_endless_output_is_capped_and_the_graders_memory_stays_bounded(tmp_path):
    """The grader's peak memory (its rusage as a fresh process's child) with
    a submission that prints 100 MB is that with one that prints nothing."""
    quiet = tmp_path / "quiet.py"
    quiet.write_text("def draw(x0, y0, x1, y1):\n    raise ValueError('quiet')\n    yield 0, 0\n")
    loud = tmp_path / "loud.py"
    loud.write_text("def draw(x0, y0, x1, y1):\n    line = 'x' * 1023 + '\\n'\n"
                    "    for _ in range(100 * 1024):\n        print(line, end='')\n"
                    "    raise ValueError('loud')\n    yield 0, 0\n")
    peaks, reports = [], []
    for path in (quiet, loud):
        measure = ("import resource, subprocess, sys\n"
                   "done = subprocess.run(sys.argv[1:], capture_output=True)\n"
                   "print(done.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
                   "sys.stdout.write(done.stdout.decode())")
        done = subprocess.run([sys.executable, "-c", measure, sys.executable, "-m", "rasterlab",
                               "check", str(path), "--against", "line-bresenham", "--cases",
                               "random", "1", "--json"], cwd=ROOT, capture_output=True,
                              text=True, timeout=120)
        first, _, rest = done.stdout.partition("\n")
        status, peak = map(int, first.split())
        assert status == 1, done.stderr
        peaks.append(peak)  # KiB on Linux
        reports.append(json.loads(rest))
    output = reports[1]["cases"][0]["output"]
    assert output.startswith("x" * 1023) and len(output) < (1 << 20) + 200
    assert f"{100 * 1024 * 1024 - (1 << 20):,} more bytes of output not kept" in output
    print("grader peak RSS (KiB), quiet and 100 MB of prints:", peaks)
    assert peaks[1] < peaks[0] + 20 * 1024, peaks


@needs_sandbox
def test_a_forged_or_endless_answer_is_refused(run_cli, tmp_path, scratch_root):
    case, _ = hostile(run_cli, tmp_path, """
        import os
        junk = b"[" * (1 << 20)
        for fd in range(3, 10):
            try:
                for _ in range(20):
                    os.write(fd, junk)
            except OSError:
                pass
        raise ValueError("unreached when the answer channel was found")
    """)
    assert case["outcome"] == "crash"  # the runner's channel is among those fds
    assert case["error"] == "the process ended with status 0 and an answer over 16 MiB"


@needs_sandbox
def test_control_characters_and_lone_surrogates_come_out_safe(run_cli, tmp_path, scratch_root):
    body = """
        print("bell\\x07 escape\\x1b[2J nul\\x00 csi\\x9b end")
        raise ValueError("bad \\x01\\x1b]0;title\\x07 \\ud800 \\udcff end")
    """
    case, _ = hostile(run_cli, tmp_path, body)
    text = json.dumps(case, ensure_ascii=False)
    assert not any(char in text for char in "\x00\x01\x07\x1b\x9b\ud800\udcff")
    assert case["message"].startswith("ValueError: bad \ufffd\ufffd]0;title\ufffd")
    junit = (tmp_path / "report.xml").read_bytes()
    ET.fromstring(junit)  # well-formed
    assert b"\x1b" not in junit and b"&#" not in junit
    status, out, _ = run_cli("check", tmp_path / "hostile.py", "--against", "line-bresenham",
                             "--cases", "random", "1")
    assert status == 1
    assert not any(char in out for char in "\x00\x01\x07\x1b\x9b\ud800\udcff")
    assert "      | bell\ufffd escape\ufffd[2J" in out  # the print, shown with its case
    out.encode("utf-8")


@needs_sandbox
def test_sleeping_for_ever_ends_at_the_wall_clock(run_cli, tmp_path, scratch_root):
    case, _ = hostile(run_cli, tmp_path, "import time\ntime.sleep(10 ** 6)\n",
                      "--time-limit", "0.5")
    assert case["outcome"] == "time" and "no result within 0.5 s" in case["error"]


@needs_sandbox
def test_twenty_gigabytes_are_refused(run_cli, tmp_path, scratch_root):
    case, _ = hostile(run_cli, tmp_path, "block = bytearray(20 << 30)\n")
    assert case["outcome"] == "memory"


# -------------------------------------------------------------- the fallback
def test_without_bubblewrap_the_report_says_the_code_is_not_isolated(
        run_cli, monkeypatch, scratch_root):
    monkeypatch.setenv("RASTERLAB_BWRAP", MISSING_BWRAP)
    status, out, err = run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                               "line-bresenham", "--cases", "random", "2")
    assert status == 0, err
    assert err.count("NOT isolated") == 1
    assert err.startswith("rasterlab: warning: the student's code is NOT isolated from your "
                          f"files and network (no bubblewrap: {MISSING_BWRAP!r} not found")
    isolation = [line for line in out.splitlines() if line.startswith("isolation:")]
    assert len(isolation) == 1 and isolation[0].startswith("isolation: NONE (")
    assert "NOT isolated from your files and network" in isolation[0]
    assert os.listdir(scratch_root) == []


def test_require_sandbox_refuses_to_run_without_one(run_cli, monkeypatch, scratch_root):
    monkeypatch.setenv("RASTERLAB_BWRAP", MISSING_BWRAP)
    status, out, err = run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                               "line-bresenham", "--require-sandbox")
    assert (status, out) == (2, "")
    assert err.startswith("rasterlab: --require-sandbox: no sandbox on this system (")
    assert len(err.splitlines()) == 1


@needs_sandbox
def test_require_sandbox_runs_where_there_is_one(run_cli):
    status, out, err = run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                               "line-bresenham", "--cases", "random", "1", "--require-sandbox")
    assert status == 0 and err == "", err
    assert "isolation: bubblewrap sandbox" in out


def test_a_runner_that_never_starts_is_rasterlabs_failure_exit_3(run_cli, tmp_path, monkeypatch):
    broken = tmp_path / "runner.py"
    broken.write_text("raise SystemExit(1)\n")
    monkeypatch.setattr(student, "CHILD", broken)
    status, out, err = run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                               "line-bresenham", "--cases", "random", "1")
    assert (status, out) == (3, "")
    assert "check failed in RasterLab itself, not in the student's code" in err
