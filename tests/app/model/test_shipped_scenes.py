"""What the shipped scenes' descriptions claim is true."""
from fractions import Fraction

import numpy as np
import pytest

from algorithms.exact import coverage as exact_coverage, triangles as exact_triangles
from algorithms.core import registry
from algorithms.core.registry import InputError
from app.model import scene as scenes
from app.model.scene import RESOURCES


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


# ------------------------------------------------ far, behind the eye, aliasing
def exact_mesh_counts(scene):
    """Independent exact coverage of the mesh moved by the scene's offset, moved back."""
    ox, oy = scene.options["offset"]
    moved = [(Fraction(x) + ox, Fraction(y) + oy) for x, y in scene.points]
    window = (ox, oy, ox + scene.width, oy + scene.height)
    counts = exact_triangles.coverage(moved, 8, "top-left", window)
    interior = exact_triangles.union_interior(moved, 8, window)
    back = {(x - ox, y - oy): c for (x, y), c in counts.items()}
    return back, {(x - ox, y - oy) for x, y in interior}


def run_counts(trace):
    counts = {}
    for p in map(tuple, trace.written_pixels().tolist()):
        counts[p] = counts.get(p, 0) + 1
    return counts


def test_far_mesh_is_watertight_exactly_and_torn_in_float32():
    scene = load("triangle-mesh-1e6")
    assert min(scene.options["offset"]) >= 1_000_000 and scene.options["precision"] == "float32"
    truth, interior = exact_mesh_counts(scene)
    assert len(scene.points) >= 30 and set(truth.values()) == {1}  # no overlap
    assert interior <= set(truth)  # no crack
    grid = (scene.width, scene.height)
    fixed = scene.spec.record(scene.points, {**scene.options, "precision": "fixed"}, grid=grid)
    assert run_counts(fixed) == truth
    single = scene.spec.record(scene.points, scene.options, grid=grid)
    drawn = run_counts(single)
    cracks = interior - set(drawn)
    assert len(cracks) > 50
    final = single.final_variables()
    assert final["cracks"] == len(cracks)
    assert final["overlaps"] == sum(1 for c in drawn.values() if c > 1)


def test_behind_eye_scene_draws_the_wedge_below_the_front_edge():
    scene = load("triangle-behind-eye")
    w = scene.options["w"]
    assert min(w) < 0 < max(w) and scene.options["near"] > 0
    front = [p for p, wk in zip(scene.points, w) if wk > 0]
    edge_y = front[0][1]
    assert all(p[1] == edge_y for p in front)  # the front edge is horizontal
    drawn = set(written("triangle-behind-eye"))
    # The visible part lies below the front edge and reaches the grid's bottom row;
    # the triangle the projected corners outline (above it) is left empty.
    assert drawn and all(y + 0.5 < edge_y for _, y in drawn)
    assert any(y == 0 for _, y in drawn) and len(drawn) > 200
    with pytest.raises(InputError, match="near"):
        pixels(scene, near=0.0)


def test_siemens_star_aliases_with_one_sample_and_less_with_sixteen():
    scene = load("aa-siemens-star")
    assert scene.options["n"] == 1
    grid = (scene.width, scene.height)
    exact = exact_coverage.triangle_coverage(scene.points, grid)

    def error(n):
        trace = scene.spec.record(scene.points, {**scene.options, "n": n}, grid=grid)
        image = np.zeros((scene.height, scene.width))
        for (x, y), v in zip(trace.written_pixels().tolist(), trace.pixel_values().tolist()):
            image[y, x] = v
        return float(np.abs(image - exact).mean())
    one, four = error(1), error(4)
    assert one > 3 * four
    # One sample per pixel can only say 0 or 1: near the centre, where the spokes are
    # thinner than a pixel, that is far from the true coverage.
    assert one > 0.1
