"""s and n in exported frames: bars at the decided column, in the window's
colours, on both origins; none where a step decides nothing."""
import numpy as np
import pytest

from app.model.derivation import distance_segments
from app.model.scene import Scene
from app.render.export import FrameRenderer
from app.render.settings import ExportSettings

SCALE = 48


def renderer(origin="bottom-left", highlight=True):
    scene = Scene(algorithm="line-bresenham-textbook", points=((1, 2), (13, 7)), width=16,
                  height=10, origin=origin)
    return FrameRenderer(scene, ExportSettings(scale=SCALE, panel="none", caption=False,
                                               highlight=highlight, reasoning=False))


def bar_colours(r, frame, segment, y_down):
    """The colours down the middle of a segment's bar (x fixed, y along it)."""
    _, _, (x0, y0), (x1, y1) = segment
    column = round(x0 * SCALE)
    low, high = sorted((y0, y1))
    end = SCALE // 8 + 1  # the bars' ends overlap by their half width
    rows = range(round(low * SCALE) + end, round(high * SCALE) - end)
    height = r.trace.height * SCALE
    return {int(frame[(y if y_down else height - 1 - y), column]) for y in rows}


@pytest.mark.parametrize("origin", ["bottom-left", "top-left"])
def test_s_and_n_bars_are_drawn_where_they_are_measured(origin):
    r = renderer(origin)
    step = 5
    frame = r.render(step)
    segments = distance_segments(r.scene.points, r.trace, step)
    palette = r.theme.palette
    s_colour, n_colour = r.colours.index_of(palette.candidate), r.colours.index_of(palette.difference)
    by_name = {segment[0]: segment for segment in segments}
    assert bar_colours(r, frame, by_name["s"], r.y_down) == {s_colour}
    assert bar_colours(r, frame, by_name["n"], r.y_down) == {n_colour}


def test_no_bars_without_a_decision_or_without_highlights():
    r = renderer()
    plain = renderer(highlight=False)
    assert not distance_segments(r.scene.points, r.trace, 1)
    assert np.array_equal(r.render(1), r.render(1))
    with_bars, without = r.render(5), plain.render(5)
    differing = np.argwhere(with_bars != without)
    assert len(differing) > 0
    # Every changed pixel lies in the one column the step decides.
    x = distance_segments(r.scene.points, r.trace, 5)[0][2][0]
    assert set(np.unique(differing[:, 1] // SCALE)) <= {int(x) - 1, int(x)}
