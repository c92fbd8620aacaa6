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
