"""The texture panel: shown for textured runs only, footprint round the pixel's uv, mip levels
on the grid, and a bad texture as a message."""
from __future__ import annotations

import math
import os

import numpy as np
import pytest

from algorithms.core.steps import PLOT
from app.render.texture_frame import LEVEL_COLOURS
from tests.support.gui import WAIT_MS
from tests.support.textures import huge_png

FLOOR = [(0, 0), (24, 0), (13.2, 15), (0, 0), (13.2, 15), (10.8, 15)]
OPTIONS = {"uv": (0, 0, 2, 0, 2, 9, 0, 0, 2, 9, 0, 9), "w": (1, 1, 10, 1, 10, 10),
           "texture": "checker:4", "filter": "trilinear"}


def _last_plot(trace):
    return max(k for k in range(len(trace)) if trace.code[int(trace.line[k])].kind == PLOT)


@pytest.mark.window("triangle-texture", FLOOR, OPTIONS, (24, 16))
def test_texture_panel_shows_the_footprint_and_levels(window, qtbot):
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    trace = window.player.trace
    index = _last_plot(trace)
    window.player.seek(index)
    qtbot.waitUntil(lambda: window.player.index == index)
    assert window.texture_dock.isVisible()
    step = trace.step(index)
    level = int(step.values["level"])
    size = 64 >> level
    # The footprint's centre is the pixel's (u, v) on the base tile, in the level's texels.
    centre = np.mean(window.texture_view.footprint_points, axis=0)
    u, v = step.values["u"], step.values["v"]
    assert centre == pytest.approx(((u - math.floor(u)) * size, (v - math.floor(v)) * size))
    image = window.texture_view.level_image.image
    x, y = step.pixel
    assert tuple(image[y, x, :3]) == tuple(LEVEL_COLOURS[level])
    window.set_scene("triangle-bbox", FLOOR[:3], {}, grid=(24, 16))
    qtbot.waitUntil(lambda: not window.texture_dock.isVisible(), timeout=WAIT_MS)


@pytest.mark.window("triangle-texture", FLOOR[:3], {}, (24, 16))
def test_an_unreadable_texture_is_a_message(window, qtbot, tmp_path):
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    fake = tmp_path / "fake.png"
    fake.write_text("no picture")
    cases = [("/no/such/texture.png", "cannot read"), (str(fake), "not an image"),
             (str(huge_png(tmp_path / "huge.png")), "larger than 1024 x 1024")]
    if hasattr(os, "mkfifo"):  # a FIFO with no writer: reading it would hang the recording
        os.mkfifo(tmp_path / "pipe.png")
        cases.append((str(tmp_path / "pipe.png"), "not a regular file"))
    for name, words in cases:
        window.open_texture(name)
        qtbot.waitUntil(lambda: words in window._error, timeout=WAIT_MS)
        assert window.player.options["texture"] == "checker:8"


@pytest.mark.window("triangle-texture", FLOOR[:3], {}, (24, 16))
def test_a_png_opened_in_the_window_is_the_texture(window, qtbot):
    from pathlib import Path
    bricks = str(Path(__file__).resolve().parents[3] / "resources" / "textures" / "bricks.png")
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    window.open_texture(bricks)
    qtbot.waitUntil(lambda: window.player.options["texture"] == bricks, timeout=WAIT_MS)
    qtbot.waitUntil(lambda: window.player.trace is not None
                    and window.player.trace.final_variables().get("texture") == "bricks.png",
                    timeout=WAIT_MS)
    assert window.texture_view.open_button.isVisibleTo(window)


@pytest.mark.window("pipeline", [(3, 3), (28, 4), (15, 20)], {}, (32, 24))
def test_the_pipeline_shows_the_scene_from_outside(window, qtbot):
    qtbot.waitUntil(lambda: window.outside_dock is not None and window.outside_dock.isVisible(),
                    timeout=WAIT_MS)
    window.player.seek(1)  # the model stage: the world from above
    qtbot.waitUntil(lambda: "Camera at (16.0, 12.0, 40.0)" in window.outside_view.caption.text(),
                    timeout=WAIT_MS)
    window.set_option("near", 0.0)
    qtbot.waitUntil(lambda: "near" in window._error, timeout=WAIT_MS)


@pytest.mark.window("pipeline", [(3, 3), (28, 4), (15, 20)], {}, (32, 24))
def test_the_issues_bad_input_is_a_message_in_the_window(window, qtbot, tmp_path):
    """Each bad input of the rendering family is one message; the window keeps going."""
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    fake = tmp_path / "fake.png"
    fake.write_text("no picture")
    cases = [("uv", (0.0, 0.0, 1.0), "option uv"), ("fov", 0.0, "fov"),
             ("fov", 180.0, "fov"), ("near", -1.0, "near"),
             ("texture", str(fake), "not an image"),
             ("texture", "/no/such/texture.png", "cannot read")]
    for name, value, words in cases:
        before = dict(window.player.options)
        window.set_option(name, value)
        qtbot.waitUntil(lambda: words in (window._error or ""), timeout=WAIT_MS)
        assert "\n" not in window._error.strip()
        window.set_scene("pipeline", [(3, 3), (28, 4), (15, 20)], before, grid=(32, 24))
        qtbot.waitUntil(lambda: window.player.trace is not None and not window._error,
                        timeout=WAIT_MS)
    # A vertex behind the eye without clipping: refused with the way out.
    window.set_option("z", (50.0, 0.0, 0.0))
    qtbot.waitUntil(lambda: window.player.options["z"] == (50.0, 0.0, 0.0), timeout=WAIT_MS)
    window.set_option("clipping", "none")
    qtbot.waitUntil(lambda: "w <= 0" in (window._error or ""), timeout=WAIT_MS)
    assert window.player.options["clipping"] == "all" and window.player.trace is not None
