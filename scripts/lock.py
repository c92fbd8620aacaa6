"""Refresh the lock, or check it.

uv.lock pins every dependency of pyproject.toml for every platform and for
every Python that pyproject.toml admits; requirements/*.txt are its exports,
hash-pinned with environment markers (one file serves Windows, macOS and
Linux), which scripts/setup.sh and CI install with pip alone:

    requirements/app.txt   what the program needs: `bash scripts/setup.sh`
    requirements/test.txt  the program and every extra, the tests' included:
                           `bash scripts/setup.sh --test`

    python scripts/lock.py             after a change to pyproject.toml: pins what it
                                       added, keeps every other pin
    python scripts/lock.py --upgrade   the newest releases the ranges allow
    python scripts/lock.py --check     exit 1 if uv.lock or an export is out of date

uv is in the test extra (run it with .venv/bin/python after
`scripts/setup.sh --test`); otherwise the uv on PATH is used.
"""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# Each export and the options of `uv export` that make it.
EXPORTS = {
    "app.txt": [],
    "test.txt": ["--all-extras"],
}


def extras() -> list[str]:
    """The extras of pyproject.toml: requirements/test.txt holds them all."""
    try:
        import tomllib
    except ImportError:  # Python 3.10
        import tomli as tomllib
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    return list(project.get("optional-dependencies", {}))


def uv() -> str:
    try:
        from uv import find_uv_bin
        return find_uv_bin()
    except ImportError:
        found = shutil.which("uv")
        if found is None:
            sys.exit("lock: uv is needed: `pip install uv`, or set up with scripts/setup.sh --test")
        return found


HEADER = "# Made from uv.lock by `python scripts/lock.py`: edit pyproject.toml, not this file.\n"


def export(options: list[str]) -> str:
    """An export of uv.lock as it is, under a header of ours (uv's names its
    own command line, which would differ between making and checking)."""
    done = subprocess.run([uv(), "export", "--frozen", "--no-emit-project", "--no-header",
                           "--format", "requirements-txt", "--quiet", *options],
                          cwd=ROOT, check=True, capture_output=True, text=True)
    return HEADER + done.stdout


def stale() -> list[str]:
    """The files that do not agree with pyproject.toml: uv.lock, if a new
    resolution would change it, and each export that differs from uv.lock's."""
    found = []
    if subprocess.run([uv(), "lock", "--check", "--quiet"], cwd=ROOT).returncode:
        found.append("uv.lock")
    for name, options in EXPORTS.items():
        path = ROOT / "requirements" / name
        if not path.is_file() or path.read_text(encoding="utf-8") != export(options):
            found.append(f"requirements/{name}")
    return found


def main(argv: list[str]) -> int:
    if argv == ["--check"]:
        found = stale()
        for name in found:
            print(f"lock: {name} is out of date; run `python scripts/lock.py`", file=sys.stderr)
        return 1 if found else 0
    if argv not in ([], ["--upgrade"]):
        print("usage: python scripts/lock.py [--upgrade | --check]", file=sys.stderr)
        return 2
    subprocess.run([uv(), "lock", *argv], cwd=ROOT, check=True)
    (ROOT / "requirements").mkdir(exist_ok=True)
    for name, options in EXPORTS.items():
        (ROOT / "requirements" / name).write_text(export(options), encoding="utf-8", newline="\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
