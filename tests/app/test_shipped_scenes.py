"""What the shipped scenes' descriptions claim is true."""
import numpy as np

from algorithms import registry
from app import scene as scenes
from app.scene import RESOURCES


def load(name):
    return scenes.load(RESOURCES / "scenes" / f"{name}.json")


def pixels(scene, **options):
    trace = scene.spec.record(scene.points, {**scene.options, **options},
                              grid=(scene.width, scene.height))
    return trace.written_pixels()


def test_float32_drift_scene_is_16_pixels_one_row_off():
    scene = load("line-float32-drift")
    (x0, y0), (x1, y1) = scene.points
    # Independent float32 accumulation, written here.
    y, slope, rows = np.float32(y0), np.float32(y1 - y0) / np.float32(x1 - x0), [y0]
    for _ in range(x1 - x0):
        y = np.float32(y + slope)
        rows.append(int(np.floor(np.float64(y) + 0.5)))
    drawn = pixels(scene)
    assert drawn[:, 1].tolist() == rows
    exact = [(2 * (y1 - y0) * k + (x1 - x0)) // (2 * (x1 - x0)) for k in range(x1 - x0 + 1)]
    off = np.array(rows) - np.array(exact)
    assert sorted(set(off.tolist())) == [0, 1] and int(off.sum()) == 16


def test_centre_ties_scene_has_a_tie_at_every_odd_column():
    scene = load("line-centre-ties")
    (x0, y0), (x1, y1) = scene.points
    assert 2 * (y1 - y0) == x1 - x0  # slope 1/2: odd columns sit on a half


def test_reversed_scene_differs_until_symmetric():
    reversed_scene = load("line-reversed")
    forward = reversed_scene.points[::-1]
    spec = reversed_scene.spec
    grid = (reversed_scene.width, reversed_scene.height)

    def drawn(points, symmetric):
        trace = spec.record(points, {"symmetric": symmetric}, grid=grid)
        return set(map(tuple, trace.written_pixels().tolist()))
    assert drawn(reversed_scene.points, False) != drawn(forward, False)
    assert drawn(reversed_scene.points, True) == drawn(forward, True)


def written(name, **options):
    scene = load(name)
    return [tuple(p) for p in pixels(scene, **options).tolist()]


def test_radius_1_is_four_pixels_and_radius_2_has_no_repeats():
    assert sorted(written("circle-radius-1")) == [(4, 5), (5, 4), (5, 6), (6, 5)]
    ring = written("circle-radius-2")
    assert len(ring) == len(set(ring)) == 12


def test_sqrt4_scene_breaks_its_outline():
    ring = set(written("circle-sqrt4-gaps"))
    # A pixel of a closed 8-connected outline has at least two outline neighbours.
    lonely = [p for p in ring
              if sum((p[0] + dx, p[1] + dy) in ring
                     for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy) < 2]
    assert lonely


def test_star_centre_is_empty_even_odd_and_filled_non_zero():
    assert (16, 12) not in set(written("polygon-star-evenodd"))
    assert (16, 12) in set(written("polygon-star-nonzero"))


def test_horizontal_edge_scene_keeps_bottom_centres_only():
    filled = set(written("polygon-horizontal-edges"))
    assert (5, 2) in filled and (5, 18) not in filled  # bottom edge y = 2.5 kept, top 18.5 not
    assert (18, 8) in filled and (18, 7) not in filled  # the notch's edge y = 8.5 is a bottom edge


def test_fan_covers_each_pixel_once_and_sliver_fills_little():
    fan = written("triangle-fan-32")
    assert len(fan) == len(set(fan)) > 300
    assert len(written("triangle-sliver")) <= 3


def test_painter_scenes_disagree_with_the_z_buffer():
    for name in ("painter-intersecting", "painter-cyclic"):
        scene = load(name)
        grid = (scene.width, scene.height)
        painter = scene.spec.record(scene.points, scene.options, grid=grid)
        options = {k: v for k, v in scene.options.items() if k in ("z", "colors", "fill_rule")}
        depth = registry.get("zbuffer").record(scene.points, options, grid=grid)
        differ = painter.raster_at(-1).colors != depth.raster_at(-1).colors
        assert differ.any(), name
