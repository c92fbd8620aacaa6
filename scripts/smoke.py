"""Install RasterLab's wheel as a user would, and use it.

Builds the wheel from this checkout, checks that it holds every shipped file,
makes a clean virtual environment in a temporary folder outside the checkout,
installs the wheel there with the pinned dependencies of requirements/app.txt
and, beside it, an unrelated distribution named ``algorithms``; then, from a
folder that holds an ``algorithms/`` folder of its own (as a student's course
folder may), runs the commands a user types and opens the window offscreen.
Both impostors fail loudly if RasterLab imports them.

    python scripts/smoke.py [--wheel-dir DIR]    (DIR: where to leave the wheel)

Prints a line per check and ends with "smoke: N passed, N failed"; exits 1
when a check failed. CI runs it on every system (.github/workflows/ci.yml),
and .ci/run after the tests. It needs the package index (or pip's cache) for
the dependencies.
"""
from __future__ import annotations

import argparse
import base64
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# The data the program opens by name; each of their files must be in the wheel.
SHIPPED = ("scenes", "templates", "students", "textures", "fonts")
PROGRAM = ("algorithms", "app", "widgets")
# Left out of the copy the wheel is built from: what a build or a run leaves.
NOT_SOURCE = shutil.ignore_patterns(".git", ".venv", "build", "dist", "*.egg-info", "__pycache__",
                                    ".pytest_cache", ".hypothesis", "out", "node_modules")
LOUD = "raise RuntimeError({!r})\n"


def build_wheel(out: Path) -> Path:
    """The wheel of this checkout, built from a copy so that no build/
    folder left in the checkout by an earlier build can add stale files."""
    source = out / "source"
    shutil.copytree(ROOT, source, ignore=NOT_SOURCE)
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps",
                    "-w", str(out), str(source)], check=True)
    return next(out.glob("rasterlab-*.whl"))


def missing_from_wheel(wheel: Path) -> list[str]:
    """The checkout's shipped data and program files that the wheel lacks."""
    with zipfile.ZipFile(wheel) as archive:
        inside = set(archive.namelist())
    wanted = [path for folder in SHIPPED for path in (ROOT / "resources" / folder).rglob("*")]
    wanted += [path for folder in PROGRAM for path in (ROOT / folder).rglob("*")]
    names = (path.relative_to(ROOT).as_posix() for path in wanted
             if path.is_file() and "__pycache__" not in path.parts)
    return sorted(name for name in names if f"rasterlab/_lib/{name}" not in inside)


def fake_algorithms_wheel(out: Path) -> Path:
    """A wheel of an unrelated distribution named ``algorithms``, whose
    top-level package ``algorithms`` raises when imported."""
    info = "algorithms-0.0.1.dist-info"
    files = {
        "algorithms/__init__.py": LOUD.format("the unrelated distribution 'algorithms' "
                                              "was imported instead of RasterLab's"),
        f"{info}/METADATA": "Metadata-Version: 2.1\nName: algorithms\nVersion: 0.0.1\n",
        f"{info}/WHEEL": "Wheel-Version: 1.0\nGenerator: rasterlab-smoke\n"
                         "Root-Is-Purelib: true\nTag: py3-none-any\n",
    }
    record = [f"{name},sha256={_digest(text.encode())},{len(text.encode())}"
              for name, text in files.items()]
    files[f"{info}/RECORD"] = "\n".join([*record, f"{info}/RECORD,,"]) + "\n"
    wheel = out / "algorithms-0.0.1-py3-none-any.whl"
    with zipfile.ZipFile(wheel, "w") as archive:
        for name, text in files.items():
            archive.writestr(name, text)
    return wheel


def _digest(data: bytes) -> str:
    return base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()


def course_folder(path: Path) -> Path:
    """A folder holding an ``algorithms/`` folder that raises when imported."""
    (path / "algorithms").mkdir(parents=True)
    (path / "algorithms" / "__init__.py").write_text(
        LOUD.format("the algorithms/ folder of the current directory was imported "
                    "instead of RasterLab's"))
    return path


def make_venv(folder: Path) -> Path:
    """A clean virtual environment; its folder of programs."""
    subprocess.run([sys.executable, "-m", "venv", str(folder)], check=True)
    return folder / ("Scripts" if os.name == "nt" else "bin")


# The window as `rasterlab` with no command opens it, closed again once its
# event loop runs; it prints the windows that were showing.
OPEN_AND_CLOSE = """
import sys
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication
import rasterlab
app = QApplication(sys.argv[:1])
def close():
    print(" ".join(type(w).__name__ for w in app.topLevelWidgets() if w.isVisible()))
    app.closeAllWindows()
    app.quit()
QTimer.singleShot(1000, close)
sys.exit(rasterlab.main([]))
"""


