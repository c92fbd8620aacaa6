"""Every writer killed with SIGKILL part way leaves, at each final name, the
previous complete file, a complete new one, or nothing; and the next run of
the same command succeeds and leaves no staging behind.

Each writer runs as a child process (``python -m rasterlab ...`` or, for a
scene save, ``python -c``), once whole to leave a previous version and to
measure when its first temporary file appears and when it ends; then it is
killed at three moments: as soon as a temporary file shows, and halfway and
nine tenths of the way from there to the end (as the last run measured
them; a quick writer may end first, which is counted as such). After each kill the folder is
checked, and the command is run again and must succeed and clean up.

The GIF and PNG-frames exports are killed in render/test_export_safety.py,
autosave in gui/test_kill_recovery.py; they are not repeated here.
"""
import csv
import io
import json
import os
import re
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree
from collections import Counter
from pathlib import Path

import pytest
from PIL import Image

from tests.support import ROOT

STUDENT = ROOT / "resources" / "students" / "bresenham_correct.py"
START_TIMEOUT = 180  # seconds; a child on a busy machine
POINTS = {"first temporary": 0.0, "halfway": 0.5, "late": 0.9}

# A scene near the size limit: saving it takes long enough to be killed.
SAVE_BIG_SCENE = """
import sys
from app.model.scene import Scene, save
marks = [{"name": f"mark {k} " + "x" * 20, "step": k} for k in range(120_000)]
save(Scene(title="big", bookmarks=marks), sys.argv[1])
"""

# writer: (command after the interpreter, outputs; a name ending in "/" is a folder)
WRITERS = {
    "worksheet pdf": (["-m", "rasterlab", "worksheet", "demo-bresenham", "--out", "ws",
                       "--format", "pdf"], ["ws/"]),
    "worksheet csv": (["-m", "rasterlab", "worksheet", "demo-bresenham", "--out", "ws",
                       "--format", "csv"], ["ws/"]),
    "worksheet md": (["-m", "rasterlab", "worksheet", "demo-bresenham", "--out", "ws",
                      "--format", "md"], ["ws/"]),
    "check --junit": (["-m", "rasterlab", "check", str(STUDENT), "--against", "line-bresenham",
                       "--junit", "grades.xml"], ["grades.xml"]),
    "run --save": (["-m", "rasterlab", "run", "--scene", "demo-bresenham", "--save", "s.json",
                    "--force"], ["s.json"]),
    "scene save": (["-c", SAVE_BIG_SCENE, "big.json"], ["big.json"]),
    "export --html": (["-m", "rasterlab", "export", "demo-bresenham", "--html", "a.html"],
                      ["a.html"]),
    "export --pdf": (["-m", "rasterlab", "export", "demo-bresenham", "--pdf", "a.pdf"],
                     ["a.pdf"]),
    "export --svg-dir": (["-m", "rasterlab", "export", "demo-bresenham", "--svg-dir", "svg"],
                         ["svg/"]),
    "export --mp4": (["-m", "rasterlab", "export", "demo-bresenham", "--mp4", "a.mp4"],
                     ["a.mp4"]),
    "export --webm": (["-m", "rasterlab", "export", "demo-bresenham", "--webm", "a.webm"],
                      ["a.webm"]),
    "export --beamer": (["-m", "rasterlab", "export", "demo-bresenham", "--pdf", "a.pdf",
                         "--beamer", "a.tex"], ["a.pdf", "a.tex"]),
}
SLOW_WRITERS = {
    "report --quick": (["-m", "rasterlab", "report", "--quick", "--out", "rep"], ["rep/"]),
}


OUTCOMES = []  # (writer, kill point, outcome), printed when the module ends


# ------------------------------------------------------------ the folder
def is_leftover(name: str) -> bool:
    """A temporary file or a staging folder (``.rasterlab-<kind>-<pid>-...``)."""
    return name.endswith(".tmp") or re.match(r"\.rasterlab-[a-z]+-\d+-", name) is not None


def watched(work: Path, outputs) -> list[Path]:
    return [work] + [work / name for name in outputs if name.endswith("/")]


def leftovers(work: Path, outputs) -> list[str]:
    return sorted(entry.name for folder in watched(work, outputs) if folder.is_dir()
                  for entry in os.scandir(folder) if is_leftover(entry.name))


def final_files(work: Path, outputs) -> dict[str, bytes]:
    """What sits at the outputs' final names, by name, leftovers aside."""
    found = {}
    for name in outputs:
        path = work / name
        if name.endswith("/"):
            if path.is_dir():
                found.update({f"{name}{p.name}": p.read_bytes() for p in path.iterdir()
                              if not is_leftover(p.name)})
        elif path.exists():
            found[name] = path.read_bytes()
    return found


