"""The reasoning drawn on the grid (app/render/reasoning.py), against
geometry worked out here with exact fractions."""
from fractions import Fraction

import pytest

from algorithms.core.steps import Span, Table
from app.model.scene import Scene
from app.render import export as ex
from app.render.reasoning import step_guides
from tests.support import record

# Vertices on the 1/256 px grid, so that snapping keeps them exactly.
TRIANGLE = [(2.25, 2.0), (28.0, 3.5), (20.0, 20.75)]
PENTAGRAM = [(10, 1), (15.75, 18), (0.5, 7.5), (19.5, 7.5), (4, 18)]


GRID_NAMES = {(1, 0): "E", (1, 1): "NE", (0, 1): "N", (-1, 1): "NW", (-1, 0): "W",
              (-1, -1): "SW", (0, -1): "S", (1, -1): "SE"}


def crossings(polygon, y_centre):
    """x where the polygon's edges cross the line y = y_centre, exactly, by
    the half-open rule ymin <= y < ymax (a vertex on the line counts once)."""
    found = []
    for (x0, y0), (x1, y1) in zip(polygon, polygon[1:] + polygon[:1]):
        (x0, y0), (x1, y1) = sorted([(Fraction(x0), Fraction(y0)), (Fraction(x1), Fraction(y1))],
                                    key=lambda p: p[1])
        if y0 <= y_centre < y1:
            found.append(x0 + (y_centre - y0) * (x1 - x0) / (y1 - y0))
    return sorted(found)


@pytest.mark.parametrize("polygon", [TRIANGLE, PENTAGRAM])
def test_scan_line_and_crossings_at_every_step_of_the_loop(polygon):
    trace = record("polygon-scanline", [polygon], grid=(32, 24))
    seen = 0
    for i in range(len(trace)):
        state = trace.state_at(i)
        guides = step_guides(trace, state)
        record_ = trace.record_at(i)
        # The AET as sorted for row y: every edge the row's centre line meets.
        if not isinstance(record_, Table) or record_.name != "AET" \
                or not trace.code[record_.line].text.strip().startswith("sort"):
            continue
        y = state.variables["y"]
        if not 0 <= y < 24:
            continue
        seen += 1
        scan = [line for line in guides.lines if line[4] == "scan"]
        assert scan == [(0.0, y + 0.5, 32.0, y + 0.5, "scan")]
        xs = sorted(x for x, _, role in guides.dots if role == "crossing")
        assert xs == pytest.approx([float(x) for x in crossings(polygon, Fraction(2 * y + 1, 2))])
    assert seen > 10


@pytest.mark.parametrize("polygon", [TRIANGLE, PENTAGRAM])
def test_the_pair_of_a_span_holds_exactly_its_pixel_centres(polygon):
    trace = record("polygon-scanline", [polygon], grid=(32, 24))
    spans = trace.steps_of(Span).tolist()
    assert spans
    for i in spans:
        span = trace.record_at(i)
        pairs = [line for line in step_guides(trace, trace.state_at(i)).lines
                 if line[4] == "pair"]
        assert len(pairs) == 1
        left, y, right, _, _ = pairs[0]
        assert y == span.y + 0.5
        # The fill rule's own statement: pixel i is filled when x_left <= i + 1/2 < x_right.
        centres = [k for k in range(-2, 40) if left <= k + 0.5 < right]
        assert centres == list(range(span.x_start, span.x_end))


def test_bresenham_midpoint_lies_between_the_candidates_and_drops_onto_the_line():
    p, q = (1, 2), (27, 13)
    trace = record("line-bresenham", [p, q], grid=(32, 24))
    ideal = [([(p[0] + 0.5, p[1] + 0.5), (q[0] + 0.5, q[1] + 0.5)], False)]
    checked = 0
    for i in range(len(trace)):
        state = trace.state_at(i)
        if len(state.candidates) != 2:
            continue
        guides = step_guides(trace, state, ideal)
        (ax, ay), (bx, by) = state.candidates
        (mx, my, role), = guides.dots
        assert role == "midpoint" and (mx, my) == ((ax + bx) / 2 + 0.5, (ay + by) / 2 + 0.5)
        (lx, ly, text), = guides.labels
        assert (lx, ly) == (mx, my) and "M" in text
        drops = [line for line in guides.lines if line[4] == "drop"]
        dx, dy = q[0] - p[0], q[1] - p[1]
        # 2 * F(M): the decision's own quantity, d = 2 (dy x - dx y + c) at M.
        f = 2 * (dy * (Fraction(mx) - Fraction(p[0]) - Fraction(1, 2))
                 - dx * (Fraction(my) - Fraction(p[1]) - Fraction(1, 2)))
        if f == 0:
            assert not drops  # the line passes through M
            continue
        (x0, y0, x1, y1, _), = drops
        assert (x0, y0) == (mx, my)
        # The drop ends on the line, at right angles to it (or at its end).
        assert abs(dy * (x1 - p[0] - 0.5) - dx * (y1 - p[1] - 0.5)) < 1e-9
        assert abs((x1 - x0) * dx + (y1 - y0) * dy) < 1e-9 or (x1, y1) == ideal[0][0][1]
        # F(M) > 0: M lies below the line, so the drop from M goes up to it.
        assert (y1 > y0) == (f > 0)
        checked += 1
    assert checked > 10


