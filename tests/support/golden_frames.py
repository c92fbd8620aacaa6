"""Golden frames: the cell colours of exported frames of a few shipped
scenes, stored under tests/app/render/golden/ and compared by
test_golden_frames.py (in the manner of manim's frames_comparison: the
control data is rewritten only on request, by
``pytest tests/app/render/test_golden_frames.py --update-golden``).

Each file NAME.npz holds ``steps`` (the first, middle and last step) and
``cells`` (3, H, W, 3): the colour at the centre of every grid cell of the
frame exported at each of those steps with the default settings, row 0 at
y = 0. Cell centres are compared, not whole pictures: text is left out,
and grid lines and outlines never reach a centre.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from PIL import Image

from app.model.scene import load
from app.render.export import ExportSettings, FrameRenderer

from tests.support import ROOT
GOLDEN_DIR = ROOT / "tests" / "app" / "render" / "golden"
SCENES = ROOT / "resources" / "scenes"
# A line, a circle, an even-odd polygon, a mesh of triangles, the painter's
# algorithm with colours, and a fill with horizontal edges.
GOLDEN = ("demo-bresenham", "circle-radius-2", "polygon-star-evenodd", "triangle-sliver",
          "painter-intersecting", "polygon-horizontal-edges")
# Text on the grid (the reasoning's labels) is left out like the rest of the text.
SETTINGS = ExportSettings(caption=False, panel="none", grid_text=False)
# The diff image: pixels a cell is wide, the colour of a differing cell, and
# the width of the grey gap between panels.
CELL_PIXELS = 8
CHANGED = (255, 0, 255)
GAP = 4


def golden_frames(name: str) -> dict[str, np.ndarray]:
    """The control data of shipped scene ``name``, as it is drawn today."""
    renderer = FrameRenderer(load(SCENES / f"{name}.json"), SETTINGS)
    last = len(renderer.trace) - 1
    steps = np.array([0, last // 2, last], dtype=np.int64)
    return {"steps": steps, "cells": np.stack([renderer.cells(int(i)) for i in steps])}


def write_golden(name: str, frames: dict[str, np.ndarray]) -> Path:
    """Store ``frames`` as the golden frames of scene ``name``; returns the file."""
    GOLDEN_DIR.mkdir(parents=True, exist_ok=True)
    path = GOLDEN_DIR / f"{name}.npz"
    np.savez_compressed(path, **frames)
    return path


def diff_image(expected: np.ndarray, got: np.ndarray, path: Path) -> Path:
    """A PNG with a row per frame: expected | got | the differing cells in
    magenta over a faded copy of the expected frame; y upwards, as exported."""
    changed = (expected != got).any(axis=3)
    faded = (expected // 4 + 191).astype(np.uint8)
    marked = np.where(changed[..., None], np.array(CHANGED, np.uint8), faded)
    rows = []
    for panels in zip(expected, got, marked):
        cells = [np.kron(panel[::-1], np.ones((CELL_PIXELS, CELL_PIXELS, 1), np.uint8))
                 for panel in panels]
        gap = np.full((cells[0].shape[0], GAP, 3), 128, np.uint8)
        rows.append(np.hstack([cells[0], gap, cells[1], gap, cells[2]]))
    blank = np.full((GAP, rows[0].shape[1], 3), 128, np.uint8)
    picture = np.vstack([part for row in rows for part in (row, blank)][:-1])
    path.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(picture).save(path)
    return path
