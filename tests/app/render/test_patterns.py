"""Patterns in grid cells: the diff's classes and the error map's sign are
told apart without colour."""
from __future__ import annotations

import numpy as np
import pytest

from algorithms.core.raster import Raster
from app.model import compare
from app.model.colours import DIFF_PATTERNS
from app.render.compose import PALETTE, diff_image, error_image
from app.render.patterns import mask, pattern_scale


@pytest.mark.parametrize("scale", range(4, 9))
def test_every_diff_class_has_its_own_pattern_at_every_scale(scale):
    masks = [mask(name, scale).tobytes() for name in DIFF_PATTERNS]
    assert len(set(masks)) == len(DIFF_PATTERNS)


def test_a_stripe_rises_to_the_right_as_seen():
    # Row 0 is the bottom of the picture: "/" marks (0, 0) and (1, 1) ...
    m = mask("stripes /", 8)
    assert m[0, 0] and m[1, 1] and m[7, 7] and not m[0, 7]
    m = mask("stripes \\", 8)
    assert m[3, 1] and m[1, 3] and not m[1, 1]


def test_the_pattern_scale_fits_the_grid():
    assert pattern_scale(32, 24) == 8
    assert pattern_scale(400, 300) == 5
    assert pattern_scale(1024, 10) == 1  # cells too small on screen: no pattern


def test_the_diff_image_cuts_each_class_pattern_in_the_background_colour():
    a, b = Raster(4, 1), Raster(4, 1)
    a.write(0, 0)  # only A at x = 0
    b.write(1, 0)  # only B at x = 1
    a.write(2, 0)  # both at x = 2; x = 3 empty
    b.write(2, 0)
    d = compare.diff(a, b)
    plain = diff_image(d, PALETTE)
    big = diff_image(d, PALETTE, scale=8)
    assert big.shape == (8, 32, 4)
    background = np.array([int(PALETTE.background[k:k + 2], 16) for k in (1, 3, 5)])
    for x, name in ((0, "stripes /"), (1, "stripes \\"), (2, "plain")):
        cell = big[:, 8 * x:8 * x + 8, :3]
        marked = (cell == background).all(axis=-1)
        assert np.array_equal(marked, mask(name, 8)), name
        assert (cell[~marked] == plain[0, x, :3]).all()  # the rest keeps the class's colour
    assert (big[:, 24:, :3] == background).all()


def test_the_error_map_hatches_too_little_only():
    image = error_image(np.array([[-1.0, 1.0, 0.0]]), signed=True, scale=6)
    white = (image[..., :3] == 255).all(axis=-1)
    assert np.array_equal(white[:, :6], mask("stripes \\", 6))
    assert not white[:, 6:12].any() and white[:, 12:].all()
    assert np.array_equal(error_image(np.array([[-1.0]]), signed=True)[0, 0, :3], [0, 0x72, 0xb2])
