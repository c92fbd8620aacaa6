"""Coverage colouring and span boxes in the numpy composition; the step
read-outs keyed on value names."""
import numpy as np

from algorithms.core.raster import Raster
from algorithms.core.steps import PLOT, VISIT
from app.model.insight import row_tones, inside_chips
from app.render.compose import (DARK_PALETTE, PALETTE, Overlay, compose, coverage_counts,
                                coverage_image)


def rgba(color):
    value = int(color.lstrip("#"), 16)
    return [(value >> 16) & 255, (value >> 8) & 255, value & 255, 255]


def test_coverage_colours_and_counts():
    raster = Raster(4, 1)
    for x, times in ((1, 1), (2, 2), (3, 5)):
        for _ in range(times):
            raster.write(x, 0)
    image = compose(raster, coverage=True)
    assert [image[0, x].tolist() for x in range(4)] == [rgba(c) for c in PALETTE.coverage]
    assert coverage_counts(raster) == (1, 1, 1, 1)
    # The default composition is unchanged.
    assert compose(raster)[0, 2].tolist() == rgba(PALETTE.overdraw)


def test_overlaps_carry_a_pattern_in_the_background_colour():
    # Cells written 0, 1, 2 and 3 times, at 8 image pixels a cell.
    raster = Raster(4, 1)
    for x, times in ((1, 1), (2, 2), (3, 3)):
        for _ in range(times):
            raster.write(x, 0)
    for palette in (PALETTE, DARK_PALETTE):
        for image in (compose(raster, palette=palette, scale=8, coverage=True),
                      coverage_image(raster.counts, palette, 8)):
            ground, once, twice, more = (rgba(c) for c in palette.coverage)
            def at(x, dx, dy):  # pixel (dx, dy) of cell (x, 0), clear of the grid lines
                return image[dy, 8 * x + dx].tolist()
            # Twice: stripes "/" every 4 pixels, marked where dx - dy is 0 or 4.
            assert at(2, 2, 2) == ground and at(2, 5, 1) == ground
            assert at(2, 3, 2) == twice and at(2, 2, 5) == twice
            # Three times or more: a cross, on both diagonals of the cell.
            assert at(3, 3, 3) == ground and at(3, 1, 6) == ground
            assert at(3, 3, 2) == more and at(3, 5, 1) == more
            # Written once, or not at all: one colour over the whole cell.
            assert {tuple(p) for p in image[1:8, 9:16].reshape(-1, 4).tolist()} == {tuple(once)}
            assert {tuple(p) for p in image[1:8, 1:8].reshape(-1, 4).tolist()} == {tuple(ground)}


def test_coverage_patterns_need_room():
    raster = Raster(2, 1)
    raster.write(1, 0)
    raster.write(1, 0)
    image = compose(raster, scale=3, coverage=True)
    assert {tuple(p) for p in image[:, 3:].reshape(-1, 4).tolist()} == {tuple(rgba(PALETTE.coverage[2]))}


def test_span_box_outlines_the_whole_run():
    raster = Raster(6, 2)
    image = compose(raster, Overlay(spans=[(1, 4, 0)]), scale=10)
    current = rgba(PALETTE.current)
    assert image[0, 15].tolist() == current and image[9, 35].tolist() == current  # top, bottom
    assert image[5, 10].tolist() == current and image[5, 39].tolist() == current  # ends
    assert image[5, 25].tolist() == rgba(PALETTE.background)  # inside the box
    assert image[5, 45].tolist() == rgba(PALETTE.background)  # beyond the run
    # At scale 1 the run is tinted instead.
    small = compose(raster, Overlay(spans=[(1, 4, 0)]))
    changed = np.argwhere((small != compose(raster)).any(axis=2)).tolist()
    assert changed == [[0, 1], [0, 2], [0, 3]]


def test_row_tones_follow_signs_and_ranges():
    rows = [("e0", "3.5"), ("e1", "-2"), ("e2", "0"), ("e1 exactly", "-7/2"),
            ("alpha", "0.25"), ("beta", "1.5"), ("x", "-4"), ("verdict", "in")]
    assert row_tones(rows) == {"e0": "positive", "e1": "negative", "e2": "zero",
                               "e1 exactly": "negative", "alpha": "positive",
                               "beta": "negative"}


def test_inside_chips():
    texts = [c[0] for c in inside_chips({"e0": 1.0, "e1": 2.0, "e2": 3.0}, PLOT)]
    assert texts == ["e0 > 0", "e1 > 0", "e2 > 0", "inside", "filled"]
    # A clockwise triangle tested without swapping: all negative is inside too.
    assert "inside" in [c[0] for c in inside_chips({"e0": -1.0, "e1": -2.0, "e2": -3.0}, VISIT)]
    chips = inside_chips({"e0": 1.0, "e1": -2.0, "e2": 3.0}, VISIT)
    assert chips[3][0] == "outside" and "e1" in chips[3][2] and chips[-1][0] == "not filled"
    assert inside_chips({"e0": 0.0, "e1": 2.0, "e2": 3.0}, PLOT)[3][0] == "on e0"
    weights = [c[0] for c in inside_chips({"alpha": 0.2, "beta": 0.3, "gamma": 0.5}, "calc")]
    assert weights == ["\u03b1 0.2", "\u03b2 0.3", "\u03b3 0.5", "inside"]
    assert inside_chips({"x": 1.0}, PLOT) == []
