"""polygon-scanline against scikit-image's skimage.draw.polygon / polygon2mask.

The difference, stated: scikit-image fills a pixel when its centre is inside
by the even-odd rule *or lies on the outline*, on any edge or vertex (its
point-in-polygon test reports "edge" and "vertex" apart from "inside", and
draw.polygon keeps all three). RasterLab keeps a centre on the outline only
when it is on a left edge or a bottom horizontal edge, so that polygons
sharing an edge never share a pixel. Hence, for one contour:

* at every pixel centre off the outline, both give the same answer;
* at every centre on the outline of a simple polygon, scikit-image fills
  the pixel; RasterLab fills exactly those on left and bottom edges (the
  oracle's answer), so a square with its sides on centres is one row and
  one column larger in scikit-image.

(At a point where a self-intersecting outline crosses itself, scikit-image
sees no edge and falls back to its parity test, so the second statement is
made for simple polygons only.)

Conventions mapped: scikit-image puts pixel centres at whole (row, column)
coordinates, RasterLab at (i + 1/2, j + 1/2); so a vertex (x, y) is given
to scikit-image as (row, column) = (y - 1/2, x - 1/2), and its pixel
(r, c) is RasterLab's (c, r). scikit-image is given the vertices already
snapped to 1/256 px; on such small multiples of 1/256 its float64
arithmetic is exact, so no tolerance is needed.
"""
import numpy as np
from hypothesis import given, settings
from skimage.draw import polygon, polygon2mask

from algorithms.exact import polygons as oracle
from algorithms.polygons import SCANLINE
from test_polygons_cases import contour, kernel_pixels, star_shaped

SHAPE = (40, 40)  # rows, columns: every test polygon lies in [1, 30]^2


def snapped(points):
    """The polygon as RasterLab fills it: vertices on the 1/256 grid."""
    return [(oracle.snap(x) / 256, oracle.snap(y) / 256) for x, y in points]


def skimage_pixels(points) -> set[tuple[int, int]]:
    points = snapped(points)
    rows = np.array([y - 0.5 for _, y in points])
    columns = np.array([x - 0.5 for x, _ in points])
    rr, cc = polygon(rows, columns, SHAPE)
    return {(int(c), int(r)) for r, c in zip(rr, cc)}


def shifted(points, by=1):
    return [(x + by, y + by) for x, y in points]


def centres_on_outline(points):
    on, i0, j0 = oracle.outline_grid(oracle.snap_polygon([points]), (0, 0, SHAPE[1], SHAPE[0]))
    js, is_ = np.nonzero(on)
    return set(zip(is_.tolist(), js.tolist()))


def check(points, simple: bool):
    ours = set(kernel_pixels(SCANLINE, [points]))
    theirs = skimage_pixels(points)
    outline = centres_on_outline(points)
    assert (ours ^ theirs) <= outline
    if simple:
        assert outline <= theirs
        assert theirs - ours == outline - oracle.covered_pixels([points])


@settings(max_examples=120)
@given(contour(size=28))
def test_any_contour_agrees_off_the_outline(points):
    check(shifted(points), simple=False)


@settings(max_examples=120)
@given(star_shaped(size=28))
def test_simple_polygons_differ_only_on_the_outline_which_skimage_fills(points):
    check(shifted(points), simple=True)


def test_square_on_centres_is_one_row_and_column_larger_in_skimage():
    square = [(1.5, 1.5), (6.5, 1.5), (6.5, 6.5), (1.5, 6.5)]
    ours = set(kernel_pixels(SCANLINE, [square]))
    theirs = skimage_pixels(square)
    assert ours == {(i, j) for i in range(1, 6) for j in range(1, 6)}
    assert theirs == {(i, j) for i in range(1, 7) for j in range(1, 7)}


def test_polygon2mask_is_the_same_fill():
    points = [(2.2, 1.1), (14.7, 3.3), (12.1, 9.9), (8.5, 4.5), (3.3, 12.6)]
    mask = polygon2mask(SHAPE, np.array([(y - 0.5, x - 0.5) for x, y in snapped(points)]))
    rows, columns = np.nonzero(mask)
    assert {(int(c), int(r)) for r, c in zip(rows, columns)} == skimage_pixels(points)
    check(points, simple=True)
