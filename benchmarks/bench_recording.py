"""Recording in the background: event-loop latency and monitor overhead.

Prints:
* the cost of a progress/cancel monitor on a 1M-step Bresenham recording
  (--repeats runs with and without the monitor, interleaved);
* the event loop's gaps (a 10 ms timer) in the main window while a flood
  fill of a 1024 x 1024 region records in the worker: max and p99 while
  recording, and the gap while the new trace is installed and shown.

    python benchmarks/bench_recording.py [--steps 1000000] [--repeats 5]
        [--switch SECONDS]   (the worker's switch interval; default app.recording's)
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import numpy as np  # noqa: E402

from algorithms.core import registry  # noqa: E402
from algorithms.core.trace import RecordMonitor  # noqa: E402

SQUARE = [(0, 0), (1025, 0), (1025, 1025), (0, 1025)]


def timed(action) -> float:
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def overhead(steps: int, repeats: int) -> None:
    spec = registry.get("line-bresenham")
    p, q = (0, 0), (steps - 1, (steps - 1) * 3 // 10)
    heard = []
    plain, watched = [], []
    # Interleaved, so that a change in the machine's load hits both alike.
    for _ in range(repeats):
        plain.append(timed(lambda: spec.record([p, q], grid=(4096, 4096))))
        watched.append(timed(lambda: spec.record([p, q], grid=(4096, 4096),
                                                 monitor=RecordMonitor(heard.append))))
    print(f"recording {steps:,} Bresenham steps ({repeats} runs each, interleaved):")
    for name, times in (("without a monitor", plain), ("with a monitor", watched)):
        print(f"  {name:18} min {min(times) * 1000:7.1f} ms, median "
              f"{statistics.median(times) * 1000:7.1f} ms")
    print(f"  monitor overhead: {(min(watched) / min(plain) - 1) * 100:+.1f}% (min), "
          f"{(statistics.median(watched) / statistics.median(plain) - 1) * 100:+.1f}% (median); "
          f"{len(heard) // repeats} reports a run")


def latency() -> None:
    from app.gui.recording import GapMeter
    from PySide6.QtWidgets import QApplication
    app = QApplication.instance() or QApplication([])
    from app.gui.window import MainWindow
    window = MainWindow("flood-fill", [[(0, 0), (6, 0), (6, 6), (0, 6)]], grid=(1030, 1030))
    window.show()  # the player keeps the program's own wait (app.model.session.SYNC_WAIT)
    for _ in range(20):
        app.processEvents()
    meter = GapMeter(10)
    started = meter.restart()
    window.set_points(SQUARE)
    returned = time.perf_counter()
    job = window.player.session.job
    while window.player.recording:
        app.processEvents()
        time.sleep(0.001)
    settled = time.perf_counter() + 0.1  # the new trace is shown within these ticks
    while time.perf_counter() < settled:
        app.processEvents()
        time.sleep(0.001)
    meter.stop()
    during, after = meter.split(job.finished_at)
    print(f"flood fill of a 1024 x 1024 region: {len(window.player.trace):,} steps recorded "
          f"in the worker in {job.finished_at - started:.2f} s (the edit waited "
          f"{window.player.sync_wait * 1000:.0f} ms for it first)")
    print(f"  event-loop gaps while recording ({len(during)} ticks of 10 ms): "
          f"max {max(during) * 1000:.1f} ms, p99 {np.percentile(during, 99) * 1000:.1f} ms"
          "  (target < 100 ms)")
    gap, at = max((gap, at) for gap, at in meter.ticks if at <= job.finished_at)
    print(f"  the longest ended {(at - started) * 1000:.0f} ms after the edit began; "
          f"the edit itself took {(returned - started) * 1000:.1f} ms")
    print(f"  installing and showing the trace: longest gap {max(after) * 1000:.1f} ms")
    window.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--switch", type=float, default=None,
                        help="switch interval while a worker records (seconds)")
    args = parser.parse_args()
    if args.switch is not None:
        import app.gui.recording
        app.gui.recording.SWITCH_INTERVAL = args.switch
    overhead(args.steps, args.repeats)
    latency()


if __name__ == "__main__":
    main()
