"""Grading a class: 150 generated submissions (correct, wrong and looping)
checked against line-bresenham with `rasterlab check ... --jobs 2`, as a
lecturer runs it. Prints the total and the time per submission, overall
and per kind; a looping submission stops after --give-up-after time-outs.

    python benchmarks/bench_batch.py [--count 150] [--jobs 2] [--cases hard]
"""
from __future__ import annotations

import argparse
import csv
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STUDENTS = ROOT / "resources" / "students"
LOOPS = "def draw(x0, y0, x1, y1):\n    while True:\n        pass\n    yield x0, y0\n"
# Of every ten submissions: six correct, three wrong, one looping.
MIX = ["correct"] * 6 + ["wrong"] * 3 + ["looping"]


def write_class(folder: Path, count: int) -> dict:
    """One folder per student, s001 ... ; their kinds by id."""
    texts = {"correct": (STUDENTS / "bresenham_correct.py").read_text(),
             "wrong": (STUDENTS / "off_by_one.py").read_text(), "looping": LOOPS}
    kinds = {}
    for n in range(count):
        student_id, kind = f"s{n + 1:03d}", MIX[n % len(MIX)]
        (folder / student_id).mkdir()
        (folder / student_id / "line.py").write_text(texts[kind])
        kinds[student_id] = kind
    return kinds


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=150)
    parser.add_argument("--jobs", default="2")
    parser.add_argument("--cases", nargs="+", default=["hard"])
    parser.add_argument("--time-limit", default="2")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="rasterlab-bench-batch-") as folder:
        folder = Path(folder)
        kinds = write_class(folder, args.count)
        marks = folder / "marks.csv"
        command = [sys.executable, "-m", "rasterlab", "check",
                   *sorted(str(path) for path in folder.iterdir() if path.is_dir()),
                   "--against", "line-bresenham", "--cases", *args.cases,
                   "--time-limit", args.time_limit, "--jobs", args.jobs, "--csv", str(marks)]
        started = time.perf_counter()
        done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
        total = time.perf_counter() - started
        if done.returncode not in (0, 1):
            print(done.stderr, file=sys.stderr)
            return 1
        rows = list(csv.DictReader(marks.open()))
    print(done.stdout.splitlines()[0])
    print(done.stdout.splitlines()[2])
    print(f"{len(rows)} submissions, --jobs {args.jobs}: {total:.1f} s in all, "
          f"{total / len(rows):.2f} s per submission (wall clock, the command as a whole)")
    for kind in ("correct", "wrong", "looping"):
        seconds = [float(row["seconds"]) for row in rows if kinds[row["id"]] == kind]
        print(f"  {kind:8} {len(seconds):4} submissions: median {statistics.median(seconds):.2f} s, "
              f"max {max(seconds):.2f} s each (its own grading, one job)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
