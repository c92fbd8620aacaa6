"""The seed fill's kernel: its final raster at once, by a compiled span fill.

Every order of the seed fill (stack, queue, spans) fills the same pixels,
those joined to the seed through pixels of the seed's state, so the kernel
needs no order. It marks the outline's pixels that lie on the grid and
fills the seed's component with the scan-line seed fill, a run of a row at
a time; both loops are compiled where numba is installed (see ``compiled.py``). The seed is found
and checked as the generator does it, with the same messages.

The result is the grid's states, indexed [y, x]: 0 untouched, 1 boundary,
2 filled, as the generator's final raster shows them in the boundary colour
and the fill colour.
"""
from __future__ import annotations

import numpy as np

from algorithms.core.compiled import compiled
from algorithms.fill.seed import BOUNDARY, FILLED, FREE, circle_outline, circle_seed, inside_pixel, seed_pixel


class _Grid:
    """What the seed checks ask of a grid: its size and whether a pixel is on it."""

    def __init__(self, width: int, height: int):
        self.width, self.height = width, height

    def inside(self, x: int, y: int) -> bool:
        return 0 <= x < self.width and 0 <= y < self.height


def flood_fill_state(points, options, grid) -> np.ndarray:
    """The ``flood-fill`` generator's final raster as states (see the module)."""
    width, height = int(grid[0]), int(grid[1])
    four = options["outline"] == "4"
    cells = np.zeros((height, width), np.uint8)
    _draw_outline(cells, points, four)

    def free(x, y):
        return 0 <= x < width and 0 <= y < height and cells[y, x] == FREE

    def on_outline(x, y):
        return cells[y, x] == BOUNDARY

    seed = seed_pixel("flood-fill", options, lambda: inside_pixel(points, free, grid),
                      _Grid(width, height), on_outline)
    return _filled(cells, seed, options)


def circle_fill_state(points, options, grid) -> np.ndarray:
    """The ``flood-fill-circle`` generator's final raster as states."""
    (centre,) = points
    width, height = int(grid[0]), int(grid[1])
    ring = np.asarray(circle_outline(centre, options["radius"], options["outline"] == "4"),
                      np.int64).reshape(-1, 2)
    on = (ring[:, 0] >= 0) & (ring[:, 0] < width) & (ring[:, 1] >= 0) & (ring[:, 1] < height)
    cells = np.zeros((height, width), np.uint8)
    cells[ring[on, 1], ring[on, 0]] = BOUNDARY
    area = _Grid(width, height)

    def on_outline(x, y):
        return cells[y, x] == BOUNDARY

    if options["seed"] == "auto" and not (area.inside(*centre) and not on_outline(*centre)):
        return cells  # no free pixel inside: the generator draws the outline only
    seed = seed_pixel("flood-fill-circle", options,
                      lambda: circle_seed(centre, area, on_outline), area, on_outline)
    return _filled(cells, seed, options)


def _filled(cells, seed, options):
    x, y = int(seed[0]), int(seed[1])
    span_fill(cells, x, y, cells[y, x], FILLED, options["connectivity"] == "8")
    return cells


def _draw_outline(cells, contours, four: bool) -> None:
    """Mark the on-grid pixels of every closed contour's segments, as
    fill.outline_pixels gives them, as boundary (one compiled call)."""
    height, width = cells.shape
    params = [found for contour in contours for k, p in enumerate(contour)
              if (found := _segment_params(p, contour[(k + 1) % len(contour)], width, height))]
    if params:
        mark_segments(cells, np.array(params, np.int64), four)


