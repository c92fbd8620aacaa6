"""The geometric overlays of a triangle run's step, against exact geometry
written here, and the same strokes in an exported frame."""
from dataclasses import replace
from fractions import Fraction

import numpy as np
import pytest

from app.render import octant_overlay, overlays
from app.render.export import ExportSettings, FrameRenderer
from app.model import scene as scenes
from tests.support import record

TRIANGLE = ((4.25, 3.5), (27.5, 8.75), (11.125, 21.25))


def twice_area(a, b, c):
    a, b, c = ([Fraction(v) for v in p] for p in (a, b, c))
    return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])


@pytest.fixture(scope="module")
def trace():
    return record("triangle-bbox", TRIANGLE, {}, (32, 24))


def plotted_steps(trace, count=6):
    steps = [i for i in range(len(trace)) if trace.step(i).writes]
    return steps[::max(1, len(steps) // count)]


def test_sub_triangle_areas_are_the_runs_weights(trace):
    whole = twice_area(*TRIANGLE)
    for i in plotted_steps(trace):
        step = trace.step(i)
        strokes = overlays.overlay_strokes(trace, i, ["sub-triangles"])
        assert len(strokes) == 3
        p = (step.pixel[0] + 0.5, step.pixel[1] + 0.5)
        for k, stroke in enumerate(strokes):
            corners = stroke.points[:3]
            assert corners[k] == p and stroke.points[3] == corners[0]
            # Area of the sub-triangle opposite P_k over the whole: e_k / 2A.
            assert float(twice_area(*corners) / whole) == pytest.approx(
                step.values[f"e{k}"] / float(whole), abs=1e-12)


def test_distances_are_perpendicular_and_as_long_as_e_over_the_edge(trace):
    for i in plotted_steps(trace):
        step = trace.step(i)
        strokes = overlays.overlay_strokes(trace, i, ["distances"])
        p = np.array([step.pixel[0] + 0.5, step.pixel[1] + 0.5])
        for k, stroke in enumerate(strokes):
            a, b = np.array(TRIANGLE[(k + 1) % 3]), np.array(TRIANGLE[(k + 2) % 3])
            start, foot = np.array(stroke.points[0]), np.array(stroke.points[1])
            assert np.allclose(start, p)
            edge = b - a
            assert abs(edge[0] * (foot - a)[1] - edge[1] * (foot - a)[0]) < 1e-9  # on the line
            assert abs(np.dot(edge, p - foot)) < 1e-9  # at a right angle
            assert np.linalg.norm(p - foot) == pytest.approx(
                abs(step.values[f"e{k}"]) / np.linalg.norm(edge), rel=1e-12)


def inside_polygon(point, polygon) -> bool:
    """Ray casting: is ``point`` inside ``polygon`` (not on its edge)?"""
    x, y = point
    inside = False
    for (x0, y0), (x1, y1) in zip(polygon, polygon[1:] + polygon[:1]):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            inside = not inside
    return inside


def test_half_planes_are_one_calm_tint_on_the_positive_side_and_thin_edges(trace):
    shapes = overlays.overlay_shapes(trace, 10, ["half-planes"])
    # Three thin edge lines, no hatching, and one fill per edge in one tint.
    assert len(shapes.strokes) == 3 and {s.width for s in shapes.strokes} == {1.0}
    assert [s.colour for s in shapes.strokes] == list(overlays.EDGE_COLOURS)
    assert len(shapes.fills) == 3 and len({(f.colour, f.alpha) for f in shapes.fills}) == 1
    assert shapes.fills[0].alpha <= 0.15
    for k, fill in enumerate(shapes.fills):
        a, b = TRIANGLE[(k + 1) % 3], TRIANGLE[(k + 2) % 3]

        def e(x, y):
            return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])

        for x in np.arange(0.25, 32, 1.0):
            for y in np.arange(0.25, 24, 1.0):
                if abs(e(x, y)) > 1e-6:
                    assert inside_polygon((x, y), list(fill.points)) == (e(x, y) > 0)