def exact_side(p, q, a, b):
    """Where the line through the centres of pixels p and q crosses the
    line through the centres of candidates a and b, as t along a -> b
    (M at t = 1/2), exactly; None when the two are parallel."""
    (px, py), (qx, qy) = [(Fraction(x) + Fraction(1, 2), Fraction(y) + Fraction(1, 2))
                          for x, y in (p, q)]
    (ax, ay), (bx, by) = [(Fraction(x) + Fraction(1, 2), Fraction(y) + Fraction(1, 2))
                          for x, y in (a, b)]
    # a + t (b - a) on the line: (qx - px)(y - py) = (qy - py)(x - px).
    ux, uy = bx - ax, by - ay
    under = (qx - px) * uy - (qy - py) * ux
    if under == 0:
        return None
    return ((qy - py) * (ax - px) - (qx - px) * (ay - py)) / under


@pytest.mark.parametrize("p, q", [((1, 2), (27, 13)), ((3, 20), (9, 2)),
                                  ((28, 4), (2, 9)), ((5, 5), (25, 15))])
@pytest.mark.parametrize("y_down", [False, True])
def test_the_label_at_m_says_which_side_the_line_passes(p, q, y_down):
    """"line above M: NE" -- the side worked out exactly, in the
    picture's own terms (with the origin top-left, larger y is lower), and
    the branch named for that candidate is the one Bresenham takes."""
    trace = record("line-bresenham", [p, q], grid=(32, 24))
    ideal = [([(p[0] + 0.5, p[1] + 0.5), (q[0] + 0.5, q[1] + 0.5)], False)]
    seen = set()
    for i in range(len(trace)):
        state = trace.state_at(i)
        if len(state.candidates) != 2:
            continue
        a, b = state.candidates
        (_x, _y, text), = step_guides(trace, state, ideal, y_down).labels
        t = exact_side(p, q, a, b)
        if t == Fraction(1, 2):
            assert text == "line through M (a tie)"
            seen.add("tie")
            continue
        chosen = b if t > Fraction(1, 2) else a
        other = a if chosen == b else b
        if chosen[1] != other[1]:
            up = (chosen[1] > other[1]) != y_down
            words = "above" if up else "below"
        else:
            words = "right of" if chosen[0] > other[0] else "left of"
        branch = "NE" if chosen == b else "E"
        # The step as it goes in the picture (the code's names are octant 1's).
        before = trace.step(i - 1).pixel
        move = (chosen[0] - before[0], (before[1] - chosen[1]) if y_down else chosen[1] - before[1])
        grid = GRID_NAMES[move]
        shown = grid if grid == branch else f"{grid} (code: {branch})"
        assert text == f"line {words} M: {shown}", (i, text)
        # Bresenham decides exactly: the branch it takes is that side's.
        assert state.step.branch == branch and tuple(state.step.pixel) == tuple(chosen)
        seen.add(words)
    assert len(seen) >= 1


def test_an_octant_8_line_names_its_diagonal_step_se():
    """P -> Q down and to the right, shallow (octant 8): the diagonal step
    goes south-east on the grid, whatever the octant-1 code calls it."""
    p, q = (1, 9), (13, 4)
    trace = record("line-bresenham", [p, q], grid=(16, 12))
    ideal = [([(p[0] + 0.5, p[1] + 0.5), (q[0] + 0.5, q[1] + 0.5)], False)]
    texts = [step_guides(trace, trace.state_at(i), ideal).labels[0][2]
             for i in range(len(trace)) if len(trace.state_at(i).candidates) == 2]
    diagonal = [t for t in texts if "SE" in t]
    assert diagonal and all(t.endswith(": SE (code: NE)") for t in diagonal)
    assert not any(t.endswith(": NE") for t in texts)
    assert any(t.endswith(": E") for t in texts)


def test_the_label_at_m_names_a_tie():
    """(0, 0) -> (4, 1) passes exactly through the midpoint at x = 2."""
    trace = record("line-bresenham", [(0, 0), (4, 1)], grid=(8, 4))
    ideal = [([(0.5, 0.5), (4.5, 1.5)], False)]
    texts = [step_guides(trace, trace.state_at(i), ideal).labels[0][2]
             for i in range(len(trace)) if len(trace.state_at(i).candidates) == 2]
    assert "line through M (a tie)" in texts
    assert "line above M: NE" in texts and "line below M: E" in texts


