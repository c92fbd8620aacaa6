"""The pipeline's outline (its clipped triangles on the screen) is drawn by the
window and by exported frames alike, from the same geometry (run_paths)."""
import math

import numpy as np

from app.model.scene import load
from app.render.compose import PALETTE
from app.render.export import ExportSettings, FrameRenderer, auto_scale
from tests.support import ROOT
from tests.support.gui import WAIT_MS, settle, shown_window

SCENE = ROOT / "resources" / "scenes" / "rendering" / "pipeline-near-crossing.json"


def _hex(rgb) -> str:
    return "#%02x%02x%02x" % tuple(int(c) for c in rgb[:3])


def _midpoints(paths):
    for points, closed in paths:
        ends = list(points) + ([points[0]] if closed else [])
        for (x0, y0), (x1, y1) in zip(ends, ends[1:]):
            yield (x0 + x1) / 2, (y0 + y1) / 2


def test_window_and_export_draw_the_same_pipeline_outline(qtbot):
    scene = load(SCENE)
    window = shown_window(qtbot)
    window.resize(1500, 950)
    window.set_scene(scene.algorithm, scene.points, scene.options, (scene.width, scene.height))
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    settle(qtbot, window)
    trace = window.player.trace
    scale = auto_scale(scene.width, scene.height)
    renderer = FrameRenderer(scene, ExportSettings(scale=scale), trace)
    # Clipped against the near plane and the frustum's sides: one polygon of more
    # than three corners, inside the grid.
    (corners, closed), = renderer.paths
    assert closed and len(corners) > 3
    assert all(-1e-9 <= x <= scene.width + 1e-9 and -1e-9 <= y <= scene.height + 1e-9
               for x, y in corners)
    # The window's outline is the export's, vertex for vertex.
    xs, ys = window.grid.primitive.getData()
    want = [(x, y) for points, closed in renderer.paths
            for x, y in list(points) + [points[0]] + [(math.nan, math.nan)]]
    assert len(xs) == len(want)
    for x, y, (wx, wy) in zip(xs, ys, want):
        assert (math.isnan(x) and math.isnan(wx)) or (abs(x - wx) < 1e-9 and abs(y - wy) < 1e-9)
    # Every inner outline edge's midpoint shows the primitive's colour in the exported
    # frame (origin bottom-left: frame rows run down from y = height).
    frame = renderer.rgb(len(trace) - 1)
    height = scene.height * scale
    inner = [(mx, my) for mx, my in _midpoints(renderer.paths)
             if 0.5 < mx < scene.width - 0.5 and 0.5 < my < scene.height - 0.5]
    assert len(inner) >= 2
    for mx, my in inner:
        col, row = int(mx * scale), int(height - my * scale)
        patch = frame[max(0, row - 1):row + 2, max(0, col - 1):col + 2].reshape(-1, 3)
        assert PALETTE.primitive in {_hex(p) for p in patch}, (mx, my)
    # Without the primitive the export draws no outline colour at all.
    bare = FrameRenderer(scene, ExportSettings(scale=scale, primitive=False), trace)
    assert not (bare.rgb(len(trace) - 1) == np.array(
        [int(PALETTE.primitive[k:k + 2], 16) for k in (1, 3, 5)])).all(axis=2).any()
