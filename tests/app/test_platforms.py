"""The command line's, the check's, the exports' and the window's paths that
differ between Windows, macOS and Linux, run here with each platform's part
faked (tests/app/model/test_portability.py does the same for files and
processes).

What is faked, and how far that goes:

* The check's limits: ``resource`` as Windows has it (no module), as macOS
  answers when it refuses RLIMIT_AS (ValueError) and as Linux has it. The
  fakes stand in for the module only; the child process, the parent's
  wall-clock timeout and the report are the real ones. Run here, the
  "macOS" child limits its data segment with Linux's RLIMIT_DATA: that
  proves the fallback is taken and enforced by Linux, not that macOS's
  kernel enforces RLIMIT_DATA (it is documented to ignore it for memory
  that malloc maps). That Windows really has no ``resource`` module and no
  SIGXCPU is Python's documentation, not something this machine shows.
* UTF-8 output: a child process whose standard streams Python opens as
  cp1252 (PYTHONIOENCODING, what a Windows console's redirection gives) or
  ASCII (LC_ALL=C), and a check's child whose stderr pipe is ASCII. It
  proves the bytes written are UTF-8; not that a Windows console or editor
  shows the glyphs, nor which code page a real Windows pipe has.
* Fonts: the shipped DejaVu files are the ones loaded, they hold every
  glyph the frames draw, and the exports work with the system's font
  lookup pointed at an empty folder and an empty fontconfig. The empty
  fontconfig stands in for a system without DejaVu (Windows, macOS): on
  those systems Qt and Pillow search their own folders, which this machine
  does not have.
* The presentation key: the choice between Qt's standard full-screen keys
  and F11 is tested with the bindings each system's Qt theme documents; the
  bindings themselves come from Qt's platform theme, which only the real
  system runs (the window test in tests/app/gui/test_window_view.py).
"""
from __future__ import annotations

import io
import json
import os
import subprocess
import sys
import types
from pathlib import Path

import pytest
from fontTools.ttLib import TTFont
from PySide6.QtGui import QKeySequence
from pypdf import PdfReader

from app import cli
from app.analysis import charts
from app.gui.window_view import presentation_keys
from app.model.shipped import FONTS
from app.render import text as frame_text
from app.render import vector
from app.teaching import student, student_child
from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
MIB = 1 << 20


# ------------------------------------------------------------ the check's limits
class FakeResource:
    """The ``resource`` module's calls, answered as ``refuse`` says: a limit
    name there raises the error given (macOS refuses RLIMIT_AS with ValueError)."""

    RLIM_INFINITY = -1
    RLIMIT_CPU, RLIMIT_FSIZE, RLIMIT_DATA, RLIMIT_CORE, RLIMIT_AS = 0, 1, 2, 4, 9
    NAMES = {0: "CPU", 1: "FSIZE", 2: "DATA", 4: "CORE", 9: "AS"}

    def __init__(self, refuse=None, hard=None):
        self.refuse, self.hard, self.set = refuse or {}, hard or {}, {}

    def getrlimit(self, number):
        return (self.RLIM_INFINITY, self.hard.get(self.NAMES[number], self.RLIM_INFINITY))

    def setrlimit(self, number, pair):
        name = self.NAMES[number]
        if name in self.refuse:
            raise self.refuse[name]("current limit exceeds maximum limit")
        self.set[name] = pair


def test_linux_limits_cpu_time_and_the_address_space():
    linux = FakeResource()
    held = student_child.set_limits(64 * MIB, 2, linux)
    assert held == {"cpu": True, "memory": "address space"}
    assert linux.set == {"AS": (64 * MIB, 64 * MIB), "CPU": (2, 3), "CORE": (0, 0),
                         "FSIZE": (16 * MIB, 16 * MIB)}