@pytest.mark.parametrize("name", ["circle-midpoint", "circle-bresenham"])
@pytest.mark.parametrize("radius", [7, 10])
def test_the_label_at_m_says_which_side_the_circle_passes(name, radius):
    """F(M) = |M - C|^2 - R^2 < 0 puts M inside, so the circle passes above
    M and E is its candidate; F(M) > 0, below and SE. The midpoint circle
    decides exactly so, and Bresenham's (d = 3 - 2R) lands on the same
    pixels for a whole radius, though its mirrors come before its
    decisions."""
    centre = (12, 12)
    trace = record(name, [centre], {"radius": radius}, grid=(25, 25))
    checked = 0
    for i in range(len(trace)):
        state = trace.state_at(i)
        if len(state.candidates) != 2:
            continue
        (ax, ay), (bx, by) = state.candidates
        mx, my = Fraction(ax + bx + 1, 2), Fraction(ay + by + 1, 2)
        f = (mx - centre[0] - Fraction(1, 2)) ** 2 + (my - centre[1] - Fraction(1, 2)) ** 2 \
            - radius ** 2
        (_x, _y, text), = step_guides(trace, state, ()).labels
        assert f != 0  # M is never on a whole-radius circle
        expected = "circle above M: E" if f < 0 else "circle below M: SE"
        assert text == expected, (i, text)
        assert expected.endswith(": " + state.step.branch)
        checked += 1
    assert checked >= 4


def test_supersampling_marks_the_step_s_own_sample():
    trace = record("aa-supersample", TRIANGLE, {"n": 4}, grid=(32, 24))
    for i in range(1, min(len(trace), 400)):
        state = trace.state_at(i)
        step = state.step
        if step.record is not None or "sx" not in step.values:
            continue
        guides = step_guides(trace, state)
        own = [(x, y) for x, y, role in guides.dots if role == "sample"]
        assert own == [(step.values["sx"], step.values["sy"])]
        return
    pytest.fail("no sample step found")


@pytest.mark.parametrize("origin", ["bottom-left", "top-left"])
@pytest.mark.parametrize("theme", ["light", "dark"])
def test_exported_frame_draws_the_scan_line_through_the_row_centres(origin, theme):
    scene = Scene(algorithm="polygon-scanline", points=[TRIANGLE], width=32, height=24,
                  origin=origin)
    renderer = ex.FrameRenderer(scene, ex.ExportSettings(scale=10, caption=False,
                                                         panel="none", theme=theme))
    trace = renderer.trace
    i = int(trace.steps_of(Span)[len(trace.steps_of(Span)) // 2])
    y = trace.record_at(i).y
    image = renderer.rgb(i)
    row = (y * 10 + 5) if origin == "top-left" else (24 * 10 - 1 - (y * 10 + 5))
    colour = ex.THEMES[theme].palette.guide
    guide = tuple(int(colour[k:k + 2], 16) for k in (1, 3, 5))
    # At the right-hand end of the grid, away from every cell mark.
    assert tuple(image[row, 31 * 10 + 2]) == guide
    assert tuple(image[row - 3 if origin == "bottom-left" else row + 3, 31 * 10 + 2]) != guide
    # Without highlights, no reasoning either.
    plain = ex.FrameRenderer(scene, ex.ExportSettings(scale=10, caption=False, panel="none",
                                                      theme=theme, highlight=False))
    assert tuple(plain.rgb(i)[row, 31 * 10 + 2]) != guide


def test_vector_frames_draw_the_same_reasoning():
    from app.render.vector import draw_frame
    cell = 4  # the scale: frame units per cell
    scene = Scene(algorithm="polygon-scanline", points=[TRIANGLE], width=32, height=24)
    renderer = ex.FrameRenderer(scene, ex.ExportSettings(scale=4))
    trace = renderer.trace
    i = int(trace.steps_of(Span)[3])
    y = trace.record_at(i).y
    drawing = draw_frame(renderer, i)
    guide = ex.LIGHT.palette.guide
    lines = [shape for shape in drawing.shapes if shape[0] == "line" and shape[2] == guide]
    # The scan line across the grid at y + 1/2 (y up: 24 - y - 1/2 from the top), and the pair.
    row = (24 - y - 0.5) * cell
    assert ([(0.0, row), (32.0 * cell, row)], 1.0) in [(shape[1], shape[3]) for shape in lines]
    assert any(shape[3] == 4.0 for shape in lines)
    assert f"y + \u00bd = {y + 0.5:g}" in drawing.texts()
    plain = draw_frame(ex.FrameRenderer(scene, ex.ExportSettings(scale=4, reasoning=False)), i)
    assert not [shape for shape in plain.shapes if guide in shape]


def test_the_integer_edge_walks_crossings_are_its_exact_x():
    from fractions import Fraction

    from app.render.reasoning import step_guides
    from tests.support import record
    contour = [(2, 2), (12, 3), (8, 9)]
    trace = record("polygon-scanline-integer", [contour])
    spans = [i for i in range(len(trace)) if trace.step(i).record is not None
             and type(trace.step(i).record).__name__ == "Span"]
    assert spans
    for index in spans:
        guides = step_guides(trace, trace.state_at(index), [])
        y = trace.variables_at(index)["y"]
        line = Fraction(int(y)) + Fraction(1, 2)
        expected = sorted(float(Fraction(ax) + (line - ay) * Fraction(bx - ax, by - ay))
                          for (ax, ay), (bx, by) in zip(contour, contour[1:] + contour[:1])
                          if min(ay, by) <= line < max(ay, by))
        assert sorted(x for x, _, _ in guides.dots) == pytest.approx(expected)
