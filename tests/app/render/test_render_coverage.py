"""Coverage colouring and span boxes in the numpy composition; the step
read-outs keyed on value names."""
import numpy as np

from algorithms.core.raster import Raster
from algorithms.core.steps import PLOT, VISIT
from app.model.insight import row_tones, inside_chips
from app.render.compose import PALETTE, Overlay, compose, coverage_counts


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
