"""Slide-ready frames: text size, a tight layout, labelled short values,
the tables panel, axes with ticks at the cell boundaries, vertex labels."""
import re

import numpy as np
import pytest

from algorithms.core.steps import Span
from app.model.scene import Scene, load
from app.render import export as ex
from app.render.text import _pack, _Font
from tests.support import ROOT

SCENES = ROOT / "resources" / "scenes"


def rgb(colour):
    return tuple(int(colour[k:k + 2], 16) for k in (1, 3, 5))


def test_text_size_is_an_option_and_the_default_reads_on_a_slide(run_cli, tmp_path):
    scene = load(SCENES / "demo-bresenham.json")
    small = ex.FrameRenderer(scene, ex.ExportSettings(text_size=12))
    large = ex.FrameRenderer(scene, ex.ExportSettings(text_size=36))
    default = ex.FrameRenderer(scene, ex.ExportSettings())
    assert large.caption_height >= 2.5 * small.caption_height
    assert abs(large.panel_width - 3 * small.panel_width) <= 3
    # Default: about a thirtieth of the grid's side; on a 640-pixel grid
    # 21 px, against the 13 px a frame of 1,000 pixels had.
    assert default.text_size == round(640 / 30) and default.text_size >= 16
    code, out, err = run_cli("export", SCENES / "demo-bresenham.json", "--gif",
                             tmp_path / "a.gif", "--text-size", "7")
    assert code == 2 and err.count("\n") == 1 and "--text-size" in err


