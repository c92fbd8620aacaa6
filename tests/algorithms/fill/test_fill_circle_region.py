"""Seed fill inside a circle and flood fill of a region of one colour,
against scikit-image's flood (which fills the connected pixels equal to the
seed's value) on an outline drawn by the exact circle oracle."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from skimage.segmentation import flood

from algorithms.exact import circles as exact_circles
from algorithms.fill.flood import outline_pixels
from algorithms.core.registry import InputError, get

BOUNDARY, FILL = 0xC0392B, 0x2E86DE
ORDERS = ("stack", "queue", "span")
GRID = (40, 36)


def circle_fill(centre, radius, grid=GRID, **options):
    return get("flood-fill-circle").record([centre], {"radius": radius, **options}, grid=grid)


def polygon_fill(contours, grid=GRID, **options):
    return get("flood-fill").record(contours, options, grid=grid)


def colours(trace):
    return trace.raster_at(len(trace) - 1).colors


def image_of(pixels, grid=GRID):
    """1 where the outline is, 0 elsewhere, indexed [y, x]."""
    image = np.zeros(grid[::-1], dtype=np.uint8)
    for x, y in pixels:
        if 0 <= x < grid[0] and 0 <= y < grid[1]:
            image[y, x] = 1
    return image


def ring(centre, radius):
    return {(centre[0] + x, centre[1] + y) for x, y in exact_circles.midpoint_circle(radius)}


@pytest.mark.parametrize("radius", [1, 2, 3, 7, 15])
@pytest.mark.parametrize("order", ORDERS)
def test_four_connected_fill_stays_inside_the_circle(radius, order):
    centre = (20, 17)
    trace = circle_fill(centre, radius, order=order)
    outline = ring(centre, radius)
    expected = flood(image_of(outline), centre[::-1], connectivity=1)
    colors = colours(trace)
    assert np.array_equal(colors == FILL, expected)
    assert {(int(x), int(y)) for y, x in zip(*np.nonzero(colors == BOUNDARY))} == outline
    assert trace.final_variables()["filled"] == int(expected.sum())


@pytest.mark.parametrize("radius", [3, 9])
def test_eight_connected_fill_leaks_through_the_rings_diagonal_steps(radius):
    centre = (20, 17)
    outline = ring(centre, radius)
    leaked = colours(circle_fill(centre, radius, connectivity="8")) == FILL
    expected = flood(image_of(outline), centre[::-1], connectivity=2)
    assert np.array_equal(leaked, expected)
    # The leak reaches the grid's corner, far outside the circle.
    assert leaked[0, 0]


@pytest.mark.parametrize("radius", [2, 5, 9, 16])
@pytest.mark.parametrize("order", ORDERS)
def test_four_connected_ring_holds_an_eight_connected_fill(radius, order):
    centre = (20, 17)
    trace = circle_fill(centre, radius, connectivity="8", outline="4", order=order)
    colors = colours(trace)
    boundary = colors == BOUNDARY
    ys, xs = np.nonzero(boundary)
    assert ring(centre, radius) <= set(zip(xs.tolist(), ys.tolist()))
    expected = flood(boundary.astype(np.uint8), centre[::-1], connectivity=2)
    assert np.array_equal(colors == FILL, expected)
    # Nothing outside the circle's bounding box is filled.
    filled_y, filled_x = np.nonzero(expected)
    assert np.all(np.abs(filled_x - centre[0]) < radius)
    assert np.all(np.abs(filled_y - centre[1]) < radius)


def test_radius_zero_draws_its_centre_and_fills_nothing_by_default():
    trace = circle_fill((5, 5), 0, grid=(11, 11))
    colors = colours(trace)
    assert colors[5, 5] == BOUNDARY
    assert int(trace.raster_at(len(trace) - 1).counts.sum()) == 1
    assert trace.final_variables()["filled"] == 0
    # A seed outside the one-pixel circle fills the rest of the grid.
    trace = circle_fill((5, 5), 0, grid=(11, 11), seed=(0, 0))
    assert int((colours(trace) == FILL).sum()) == 11 * 11 - 1


# ------------------------------------------------------------ region mode
@pytest.mark.parametrize("connectivity", ["4", "8"])
@pytest.mark.parametrize("order", ORDERS)
def test_region_mode_from_the_outline_recolours_the_outline(connectivity, order):
    contours = [[(4, 4), (30, 6), (18, 28)], [(34, 30), (38, 30), (38, 34)]]
    outline = outline_pixels(contours)
    seed = outline[3]
    trace = polygon_fill(contours, seed=seed, mode="region", connectivity=connectivity,
                         order=order)
    image = image_of(outline)
    expected = flood(image, seed[::-1], connectivity=1 if connectivity == "4" else 2)
    colors = colours(trace)
    assert np.array_equal(colors == FILL, expected)
    # The other triangle's outline keeps the boundary colour; the rest is untouched.
    assert np.array_equal(colors == BOUNDARY, (image == 1) & ~expected)
    assert trace.start.constants["spreads over"] == "the outline"


@settings(max_examples=60)
@given(st.lists(st.tuples(st.integers(0, 25), st.integers(0, 20)), min_size=3, max_size=6),
       st.tuples(st.integers(0, 25), st.integers(0, 20)), st.sampled_from(["4", "8"]))
def test_region_mode_is_the_flood_of_the_seeds_colour(contour, seed, connectivity):
    grid = (26, 21)
    image = image_of(outline_pixels([contour]), grid)
    expected = flood(image, seed[::-1], connectivity=1 if connectivity == "4" else 2)
    trace = polygon_fill([contour], grid=grid, seed=seed, mode="region",
                         connectivity=connectivity)
    assert np.array_equal(colours(trace) == FILL, expected)
    if image[seed[::-1]] == 0:
        # From a free pixel, region and boundary fills agree.
        boundary = polygon_fill([contour], grid=grid, seed=seed, connectivity=connectivity)
        assert np.array_equal(colours(boundary) == FILL, expected)
    else:
        with pytest.raises(InputError, match="mode=region"):
            polygon_fill([contour], grid=grid, seed=seed, connectivity=connectivity)


def test_explain_names_the_outline_pixels_pushed_in_region_mode():
    contours = [[(2, 2), (12, 2), (12, 9), (2, 9)]]
    trace = polygon_fill(contours, grid=(16, 12), seed=(2, 2), mode="region", order="queue")
    spec = get("flood-fill")
    first_fill = next(i for i in range(len(trace))
                      if trace.code[trace.step(i).line].text.strip().startswith("fill p"))
    rows = dict(spec.explain(trace, first_fill))
    # From the corner (2, 2) the outline runs east and north.
    assert rows["pushed"] == "(3, 2) (2, 3)"
