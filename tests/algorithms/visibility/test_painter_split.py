"""The painter's algorithm with BSP splitting, against an exact oracle: at
each pixel centre, the triangle nearest the viewer (smallest z of its plane
there, in fractions), where the nearest is clear."""
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.model import scene as scenes
from app.model.scene import RESOURCES
from tests.support import record
from tests.support.visibility_oracles import check_split as check

GRID = (24, 18)


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
