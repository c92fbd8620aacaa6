"""The sections of run_all.py: each times its workloads and adds its targets.

A section is ``name(results, quick)``; ``results`` is run_all.Results.
"""
from __future__ import annotations

import collections
import gc
import math
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from algorithms import triangles  # noqa: E402
from algorithms.core import compiled, registry  # noqa: E402
from algorithms.lines.batch import bresenham_lines  # noqa: E402
from algorithms.circles.batch import draw_midpoint_circles, midpoint_circles  # noqa: E402
from algorithms.antialias.lines import wu  # noqa: E402
from algorithms.antialias.wu_kernel import draw_wu_lines  # noqa: E402
from algorithms.antialias.wu_kernel import wu_lines as batched_wu_lines  # noqa: E402
from algorithms.circles.midpoint import midpoint_circle_pixels  # noqa: E402
from algorithms.lines.bresenham import bresenham_pixels  # noqa: E402
from algorithms.polygons import scanline_fill_many, scanline_pixels  # noqa: E402

SIZE = 1024


def _cv2():
    import cv2  # a test dependency: opencv-python-headless

    cv2.setNumThreads(1)  # ours runs on one core too
    return cv2


# ------------------------------------------------------------------ kernels
def kernels(results, quick: bool) -> None:
    repeats = 5 if quick else 11
    # numba is optional (rasterlab[fast]): the figures say which loops they timed.
    print(f"compiled loops: {compiled.path()} (algorithms/core/compiled.py)")
    rng = np.random.default_rng(7)
    _triangle_figures(results, rng, repeats)
    _polygon_figures(results, rng, repeats, 2000 if quick else 10_000)
    _line_figures(results, rng, repeats, 2000 if quick else 10_000)
    _circle_figures(results, rng, repeats)
    _flood_figure(results, 256 if quick else 1024, max(3, repeats // 2))


def _kernel_target(results, name, ratio, note=""):
    results.target(f"kernel {name} vs cv2", ratio, 1.0, "x", note)


def _large_triangles(n, rng):
    tris = []
    for _ in range(n):
        u, v = rng.uniform(0.05, 0.95, 2)
        tris += [(u * SIZE, 0.0), (SIZE, v * SIZE), (0.0, SIZE)]
    return np.round(np.array(tris) * 256) / 256


def _small_shapes(n, corners, rng, spread=6.0):
    centres = rng.uniform(8, SIZE - 8, (n, 1, 2))
    offsets = rng.uniform(-spread, spread, (n, corners, 2))
    return np.round((centres + offsets) * 256) / 256


def _cv2_polys(shapes):
    # OpenCV's fixed point (shift=8) with pixel centres at whole numbers.
    return [np.round((s - 0.5) * 256).astype(np.int32) for s in shapes]


def _triangle_figures(results, rng, repeats):
    cv2 = _cv2()
    from PIL import Image, ImageDraw

    large = _large_triangles(20, rng)
    polys = _cv2_polys(large.reshape(-1, 3, 2))
    canvas = np.zeros((SIZE, SIZE), np.uint8)
    # Both sides fill a uint8 canvas with 1; ours snaps the float vertices itself.
    ours = _warm(lambda: triangles.fill_canvas(large, (SIZE, SIZE), canvas, 1))
    peer = lambda: [cv2.fillPoly(canvas, [p], 1, cv2.LINE_8, 8) for p in polys]  # noqa: E731
    _kernel_target(results, "20 large triangles",
                   results.pair("20 large triangles 1024^2 (exact, uint8 canvas)", ours, peer,
                                repeats, "cv2.fillPoly"))
    image = Image.new("L", (SIZE, SIZE))
    draw = ImageDraw.Draw(image)
    flat = [[(float(x) - 0.5, float(y) - 0.5) for x, y in t] for t in large.reshape(-1, 3, 2)]
    results.pair("20 large triangles 1024^2 (exact, uint8 canvas)", ours,
                 lambda: [draw.polygon(t, fill=1) for t in flat], repeats, "Pillow")
    small = _small_shapes(10_000, 3, rng).reshape(-1, 2)
    small_polys = _cv2_polys(small.reshape(-1, 3, 2))
    _kernel_target(results, "10k small triangles", results.pair(
        "10k small triangles (exact, uint8 canvas)",
        _warm(lambda: triangles.fill_canvas(small, (SIZE, SIZE), canvas, 1)),
        lambda: [cv2.fillPoly(canvas, [p], 1, cv2.LINE_8, 8) for p in small_polys], repeats,
        "cv2.fillPoly"))


def _warm(action):
    """``action`` run once: the compiled loops load from numba's cache before timing."""
    action()
    return action


def _polygon_figures(results, rng, repeats, count):
    cv2 = _cv2()
    shapes = _small_shapes(count, 5, rng)
    polys = _cv2_polys(shapes)
    lists = [[tuple(p) for p in s.tolist()] for s in shapes]
    counts = np.zeros((SIZE, SIZE), np.int32)

    def ours():
        for points in lists:
            pixels = scanline_pixels([points])
            counts[pixels[:, 1].clip(0, SIZE - 1), pixels[:, 0].clip(0, SIZE - 1)] += 1

    canvas = np.zeros((SIZE, SIZE), np.uint8)
    peer = lambda: [cv2.fillPoly(canvas, [p], 1, cv2.LINE_8, 8) for p in polys]  # noqa: E731
    results.pair(f"{count} small polygons (kernel per polygon)", ours, peer, repeats,
                 "cv2.fillPoly")
    # One call for all of them, filling a uint8 canvas with 1 as the peer does.
    batched = _warm(lambda: scanline_fill_many(shapes, (SIZE, SIZE), canvas, 1))
    ratio = results.pair(f"{count} small polygons (batched, uint8 canvas)", batched, peer,
                         repeats, "cv2.fillPoly")
    _kernel_target(results, "small polygons", ratio, f"{count} polygons, batched")


def _line_figures(results, rng, repeats, count):
    cv2 = _cv2()
    from skimage.draw import line, line_aa

    ends = rng.integers(20, SIZE - 20, (count, 1, 2)) + rng.integers(-8, 9, (count, 2, 2))
    lines = [((int(a[0]), int(a[1])), (int(b[0]), int(b[1]))) for a, b in ends]
    canvas = np.zeros((SIZE, SIZE), np.uint8)

    def ours():
        for points in lines:
            pixels = bresenham_pixels(points, {"symmetric": False})
            canvas[pixels[:, 1], pixels[:, 0]] = 1

    peer = lambda: [cv2.line(canvas, p, q, 1, 1, cv2.LINE_8) for p, q in lines]  # noqa: E731
    results.pair(f"{count} short lines (kernel per line)", ours, peer, repeats, "cv2.line")
    starts, stops = ends[:, 0], ends[:, 1]

    def batched():
        pixels, _ = bresenham_lines(starts, stops)
        canvas[pixels[:, 1], pixels[:, 0]] = 1

    ratio = results.pair(f"{count} short lines (batched kernel)", batched, peer, repeats,
                         "cv2.line")
    _kernel_target(results, "short lines", ratio, f"{count} lines, batched")
    long_lines = [((int(a), 0), (int(b), SIZE - 1)) for a, b in rng.integers(0, SIZE, (32, 2))]

    def ours_long():
        for points in long_lines:
            pixels = bresenham_pixels(points, {"symmetric": False})
            canvas[pixels[:, 1], pixels[:, 0]] = 1

    def skimage_long():
        for (x0, y0), (x1, y1) in long_lines:
            rr, cc = line(y0, x0, y1, x1)
            canvas[rr, cc] = 1

    results.pair("32 long lines (Bresenham kernel)", ours_long, skimage_long, repeats,
                 "skimage.line")
    wu_lines = lines[:max(200, count // 10)]
    wu_options = {"endpoints": "full"}
    cv2_wu = lambda: [cv2.line(canvas, p, q, 255, 1, cv2.LINE_AA)  # noqa: E731
                      for p, q in wu_lines]
    results.pair(f"{len(wu_lines)} Wu lines (generator)",
                 lambda: [collections.deque(wu(p, wu_options), 0) for p in wu_lines], cv2_wu,
                 repeats, "cv2.line AA")
    wu_starts, wu_ends = ends[:len(wu_lines), 0], ends[:len(wu_lines), 1]

    def wu_batched():
        pixels, intensity, _ = batched_wu_lines(wu_starts, wu_ends)
        canvas[pixels[:, 1], pixels[:, 0]] = intensity * 255

    results.pair(f"{len(wu_lines)} Wu lines (batched kernel)", wu_batched, cv2_wu, repeats,
                 "cv2.line AA")
    # Intensities into the canvas as grey levels, as the peers leave it.
    wu_drawn = lambda: draw_wu_lines(canvas, wu_starts, wu_ends)  # noqa: E731
    wu_drawn()  # the first call compiles (or loads the compiled loop)
    ratio = results.pair(f"{len(wu_lines)} Wu lines (into canvas, compiled)", wu_drawn, cv2_wu,
                         repeats, "cv2.line AA")
    _kernel_target(results, "Wu lines", ratio, "batched, compiled, into the canvas")

    def skimage_wu():
        for (x0, y0), (x1, y1) in wu_lines:
            rr, cc, val = line_aa(y0, x0, y1, x1)
            canvas[rr, cc] = val * 255

    results.pair(f"{len(wu_lines)} Wu lines (into canvas, compiled)", wu_drawn, skimage_wu,
                 repeats, "skimage.aa")


def _circle_figures(results, rng, repeats):
    cv2 = _cv2()
    from skimage.draw import circle_perimeter

    centres = [tuple(int(v) for v in c) for c in rng.integers(20, SIZE - 20, (1000, 2))]
    canvas = np.zeros((SIZE, SIZE), np.uint8)

    def ours():
        for centre in centres:
            pixels = midpoint_circle_pixels([centre], {"radius": 10})
            canvas[pixels[:, 1], pixels[:, 0]] = 1

    peer = lambda: [cv2.circle(canvas, c, 10, 1, 1, cv2.LINE_8) for c in centres]  # noqa: E731
    results.pair("1000 circles r = 10 (kernel per circle)", ours, peer, repeats, "cv2.circle")

    def batched():
        pixels, _ = midpoint_circles(centres, 10)
        canvas[pixels[:, 1], pixels[:, 0]] = 1

    results.pair("1000 circles r = 10 (batched kernel)", batched, peer, repeats, "cv2.circle")
    into_canvas = lambda: draw_midpoint_circles(canvas, centres, 10)  # noqa: E731
    ratio = results.pair("1000 circles r = 10 (batched, into canvas)", into_canvas, peer,
                         repeats, "cv2.circle")
    _kernel_target(results, "circles r = 10", ratio, "batched, into the canvas")

    def skimage_circles():
        for x, y in centres:
            rr, cc = circle_perimeter(y, x, 10)
            canvas[rr, cc] = 1

    results.pair("1000 circles r = 10 (batched, into canvas)", into_canvas, skimage_circles,
                 repeats, "skimage")


def _flood_figure(results, side, repeats):
    spec = registry.get("flood-fill")
    contour, peer = _flood_scene(side)
    results.pair(f"flood fill {side}^2, span order (recording)",
                 lambda: spec.record([contour], {"order": "span"}, (side, side),
                                     step_cap=50_000_000), peer, repeats, "cv2.floodFill")
    # The kernel draws the outline itself and gives the filled raster; the
    # seed is given, as cv2 is given it. It takes a millisecond, so --quick
    # times it on the target's 1024^2 too. Its first call compiles (or
    # loads the compiled code), so it runs once before the timing.
    contour, peer = _flood_scene(SIZE)
    options = spec.resolve({"seed": (SIZE // 2, SIZE // 2)})
    kernel = lambda: spec.kernel([contour], options, (SIZE, SIZE))  # noqa: E731
    kernel()
    ratio = results.pair(f"flood fill {SIZE}^2 (kernel: outline + fill)", kernel, peer,
                         max(repeats, 9), "cv2.floodFill")
    _kernel_target(results, "flood fill", ratio, f"{SIZE}^2, span fill kernel")


def _flood_scene(side):
    """A square outline one pixel in from the grid's edges, and cv2's fill of
    its inside (4-connected) from the centre, the outline drawn in already."""
    cv2 = _cv2()
    contour = [(1, 1), (side - 2, 1), (side - 2, side - 2), (1, side - 2)]
    image = np.zeros((side, side), np.uint8)
    image[1, 1:side - 1] = image[side - 2, 1:side - 1] = 255
    image[1:side - 1, 1] = image[1:side - 1, side - 2] = 255

    def peer():
        mask = np.zeros((side + 2, side + 2), np.uint8)
        cv2.floodFill(image.copy(), mask, (side // 2, side // 2), 128, flags=4)
    return contour, peer


def interleaved(ours, peer, repeats: int):
    """The results of ``ours()`` and ``peer()`` called in pairs, each side
    first in every other pair, so that a slow spell of the machine falls on
    both."""
    mine, theirs = [], []
    for k in range(repeats):
        if k % 2:
            theirs.append(peer())
            mine.append(ours())
        else:
            mine.append(ours())
            theirs.append(peer())
    return mine, theirs


# ---------------------------------------------------------------- recording
RECORDED = (
    ("Bresenham", "line-bresenham", lambda s: ([(0, 0), (s - 1, s // 3)], {}), 4096),
    ("midpoint circle", "circle-midpoint", lambda s: ([(s // 2, s // 2)], {"radius": s // 2 - 2}),
     4096),
    ("triangle-bbox", "triangle-bbox", lambda s: ([(1.5, 2), (s - 3.25, 7), (s / 2, s - 2)], {}),
     1024),
    ("supersampling", "aa-supersample", lambda s: ([(1.5, 2), (s - 3.25, 7), (s / 2, s - 2)],
                                                    {"n": 2}), 128),
    ("scan-line fill", "polygon-scanline",
     lambda s: ([[(2, 2), (s - 3, 5), (s // 2, s - 3)], [(s // 3, s // 3), (s // 2, s // 3),
                                                          (s // 2, s // 2)]], {}), 1024),
    ("flood fill", "flood-fill", lambda s: ([[(1, 1), (s - 2, 1), (s - 2, s - 2), (1, s - 2)]],
                                            {}), 512),
)


def recording(results, quick: bool) -> None:
    repeats = 3 if quick else 7
    for label, name, make, side in RECORDED:
        side = side // 2 if quick and side in (512, 1024) else side
        spec = registry.get(name)
        points, options = make(side)
        grid = (side, side)
        record = lambda: spec.record(points, options, grid, step_cap=50_000_000)  # noqa: E731
        run = lambda: collections.deque(spec.frames(points, options, grid), 0)  # noqa: E731
        # A run of a few milliseconds is repeated within each sample (both
        # sides alike), so that one preemption does not decide a pair.
        times = min(1000, max(1, math.ceil(0.03 / _timed(run))))
        ours = lambda: [record() for _ in range(times)]  # noqa: E731
        bare = lambda: [run() for _ in range(times)]  # noqa: E731
        each = f" ({times} runs a sample)" if times > 1 else ""
        ratio = results.pair(f"record {label} / bare generator{each}", ours, bare, repeats,
                             "generator")
        results.target(f"recording {label} / bare generator", ratio, 2.0, "x")
        kept, peak, steps = _memory(record)
        print(f"{'  kept per step':<44} {kept / steps:9.1f} B  peak/kept {peak / kept:5.2f}"
              f"  ({steps:,} steps)")
        results.target(f"bytes kept per step, {label}", kept / steps, 64, "B")
        if steps > 200_000:  # on small runs the fixed chunk buffers decide the peak
            results.target(f"recording peak / kept, {label}", peak / kept, 2.0, "x")


def _memory(record):
    """Bytes a recording keeps (after collecting its garbage) and its peak."""
    gc.collect()
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    trace = record()
    peak = tracemalloc.get_traced_memory()[1]
    gc.collect()  # cycles of finished generators are garbage, not kept
    kept = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    return kept - before, peak - before, len(trace)


# ------------------------------------------------------------------- access
def access(results, quick: bool) -> None:
    """state_at at random steps of big runs on big grids (no peer: a time bound)."""
    spec = registry.get("triangle-bbox")
    side = 4096
    cap = 1_000_000 if quick else 5_000_000
    span = int((2 * cap) ** 0.5)  # a right triangle whose box holds about ``cap`` pixels
    runs = [(f"triangle-bbox {cap:,} steps on {side}^2", spec,
             [(1.5, 1.5), (span + 0.5, 1.5), (1.5, span + 0.5)], {}, (side, side), cap)]
    fill_side = 512 if quick else 2048
    contour = [(1, 1), (fill_side - 2, 1), (fill_side - 2, fill_side - 2), (1, fill_side - 2)]
    runs.append((f"flood fill {fill_side}^2", registry.get("flood-fill"), [contour], {},
                 (fill_side, fill_side), 50_000_000))
    positions = 15 if quick else 40
    worst, medians = 0.0, []
    for label, spec, points, options, grid, step_cap in runs:
        trace = spec.record(points, options, grid, step_cap=step_cap)
        first = _timed(lambda: trace.state_at(len(trace) // 2))
        print(f"{label:<44} {len(trace):,} steps; first state_at (builds keyframes) "
              f"{first * 1000:.0f} ms")
        picks = random.Random(3).sample(range(len(trace)), positions)
        times = [_timed(lambda i=i: trace.state_at(i, compact=True)) * 1000 for i in picks]
        results.spread("  state_at(compact) at random steps", times, "ms")
        plain = [_timed(lambda i=i: trace.state_at(i)) * 1000 for i in picks[:5]]
        results.spread("  state_at (int32/int64 raster)", plain, "ms")
        medians.append(statistics.median(times))
        worst = max(worst, max(times))
        print(f"{'  replay caches (keyframes, pixel index)':<44} "
              f"{trace.cache_nbytes() / 2 ** 20:.0f} MiB for {trace.nbytes() / 2 ** 20:.0f} MiB "
              f"of trace")
    results.target("state_at median on big runs (worst run)", max(medians), 20.0, "ms")
    results.target("state_at slowest of the sampled steps", worst, 20.0, "ms")


def _timed(action) -> float:
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


# ------------------------------------------------------------------- report
def report(results, quick: bool) -> None:
    """The report command end to end, in a child process (its own figure)."""
    with tempfile.TemporaryDirectory() as folder:
        args = [sys.executable, "-m", "rasterlab", "report", "--out", folder] + (["--quick"] if quick
                                                                          else [])
        seconds = _timed(lambda: subprocess.run(args, cwd=ROOT, env=_env(), check=True,
                                                capture_output=True))
    what = "quick report" if quick else "full report"
    print(f"{'rasterlab report (' + what + ')':<44} {seconds:9.1f} s")
    results.target("report", seconds, 60.0, "s", what)


def _env():
    return {**os.environ, "PYTHONPATH": str(ROOT), "QT_QPA_PLATFORM": "offscreen"}


# ------------------------------------------------------------ window, start-up
def window(results, quick: bool) -> None:
    """Whole-window steps at 2048^2 and 4096^2, in a child process (Qt offscreen)."""
    for side in (2048, 4096):
        # Steps are a few ms and this machine's speed drifts between runs:
        # 200 pairs give a median that moves less between full runs.
        args = [sys.executable, str(ROOT / "benchmarks" / "run_all_window.py"), str(side),
                str(40 if quick else 200)]
        out = subprocess.run(args, cwd=ROOT, env=_env(), check=True, capture_output=True,
                             text=True).stdout.split()
        window_ms = [float(v) for v in out[1::2]]
        bare_ms = [float(v) for v in out[0::2]]
        ratios = [w / b for w, b in zip(window_ms, bare_ms)]
        median = statistics.median(window_ms)
        print(f"{'window step ' + str(side) + '^2 (seek + event loop)':<44} ours {median:9.2f} ms  "
              f"{'bare ImageItem':<14} {statistics.median(bare_ms):9.2f} ms  ratio min "
              f"{min(ratios):7.2f}x median {statistics.median(ratios):7.2f}x max "
              f"{max(ratios):7.2f}x  ({len(ratios)} pairs)")
        results.target(f"window step {side}^2", median, 5.0, "ms")


# Both sides print the wall clock once the first paint of their window is
# done (the event after it), then quit: start-up is the time from spawning
# the process to that moment. Closing the window and the interpreter's exit
# come after it and are timed apart.
SHOWN = """
import time
from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QApplication


class Shown(QObject):
    seen = False

    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Paint and not self.seen:
            self.seen = True
            QTimer.singleShot(0, self.report)
        return False

    def report(self):
        print("SHOWN", time.time(), flush=True)
        QApplication.instance().quit()


def watch(app):
    app.shown = Shown()
    app.installEventFilter(app.shown)
"""

# Ours loads as the `rasterlab` command without a command does: the command
# line's module, then launch(); the watcher needs a QApplication, made here
# before launch() would.
STARTUP_OURS = """
from app import cli
""" + SHOWN + """
app = QApplication([])
watch(app)
from app.gui import launch
launch()
"""

STARTUP_PEER = SHOWN + """
from PySide6.QtWidgets import QMainWindow
import pyqtgraph as pg
app = QApplication([])
watch(app)
window = QMainWindow()
window.setCentralWidget(pg.PlotWidget())
window.show()
app.exec()
"""


def startup(results, quick: bool) -> None:
    with tempfile.TemporaryDirectory() as home:
        # Bytecode cached (in the temporary folder) as an installed program
        # has it, for both sides; settings from an empty home.
        env = {**_env(), "HOME": home, "XDG_CONFIG_HOME": home, "XDG_DATA_HOME": home,
               "PYTHONPYCACHEPREFIX": str(Path(home) / "pycache")}
        env.pop("PYTHONDONTWRITEBYTECODE", None)

        def run(code):
            """Seconds from spawning to the window shown, and to the process's end."""
            began = time.time()
            out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, check=True,
                                 capture_output=True, text=True).stdout
            ended = time.time()
            return float(out.rsplit("SHOWN", 1)[1].split()[0]) - began, ended - began

        run(STARTUP_OURS)  # warm up: compile and cache both sides once
        run(STARTUP_PEER)
        ours, peer = interleaved(lambda: run(STARTUP_OURS), lambda: run(STARTUP_PEER),
                                 3 if quick else 21)
        ratio = results.compare("start-up to first window shown (rasterlab)",
                                [o[0] for o in ours], [p[0] for p in peer], "PySide6+pg")
        results.compare("  to the process's end (window closed)", [o[1] for o in ours],
                        [p[1] for p in peer], "PySide6+pg")
    results.target("start-up / minimal PySide6 + pyqtgraph window", ratio, 1.3, "x")
    probe = ("import sys; from app import cli; cli.main(['list']); "
             "cli.main(['run', 'line-bresenham', '--points', '0,0', '5,2']); "
             "print('QT', sorted(m for m in sys.modules if m.split('.')[0] in "
             "('PySide6', 'pyqtgraph', 'shiboken6')))")
    out = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, env=_env(), check=True,
                         capture_output=True, text=True).stdout
    loaded = out.rsplit("QT", 1)[-1].strip()
    print(f"{'Qt modules loaded by list + run':<44} {loaded}")
    results.target("Qt modules imported by list/run", 0 if loaded == "[]" else
                   loaded.count(",") + 1, 0, "modules")
