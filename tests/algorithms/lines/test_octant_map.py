"""octant_map against a table written by hand: every octant's interior
direction and every boundary direction, with the mirrors that take it to the
first octant (x -> -x, y -> -y, then x <-> y)."""
from __future__ import annotations

import pytest

from algorithms.lines.common import Octant, octant_map

# (dx, dy): (octant, flip_x, flip_y, swap)
TABLE = {
    (5, 2): (1, False, False, False),
    (2, 5): (2, False, False, True),
    (-2, 5): (3, True, False, True),
    (-5, 2): (4, True, False, False),
    (-5, -2): (5, True, True, False),
    (-2, -5): (6, True, True, True),
    (2, -5): (7, False, True, True),
    (5, -2): (8, False, True, False),
    # The boundaries: x is major at 45 degrees, and a zero step is not mirrored.
    (4, 0): (1, False, False, False),
    (4, 4): (1, False, False, False),
    (0, 4): (2, False, False, True),
    (-4, 4): (4, True, False, False),
    (-4, 0): (4, True, False, False),
    (-4, -4): (5, True, True, False),
    (0, -4): (7, False, True, True),
    (4, -4): (8, False, True, False),
    (0, 0): (0, False, False, False),
}


@pytest.mark.parametrize("direction, expected", TABLE.items())
def test_octant_and_mirrors_match_the_table(direction, expected):
    mapping = octant_map(*direction)
    assert (mapping.number, mapping.flip_x, mapping.flip_y, mapping.swap) == expected


@pytest.mark.parametrize("direction", TABLE)
def test_the_mirrors_take_the_direction_into_the_first_octant(direction):
    x, y = octant_map(*direction).apply(*direction)
    assert 0 <= y <= x


@pytest.mark.parametrize("direction", TABLE)
def test_the_line_algorithms_octant_agrees(direction):
    assert Octant((3, 3), (3 + direction[0], 3 + direction[1])).number == TABLE[direction][0]


def test_the_mapping_in_words():
    assert octant_map(-2, -5).text() == ("octant 6 -> 1: mirror x (x -> -x), then "
                                         "mirror y (y -> -y), then swap x and y")
    assert octant_map(5, 2).text() == "octant 1: already the first octant, nothing to swap"
    assert octant_map(0, 4).text() == "octant 2 -> 1: swap x and y"
    assert octant_map(0, 0).text() == "P = Q: no direction, no octant"