def test_sub_triangles_are_filled_and_labelled_at_their_centroids(trace):
    whole = twice_area(*TRIANGLE)
    for i in plotted_steps(trace):
        step = trace.step(i)
        p = (step.pixel[0] + 0.5, step.pixel[1] + 0.5)
        shapes = overlays.overlay_shapes(trace, i, ["sub-triangles"])
        assert [label.text for label in shapes.labels] == ["\u03b1", "\u03b2", "\u03b3"]
        for k in range(3):
            # The sub-triangle opposite P_k: p in P_k's place.
            corners = [p if j == k else TRIANGLE[j] for j in range(3)]
            fill, label = shapes.fills[k], shapes.labels[k]
            assert list(fill.points) == corners and 0 < fill.alpha < 1
            assert fill.colour == label.colour == overlays.EDGE_COLOURS[k]
            assert label.at == pytest.approx((sum(c[0] for c in corners) / 3,
                                              sum(c[1] for c in corners) / 3))
            # Its share of the area is P_k's weight, as the notes define it:
            # alpha = dist(p, P1P2) / dist(P0, P1P2), and so on.
            a, b = TRIANGLE[(k + 1) % 3], TRIANGLE[(k + 2) % 3]
            weight = twice_area(p, a, b) / twice_area(TRIANGLE[k], a, b)
            assert twice_area(*corners) / whole == weight


def test_an_exported_frame_fills_the_sub_triangles_as_the_shapes_say():
    scene = scenes.Scene(algorithm="triangle-bbox", points=TRIANGLE, width=32, height=24)
    settings = ExportSettings(scale=10, caption=False, panel="none", grid_lines=False,
                              highlight=False, primitive=False)
    plain = FrameRenderer(scene, settings)
    shown = FrameRenderer(scene, replace(settings, overlays=("sub-triangles",)))
    trace = plain.trace
    i = plotted_steps(trace)[2]
    shapes = overlays.overlay_shapes(trace, i, ["sub-triangles"])
    before, after = plain.rgb(i), shown.rgb(i)
    for fill in shapes.fills:
        corners = fill.points
        k = overlays.EDGE_COLOURS.index(fill.colour)
        # Between the centroid (the label) and a corner that is not p: inside, clear of both.
        far = corners[(k + 1) % 3]
        x = (2 * far[0] + sum(c[0] for c in corners) / 3) / 3
        y = (2 * far[1] + sum(c[1] for c in corners) / 3) / 3
        row, column = round((24 - y) * 10), round(x * 10)
        expected = [fill.alpha * c + (1 - fill.alpha) * b
                    for c, b in zip(fill.colour, before[row, column])]
        assert np.allclose(after[row, column], expected, atol=3), (k, after[row, column])


def test_basis_vectors_run_from_p0(trace):
    strokes = overlays.overlay_strokes(trace, 5, ["basis"])
    assert strokes[0].points == (TRIANGLE[0], TRIANGLE[1])
    assert (TRIANGLE[0], TRIANGLE[2]) in [s.points for s in strokes]


def test_no_triangle_no_overlay():
    line = record("line-bresenham", ((0, 0), (5, 3)))
    assert overlays.overlay_strokes(line, 2, overlays.OVERLAYS) == []


def test_overlay_names_are_checked():
    assert overlays.parse_overlays("all") == overlays.OVERLAYS
    assert overlays.parse_overlays("basis, distances") == ("basis", "distances")
    with pytest.raises(ValueError, match="unknown overlay"):
        overlays.parse_overlays("planes")


def test_export_draws_the_strokes_in_their_colours(trace):
    scene = scenes.Scene(algorithm="triangle-bbox", points=TRIANGLE, width=32, height=24)
    i = plotted_steps(trace)[2]
    plain = FrameRenderer(scene, ExportSettings(scale=12, panel="none", caption=False))
    drawn = FrameRenderer(scene, ExportSettings(scale=12, panel="none", caption=False,
                                                overlays=("distances",)))
    before, after = plain.rgb(i), drawn.rgb(i)
    changed = after[(before != after).any(axis=2)]
    colours = {tuple(c) for c in changed.tolist()}
    assert colours and colours <= set(overlays.EDGE_COLOURS)
    # Where the strokes run: the middle of each perpendicular, image row 0 at the top.
    height = after.shape[0]
    for stroke in overlays.overlay_strokes(trace, i, ["distances"]):
        (x0, y0), (x1, y1) = stroke.points
        if np.hypot(x1 - x0, y1 - y0) < 0.5:
            continue
        col, row = int((x0 + x1) / 2 * 12), height - 1 - int((y0 + y1) / 2 * 12)
        window = after[max(0, row - 2):row + 3, max(0, col - 2):col + 3].reshape(-1, 3)
        assert any(tuple(c) == stroke.colour for c in window.tolist())


