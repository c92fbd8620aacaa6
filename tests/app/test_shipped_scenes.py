"""What the shipped scenes' descriptions claim is true."""
import numpy as np

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
