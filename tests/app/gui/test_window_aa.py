"""The window on visibility and antialiasing runs: the depth buffer view,
the sample dots of a supersampled pixel, the coverage error overlay, and
coverages shown as numbers, never as colours."""
import math

import numpy as np
import pytest
from PySide6.QtCore import Qt

from algorithms.exact import coverage as exact_coverage
from app.render import frame as frame_view
from app.model.geometry import final_coverage
from app.render.compose import depth_image, error_image, error_stats


TRIANGLE = [(3.25, 2.5), (20.5, 6.75), (9.125, 17.25)]


pytestmark = pytest.mark.window("line-bresenham")


def _chip_rows(w):
    """The names of the variables rows drawn with a colour swatch."""
    table = w.variables.table
    return {table.item(r, 0).text() for r in range(table.rowCount())
            if table.item(r, 1).data(Qt.ItemDataRole.DecorationRole) is not None}


# ------------------------------------------------------------ depth
def test_zbuffer_shows_the_depth_view_and_it_follows_the_step(window):
    w = window
    w.set_algorithm("zbuffer")
    trace = w.player.trace
    assert trace.start.depth_value == "z"
    assert w.depth_dock.isVisibleTo(w)
    assert w.depth_action.isEnabled() and w.depth_action.isChecked()
    # Two steps between which a fragment passes the depth test.
    plots = [i for i in range(len(trace)) if trace.step(i).writes]
    a, b = plots[0] - 1, plots[len(plots) // 2]
    w.player.seek(a)
    before = w.depth_view.image_data().copy()
    w.player.seek(b)
    after = w.depth_view.image_data().copy()
    assert not np.array_equal(before, after)
    # Greys: near dark, far light, never written = the clear depth = far.
    clear = float(trace.start.constants["clear_depth"])
    depth = trace.raster_at(b).depth
    x, y = trace.step(plots[0]).pixel
    assert after[y, x, 0] < before[y, x, 0]
    untouched = np.argwhere(np.isnan(depth))[0]
    assert after[tuple(untouched)][0] == after[..., 0].max()
    assert depth_image(np.full((1, 1), np.nan), clear, 0.0, clear)[0, 0, 0] == \
        depth_image(np.full((1, 1), clear), clear, 0.0, clear)[0, 0, 0]


def test_depth_toggle_and_runs_without_depth(window):
    w = window
    w.set_algorithm("zbuffer")
    w.depth_action.setChecked(False)
    assert not w.depth_dock.isVisibleTo(w)
    w.depth_action.setChecked(True)
    assert w.depth_dock.isVisibleTo(w)
    w.set_algorithm("painter")
    assert not w.depth_dock.isVisibleTo(w)
    assert not w.depth_action.isEnabled()


def test_the_dock_shows_a_runs_accumulation_buffer_step_by_step(window):
    w = window
    w.set_algorithm("aa-supersample")
    trace = w.player.trace
    assert w.depth_action.isEnabled() and w.depth_action.text() == "Accumulation buffer"
    assert w.depth_dock.isVisibleTo(w) and w.depth_dock.windowTitle() == "Accumulation buffer"
    # a pixel's first sample inside: its cover so far over W, 0 dark, 1 light
    hit = next(i for i in range(len(trace)) if trace.step(i).branch == "hit")
    x, y = trace.step(hit).pixel
    w.player.seek(hit)
    shown = w.depth_view.image_data()
    cover = trace.step(hit).values["coverage"]
    assert shown[y, x, 0] == depth_image(np.full((1, 1), cover), 0.0, 0.0, 1.0)[0, 0, 0]
    w.player.seek(hit - 1)
    assert w.depth_view.image_data()[y, x, 0] != shown[y, x, 0]
    w.set_algorithm("painter")
    assert not w.depth_dock.isVisibleTo(w) and w.depth_action.text() == "Depth buffer"


def test_the_depth_plot_is_made_when_the_dock_first_shows_and_then_shows_the_buffer(window):
    """The depth dock is hidden at start and its plot not yet made; shown,
    it holds the picture of the step's depth buffer, cell for cell."""
    w = window
    assert not w.depth_dock.isVisibleTo(w) and w.depth_view.plot is None
    w.set_algorithm("zbuffer")
    assert w.depth_view.plot is not None and w.depth_view.plot.isVisibleTo(w)
    trace = w.player.trace
    w.player.seek(len(trace) - 1)
    depth = trace.raster_at(len(trace) - 1).depth
    shown = w.depth_view.image.image
    assert shown.shape[:2] == depth.shape
    written = ~np.isnan(depth)
    # Nearer cells are darker: order of greys follows order of depths.
    near, far = np.unravel_index(np.nanargmin(depth), depth.shape), \
        np.unravel_index(np.nanargmax(depth), depth.shape)
    assert written.any() and shown[near][0] <= shown[far][0]
    assert w.depth_view.plot.getViewBox().yInverted() == bool(w.grid.y_down)


# ------------------------------------------------------------ samples
def test_supersample_draws_the_pixels_samples_so_far(window):
    w = window
    w.set_algorithm("aa-supersample")
    w.set_points(TRIANGLE)
    trace = w.player.trace
    names = trace.value_names
    # A sample step part-way through a pixel with hits and misses.
    index = None
    for i in range(1, len(trace)):
        step = trace.step(i)
        if step.line == 3 and "sx" in step.values and trace.step(i - 1).line == 4:
            index = i
            break
    assert index is not None
    w.player.seek(index)
    xs, ys, hits, current = w.grid.sample_data()
    # Expected: the frames of this pixel up to the step, read from the trace.
    pixel = trace.step(index).pixel
    first = index
    while trace.step(first - 1).pixel == pixel:
        first -= 1
    steps = [trace.step(k) for k in range(first, index + 1)]
    assert [s.values["sx"] for s in steps] == list(xs)
    assert [s.values["sy"] for s in steps] == list(ys)
    assert [s.values["hit"] == 1.0 for s in steps] == list(hits)
    assert current == len(steps) - 1
    assert hits.any() and not hits.all()
    # Every dot lies inside the magnified cell.
    assert ((xs > pixel[0]) & (xs < pixel[0] + 1) & (ys > pixel[1]) & (ys < pixel[1] + 1)).all()
    assert "sx" in names
    # A step that tests no sample draws none.
    w.player.seek(0)
    assert w.grid.sample_data() is None


# ------------------------------------------------------------ error
def test_coverage_error_overlay_matches_exact_coverage(window):
    w = window
    w.set_algorithm("aa-supersample")
    w.set_points(TRIANGLE)
    trace = w.player.trace
    width, height = w.player.grid
    # The run's final coverage per pixel, and the exact one, worked out here.
    estimate = np.zeros((height, width))
    for i in range(len(trace)):
        step = trace.step(i)
        if step.writes:
            estimate[step.pixel[1], step.pixel[0]] = step.values["coverage"]
    snapped = [(round(x * 256) / 256, round(y * 256) / 256) for x, y in TRIANGLE]
    exact = exact_coverage.triangle_coverage(snapped, (width, height))
    touched = (estimate != 0) | (exact != 0)
    expected_rms = math.sqrt(float(np.mean((estimate - exact)[touched] ** 2)))
    expected_max = float(np.abs(estimate - exact).max())

    w.error_action.setChecked(True)
    w.player.to_last()
    accuracy = w.depth_display.accuracy
    assert accuracy.rms == pytest.approx(expected_rms, rel=1e-9, abs=1e-12)
    assert accuracy.max == pytest.approx(expected_max, rel=1e-9, abs=1e-12)
    assert f"RMS {expected_rms:.4f}" in w.error_label.text()
    assert f"max {expected_max:.4f}" in w.error_label.text()
    # The grid shows the signed map: white where right, vermillion where the
    # run covers too much, blue where too little, fullest at the largest error.
    image = w.grid.image.image
    signed = estimate - exact
    t = np.abs(signed) / expected_max
    too_much, too_little = np.array([0xd5, 0x5e, 0x00]), np.array([0x00, 0x72, 0xb2])
    end = np.where((signed < 0)[..., None], too_little, too_much)
    expected = np.rint(255 + (end - 255) * t[..., None]).astype(np.uint8)
    assert np.array_equal(image[..., :3], expected)
    assert (signed < 0).any() and (signed > 0).any()  # both signs are on show
    worst = np.unravel_index(np.argmax(np.abs(signed)), estimate.shape)
    assert tuple(image[worst][:3]) == tuple(too_much if signed[worst] > 0 else too_little)
    # The sign is not told by colour alone: over the map, cells with too
    # little coverage carry a white hatch (8 image pixels a cell on this
    # grid: its diagonal pixels are white), the others none.
    hatch = w.depth_display._hatch
    assert hatch.isVisible()
    big = hatch.image
    assert big.shape[:2] == (8 * height, 8 * width)
    for (y, x) in np.argwhere(signed != 0):
        cell = big[8 * y:8 * y + 8, 8 * x:8 * x + 8, :3]
        white = (cell == 255).all(axis=-1)
        assert white[0, 0] == (signed[y, x] < 0) or t[y, x] == 0
        assert (white.sum() >= 8) == (signed[y, x] < 0)
    # The colour bar says what the colours mean, with the largest error at its ends.
    assert w.error_scale.isVisible()
    assert f"{expected_max:.3g}" in w.error_scale.high.text()
    assert "too little" in w.error_scale.low.text()
    w.error_action.setChecked(False)
    assert w.error_label.text() == "" and not w.error_scale.isVisible()
    assert not hatch.isVisible()


def test_the_current_pixel_shows_exact_coverage_and_error(window):
    w = window
    w.set_algorithm("aa-supersample")
    w.set_points(TRIANGLE)
    trace = w.player.trace
    i = next(i for i in range(len(trace)) if "sx" in trace.step(i).values)
    w.player.seek(i)
    rows = dict(w.variables.rows())
    x, y = trace.step(i).pixel
    exact = exact_coverage.triangle_coverage(
        [(round(a * 256) / 256, round(b * 256) / 256) for a, b in TRIANGLE],
        (x, y, x + 1, y + 1))[0, 0]
    # Shown to five significant figures.
    assert float(rows["exact coverage"]) == pytest.approx(exact, rel=5e-5)
    assert "error (final)" in rows


# ------------------------------------------------------------ colours
@pytest.mark.parametrize("name", ["aa-supersample", "aa-adaptive", "aa-filter", "line-wu",
                                  "line-area"])
def test_coverage_is_a_number_never_a_colour_chip(window, name):
    w = window
    w.set_algorithm(name)
    trace = w.player.trace
    assert w.player.spec.name == name and trace.start.color_value is not None
    i = int(np.flatnonzero(trace.writes())[-1])
    w.player.seek(i)
    rows = dict(w.variables.rows())
    coverage = trace.start.pixel_value
    assert not rows[coverage].startswith("#")
    assert 0 <= float(rows[coverage]) <= 1
    assert coverage not in _chip_rows(w)
    assert rows[trace.start.color_value].startswith("#")
    assert trace.start.color_value in _chip_rows(w)
    keys = dict(frame_view.key_values(trace, trace.state_at(i)))
    assert not keys[coverage].startswith("#")
    assert keys[trace.start.color_value].startswith("#")


def test_render_helpers():
    cov = final_coverage(3, 2, [(0, 0), (1, 1), (0, 0)], [0.5, 0.25, 0.75])
    assert cov.tolist() == [[0.75, 0.0, 0.0], [0.0, 0.25, 0.0]]
    rms, top, error = error_stats(cov, np.zeros((2, 3)))
    assert top == 0.75 and rms == pytest.approx(math.sqrt((0.75 ** 2 + 0.25 ** 2) / 2))
    assert error_image(np.zeros((1, 1)))[0, 0].tolist() == [255, 255, 255, 255]
