"""Child process of run_all.py: whole-window steps against a bare ImageItem.

    python benchmarks/run_all_window.py SIDE PAIRS

Opens the main window on a Bresenham line across a SIDE x SIDE grid and
steps it forward one step at a time: the player's seek, then the event loop
until every repaint and relayout the step asked for is done (grid,
pseudo-code, variables, transport, every panel on show), as after a key
press. The peer sets a SIDE x SIDE RGBA image on a bare pyqtgraph ImageItem
and lets the event loop repaint it the same way. Prints PAIRS lines
"bare_ms window_ms", interleaved.
"""
from __future__ import annotations

import os
import sys
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import numpy as np  # noqa: E402
import pyqtgraph as pg  # noqa: E402
from PySide6.QtWidgets import QApplication  # noqa: E402

from app.gui.window import MainWindow  # noqa: E402


def _settle(app) -> None:
    """Run the event loop until it is idle: the paints a change asked for,
    and the relayouts and paints those ask for in turn."""
    app.processEvents()
    app.processEvents()


def main() -> int:
    side, pairs = int(sys.argv[1]), int(sys.argv[2])
    app = QApplication.instance() or QApplication([])
    window = MainWindow("line-bresenham", [(2, 3), (side - 3, side * 3 // 5)], grid=(side, side))
    window.resize(1280, 800)
    window.show()
    for _ in range(5):
        app.processEvents()
    player = window.player
    player.pause()
    view = pg.GraphicsLayoutWidget()
    box = view.addViewBox()
    item = pg.ImageItem(axisOrder="row-major")
    box.addItem(item)
    view.resize(800, 800)
    view.show()
    item.setImage(np.zeros((side, side, 4), np.uint8), autoLevels=False)
    box.autoRange()
    for _ in range(5):
        app.processEvents()
    images = [np.full((side, side, 4), k * 40, np.uint8) for k in range(2)]
    start = len(player.trace) // 3
    for k in range(pairs):
        t0 = time.perf_counter()
        item.setImage(images[k % 2], autoLevels=False)
        _settle(app)
        t1 = time.perf_counter()
        player.seek(start + k)
        _settle(app)
        t2 = time.perf_counter()
        print(f"{(t1 - t0) * 1000:.3f} {(t2 - t1) * 1000:.3f}")
    window.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
