"""Every performance figure of RasterLab against its peer, and the targets.

One command, one run: each figure is timed in interleaved pairs (ours, then
the peer, then ours again, the order alternating), so that a machine shared
with other work slows both sides alike. A figure is printed as the ratio
ours / peer with min / median / max over the pairs, next to both medians.
Figures without a peer (a time bound, bytes per step) print min / median /
max of their own. Then, for every target, one line:

    target <name>: <figure> (target <bound>) met
    target <name>: <figure> (target <bound>) missed

    python benchmarks/run_all.py [--quick] [--only SECTION ...]

``--quick`` uses fewer repeats and smaller workloads where the full one
takes minutes (the lines stay the same; the figure says what it measured)
and finishes in under two minutes. The peers are OpenCV (headless), Pillow
and scikit-image, the test dependencies of the project, a bare generator
(consumed without recording) and a bare pyqtgraph ImageItem.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import run_all_figures as figures  # noqa: E402

SECTIONS = ("kernels", "recording", "access", "report", "window", "startup")


class Results:
    """The figures printed so far and the target lines they feed."""

    def __init__(self):
        self.targets: list[str] = []

    def pair(self, name: str, ours, peer, repeats: int, peer_name: str) -> float:
        """Time ``ours`` and ``peer`` in interleaved pairs; print and return the median ratio."""
        mine, theirs = figures.interleaved(lambda: _timed(ours), lambda: _timed(peer), repeats)
        return self.compare(name, mine, theirs, peer_name)

    def compare(self, name: str, mine, theirs, peer_name: str) -> float:
        """Print paired times (seconds) as ratios; return the median ratio."""
        ratios = [a / b for a, b in zip(mine, theirs)]
        median = statistics.median(ratios)
        print(f"{name:<44} ours {_ms(statistics.median(mine))}  {peer_name:<14} "
              f"{_ms(statistics.median(theirs))}  ratio min {min(ratios):7.2f}x "
              f"median {median:7.2f}x max {max(ratios):7.2f}x  ({len(ratios)} pairs)")
        return median

    def spread(self, name: str, values, unit: str) -> float:
        """Print min / median / max of measured values; return the median."""
        median = statistics.median(values)
        print(f"{name:<44} min {min(values):9.2f} {unit}  median {median:9.2f} {unit}  "
              f"max {max(values):9.2f} {unit}  ({len(values)} samples)")
        return median

    def target(self, name: str, figure: float, bound: float, unit: str, note: str = "") -> None:
        met = "met" if figure <= bound else "missed"
        extra = f" [{note}]" if note else ""
        self.targets.append(f"target {name}: {_fmt(figure, unit)} (target {_fmt(bound, unit)})"
                            f" {met}{extra}")


def _fmt(value: float, unit: str) -> str:
    if unit == "x":
        return f"{value:.2f}x"
    return f"{value:.1f} {unit}"


def _ms(seconds: float) -> str:
    return f"{seconds * 1000:9.2f} ms"


def _timed(action) -> float:
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="fewer repeats, smaller workloads: under two minutes")
    parser.add_argument("--only", nargs="+", choices=SECTIONS, default=list(SECTIONS),
                        help="run only these sections")
    args = parser.parse_args(argv)
    results = Results()
    began = time.perf_counter()
    for section in SECTIONS:
        if section in args.only:
            print(f"\n== {section}")
            getattr(figures, section)(results, args.quick)
    print(f"\n== targets ({time.perf_counter() - began:.0f} s in all)")
    for line in results.targets:
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
