"""Golden frames: the cell colours of exported frames of a few shipped
scenes, stored under tests/app/render/golden/ by ``python scripts/make_golden.py``
and compared by test_golden_frames.py (in the manner of manim's
frames_comparison: the control data is made by a command, never by a test).

Each file NAME.npz holds ``steps`` (the first, middle and last step) and
``cells`` (3, H, W, 3): the colour at the centre of every grid cell of the
frame exported at each of those steps with the default settings, row 0 at
y = 0. Cell centres are compared, not whole pictures: text is left out,
and grid lines and outlines never reach a centre.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

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


def golden_frames(name: str) -> dict[str, np.ndarray]:
    """The control data of shipped scene ``name``, as it is drawn today."""
    renderer = FrameRenderer(load(SCENES / f"{name}.json"), SETTINGS)
    last = len(renderer.trace) - 1
    steps = np.array([0, last // 2, last], dtype=np.int64)
    return {"steps": steps, "cells": np.stack([renderer.cells(int(i)) for i in steps])}