@pytest.mark.parametrize("error", [ValueError, OSError])
def test_a_macos_that_refuses_the_address_space_limits_the_data_segment(error):
    mac = FakeResource(refuse={"AS": error})
    held = student_child.set_limits(64 * MIB, 2, mac)
    assert held == {"cpu": True, "memory": "data segment"}
    assert mac.set["DATA"] == (64 * MIB, 64 * MIB) and "AS" not in mac.set


def test_a_system_that_refuses_both_memory_limits_says_so():
    held = student_child.set_limits(64 * MIB, 2, FakeResource(refuse={"AS": ValueError,
                                                                       "DATA": OSError}))
    assert held == {"cpu": True, "memory": None}


def test_windows_has_no_resource_module_and_no_limit_is_claimed():
    assert student_child.set_limits(64 * MIB, 2, None) == {"cpu": False, "memory": None}


def test_a_lower_hard_limit_in_force_is_kept():
    # A grader's `ulimit -v` below ours: a process cannot raise its own hard limit.
    shell = FakeResource(hard={"AS": 32 * MIB})
    assert student_child.set_limits(64 * MIB, 2, shell)["memory"] == "address space"
    assert shell.set["AS"] == (32 * MIB, 32 * MIB)


def test_the_cpu_limit_statuses_exist_only_where_the_signals_do():
    windows = types.SimpleNamespace(SIGINT=2, SIGTERM=15, SIGBREAK=21)
    posix = types.SimpleNamespace(SIGXCPU=24, SIGKILL=9, SIGTERM=15)
    assert student.cpu_limit_statuses(windows) == frozenset()
    assert student.cpu_limit_statuses(posix) == {-24, -9}


def test_without_the_signals_a_killed_child_is_a_crash_not_a_traceback(monkeypatch):
    monkeypatch.setattr(student, "CPU_LIMIT_STATUSES", frozenset())  # Windows
    ran = student.Ran(1, b"rasterlab-runner 1\n", 0, b"", 0)  # TerminateProcess's 1
    outcome = student._outcome(ran, student.Limits(), 0.1)
    assert outcome.kind == "crash" and "status 1" in outcome.error


def child_with(tmp_path, setup: str) -> Path:
    """A stand-in for student_child.py: ``setup`` (Python source that replaces
    ``resource`` or the standard streams), then the real one's source, as
    the runner is self-contained (it runs where RasterLab is not visible)."""
    wrapper = tmp_path / "child.py"
    wrapper.write_text(f"import sys\n{setup}\n" + student.CHILD.read_text(encoding="utf-8"),
                       encoding="utf-8")
    return wrapper


NO_RESOURCE = "sys.modules['resource'] = None  # import resource raises ImportError"
MAC_RESOURCE = """
import resource as real, types
def setrlimit(number, pair):
    if number == real.RLIMIT_AS:
        raise ValueError('current limit exceeds maximum limit')
    real.setrlimit(number, pair)
fake = types.ModuleType('resource')
fake.__dict__.update({k: v for k, v in vars(real).items() if k.isupper() or k == 'getrlimit'})
fake.setrlimit = setrlimit
sys.modules['resource'] = fake
"""


def test_without_resource_the_wall_clock_still_ends_an_endless_loop(tmp_path, monkeypatch):
    monkeypatch.setattr(student, "CHILD", child_with(tmp_path, NO_RESOURCE))
    limits = student.Limits(seconds=0.2, memory=64 * MIB)
    assert student.limits_in_force(limits) == {"cpu": False, "memory": None}
    spins = tmp_path / "spins.py"  # loops before its first pixel: no step limit ends it
    spins.write_text("def draw(x0, y0, x1, y1):\n    while True:\n        pass\n"
                     "    yield x0, y0\n", encoding="utf-8")
    outcome = student.run_student(spins, [0, 0, 5, 2], limits)
    assert outcome.kind == "time" and "no result within 0.2 s" in outcome.error  # the timeout's