def _segment_params(p, q, width: int, height: int):
    """(x, rest_x, dx, y, rest_y, dy, n, count) of segment P -> Q's pixels that
    can lie on the grid, for ``mark_segments``; None when none can.

    Pixel i of the segment is (x0 + floor((2 i dx + n) / 2n), likewise y),
    n the longer extent. The major coordinate moves by one per i, so only
    the i that put it on the grid are worked out (one more each side for
    the corners): i = lo + k, with the quotient of lo's part split off in
    Python integers, so that coordinates up to the inputs' bound never
    overflow int64.
    """
    (x0, y0), (x1, y1) = (int(p[0]), int(p[1])), (int(q[0]), int(q[1]))
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy), 1)  # a point: i = 0 only, at (x0, y0)
    steep = abs(dy) > abs(dx)
    start, step, extent = (y0, 1 if dy > 0 else -1, height) if steep else \
        (x0, 1 if dx > 0 else -1, width)
    # The major coordinate is start + step * i: on the grid for i in lo .. hi.
    ends = sorted(((0 - start) * step, (extent - 1 - start) * step))
    lo, hi = max(ends[0] - 1, 0), min(ends[1] + 1, max(abs(dx), abs(dy)))
    if lo > hi:
        return None
    whole_x, rest_x = divmod(2 * lo * dx + n, 2 * n)
    whole_y, rest_y = divmod(2 * lo * dy + n, 2 * n)
    return x0 + whole_x, rest_x, dx, y0 + whole_y, rest_y, dy, n, hi - lo + 1


@compiled
def mark_segments(cells, params, four):  # pragma: no cover - compiled
    """For each row (x0, rest_x, dx, y0, rest_y, dy, n, count) of ``params``,
    mark pixel k = 0 .. count - 1, (x0 + (rest_x + 2 k dx) // 2n, likewise
    y), and with ``four`` the corner (x_k, y_k-1) of each diagonal step, as
    boundary where it lies on the grid."""
    height, width = cells.shape
    for s in range(len(params)):
        x0, rest_x, dx, y0, rest_y, dy, n, count = params[s]
        px = py = 0
        for k in range(count):
            x = x0 + (rest_x + 2 * k * dx) // (2 * n)
            y = y0 + (rest_y + 2 * k * dy) // (2 * n)
            if 0 <= x < width and 0 <= y < height:
                cells[y, x] = BOUNDARY
            if four and k and x != px and y != py and 0 <= x < width and 0 <= py < height:
                cells[py, x] = BOUNDARY
            px, py = x, y


# A stack entry: row y, a stretch xl .. xr of that row's target pixels (as
# found when it was pushed), the run pl .. pr of the row it was found from
# (filled by then) and dy, the step from that row to this one.
Y, XL, XR, PL, PR, DY = range(6)


@compiled
def span_fill(cells, x, y, target, value, eight):  # pragma: no cover - compiled
    """Set the pixels joined to (x, y) through pixels equal to ``target``
    (4- or 8-connected) to ``value`` (which must differ from ``target``).

    The scan-line seed fill, with two savings of Heckbert's (Graphics Gems,
    1990): a pushed stretch remembers how far it was seen, so its pixels are
    not read again, and the row it was found from is read only beyond the
    run that found it (that run is filled). A stretch is wholly target or
    wholly filled: a fill takes a whole run of target pixels.
    """
    height, width = cells.shape
    stack = np.empty((1024, 6), np.int64)
    stack[0] = (y, x, x, 1, 0, 1)  # the seed: no run found it (pl > pr)
    size = 1
    while size:
        size -= 1
        y, xl, xr, pl, pr, dy = stack[size]
        row = cells[y]
        if row[xl] != target:
            continue
        left, right = xl, xr
        while left > 0 and row[left - 1] == target:
            left -= 1
        while right < width - 1 and row[right + 1] == target:
            right += 1
        row[left:right + 1] = value
        lo, hi = (max(left - 1, 0), min(right + 1, width - 1)) if eight else (left, right)
        for part in range(3):
            # The row ahead in full; the row behind left and right of pl .. pr.
            ny = y + dy if part == 0 else y - dy
            a, b = (lo, hi) if part == 0 else ((lo, min(hi, pl - 1)) if part == 1
                                               else (max(lo, pr + 1), hi))
            if ny < 0 or ny >= height or a > b:
                continue
            if len(stack) - size < (b - a) // 2 + 1:
                bigger = np.empty((2 * len(stack) + b - a, 6), np.int64)
                bigger[:size] = stack[:size]
                stack = bigger
            scan = cells[ny]
            k = a
            while k <= b:
                if scan[k] == target:
                    start = k
                    while k < b and scan[k + 1] == target:
                        k += 1
                    stack[size] = (ny, start, k, left, right, ny - y)
                    size += 1
                    k += 1  # past the run's end: scan[k] is not target, or k > b
                k += 1
    return cells
