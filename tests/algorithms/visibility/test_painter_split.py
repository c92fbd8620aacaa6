"""The painter's algorithm with BSP splitting, against an exact oracle: at
each pixel centre, the triangle nearest the viewer (smallest z of its plane
there, in fractions), where the nearest is clear."""
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.visibility.zbuffer_painter import PALETTE
from app.model import scene as scenes
from app.model.scene import RESOURCES
from tests.support import record

GRID = (24, 18)


# The pieces' corners snap to 1/256 px, so an edge a cut ends on moves by
# up to 1/512 px at that end: a centre closer than this to an edge of its
# triangle may fall on either side.
SNAP = Fraction(1, 256)


def nearest(points, z, pixel, gap=Fraction(1, 50)):
    """The triangle whose plane is nearest at the pixel's centre, among those
    containing it; None when it holds the centre only on an edge or within
    SNAP of one (the fill rule and the snapped cuts decide there), or when
    another triangle holding it is within ``gap`` in depth (near the line
    where two triangles meet, or in one plane)."""
    px, py = pixel[0] + Fraction(1, 2), pixel[1] + Fraction(1, 2)
    found = []
    for t in range(len(points) // 3):
        (ax, ay), (bx, by), (cx, cy) = [tuple(Fraction(v) for v in p)
                                        for p in points[3 * t:3 * t + 3]]
        two_a = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
        if two_a == 0:
            continue
        alpha = ((bx - px) * (cy - py) - (cx - px) * (by - py)) / two_a
        beta = ((cx - px) * (ay - py) - (ax - px) * (cy - py)) / two_a
        gamma = 1 - alpha - beta
        if min(alpha, beta, gamma) >= 0:
            za, zb, zc = (Fraction(v) for v in z[3 * t:3 * t + 3])
            clear = min(alpha, beta, gamma) > 0 and not near_an_edge(
                ((ax, ay), (bx, by), (cx, cy)), (px, py))
            found.append((alpha * za + beta * zb + gamma * zc, t, clear))
    found.sort()
    if not found or (len(found) > 1 and found[1][0] - found[0][0] < gap) or not found[0][2]:
        return None
    return found[0][1]


def near_an_edge(corners, point) -> bool:
    """Whether ``point`` is within SNAP of the line through an edge (exact)."""
    for k in range(3):
        (ax, ay), (bx, by) = corners[k], corners[(k + 1) % 3]
        cross = (bx - ax) * (point[1] - ay) - (by - ay) * (point[0] - ax)
        if cross * cross < SNAP * SNAP * ((bx - ax) ** 2 + (by - ay) ** 2):
            return True
    return False


def check(points, z, grid, trace):
    colours = dict(zip(map(tuple, trace.written_pixels().tolist()), trace.pixel_values()))
    checked = 0
    for i in range(grid[0]):
        for j in range(grid[1]):
            owner = nearest(points, z, (i, j))
            if owner is None:
                continue
            checked += 1
            assert colours.get((i, j)) == int(PALETTE[owner % len(PALETTE)][1:], 16), (i, j)
    return checked


@pytest.mark.parametrize("name", ["painter-cyclic", "painter-intersecting"])
def test_splitting_fixes_the_scenes_the_painter_gets_wrong(name):
    scene = scenes.load(RESOURCES / "scenes" / f"{name}.json")
    grid = (scene.width, scene.height)
    plain = record("painter", scene.points, dict(scene.options), grid)
    fixed = record("painter-split", scene.points, {"z": scene.options["z"]}, grid)
    assert plain.final_variables()["disagree"] > 0
    final = fixed.final_variables()
    assert final["disagree"] == 0 and final["splits"] > 0
    assert final["pieces"] > len(scene.points) // 3
    assert check(scene.points, scene.options["z"], grid, fixed) > 100


def test_separate_triangles_need_no_split():
    points = ((1, 1), (10, 1), (5, 9), (12, 2), (22, 3), (16, 15))
    trace = record("painter-split", points, {"z": (0.2,) * 3 + (0.7,) * 3}, GRID)
    assert trace.final_variables()["splits"] == 0


COORD = st.integers(0, 8 * 24).map(lambda v: v / 8)
DEPTH = st.integers(1, 9).map(lambda v: v / 10)


@settings(max_examples=15)
@given(st.lists(st.tuples(COORD, COORD), min_size=6, max_size=9).filter(lambda p: len(p) % 3 == 0),
       st.lists(DEPTH, min_size=9, max_size=9))
def test_random_scenes_match_the_nearest_triangle(points, depths):
    points = [(min(x, 24), min(y, 18)) for x, y in points]
    z = tuple(depths[:len(points)])
    trace = record("painter-split", points, {"z": z}, GRID)
    check(points, z, GRID, trace)
