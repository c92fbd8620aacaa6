"""Fingerprints of what RasterLab computes, to prove a refactor changed nothing.

    python scripts/fingerprint.py > before.txt
    ... change the code ...
    python scripts/fingerprint.py > after.txt
    diff before.txt after.txt

One line per run, ``name  sha256``:

* every case of the hard-case catalogue (tests/support/catalogue.py):
  each recorded step, the pseudo-code, the final variables and the final
  raster, or the message of a refusal;
* ``rasterlab run --scene SCENE --json`` of every shipped scene;
* ``rasterlab list --json``.

The hashes cover values as Python prints them, so a value computed in a
different order (a float off in its last bit) shows as a different line.
"""
from __future__ import annotations

import hashlib
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from algorithms.core import registry  # noqa: E402
from algorithms.core.errors import InputError  # noqa: E402
from tests.support.catalogue import CASES  # noqa: E402


def _digest(parts) -> str:
    hasher = hashlib.sha256()
    for part in parts:
        hasher.update(repr(part).encode("utf-8", "surrogatepass"))
        hasher.update(b"\n")
    return hasher.hexdigest()[:24]


def _trace_parts(trace):
    yield tuple(trace.code)
    for i in range(len(trace)):
        yield trace.step(i)
    yield sorted(trace.final_variables().items())
    if len(trace):
        raster = trace.raster_at(len(trace) - 1)
        for name in ("width", "height", "counts", "colors", "depth"):
            value = getattr(raster, name)
            yield name, (value.tobytes() if hasattr(value, "tobytes") else value)


def case_lines():
    for case in CASES:
        spec = registry.get(case.algorithm)
        try:
            trace = spec.record(case.points, case.options, case.grid)
        except InputError as error:
            yield f"case {case}", _digest(["refused", str(error)])
            continue
        yield f"case {case}", _digest(_trace_parts(trace))


def command_lines():
    command = [sys.executable, "-m", "rasterlab"]
    scenes = sorted((ROOT / "resources" / "scenes").rglob("*.json"))
    for scene in scenes:
        done = subprocess.run(command + ["run", "--scene", str(scene), "--json"],
                              capture_output=True, cwd=ROOT)
        yield (f"scene {scene.relative_to(ROOT).as_posix()}",
               _digest([done.returncode, done.stdout, done.stderr]))
    done = subprocess.run(command + ["list", "--json"], capture_output=True, cwd=ROOT)
    yield "list --json", _digest([done.returncode, done.stdout, done.stderr])


def main() -> None:
    for name, digest in (*case_lines(), *command_lines()):
        print(f"{name}  {digest}", flush=True)


if __name__ == "__main__":
    main()
