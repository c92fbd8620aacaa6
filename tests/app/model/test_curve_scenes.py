"""What the shipped circle-variant and curve scenes' descriptions claim is true."""
from app.model import scene as scenes
from app.model.scene import RESOURCES
from algorithms.exact import circles as exact_circles
from tests.support.curve_oracles import chebyshev_gaps, disk_oracle, polyline_oracle


def run(name, **options):
    scene = scenes.load(RESOURCES / "scenes" / f"{name}.json")
    trace = scene.spec.record(scene.points, {**scene.options, **options},
                              grid=(scene.width, scene.height))
    return scene, trace, [tuple(p) for p in trace.written_pixels().tolist()]


def test_polar_gaps_scene_breaks_and_auto_closes():
    scene, trace, pixels = run("circle-polar-gaps")
    assert chebyshev_gaps(pixels) == trace.final_variables()["gaps"] > 0
    _, trace, pixels = run("circle-polar-gaps", dt="auto")
    assert chebyshev_gaps(pixels) == 0


def test_printed_scene_leaves_the_circle():
    scene, trace, pixels = run("circle-midpoint-printed")
    (xc, yc), = scene.points
    offsets = {(x - xc, y - yc) for x, y in pixels}
    assert offsets - exact_circles.midpoint_circle(scene.options["radius"])


def test_fractional_scene_is_the_exact_disk_and_no_integer_circle():
    scene, trace, pixels = run("circle-fractional-centre")
    assert set(pixels) == disk_oracle(scene.points[0], scene.options["radius"])
    # No integer centre and radius gives this disk with the same rule.
    assert all(set(pixels) != disk_oracle((cx + 0.5, cy + 0.5), r)
               for cx in range(12, 19) for cy in range(9, 15) for r in range(5, 10))


def test_bezier_scene_is_its_polyline_and_more_segments_change_it():
    scene, trace, pixels = run("curve-bezier-segments")
    assert pixels == polyline_oracle(scene.points, 4)[1]
    _, _, finer = run("curve-bezier-segments", segments=16)
    assert finer == polyline_oracle(scene.points, 16)[1] and set(finer) != set(pixels)


def test_jittered_motion_blur_scene_differs_from_even_instants():
    import numpy as np
    scene, trace, _ = run("aa-motion-blur-jittered")
    _, even, _ = run("aa-motion-blur-jittered", times="even")
    jittered_values, even_values = trace.pixel_values(), even.pixel_values()
    assert len(jittered_values) and not (len(jittered_values) == len(even_values)
                                         and np.allclose(jittered_values, even_values))


def test_thin_line_scene_lights_few_samples_and_leaves_gaps():
    import math
    scene, trace, pixels = run("aa-thin-line-supersample")
    (x0, y0), (x1, y1) = scene.points
    n, half = scene.options["n"], scene.options["width"] / 2
    values = trace.pixel_values()
    length = math.hypot(x1 - x0, y1 - y0)

    def on_line(x, y):  # a sample within the line's rectangle
        t = ((x - x0) * (x1 - x0) + (y - y0) * (y1 - y0)) / length ** 2
        dist = abs((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)) / length
        return 0 <= t <= 1 and dist <= half
    lit = {p: v for p, v in zip(pixels, values.tolist()) if v > 0}
    for (i, j), value in lit.items():
        hits = sum(on_line(i + (a + 0.5) / n, j + (b + 0.5) / n)
                   for a in range(n) for b in range(n))
        assert value == hits / n ** 2
    # Faint, and fewer lit pixels than the columns the line crosses: gaps.
    assert max(lit.values()) <= 1 / n ** 2 + 1e-12
    assert len({i for i, _ in lit}) < x1 - x0


def test_grey_plane_scene_is_the_plane_through_the_vertex_values():
    from fractions import Fraction
    scene, trace, pixels = run("triangle-plane-grey")
    (ax, ay), (bx, by), (cx, cy) = [tuple(Fraction(v) for v in p) for p in scene.points]
    levels = (0, 128, 255)
    two_a = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
    for (i, j), colour in zip(pixels, trace.pixel_values().tolist()):
        px, py = i + Fraction(1, 2), j + Fraction(1, 2)
        alpha = ((bx - px) * (cy - py) - (cx - px) * (by - py)) / two_a
        beta = ((cx - px) * (ay - py) - (ax - px) * (cy - py)) / two_a
        grey = alpha * levels[0] + beta * levels[1] + (1 - alpha - beta) * levels[2]
        r, g, b = (int(colour) >> 16) & 255, (int(colour) >> 8) & 255, int(colour) & 255
        assert r == g == b and abs(r - grey) <= 1


def test_subpixel_scene_lights_every_column_the_line_crosses():
    scene, trace, pixels = run("aa-line-subpixels")
    (x0, _), (x1, _) = scene.points
    assert set(range(x0, x1 + 1)) <= {x for x, _ in pixels}
    assert max(trace.pixel_values()) == 1.0


def test_printed_columns_scene_is_empty_and_counts_what_is_missing():
    from tests.support.triangle_variant_oracles import cramer_oracle
    scene, trace, pixels = run("triangle-columns-printed")
    expected = cramer_oracle(scene.points, (scene.width, scene.height))
    assert pixels == [] and trace.final_variables()["missing"] == sum(expected.values()) > 0
    _, correct, filled = run("triangle-columns-printed", swap="correct")
    assert sorted(filled) == sorted(expected)


def test_span_interpolation_scene_is_the_plane():
    from tests.support.triangle_variant_oracles import plane_value
    scene, trace, pixels = run("triangle-span-interpolate")
    f = trace.series("f")[trace.writes()]
    assert len(pixels) > 100
    assert all(value == float(plane_value(scene.points, scene.options["s"], pixel))
               for pixel, value in zip(pixels, f))


def test_split_painter_scene_agrees_with_the_z_buffer():
    scene, trace, pixels = run("painter-split-cyclic")
    final = trace.final_variables()
    assert final["disagree"] == 0 and final["splits"] == 3 and final["pieces"] == 9


def test_bresenham_circle_scene_equals_the_midpoint_circle():
    scene, trace, pixels = run("circle-bresenham")
    (xc, yc), = scene.points
    assert {(x - xc, y - yc) for x, y in pixels} == \
        exact_circles.midpoint_circle(scene.options["radius"])


def test_shared_edge_scene_fills_the_diagonal_twice():
    from collections import Counter
    scene, trace, pixels = run("triangle-cramer-shared-edge")
    twice = {p for p, n in Counter(pixels).items() if n == 2}
    # Centres on the diagonal from (4.5, 4.5) to (26.5, 20.5): 16 (x - 4) = 22 (y - 4).
    assert twice and all(16 * (x - 4) == 22 * (y - 4) for x, y in twice)


def test_wireframe_scene_differs_from_the_fill():
    from tests.support.triangle_variant_oracles import wireframe_oracle
    scene, trace, pixels = run("triangle-wireframe")
    grid = (scene.width, scene.height)
    assert pixels == wireframe_oracle(scene.points, grid)
    from algorithms.core import registry
    bbox = {tuple(p) for p in registry.get("triangle-bbox").record(
        scene.points, {}, grid).written_pixels().tolist()}
    assert set(pixels) - bbox and bbox - set(pixels)


def test_trilinear_scene_weights_add_up_to_one():
    import numpy as np
    scene, trace, pixels = run("triangle-trilinear")
    total = sum(trace.series(n)[trace.writes()] for n in ("alpha", "beta", "gamma"))
    assert len(pixels) > 100 and np.allclose(total, 1.0, atol=1e-12)