def test_a_tall_code_panel_leaves_no_band_under_the_grid():
    renderer = ex.FrameRenderer(load(SCENES / "triangle-behind-eye.json"))
    assert renderer.body_height == renderer.grid_size[1]
    last = len(renderer.trace) - 1
    # The current line is on show at every step, the last one included.
    for index in (1, last // 2, last):
        panel = renderer.rgb(index)[:renderer.body_height, renderer.grid_size[0] + 2:]
        assert (panel == rgb(ex.LIGHT.current_line)).all(axis=2).any()


def test_caption_values_are_labelled_short_and_whole():
    renderer = ex.FrameRenderer(load(SCENES / "triangle-behind-eye.json"))
    state = renderer.trace.state_at(len(renderer.trace) // 2)
    parts = renderer._text.caption_parts(state)
    assert len(parts) > 6
    for part in parts:
        assert re.match(r"^[^=:]+( = |: )", part), part  # every value has its name
        for whole, decimals in re.findall(r"(\d+)\.(\d+)", part):
            # e0 = 8675.2, not 8675.21484375: five significant figures.
            assert len((whole + decimals).lstrip("0")) <= max(5, len(whole) + 1), part
    face = _Font("mono", 21)
    lines = _pack(parts, " · ", face, 1200, 2)
    assert len(lines) <= 2
    # A part is never split between lines.
    assert all(part in lines[0].split(" · ") + lines[-1].split(" · ") for part in
               parts[:len(lines[0].split(" · "))])


def test_the_tables_panel_shows_the_et_and_the_aet():
    scene = load(SCENES / "polygon-star-evenodd.json")
    renderer = ex.FrameRenderer(scene, ex.ExportSettings(panel="tables"))
    trace = renderer.trace
    first_span = int(trace.steps_of(Span)[0])
    names = [table.name for table in renderer._text._tables.at(first_span)]
    assert names == ["ET", "AET"]
    gw = renderer.grid_size[0]
    before = renderer.rgb(first_span - 1)[:, gw + 2:]
    after = renderer.rgb(first_span + 3)[:, gw + 2:]
    assert not np.array_equal(before, after)


@pytest.mark.parametrize("origin", ["bottom-left", "top-left"])
def test_axis_ticks_stand_at_the_cell_boundaries(origin):
    scene = Scene(algorithm="line-bresenham", points=((1, 2), (12, 7)), width=14, height=9,
                  origin=origin)
    renderer = ex.FrameRenderer(scene, ex.ExportSettings(scale=10, axes=True, caption=False,
                                                         panel="none"))
    image = renderer.rgb(0)
    left, (gw, gh) = renderer.grid_left, renderer.grid_size
    muted, outside = rgb(ex.LIGHT.muted), rgb(ex.LIGHT.palette.outside)
    # Bottom strip: a tick at x = k cells for k = 0 .. 13 (the last
    # boundary, x = 14, is the grid's edge), and none half-way.
    for k in range(14):
        assert tuple(image[gh, left + 10 * k]) == muted, k
        assert tuple(image[gh, left + 10 * k + 5]) == outside, k
    # Left strip: row of boundary y = k, in the scene's own origin.
    for k in range(1, 9):
        row = 10 * k if origin == "top-left" else gh - 10 * k
        assert tuple(image[row, left - 1]) == muted, k
        assert tuple(image[row + 5, left - 1]) == outside, k


@pytest.mark.parametrize("origin", ["bottom-left", "top-left"])
def test_large_cells_are_numbered_at_their_centres(origin):
    """At 40 px a cell, every cell's index stands inside the cell, clear of
    the boundary ticks; the ticks stay at the boundaries."""
    scene = Scene(algorithm="line-bresenham", points=((1, 2), (12, 7)), width=14, height=9,
                  origin=origin)
    renderer = ex.FrameRenderer(scene, ex.ExportSettings(scale=40, axes=True, caption=False,
                                                         panel="none"))
    image = renderer.rgb(0)
    left, (gw, gh) = renderer.grid_left, renderer.grid_size
    ink = (image == rgb(ex.LIGHT.text)).all(axis=2)
    muted = rgb(ex.LIGHT.muted)
    below = ink[gh + 2 * renderer.axes.tick:, left:left + gw].any(axis=0)  # per column
    beside = ink[:gh, :left - 2 * renderer.axes.tick].any(axis=1)           # per row
    for k in range(14):
        assert tuple(image[gh, left + 40 * k]) == muted, k
        assert below[40 * k + 8:40 * k + 32].any(), k        # a label in cell k
        assert not below[max(0, 40 * k - 3):40 * k + 4].any(), k  # none on its boundary
    for k in range(9):
        # Cell k spans rows [40k, 40k + 40) from the top (top-left origin)
        # or from the bottom.
        top = 40 * k if origin == "top-left" else gh - 40 * (k + 1)
        assert beside[top + 8:top + 32].any(), k
        edge = 40 * k if origin == "top-left" else gh - 40 * k
        assert not beside[max(0, edge - 3):edge + 4].any(), k


def test_vertex_labels_are_an_option():
    scene = load(SCENES / "polygon-star-evenodd.json")
    plain = ex.FrameRenderer(scene, ex.ExportSettings(caption=False, panel="none"))
    labelled = ex.FrameRenderer(scene, ex.ExportSettings(caption=False, panel="none",
                                                         vertex_labels=True))
    assert [name for _, _, name in labelled.vertex_labels] == ["P1", "P2", "P3", "P4", "P5"]
    x, y, _ = labelled.vertex_labels[0]
    left, top = labelled._grid_point(x, y)
    box = (slice(max(0, int(top) - 40), int(top)), slice(int(left), int(left) + 40))
    assert not np.array_equal(plain.rgb(0)[box], labelled.rgb(0)[box])


@pytest.mark.parametrize("name", ["circle-radius-1", "triangle-behind-eye", "triangle-fan-32"])
def test_the_caption_has_room_for_every_value_of_every_step(name):
    from algorithms.core.trace import FrameState
    from app.model.scene import load as load_scene
    from app.render.export import ExportSettings as Settings, FrameRenderer as Renderer
    from tests.support import ROOT as root
    renderer = Renderer(load_scene(root / "resources" / "scenes" / f"{name}.json"), Settings())
    text = renderer._text
    room = renderer.size[0] - 2 * text.pad
    separator = text.mono.width("   \u00b7   ")
    trace = renderer.trace
    for index in range(0, len(trace), max(1, len(trace) // 300)):
        state = FrameState(index, trace.step(index), None, trace.variables_at(index), [])
        widths = [text.mono.width(part) for part in text.caption_parts(state)]
        if not widths:
            continue
        # Each value fits a line, and all of them fit the caption's lines.
        assert max(widths) <= room, (index, max(widths), room)
        assert sum(widths) + separator * (len(widths) - 1) <= text.value_lines * room, index