def test_cramer_run_names_its_triangle_for_the_overlays():
    trace = record("triangle-cramer", TRIANGLE, {}, (32, 24))
    assert overlays.current_triangle(trace, len(trace) // 2) == TRIANGLE


# ------------------------------------------------------------ octants
LINE = ((14, 14), (8, 1))  # dx = -6, dy = -13: octant 6


def octant_strokes(line=((14.5, 14.5), (8.5, 1.5))):
    trace = record("line-bresenham", LINE)
    return overlays.overlay_strokes(trace, 3, ["octants"], line)


def test_the_octant_diagram_outlines_the_lines_octant_and_its_image():
    from app.render import octant_overlay as octo
    strokes = octant_strokes()
    by_colour = {}
    for stroke in strokes:
        by_colour.setdefault(stroke.colour, []).append(stroke)
    # Octant 6 lies between 225 and 270 degrees: its rays end there, seen from P.
    ends = {tuple(round(v, 6) for v in s.points[-1]) for s in by_colour[octo.OCTANT_COLOUR]
            if len(s.points) == 2 and s.points[0] == (14.5, 14.5)}
    r = octo.RADIUS
    assert ends == {(round(14.5 - r * 0.5 ** 0.5, 6), round(14.5 - r * 0.5 ** 0.5, 6)),
                    (14.5, round(14.5 - r, 6))}
    # The image in octant 1: (13, 6) from P.
    (image,) = by_colour[octo.IMAGE_COLOUR]
    assert image.points == ((14.5, 14.5), (27.5, 20.5))
    # Three mirrors, dashed: dashes along the vertical, the horizontal and y = x.
    directions = set()
    for s in by_colour[octo.MIRROR_COLOUR]:
        (x0, y0), (x1, y1) = s.points
        directions.add((round(x1 - x0, 6) != 0, round(y1 - y0, 6) != 0))
    assert directions == {(False, True), (True, False), (True, True)}
    # Eight rays, and the octant's number drawn in its colour beside seven others.
    assert sum(1 for s in by_colour[octo.RAY_COLOUR] if s.points[0] == (14.5, 14.5)) == 8


def test_the_octant_overlay_needs_a_line():
    trace = record("line-bresenham", LINE)
    assert overlays.overlay_strokes(trace, 3, ["octants"], None) == []
    assert not any(s.colour == octant_overlay.MIRROR_COLOUR for s in octant_strokes(((3.5, 3.5), (9.5, 5.5))))


def test_octants_is_named_and_a_scene_can_switch_it_on():
    from app.model import shipped
    assert overlays.parse_overlays("octants") == ("octants",)
    assert overlays.parse_overlays("none") == ()
    scene = scenes.load(shipped.scene_path("line-octants"))
    assert overlays.scene_overlays(scene) == ("octants",)
    assert overlays.scene_overlays(scene.replace(view={"overlays": ["later", "octants"]})) \
        == ("octants",)
    with pytest.raises(scenes.SceneError, match="view.overlays"):
        scenes._view({"overlays": "octants"})


def test_export_draws_the_octant_diagram():
    from app.model import shipped
    from app.render import octant_overlay as octo
    scene = scenes.load(shipped.scene_path("line-octants"))
    # No highlight: its marks are drawn over the strokes.
    settings = dict(scale=12, panel="none", caption=False, highlight=False)
    plain = FrameRenderer(scene, ExportSettings(**settings)).rgb(3)
    drawn = FrameRenderer(scene, ExportSettings(**settings, overlays=("octants",))).rgb(3)
    changed = [tuple(c) for c in drawn[(plain != drawn).any(axis=2)].tolist()]
    assert {octo.OCTANT_COLOUR, octo.MIRROR_COLOUR, octo.IMAGE_COLOUR} <= set(changed)
    assert set(changed) <= set(octo.COLOURS)