def test_the_report_names_the_limits_a_windows_child_cannot_set(tmp_path, monkeypatch, run_cli):
    monkeypatch.setattr(student, "CHILD", child_with(tmp_path, NO_RESOURCE))
    status, out, err = run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                               "line-bresenham", "--cases", "random", "1")
    assert status == 0, err
    assert out.splitlines()[1] == ("limits per case: wall clock 3 s (then the process is ended); "
                                   "CPU-time limit not enforced on this system; memory limit not "
                                   "enforced on this system")
    status, out, _ = run_cli("check", SAMPLES / "bresenham_correct.py", "--against",
                             "line-bresenham", "--cases", "random", "1", "--json")
    assert json.loads(out)["limits"] == {"wall_clock_seconds": 3, "cpu_seconds": None,
                                         "memory_bytes": None, "memory_limits": None}


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_DATA as Linux keeps it")
def test_the_macos_fallback_limits_memory_through_the_data_segment(tmp_path, monkeypatch):
    monkeypatch.setattr(student, "CHILD", child_with(tmp_path, MAC_RESOURCE))
    limits = student.Limits(seconds=2, memory=64 * MIB)
    assert student.limits_in_force(limits) == {"cpu": True, "memory": "data segment"}
    outcome = student.run_student(SAMPLES / "allocates.py", [0, 0, 5, 2], limits)
    assert outcome.kind == "memory", outcome.error


def test_this_system_holds_the_limits_its_platform_allows():
    held = student.limits_in_force(student.Limits(seconds=1, memory=128 * MIB))
    if sys.platform.startswith("linux"):
        assert held == {"cpu": True, "memory": "address space"}
    elif sys.platform == "darwin":
        assert held["cpu"] and held["memory"] in ("address space", "data segment")
    elif sys.platform == "win32":
        assert held == {"cpu": False, "memory": None}


# ------------------------------------------------------------------ UTF-8 output
ASCII_PIPES = "sys.stderr.reconfigure(encoding='ascii')  # a pipe on a code page that lacks ≤"


def test_a_students_print_of_any_glyph_reaches_the_report(tmp_path, monkeypatch):
    monkeypatch.setattr(student, "CHILD", child_with(tmp_path, ASCII_PIPES))
    prints = tmp_path / "prints.py"
    prints.write_text("def draw(x0, y0, x1, y1):\n"
                      "    print('d\u1d62\u208a\u2081 \u2264 0 \u25b6')\n"
                      "    yield x0, y0\n", encoding="utf-8")
    outcome = student.run_student(prints, [0, 0, 5, 2])
    assert outcome.kind == "ok", outcome.error
    assert outcome.output.strip() == "d\u1d62\u208a\u2081 \u2264 0 \u25b6"


SCANLINE_CSV = ["run", "polygon-scanline", "--points", "0,0", "9,4", "2,7", "--steps", "--csv"]


def environment(**env) -> dict:
    """A child's environment: no PYTHON* or locale settings of ours, only
    ``env`` (SYSTEMROOT kept: Python on Windows cannot start without it)."""
    kept = {name: os.environ[name] for name in ("PATH", "SYSTEMROOT") if name in os.environ}
    return {**kept, "PYTHONPATH": str(ROOT), **env}


def rasterlab(args, **env):
    """``python -m rasterlab ARGS`` with the given environment, as bytes."""
    return subprocess.run([sys.executable, "-m", "rasterlab", *args], cwd=ROOT,
                          env=environment(**env), capture_output=True, timeout=120)


@pytest.mark.parametrize("env", [{"PYTHONIOENCODING": "cp1252"},
                                 {"LC_ALL": "C", "PYTHONUTF8": "0"}],
                         ids=["windows-code-page", "c-locale"])
def test_the_steps_csv_is_utf8_whatever_the_streams_encoding(env):
    done = rasterlab(SCANLINE_CSV, **env)
    assert done.returncode == 0, done.stderr.decode("utf-8", "replace")
    csv = done.stdout.decode("utf-8")  # strict: every byte is UTF-8
    assert "x=\u22480.14286" in csv  # ≈, which neither cp1252 nor ASCII can write


