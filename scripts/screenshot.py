"""Save a picture of the main window for the README.

Bresenham half-way along the demo segment, just after switching from DDA,
so the picture shows the step's pixel, the two candidates of its decision,
the pixels where the two algorithms differ, the pseudo-code line and the
variables.

    python scripts/screenshot.py [OUT.png] [--size 1280x800]
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from PySide6.QtWidgets import QApplication  # noqa: E402

from app.window import DEMO_POINTS, MainWindow  # noqa: E402


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Save a screenshot of the main window.")
    parser.add_argument("out", nargs="?", default=str(ROOT / "resources" / "screenshot.png"))
    parser.add_argument("--size", default="1280x800", help="window size WxH (default 1280x800)")
    parser.add_argument("--step", type=int, default=12, help="step to show (default 12)")
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.lower().split("x"))

    app = QApplication.instance() or QApplication([])
    app.setStyle("Fusion")
    window = MainWindow("line-dda", DEMO_POINTS)
    window.resize(width, height)
    window.show()
    window.set_algorithm("line-bresenham")
    window.player.seek(args.step)
    # The status bar as if the cursor rested on the step's pixel.
    window._hover(window.player.state().pixel)
    for _ in range(10):
        app.processEvents()
    window.grab().save(args.out)
    print(f"saved {args.out} ({width}x{height})")
    window.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