# ------------------------------------------------------------ validity
def ebml_number(data: bytes, at: int, keep_marker: bool) -> tuple[int, int]:
    """An EBML variable-length number at ``at``: (value, where it ends). The
    count of leading zero bits of the first byte gives the length; an
    element ID keeps its marker bit, a size drops it."""
    first = data[at]
    assert first, "an EBML number longer than 8 bytes"
    length = 9 - first.bit_length()
    assert at + length <= len(data), "an EBML number cut short"
    value = first if keep_marker else first & (0xFF >> length)
    for byte in data[at + 1:at + length]:
        value = value << 8 | byte
    return value, at + length


def webm_elements(data: bytes) -> list[int]:
    """The top-level EBML element IDs; each declared size must fit, and the
    sizes must add up to the file's (a finished WebM's Segment has its
    size written in; one cut short does not)."""
    ids, at = [], 0
    while at < len(data):
        element, at = ebml_number(data, at, keep_marker=True)
        size, at = ebml_number(data, at, keep_marker=False)
        assert at + size <= len(data), "an element cut short"
        ids.append(element)
        at += size
    return ids


def mp4_boxes(data: bytes) -> list[bytes]:
    """The top-level box types; the sizes must add up to the file's."""
    kinds, at = [], 0
    while at < len(data):
        assert at + 8 <= len(data), "a box header cut short"
        size = int.from_bytes(data[at:at + 4], "big")
        if size == 1:
            size = int.from_bytes(data[at + 8:at + 16], "big")
        assert size >= 8 and at + size <= len(data), "a box cut short"
        kinds.append(data[at + 4:at + 8])
        at += size
    return kinds


def check_complete(name: str, data: bytes) -> None:
    """Fails unless ``data`` is a whole file of the kind its name says."""
    suffix = Path(name).suffix
    assert data, f"{name}: empty"
    if suffix == ".json":
        json.loads(data)
    elif suffix == ".pdf":
        assert data.startswith(b"%PDF-") and data.rstrip().endswith(b"%%EOF"), name
    elif suffix in (".xml", ".svg"):
        ElementTree.fromstring(data)
    elif suffix == ".csv":
        rows = list(csv.reader(io.StringIO(data.decode("utf-8"))))
        assert len(rows) > 1 and len({len(row) for row in rows}) == 1, name
    elif suffix in (".md", ".tex"):
        text = data.decode("utf-8")
        assert text.endswith("\n"), name
        assert text.count("\\begin{") == text.count("\\end{"), name
    elif suffix == ".html":
        assert data.decode("utf-8").rstrip().endswith("</html>"), name
    elif suffix == ".png":
        Image.open(io.BytesIO(data)).verify()
    elif suffix == ".webm":
        assert webm_elements(data) == [0x1A45DFA3, 0x18538067], name  # EBML header, Segment
    elif suffix == ".mp4":
        kinds = mp4_boxes(data)
        assert kinds[0] == b"ftyp" and b"moov" in kinds and b"mdat" in kinds, (name, kinds)
    else:
        raise AssertionError(f"{name}: no check for this kind of file")


# ------------------------------------------------------------ the child
def start(work: Path, command) -> subprocess.Popen:
    env = dict(os.environ, PYTHONPATH=str(ROOT), QT_QPA_PLATFORM="offscreen")
    with open(work.parent / "stderr", "wb") as errors:  # the child keeps its own copy
        return subprocess.Popen([sys.executable, *command], cwd=work, env=env,
                                stdout=subprocess.DEVNULL, stderr=errors)


def hard_kill(child: subprocess.Popen) -> None:
    if hasattr(signal, "SIGKILL"):
        os.kill(child.pid, signal.SIGKILL)
    else:  # Windows: TerminateProcess, as abrupt
        child.kill()


def finish(child: subprocess.Popen) -> int:
    try:
        return child.wait(timeout=START_TIMEOUT)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()


def whole_run(work: Path, command, outputs) -> tuple[float, float]:
    """Run to the end; (seconds until a temporary file showed, seconds in all)."""
    began = time.monotonic()
    child = start(work, command)
    first = None
    while child.poll() is None:
        if first is None and leftovers(work, outputs):
            first = time.monotonic() - began
        time.sleep(0.002)
    took = time.monotonic() - began
    assert finish(child) == 0, (work.parent / "stderr").read_text(errors="replace")[-2000:]
    return (took / 2 if first is None else first), took


def killed_run(work: Path, command, outputs, first: float, took: float, share: float,
               known: set) -> bool:
    """Start the command and kill it ``share`` of the way from its first
    temporary file (one not in ``known``) to its end, as the last run
    measured them; False when it ended before the kill."""
    began = time.monotonic()
    child = start(work, command)
    deadline = began + first + share * (took - first)
    while child.poll() is None:
        now = time.monotonic()
        seen = share == 0 and set(leftovers(work, outputs)) - known
        if seen or (share > 0 and now >= deadline):
            hard_kill(child)
            break
        assert now < began + START_TIMEOUT, "the child never got going"
        time.sleep(0.002)
    return finish(child) != 0