def test_an_error_line_keeps_its_glyphs_on_a_code_page():
    done = rasterlab(["run", "--scene", "\u2264d\u1d62\u208a\u2081\u25b6"],
                     PYTHONIOENCODING="cp1252")
    assert done.returncode == 2
    assert done.stderr.decode("utf-8").startswith("rasterlab: \u2264d\u1d62\u208a\u2081\u25b6: ")


def test_streams_write_utf8_and_never_raise_on_a_name():
    code_page = io.TextIOWrapper(io.BytesIO(), encoding="cp1252", errors="strict")
    ascii_stream = io.TextIOWrapper(io.BytesIO(), encoding="ascii", errors="backslashreplace")
    utf8 = io.TextIOWrapper(io.BytesIO(), encoding="UTF8")
    cli.utf8_streams([code_page, ascii_stream, utf8, io.StringIO(), None])  # None: pythonw
    for stream in (code_page, ascii_stream):
        stream.write("\u2264 d\u1d62\u208a\u2081 \u25b6")
        stream.flush()
        assert stream.buffer.getvalue() == "\u2264 d\u1d62\u208a\u2081 \u25b6".encode("utf-8")
    # strict becomes backslashreplace: a lone surrogate (os.fsdecode of a
    # byte that is not UTF-8) is written as text instead of raising
    assert (code_page.errors, ascii_stream.errors, utf8.errors) == ("backslashreplace",) * 3
    assert utf8.encoding == "UTF8"  # left as it was
    utf8.write("\udcff.gif")
    utf8.flush()
    assert utf8.buffer.getvalue() == b"\\udcff.gif"


# ------------------------------------------------------------------------- fonts
# Every glyph the frames and worksheets draw beyond ASCII: the relations
# and ≈ of notation.tidy, its subscripts, the ellipsis, the separator, ▶.
GLYPHS = "\u2264\u2265\u2260\u2248\u2212\u2026\u00b7\u25b6" + "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ"
NOT_IN_DEJAVU = "\ue000"  # a private-use code point: drawn as the font's .notdef box


@pytest.mark.parametrize("kind", sorted(frame_text.FONT_FILES))
def test_frames_load_the_shipped_fonts(kind):
    face = frame_text.font(kind, 24)
    assert Path(face.path).parent == FONTS and Path(face.path).is_file()


@pytest.mark.parametrize("kind", sorted(frame_text.FONT_FILES))
def test_the_shipped_fonts_hold_every_glyph_the_program_draws(kind):
    cmap = TTFont(frame_text.font_path(kind)).getBestCmap()
    assert [c for c in GLYPHS if ord(c) not in cmap] == []
    assert ord(NOT_IN_DEJAVU) not in cmap
    face = frame_text.font(kind, 24)
    missing = face.getmask(NOT_IN_DEJAVU)
    for glyph in "\u2264d\u1d62\u208a\u2081\u25b6":
        mask = face.getmask(glyph)
        assert mask.getbbox() is not None, glyph  # ink, not a blank
        assert (mask.size, bytes(mask)) != (missing.size, bytes(missing)), glyph


def test_charts_use_the_shipped_font():
    assert Path(charts.font(12).path).parent == FONTS


def test_the_pdf_takes_its_fonts_from_the_package():
    pdf = vector._new_pdf()
    assert {Path(font.ttffile).parent for font in pdf.fonts.values()} == {FONTS}


def no_system_fonts(tmp_path) -> dict:
    """An environment whose font lookups find nothing: an empty fontconfig
    (Qt) and empty data folders (Pillow's search by name)."""
    empty = tmp_path / "nothing"
    empty.mkdir()
    config = tmp_path / "fonts.conf"
    config.write_text('<?xml version="1.0"?>\n<fontconfig></fontconfig>\n', encoding="utf-8")
    return {"FONTCONFIG_FILE": str(config), "XDG_DATA_DIRS": str(empty),
            "XDG_DATA_HOME": str(empty), "HOME": str(empty), "QT_QPA_PLATFORM": "offscreen"}