class Smoke:
    """Runs the checks, each a command in the course folder, and counts them."""

    def __init__(self, bin_dir: Path, course: Path, env: dict):
        self.bin_dir, self.course, self.env = bin_dir, course, env
        self.passed, self.failed = 0, 0

    def program(self, name: str) -> str:
        suffix = ".exe" if os.name == "nt" else ""
        return str(self.bin_dir / f"{name}{suffix}")

    def check(self, title: str, command: list[str], *expected: str) -> str:
        """Run the command; it passes when it exits 0 and prints every expected text."""
        start = time.perf_counter()
        done = subprocess.run(command, cwd=self.course, env=self.env, capture_output=True,
                              text=True, encoding="utf-8", errors="replace")
        seconds = time.perf_counter() - start
        absent = [text for text in expected if text not in done.stdout]
        self.record(not done.returncode and not absent, f"{title} ({seconds:.1f} s)",
                    f"exit {done.returncode}; missing {absent}\n{done.stdout[-2000:]}"
                    f"{done.stderr[-2000:]}")
        return done.stdout

    def record(self, ok: bool, title: str, why: str = "") -> None:
        if ok:
            self.passed += 1
            print(f"ok    {title}", flush=True)
        else:
            self.failed += 1
            print(f"FAIL  {title}\n      {why.strip()}", flush=True)

    def output(self, name: str, header: bytes) -> None:
        """An exported file: it exists and starts as its format says."""
        path = self.course / name
        start = path.read_bytes()[:len(header)] if path.is_file() else b""
        self.record(start == header, f"{name} starts with {header!r}",
                    f"{'found ' + repr(start) if path.is_file() else 'no file'}")


def run_checks(smoke: Smoke, wheel: Path) -> None:
    rasterlab, python = smoke.program("rasterlab"), smoke.program("python")
    version = wheel.name.split("-")[1]
    smoke.check("rasterlab --version", [rasterlab, "--version"], version)
    smoke.check("rasterlab list", [rasterlab, "list"], "line-bresenham", "polygon-scanline")
    scenes = [path.relative_to(ROOT / "resources" / "scenes").with_suffix("").as_posix()
              for path in (ROOT / "resources" / "scenes").rglob("*.json")]
    smoke.check("rasterlab list --scenes", [rasterlab, "list", "--scenes"], *scenes)
    smoke.check("rasterlab run --scene demo-bresenham",
                [rasterlab, "run", "--scene", "demo-bresenham"], "line-bresenham", "pixels: 3,4 ")
    smoke.check("rasterlab export demo-bresenham --gif --pdf --html",
                [rasterlab, "export", "demo-bresenham", "--gif", "demo.gif", "--pdf", "demo.pdf",
                 "--html", "demo.html"])
    smoke.output("demo.gif", b"GIF89a")
    smoke.output("demo.pdf", b"%PDF-")
    smoke.output("demo.html", b"<!DOCTYPE html>")
    students = smoke.check("the shipped student samples are found",
                           [python, "-c", "import rasterlab\nfrom app.model import shipped\n"
                                            "print(shipped.STUDENTS)"],
                           "_lib").strip()
    smoke.check("rasterlab check bresenham_correct.py",
                [rasterlab, "check", str(Path(students) / "bresenham_correct.py"),
                 "--against", "line-bresenham"], "PASS", "cases pass")
    smoke.check("python -m rasterlab list", [python, "-m", "rasterlab", "list"], "line-bresenham")
    smoke.check("the window opens offscreen and closes", [python, "-c", OPEN_AND_CLOSE],
                "MainWindow")
    where = smoke.check("RasterLab's own packages are imported",
                        [python, "-c", "import json, rasterlab, app, algorithms; "
                                       "print(json.dumps([app.__file__, algorithms.__file__]))"])
    venv = smoke.bin_dir.parent.resolve()  # resolved: macOS's temporary folder is a link
    smoke.record(bool(where) and all(Path(path).resolve().is_relative_to(venv)
                                     and "_lib" in Path(path).parts for path in json.loads(where)),
                 "app and algorithms live in the venv's rasterlab/_lib", where)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--wheel-dir", type=Path, help="leave the wheel built in this folder")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="rasterlab-smoke-") as temporary:
        tmp = Path(temporary)
        dist = tmp / "dist"
        dist.mkdir()
        start = time.perf_counter()
        wheel = build_wheel(dist)
        with zipfile.ZipFile(wheel) as archive:
            count = len(archive.namelist())
        print(f"wheel {wheel.name}: {wheel.stat().st_size / 1e6:.2f} MB, {count} files, "
              f"built in {time.perf_counter() - start:.0f} s", flush=True)
        if args.wheel_dir:
            args.wheel_dir.mkdir(parents=True, exist_ok=True)
            shutil.copy2(wheel, args.wheel_dir)
        bin_dir = make_venv(tmp / "venv")
        pip = [str(bin_dir / "python"), "-m", "pip", "install", "--quiet",
               "--disable-pip-version-check"]
        subprocess.run([*pip, "--require-hashes", "-r", str(ROOT / "requirements" / "app.txt")],
                       check=True)
        # The impostor goes in after RasterLab, so it would overwrite a file they shared.
        subprocess.run([*pip, "--no-deps", str(wheel)], check=True)
        subprocess.run([*pip, "--no-deps", str(fake_algorithms_wheel(dist))], check=True)
        print(f"installed in a clean venv in {time.perf_counter() - start:.0f} s", flush=True)

        env = {key: value for key, value in os.environ.items()
               if key not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}
        # Offscreen, and the settings and recovery files kept in the temporary folder.
        env.update(QT_QPA_PLATFORM="offscreen", RASTERLAB_SETTINGS=str(tmp / "settings.ini"),
                   RASTERLAB_DATA_DIR=str(tmp / "data"))
        smoke = Smoke(bin_dir, course_folder(tmp / "course"), env)
        missing = missing_from_wheel(wheel)
        smoke.record(not missing, "the wheel holds every shipped file and module",
                     f"missing: {missing}")
        run_checks(smoke, wheel)
    print(f"smoke: {smoke.passed} passed, {smoke.failed} failed")
    return 1 if smoke.failed else 0


if __name__ == "__main__":
    sys.exit(main())
