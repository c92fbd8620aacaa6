"""The window's patched picture equals the whole picture composed afresh."""
import numpy as np
import pytest

from algorithms.core.registry import get
from app.render.compose import PALETTE, compose
from app.render.incremental import StepImages


@pytest.mark.parametrize("name, points, options", [
    ("line-parametric", [(1, 2), (27, 13)], {"dt": 0.01, "colors": ["#ff0000", "#00ffff"]}),
    ("flood-fill", [[(3, 2), (27, 3), (20, 11), (28, 20), (12, 15), (4, 21)]], {"order": "span"}),
    ("zbuffer", [(2, 2), (28, 6), (10, 20), (4, 18), (26, 20), (18, 3)], {}),
])
@pytest.mark.parametrize("coverage", [False, True])
def test_stepping_patches_exactly_the_changed_cells(name, points, options, coverage):
    trace = get(name).record(points, options, (32, 24))
    n = len(trace)
    walk = [0, 1, 2, 5, 4, 3, n // 2, n // 2 + 1, n // 2 - 7, n - 1, n - 2, 0, n - 1]
    images = StepImages()
    for index in walk:
        state = trace.state_at(index, compact=True)
        shown = images.image(trace, state, PALETTE, coverage=coverage)
        expected = compose(trace.state_at(index).raster, None, PALETTE, coverage=coverage)
        assert shown.shape == expected.shape and np.array_equal(shown, expected), index


def test_another_run_or_a_long_jump_recomposes(monkeypatch):
    import app.render.incremental as incremental

    monkeypatch.setattr(incremental, "MOST_STEPS", 2)
    spec = get("line-bresenham")
    a = spec.record([(0, 0), (30, 9)], grid=(32, 24))
    b = spec.record([(0, 20), (30, 2)], grid=(32, 24))
    images = StepImages()
    for trace, index in [(a, 3), (b, 3), (b, 4), (b, 20), (a, 20)]:
        shown = images.image(trace, trace.state_at(index, compact=True), PALETTE)
        assert np.array_equal(shown, compose(trace.state_at(index).raster, None, PALETTE))



def test_changed_bounds_the_recoloured_cells_and_no_more():
    trace = get("flood-fill").record(
        [[(3, 2), (27, 3), (20, 11), (28, 20), (12, 15), (4, 21)]], {"order": "span"}, (32, 24))
    images = StepImages()
    before = images.image(trace, trace.state_at(0, compact=True), PALETTE).copy()
    assert images.changed is None  # composed afresh
    images.image(trace, trace.state_at(0, compact=True), PALETTE)
    assert images.changed == (0, 0, 0, 0)  # the same step: nothing
    previous = 0
    for index in [1, 2, 9, 8, 30, len(trace) - 1, 3]:
        after = images.image(trace, trace.state_at(index, compact=True), PALETTE).copy()
        x0, y0, x1, y1 = images.changed
        rows, columns = np.nonzero((after != before).any(axis=2))
        assert ((columns >= x0) & (columns < x1) & (rows >= y0) & (rows < y1)).all(), index
        # No wider than the cells the steps in between wrote.
        lo, hi = sorted((previous, index))
        written = trace.written(lo + 1, hi + 1).pixels
        assert (x0, y0) == tuple(written.min(axis=0)) and (x1, y1) == tuple(written.max(axis=0) + 1)
        before, previous = after, index
