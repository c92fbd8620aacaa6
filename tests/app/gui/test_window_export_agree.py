"""The window and an exported frame show the same cells.

The window draws the grid with Qt items over a composed image; export
composes the whole frame with numpy. For a few shipped scenes both are
rendered at the same cell size (the window's grid grabbed with ``grab()``
at the export's automatic scale: 20 screen pixels a cell for a 32 x 24
grid, 32 for an 11 x 11 one) at the first, the
middle and the last step, and the colour at each cell's centre, where no
grid line, outline or text reaches, must be the same in both.

The ideal primitive (a 2.5 px pen in the window, a line as wide as the
scale allows in files) runs through cell centres, so it is off in both;
the window's vertex handles and their labels are input controls that
exports never draw, so they are hidden in the window. A scene with more
colours than a GIF's palette holds agrees up to that palette.
"""
from pathlib import Path

import numpy as np
import pytest
import pyqtgraph as pg
from PySide6.QtCore import QRectF

from app.model.scene import load
from tests.support import ROOT
from app.render.export import ExportSettings, FrameRenderer, auto_scale
from tests.support.gui import WAIT_MS, settle, shown_window

SCENES = ROOT / "resources" / "scenes"
AGREEING = ["demo-bresenham", "circle-radius-2", "polygon-star-evenodd", "triangle-mesh-1e6",
            "painter-intersecting"]


def show_in_window(qtbot, scene):
    window = shown_window(qtbot)
    window.resize(1500, 950)
    window.set_scene(scene.algorithm, scene.points, scene.options, (scene.width, scene.height))
    window.set_y_down(scene.origin == "top-left")
    window.show_primitive.setChecked(False)
    qtbot.waitUntil(lambda: window.player.trace is not None and not window.player.recording,
                    timeout=WAIT_MS)
    settle(qtbot, window)  # the new size has reached the grid
    grid = window.grid
    for item in grid.view_box.addedItems:
        if isinstance(item, (pg.ScatterPlotItem, pg.TextItem)):
            item.hide()
    return window


def set_cell_size(grid, cell: int) -> None:
    """Show the grid from its corner at ``cell`` screen pixels a cell."""
    box = grid.view_box
    width, height = box.width(), box.height()
    assert width >= grid.grid_size[0] * cell and height >= grid.grid_size[1] * cell
    box.setRange(QRectF(0, 0, width / cell, height / cell), padding=0)


def window_cells(qtbot, window, index: int, cell: int) -> np.ndarray:
    """(H, W, 3) colours at the cell centres of the window's grid, row 0 at y = 0."""
    window.player.seek(index)
    qtbot.wait(10)
    grid = window.grid
    for item in grid.view_box.addedItems:
        if isinstance(item, pg.TextItem):
            item.hide()  # a step's labels (M's words): the export leaves text out here
    width, height = grid.grid_size
    a, b = grid.widget_pos_of((0.0, 0.0)), grid.widget_pos_of((1.0, 1.0))
    assert abs(b.x() - a.x()) == cell and abs(b.y() - a.y()) == cell
    image = grid.viewport().grab().toImage()
    cells = np.zeros((height, width, 3), dtype=np.uint8)
    for y in range(height):
        for x in range(width):
            where = grid.widget_pos_of((x + 0.5, y + 0.5))
            colour = image.pixelColor(int(where.x()), int(where.y()))
            cells[y, x] = colour.red(), colour.green(), colour.blue()
    return cells


def differing(a, b) -> list:
    ys, xs = np.nonzero((a != b).any(axis=2))
    return [((int(x), int(y)), "#%02x%02x%02x" % tuple(a[y, x]), "#%02x%02x%02x" % tuple(b[y, x]))
            for x, y in zip(xs, ys)]


def window_and_export(qtbot, name):
    """The scene shown in the window at the export's automatic scale, and
    its export renderer drawing the window's own trace at that scale."""
    scene = load(SCENES / f"{name}.json")
    window = show_in_window(qtbot, scene)
    cell = auto_scale(scene.width, scene.height)
    set_cell_size(window.grid, cell)
    renderer = FrameRenderer(scene, ExportSettings(scale=cell, primitive=False, grid_text=False),
                             window.player.trace)
    return window, renderer, cell


@pytest.mark.parametrize("name", AGREEING)
def test_window_and_export_show_the_same_cells(qtbot, name):
    window, renderer, cell = window_and_export(qtbot, name)
    last = len(renderer.trace) - 1
    for index in (0, last // 2, last):
        shown = window_cells(qtbot, window, index, cell)
        exported = renderer.cells(index)
        assert len(np.unique(shown.reshape(-1, 3), axis=0)) >= (1 if index == 0 else 2)
        wrong = differing(shown, exported)
        assert not wrong, (f"{name} step {index}: {len(wrong)} cells differ "
                           f"(cell, window, export): {wrong[:8]}")


def test_more_colours_than_a_gif_holds_agree_up_to_the_palette(qtbot):
    """Interpolated colours: the window shows each exactly, a GIF's palette
    holds at most 253, so an exported cell shows the palette entry nearest
    to the window's colour."""
    window, renderer, cell = window_and_export(qtbot, "triangle-behind-eye")
    last = len(renderer.trace) - 1
    shown = window_cells(qtbot, window, last, cell)
    assert len(np.unique(shown.reshape(-1, 3), axis=0)) > len(renderer.colours)
    opaque = np.concatenate([shown, np.full(shown.shape[:2] + (1,), 255, np.uint8)], axis=2)
    nearest = renderer.colours.rgb[renderer.colours.indices(opaque)]
    wrong = differing(nearest, renderer.cells(last))
    assert not wrong, f"{len(wrong)} cells differ (cell, window's nearest, export): {wrong[:8]}"
