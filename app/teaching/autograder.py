"""Gradescope's autograder zip for one algorithm and its cases.

Gradescope (gradescope-autograders.readthedocs.io, "specs") builds an
Ubuntu image from the zip's setup.sh, copies the zip's files to
/autograder/source, and for each submission runs run_autograder, which
must leave /autograder/results/results.json; the student's files are in
/autograder/submission. The zip holds, at its root: setup.sh (installs
Python, bubblewrap and RasterLab: the given wheel, which the zip carries,
or the released package from pip), run_autograder (runs `rasterlab check
/autograder/submission --against ALGO --format gradescope --out
/autograder/results/results.json`) and the cases' scene files.
"""
from __future__ import annotations

import io
import shlex
import zipfile
from pathlib import Path

from algorithms.core.registry import InputError

SOURCE = "/autograder/source"
EXECUTABLE = 0o100755 << 16  # a regular file, rwxr-xr-x, as zip's external attributes hold it


def setup_script(wheel: str | None, version: str) -> str:
    install = (f"python3 -m pip install {shlex.quote(f'{SOURCE}/{wheel}')}" if wheel
               else f"python3 -m pip install {shlex.quote(f'rasterlab=={version}')}")
    return "\n".join([
        "#!/usr/bin/env bash",
        "# Written by `rasterlab grader gradescope`: installs what run_autograder needs.",
        "set -euo pipefail",
        "apt-get update",
        "# bubblewrap sandboxes each case where the image lets it make namespaces.",
        "apt-get install -y --no-install-recommends python3 python3-pip bubblewrap",
        # Ubuntu 23.04 and later mark the system Python as managed by apt.
        "export PIP_BREAK_SYSTEM_PACKAGES=1",
        install, ""])


def run_script(check_words: list[str]) -> str:
    command = " ".join(shlex.quote(word) for word in check_words)
    return "\n".join([
        "#!/usr/bin/env bash",
        "# Written by `rasterlab grader gradescope`: grades the submission into results.json.",
        "mkdir -p /autograder/results",
        f"python3 -m {command}",
        "status=$?",
        "# 0: every case passed; 1: some failed. results.json holds the grade either way;",
        "# 2 or 3 (bad input, RasterLab's own failure) fail the run for the course staff to see.",
        '[ "$status" -le 1 ]', ""])


def check_words(against: str, cases: list[str], seed: str, time_limit: str, memory_limit: str,
                points: str | None) -> list[str]:
    """`rasterlab check`'s words in run_autograder; scene files as the zip holds them."""
    in_zip = [f"{SOURCE}/scenes/{Path(word).name}" if word.endswith(".json") else word
              for word in cases]
    words = ["rasterlab", "check", "/autograder/submission", "--against", against,
             "--cases", *in_zip, "--seed", seed, "--time-limit", time_limit,
             "--memory-limit", memory_limit]
    if points:
        words += ["--points", points]
    return words + ["--format", "gradescope", "--out", "/autograder/results/results.json",
                    "--force"]


def zip_bytes(check: list[str], cases: list[str], wheel: Path | None, version: str) -> bytes:
    """The autograder zip: setup.sh and run_autograder (executable), the
    scene files of ``cases`` under scenes/, and the wheel if one is given."""
    scenes = [Path(word) for word in cases if word.endswith(".json")]
    names = [path.name for path in scenes]
    if len(set(names)) != len(names):
        raise InputError("--cases: two scene files with one name; the zip holds them by name")
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        _add(archive, "setup.sh", setup_script(wheel.name if wheel else None, version))
        _add(archive, "run_autograder", run_script(check))
        for path in scenes:
            archive.write(path, f"scenes/{path.name}")
        if wheel is not None:
            archive.write(wheel, wheel.name)
    return out.getvalue()


def _add(archive: zipfile.ZipFile, name: str, text: str) -> None:
    info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
    info.external_attr = EXECUTABLE
    info.compress_type = zipfile.ZIP_DEFLATED
    archive.writestr(info, text.encode("utf-8"))
