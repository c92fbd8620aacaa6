"""Save pictures of the main window for the README.

Without ``--scene``: Bresenham half-way along the demo segment, just after
switching from DDA, so the picture shows the step's pixel, the two
candidates of its decision, the pixels where the two algorithms differ, the
pseudo-code line and the variables.

With ``--scene`` one of the family pictures, or ``--all`` for every one of
them, saved as resources/screenshot-SCENE.png:

    circle    the midpoint circle mid-run
    polygon   the scan-line fill of a concave polygon with a hole, its edge
              table and active edge table on show
    fill      a flood fill mid-run, with its queue
    triangle  one triangle mid-traversal, with its edge values
    mesh      a small mesh with the coverage overlay
    samples   supersampling a triangle on a small grid: the samples of an
              edge pixel as dots (hit filled, miss hollow)
    depth     the z-buffer on two piercing triangles, with the depth buffer
    painter   the painter's algorithm on the same triangles, compared with
              the z-buffer: the pixels where the two disagree

    python scripts/screenshot.py [OUT.png] [--size 1280x800] [--step N]
    python scripts/screenshot.py --scene polygon [OUT.png]
    python scripts/screenshot.py --all
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

from app.gui.window import DEMO_POINTS, MainWindow  # noqa: E402

RESOURCES = ROOT / "resources"


def line_scene(app, size, step):
    window = _window(app, "line-dda", DEMO_POINTS, size=size)
    window.set_algorithm("line-bresenham")
    window.player.seek(step)
    return window


def circle_scene(app, size, _step):
    window = _window(app, "circle-midpoint", [(15, 11)], {"radius": 9}, size=size)
    trace = window.player.trace
    # A decision past the middle of the run: its E and SE candidates show.
    window.player.seek(next(i for i in range(len(trace) // 2, len(trace))
                            if trace.candidates_at(i)))
    return window


def polygon_scene(app, size, _step):
    outer = [(2.5, 2.25), (29.25, 3.5), (21.5, 11.75), (28.75, 21.5), (12.0, 15.25),
             (3.25, 21.0)]
    hole = [(7.0, 6.25), (15.5, 6.5), (10.25, 11.5)]
    window = _window(app, "polygon-scanline", [outer, hole], size=size)
    trace = window.player.trace
    # A span on a row that crosses the hole, just after a fresh active
    # edge table with four edges in it.
    spans = trace.spans()
    spans = spans["step"][spans["y"] == 9].tolist()
    window.player.seek(spans[-1])
    return window


def fill_scene(app, size, _step):
    outline = [(3, 2), (27, 3), (20, 11), (28, 20), (12, 15), (4, 21)]
    window = _window(app, "flood-fill", [outline], {"order": "queue", "seed": (9, 8)},
                     size=size)
    window.player.seek(window.player.last * 2 // 5)
    return window


def triangle_scene(app, size, _step):
    window = _window(app, "triangle-bbox", [(4.25, 3.5), (27.5, 8.75), (11.125, 21.25)],
                     size=size)
    trace = window.player.trace
    # A centre just outside one edge, about half-way through the box.
    middle = len(trace) // 2
    index = next(i for i in range(middle, len(trace))
                 if trace.step(i).kind == "visit" and "e0" in trace.step(i).values)
    window.player.seek(index)
    return window


def mesh_scene(app, size, _step):
    # A fan of four triangles round a centre vertex, every vertex on a pixel
    # centre: the shared edges run through pixel centres, which the
    # inclusive rule gives to both triangles (the top-left rule to one).
    c, a, b, d, e = (16.5, 12.5), (4.5, 4.5), (28.5, 4.5), (28.5, 20.5), (4.5, 20.5)
    mesh = [c, a, b, c, b, d, c, d, e, c, e, a]
    window = _window(app, "triangle-scan", mesh, {"fill_rule": "inclusive"}, size=size)
    window.coverage.setChecked(True)
    window.player.to_last()
    return window


def samples_scene(app, size, _step):
    window = _window(app, "aa-supersample", [(1.3, 1.2), (10.6, 3.1), (4.2, 8.4)],
                     grid=(12, 9), size=size)
    trace = window.player.trace
    # The last sample of an edge pixel some of whose samples hit and some miss.
    index = None
    for i in range(len(trace) // 3, len(trace) - 1):
        step, after = trace.step(i), trace.step(i + 1)
        if "sx" in step.values and "sx" not in after.values and 0.3 < step.values["coverage"] < 0.8:
            index = i
            break
    window.player.seek(index if index is not None else len(trace) // 2)
    return window


def _visibility(app, algorithm, size):
    from algorithms.visibility.zbuffer_painter import intersecting_scene
    scene = intersecting_scene()
    options = {k: v for k, v in scene["options"].items() if k != "sort"}
    return _window(app, algorithm, scene["points"], options, grid=scene["grid"], size=size)


def depth_scene(app, size, _step):
    window = _visibility(app, "zbuffer", size)
    window.player.seek(len(window.player.trace) * 3 // 4)
    return window


def painter_scene(app, size, _step):
    window = _visibility(app, "zbuffer", size)
    window.set_algorithm("painter")
    window.compare.setChecked(True)
    window.player.to_last()
    return window


SCENES = {"line": line_scene, "circle": circle_scene, "polygon": polygon_scene,
          "fill": fill_scene, "triangle": triangle_scene, "mesh": mesh_scene,
          "samples": samples_scene, "depth": depth_scene, "painter": painter_scene}
# Scenes with the tables panel under the grid want a taller window.
SIZES = {"polygon": (1280, 900), "painter": (1280, 900)}


def _window(app, algorithm, points, options=None, size=(1280, 800), grid=None):
    window = MainWindow(algorithm, points, options) if grid is None else \
        MainWindow(algorithm, points, options, grid=tuple(grid))
    window.resize(*size)
    window.show()
    for _ in range(5):
        app.processEvents()
    return window


def save(app, scene: str, out: Path, size, step: int) -> None:
    window = SCENES[scene](app, size, step)
    # The status bar as if the cursor rested on the step's pixel.
    state = window.player.state()
    window.grid.hoverChanged.emit(state.pixel if state is not None else None)
    for _ in range(10):
        app.processEvents()
    window.grab().save(str(out))
    print(f"saved {out} ({size[0]}x{size[1]})")
    window.close()


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Save screenshots of the main window.")
    parser.add_argument("out", nargs="?", help="the picture to write")
    parser.add_argument("--scene", choices=sorted(SCENES), default="line")
    parser.add_argument("--all", action="store_true",
                        help="every family scene, as resources/screenshot-SCENE.png")
    parser.add_argument("--size", default=None, help="window size WxH (default 1280x800)")
    parser.add_argument("--step", type=int, default=12, help="step of the line scene (default 12)")
    args = parser.parse_args(argv)

    app = QApplication.instance() or QApplication([])
    app.setStyle("Fusion")
    scenes = [name for name in SCENES if name != "line"] if args.all else [args.scene]
    for scene in scenes:
        size = SIZES.get(scene, (1280, 800))
        if args.size:
            size = tuple(int(v) for v in args.size.lower().split("x"))
        if args.out and not args.all:
            out = Path(args.out)
        else:
            out = RESOURCES / ("screenshot.png" if scene == "line" else f"screenshot-{scene}.png")
        save(app, scene, out, size, args.step)
    return 0


if __name__ == "__main__":
    sys.exit(main())