def describe(before: dict, after: dict) -> str:
    """How the files at the final names compare with the previous run's."""
    if not after:
        return "nothing at the final names"
    kept = sum(after[name] == data for name, data in before.items())
    if kept == len(before):
        return "previous files unchanged"
    return "new files, whole" if kept == 0 else "previous and new files, each whole"


# ------------------------------------------------------------ the tests
def kill_writer(tmp_path, writer, command, outputs) -> list[str]:
    """Kill ``writer`` at each point, check what it left and that the next
    run succeeds with whole files; the leftovers the next runs kept."""
    work = tmp_path / "work"
    work.mkdir()
    first, took = whole_run(work, command, outputs)
    kept = []
    for point, share in POINTS.items():
        before = final_files(work, outputs)
        assert before
        known = set(leftovers(work, outputs))
        if not killed_run(work, command, outputs, first, took, share, known):
            OUTCOMES.append((writer, point, "ended before the kill"))
        else:
            after = final_files(work, outputs)
            # No previous file is lost and nothing else appears at a final name.
            assert not after or set(after) == set(before), sorted(set(after) ^ set(before))
            for name, data in after.items():
                if data != before[name]:
                    check_complete(name, data)
            debris = set(leftovers(work, outputs)) - known
            OUTCOMES.append((writer, point, describe(before, after)
                             + (", temporaries left" if debris else "")))
        first, took = whole_run(work, command, outputs)  # the next run recovers
        kept += sorted(set(leftovers(work, outputs)) - known)
        for name, data in final_files(work, outputs).items():
            check_complete(name, data)
    return kept


def no_leftovers(writer, kept):
    assert not kept, f"{writer}: the next run left {kept}"


@pytest.mark.parametrize("writer", sorted(WRITERS))
def test_a_killed_writer_leaves_whole_files_and_the_next_run_cleans_up(tmp_path, writer):
    no_leftovers(writer, kill_writer(tmp_path, writer, *WRITERS[writer]))


@pytest.mark.slow
@pytest.mark.parametrize("writer", sorted(SLOW_WRITERS))
def test_a_killed_report_leaves_whole_files_and_the_next_run_cleans_up(tmp_path, writer):
    no_leftovers(writer, kill_writer(tmp_path, writer, *SLOW_WRITERS[writer]))


@pytest.fixture(scope="module", autouse=True)
def figures(request):
    """Print writers x kill points and their outcomes, to be quoted."""
    yield
    if not OUTCOMES:
        return
    writers = {writer for writer, _, _ in OUTCOMES}
    lines = [f"kill -9: {len(writers)} writers x {len(POINTS)} kill points = {len(OUTCOMES)} kills"]
    lines += [f"  {outcome}: {count}"
              for outcome, count in sorted(Counter(o for _, _, o in OUTCOMES).items())]
    lines += [f"  {writer:<18} {point:<16} {outcome}" for writer, point, outcome in OUTCOMES]
    capture = request.config.pluginmanager.getplugin("capturemanager")
    with capture.global_and_fixture_disabled():  # shown without -s, as capsys.disabled does
        print("\n" + "\n".join(lines))


# A worksheet is two files (and a manifest); a kill between the sheet and its
# key must not leave a new sheet beside the old key. The PDF writer is the
# writer's own parameter, so the child dies exactly between the two: os._exit
# skips every cleanup, as a kill does, on every system.
KILL_BETWEEN = """
import os, sys
from app.model import scene as scenes, shipped
from app.teaching import worksheet

def pdf_writer(sheet, path, answers):
    if answers and sys.argv[2] == "kill":
        os._exit(9)
    path.write_bytes(sheet.title.encode("utf-8"))

sheet = worksheet.build(scenes.load(shipped.scene_path(sys.argv[1])),
                        None)
worksheet.write(sheet, "ws", "pdf", pdf_writer)
"""


def test_a_worksheet_killed_between_sheet_and_key_keeps_the_earlier_pair(tmp_path):
    def write(scene, how):
        env = dict(os.environ, PYTHONPATH=str(ROOT))
        return subprocess.run([sys.executable, "-c", KILL_BETWEEN, scene, how], cwd=tmp_path,
                              env=env, capture_output=True, timeout=START_TIMEOUT).returncode

    def pair():
        return [(tmp_path / "ws" / name).read_bytes() for name in ("worksheet.pdf",
                                                                    "answers.pdf")]
    assert write("demo-bresenham", "whole") == 0
    earlier = pair()
    assert earlier[0] == earlier[1] != b""
    assert write("line-midpoint", "kill") == 9
    assert pair() == earlier
    assert write("line-midpoint", "whole") == 0  # and the next run cleans up
    assert pair()[0] == pair()[1] != earlier[0]
    assert sorted(p.name for p in (tmp_path / "ws").iterdir()) == [
        ".rasterlab-worksheet.json", "answers.pdf", "worksheet.pdf"]
