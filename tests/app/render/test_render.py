"""The numpy composition of the grid image (no Qt involved)."""
import numpy as np
import pytest

from algorithms.core.raster import Raster
from app.model.geometry import differences
from app.render.compose import PALETTE, Overlay, compose, packed_rgba, top_down


def rgba(color, alpha=255):
    value = int(color.lstrip("#"), 16)
    return [(value >> 16) & 255, (value >> 8) & 255, value & 255, alpha]


def small_raster():
    # 3 x 2 grid: (0, 0) written once, (1, 0) twice, (2, 1) once.
    raster = Raster(3, 2)
    raster.write(0, 0)
    raster.write(1, 0)
    raster.write(1, 0)
    raster.write(2, 1)
    return raster


def test_cells_take_ink_overdraw_and_background():
    image = compose(small_raster())
    assert image.shape == (2, 3, 4) and image.dtype == np.uint8
    # Row 0 is y = 0, as in Raster.counts.
    assert image[0, 0].tolist() == rgba(PALETTE.ink)
    assert image[0, 1].tolist() == rgba(PALETTE.overdraw)
    assert image[0, 2].tolist() == rgba(PALETTE.background)
    assert image[1, 0].tolist() == rgba(PALETTE.background)
    assert image[1, 2].tolist() == rgba(PALETTE.ink)


def test_written_values_are_colours():
    raster = Raster(2, 2, with_colors=True)
    raster.write(0, 0, 0xFF8000)
    raster.write(1, 1, 0x0000FF)
    raster.write(1, 1, 0x00FF00)  # last write wins, and it is an overdraw
    image = compose(raster)
    assert image[0, 0].tolist() == [255, 128, 0, 255]
    # Colour cells written twice keep their hue, darkened.
    assert image[1, 1].tolist() == [0, 153, 0, 255]
    assert image[0, 1].tolist() == rgba(PALETTE.background)


def test_scale_one_tints_highlighted_cells():
    plain = compose(small_raster())
    tinted = compose(small_raster(), Overlay(current=(2, 1), candidates=[(2, 0)]))
    changed = np.argwhere((plain != tinted).any(axis=2)).tolist()
    assert sorted(changed) == [[0, 2], [1, 2]]


def test_scaled_image_has_grid_lines_and_outlines():
    overlay = Overlay(current=(0, 0), candidates=[(1, 1)],
                      differences=np.array([[2, 1]]))
    image = compose(small_raster(), overlay, scale=10)
    assert image.shape == (20, 30, 4)
    # Grid lines at every cell border inside the grid.
    assert image[10, 5].tolist() == rgba(PALETTE.grid)
    assert image[5, 20].tolist() == rgba(PALETTE.grid)
    assert image[5, 25].tolist() == rgba(PALETTE.background)
    # The current cell's ring sits just inside its border; its middle keeps the ink.
    assert image[1, 5].tolist() == rgba(PALETTE.current)
    assert image[5, 5].tolist() == rgba(PALETTE.ink)
    # The candidate ring is further in; the difference ring is on the edge.
    assert image[12, 15].tolist() == rgba(PALETTE.candidate)
    assert image[10, 25].tolist() == rgba(PALETTE.difference)
    assert image[15, 29].tolist() == rgba(PALETTE.difference)


def test_scaled_image_draws_the_ideal_primitive():
    raster = Raster(4, 4)
    image = compose(raster, Overlay(primitive=[(0.5, 0.5), (3.5, 3.5)]), scale=8)
    on_line = image[16, 16]  # the middle of the diagonal
    assert on_line.tolist() == rgba(PALETTE.primitive)
    assert image[4, 28].tolist() == rgba(PALETTE.background)


def test_top_down_flips_only_the_y_up_frame():
    image = compose(small_raster())
    assert np.array_equal(top_down(image)[0], image[1])
    assert top_down(image, y_down=True) is image


def test_differences_lists_cells_written_by_one_run_only():
    a, b = Raster(4, 3), Raster(4, 3)
    for x, y in [(0, 0), (1, 1), (2, 1)]:
        a.write(x, y)
    for x, y in [(0, 0), (1, 2), (2, 1), (2, 1)]:
        b.write(x, y)
    assert sorted(map(tuple, differences(a, b).tolist())) == [(1, 1), (1, 2)]
    assert differences(a, Raster(5, 3)).shape == (0, 2)


def test_packed_rgba_byte_order():
    assert np.array([packed_rgba("#102030")]).view(np.uint8).tolist() == [16, 32, 48, 255]


def test_bad_scale_is_refused():
    with pytest.raises(ValueError):
        compose(small_raster(), scale=0)