def font_names(pdf_path) -> set[str]:
    """The base names of the fonts a PDF's pages use, without the subset
    prefix and the style (fpdf2 writes DejaVuSansBook, Qt DejaVuSans-Bold)."""
    names = set()
    for page in PdfReader(pdf_path).pages:
        for font in page["/Resources"]["/Font"].values():
            name = str(font.get_object()["/BaseFont"]).lstrip("/").split("+")[-1]
            names.add(name.split("-")[0].removesuffix("Book").removesuffix("Bold"))
    return names


def test_pdf_export_needs_no_system_font(tmp_path):
    out = tmp_path / "demo.pdf"
    done = rasterlab(["export", "demo-bresenham", "--pdf", str(out), "--to", "3"],
                     **no_system_fonts(tmp_path))
    assert done.returncode == 0, done.stderr.decode("utf-8", "replace")
    assert font_names(out) == {"DejaVuSans", "DejaVuSansMono"}


QT_FAMILY = """
from PySide6.QtGui import QFont, QFontInfo
from app.gui.worksheet_pdf import application
application()
print(QFontInfo(QFont("DejaVu Sans")).family())
"""


def test_the_worksheet_pdf_uses_the_shipped_fonts_on_a_system_without_them(tmp_path):
    env = no_system_fonts(tmp_path)
    without = subprocess.run([sys.executable, "-c", QT_FAMILY], cwd=ROOT, capture_output=True,
                             text=True, timeout=120, env=environment(**env))
    assert without.returncode == 0, without.stderr
    assert without.stdout.strip() != "DejaVu Sans"  # Qt finds no DejaVu of its own here
    scene = ROOT / "resources" / "scenes" / "line-reversed.json"
    done = rasterlab(["worksheet", str(scene), "--out", str(tmp_path / "sheet")], **env)
    assert done.returncode == 0, done.stderr.decode("utf-8", "replace")
    for name in ("worksheet.pdf", "answers.pdf"):
        assert font_names(tmp_path / "sheet" / name) == {"DejaVuSans", "DejaVuSansMono"}


LAUNCH = """
from PySide6.QtCore import QTimer
from PySide6.QtGui import QFont, QFontInfo
from PySide6.QtWidgets import QApplication
app = QApplication([])
QTimer.singleShot(0, app.quit)
from app.gui import launch
launch()
print(QFontInfo(QFont("DejaVu Sans")).family(), QFontInfo(QFont("DejaVu Sans Mono")).family())
"""


def test_the_window_registers_the_shipped_fonts(tmp_path):
    env = environment(XDG_CONFIG_HOME=str(tmp_path), **no_system_fonts(tmp_path))
    done = subprocess.run([sys.executable, "-c", LAUNCH], cwd=ROOT, capture_output=True,
                          text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().splitlines()[-1] == "DejaVu Sans DejaVu Sans Mono"


def test_qt_registers_the_shipped_families_once(qapp):
    from app.gui.fonts import register_shipped_fonts
    families = register_shipped_fonts()
    assert families == ["DejaVu Sans", "DejaVu Sans Mono"]
    assert register_shipped_fonts() == families


# ---------------------------------------------------------------- presentation
def keys(*texts):
    return [QKeySequence(text) for text in texts]


@pytest.mark.parametrize("platform, standard, expected", [
    ("darwin", ["Ctrl+Meta+F"], ["Ctrl+Meta+F"]),                 # Cmd+Ctrl+F; F11 is the OS's
    ("win32", ["F11", "Alt+Return"], ["F11", "Alt+Return"]),
    ("linux", ["F11", "Ctrl+Shift+F"], ["F11", "Ctrl+Shift+F"]),  # KDE
    ("linux", ["Ctrl+Shift+F"], ["F11", "Ctrl+Shift+F"]),         # a standard without F11
    ("linux", [], ["F11"]),
])
def test_presentation_keys_per_system(platform, standard, expected):
    assert presentation_keys(keys(*standard), platform) == keys(*expected)
