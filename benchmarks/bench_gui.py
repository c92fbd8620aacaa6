"""Cost of one GUI frame update on a 512 x 512 grid, offscreen.

A frame update is what happens when the step on show changes:
``state_at`` (replay), ``compose`` (RGBA image), ``setImage`` and a
synchronous repaint of the grid. It is timed on its own ("grid") and as the
whole window does it, with the pseudo-code and variables panels ("window").

Prints the median and 90th percentile over the steps of a long Bresenham
run (the target is a median of at most 5 ms for the grid).

    python benchmarks/bench_gui.py [--steps 200] [--grid 512]
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

from PySide6.QtWidgets import QApplication  # noqa: E402

from app.render.compose import compose  # noqa: E402
from app.gui.window import MainWindow  # noqa: E402


def percentile(values, fraction):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(fraction * (len(ordered) - 1))))]


def report(name, seconds):
    ms = [s * 1000 for s in seconds]
    print(f"{name:<34} median {statistics.median(ms):6.2f} ms   p90 {percentile(ms, 0.9):6.2f} ms"
          f"   ({len(ms)} frames)")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=200, help="frames to time (default 200)")
    parser.add_argument("--grid", type=int, default=512, help="grid side (default 512)")
    args = parser.parse_args(argv)

    app = QApplication.instance() or QApplication([])
    side = args.grid
    points = [(2, 3), (side - 3, side * 3 // 5)]
    window = MainWindow("line-bresenham", points, grid=(side, side))
    window.resize(1280, 800)
    window.show()
    for _ in range(5):
        app.processEvents()
    player, grid = window.player, window.grid
    trace = player.trace
    frames = len(trace)
    stride = max(1, (frames - 1) // args.steps)
    indices = [(k * stride) % frames for k in range(1, args.steps + 1)]
    print(f"grid {side}x{side}, Bresenham {points[0]} -> {points[1]}: {frames} steps; "
          f"timing {len(indices)} of them")

    # The grid alone: replay, compose, setImage, repaint.
    replay, composing, showing, total = [], [], [], []
    for i in indices:
        t0 = time.perf_counter()
        state = trace.state_at(i)
        t1 = time.perf_counter()
        image = compose(state.raster)
        t2 = time.perf_counter()
        grid.set_image(image)
        grid.set_highlights([state.pixel] if state.pixel else [], state.candidates)
        grid.viewport().repaint()
        t3 = time.perf_counter()
        replay.append(t1 - t0)
        composing.append(t2 - t1)
        showing.append(t3 - t2)
        total.append(t3 - t0)
    report("  state_at", replay)
    report("  compose", composing)
    report("  setImage + outlines + repaint", showing)
    report("grid frame update", total)

    # The whole window: the player moves, every panel follows, all repaint.
    whole = []
    for i in indices:
        player.pause()
        t0 = time.perf_counter()
        player.seek(i if i != player.index else (i + 1) % frames)
        grid.viewport().repaint()
        window.code.repaint()
        window.variables.repaint()
        whole.append(time.perf_counter() - t0)
    report("window frame update (all panels)", whole)
    window.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
