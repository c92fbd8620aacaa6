"""The seed fill's kernel: the generator's final raster, and independent oracles
(the outline's pixels in exact integers, the region by skimage's flood and a BFS)."""
from collections import deque

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from skimage.segmentation import flood

from algorithms.core.registry import InputError, get
from tests.support import record

BOUNDARY, FILL = 0xC0392B, 0x2E86DE
FOUR = ((1, 0), (-1, 0), (0, 1), (0, -1))
EIGHT = FOUR + ((1, 1), (-1, 1), (-1, -1), (1, -1))


def kernel(name, points, grid, **options):
    spec = get(name)
    return spec.kernel(points, spec.resolve(options), grid)


def generator_states(name, points, grid, **options):
    """The generator's final raster as states: 1 boundary colour, 2 fill colour."""
    trace = record(name, points, {"order": "span", **options}, grid)
    assert not trace.truncated
    raster = trace.raster_at(len(trace) - 1)
    written = raster.counts > 0
    states = np.zeros((grid[1], grid[0]), np.uint8)
    states[written & (raster.colors == BOUNDARY)] = 1
    states[written & (raster.colors == FILL)] = 2
    return states


def assert_kernel_is_generator(name, points, grid, **options):
    fast = kernel(name, points, grid, **options)
    assert fast.shape == (grid[1], grid[0]) and fast.dtype == np.uint8
    assert np.array_equal(fast, generator_states(name, points, grid, **options))
    return fast


def segment_on_grid(p, q, grid, four):
    """The segment's pixels on the grid, by its rule in Python integers:
    pixel i is (x0 + floor((2 i dx + n) / 2n), likewise y), n the longer extent,
    and with ``four`` the corner (x_i+1, y_i) of each diagonal step."""
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))

    def at(i):
        if n == 0:
            return x0, y0
        return x0 + (2 * i * dx + n) // (2 * n), y0 + (2 * i * dy + n) // (2 * n)
    # The major coordinate moves by one per i: the i that can reach the grid.
    start, step, size = (y0, dy, grid[1]) if abs(dy) > abs(dx) else (x0, dx, grid[0])
    sign = 1 if step >= 0 else -1
    found = set()
    for c in range(-1, size + 1):
        i = (c - start) * sign
        if 0 <= i <= n:
            found.add(at(i))
            if four and i < n:
                a, b = at(i), at(i + 1)
                if a[0] != b[0] and a[1] != b[1]:
                    found.add((b[0], a[1]))
    return {(x, y) for x, y in found if 0 <= x < grid[0] and 0 <= y < grid[1]}


def outline_states(contours, grid, four):
    states = np.zeros((grid[1], grid[0]), np.uint8)
    for contour in contours:
        for k, p in enumerate(contour):
            for x, y in segment_on_grid(p, contour[(k + 1) % len(contour)], grid, four):
                states[y, x] = 1
    return states


def bfs(states, seed, connectivity):
    height, width = states.shape
    target = states[seed[1], seed[0]]
    seen, todo = {seed}, deque([seed])
    while todo:
        x, y = todo.popleft()
        for dx, dy in (FOUR if connectivity == "4" else EIGHT):
            q = (x + dx, y + dy)
            if 0 <= q[0] < width and 0 <= q[1] < height and q not in seen \
                    and states[q[1], q[0]] == target:
                seen.add(q)
                todo.append(q)
    return seen


def check_oracles(fast, contours, grid, seed, connectivity="4", outline="8"):
    states = outline_states(contours, grid, outline == "4")
    region = flood(states, (seed[1], seed[0]), connectivity=1 if connectivity == "4" else 2)
    want = states.copy()
    want[region] = 2
    assert np.array_equal(fast, want)
    assert set(zip(*np.nonzero(fast == 2)[::-1])) == bfs(states, seed, connectivity)


# ------------------------------------------------------------- hard cases
ROOM = [(0, 0), (20, 0), (20, 10), (0, 10)]
WALLS = [[(10, 0), (10, 4), (10, 4)], [(11, 5), (11, 10), (11, 10)]]  # one diagonal gap
TRIANGLE = [[(2, 2), (12, 2), (2, 12)]]
CASES = [
    ("a box", [[(2, 2), (20, 2), (20, 15), (2, 15)]], (24, 20), {}),
    ("a hole", [[(1, 1), (22, 1), (22, 18), (1, 18)], [(8, 6), (14, 6), (14, 12), (8, 12)]],
     (24, 20), {"seed": (10, 8)}),
    ("seed on the grid's corner", [[(5, 5), (15, 5), (15, 15)]], (20, 18), {"seed": (0, 0)}),
    ("seed on the grid's right edge", [[(5, 5), (15, 5), (15, 15)]], (20, 18), {"seed": (19, 9)}),
    ("outline off the grid on three sides", [[(-5, -3), (30, 4), (8, 40)]], (16, 12), {}),
    ("diagonal gap, 4", [ROOM] + WALLS, (21, 11), {"seed": (3, 3)}),
    ("diagonal gap, 8", [ROOM] + WALLS, (21, 11), {"seed": (3, 3), "connectivity": "8"}),
    ("8 leaks out of a triangle", TRIANGLE, (24, 20), {"seed": (4, 4), "connectivity": "8"}),
    ("outline=4 holds 8", TRIANGLE, (24, 20), {"seed": (4, 4), "connectivity": "8",
                                               "outline": "4"}),
    ("region mode inside", TRIANGLE, (24, 20), {"seed": (4, 4), "mode": "region"}),
    ("region mode on the outline", TRIANGLE, (24, 20), {"seed": (2, 2), "mode": "region"}),
    ("region mode on the outline, 8", TRIANGLE, (24, 20), {"seed": (7, 7), "mode": "region",
                                                           "connectivity": "8"}),
    ("region mode outside", TRIANGLE, (24, 20), {"seed": (20, 1), "mode": "region"}),
]


@pytest.mark.parametrize("label, contours, grid, options", CASES, ids=[c[0] for c in CASES])
def test_hard_cases(label, contours, grid, options):
    fast = assert_kernel_is_generator("flood-fill", contours, grid, **options)
    seed = get("flood-fill").resolve(options)["seed"]
    seed = tuple(record("flood-fill", contours, options, grid).start.constants["seed"]) \
        if seed == "auto" else seed
    check_oracles(fast, contours, grid, seed, options.get("connectivity", "4"),
                  options.get("outline", "8"))


def test_the_diagonal_gap_joins_the_rooms_only_with_eight_neighbours():
    four = kernel("flood-fill", [ROOM] + WALLS, (21, 11), seed=(3, 3))
    eight = kernel("flood-fill", [ROOM] + WALLS, (21, 11), seed=(3, 3), connectivity="8")
    assert four[4, 11] == 0 and eight[4, 11] == 2  # (11, 4): across the gap
    assert (eight == 2).sum() - (four == 2).sum() == 9 * 4 + 8 * 5


def test_huge_coordinates_keep_exact_pixels():
    # Products of these coordinates overflow int64: the grid's part is exact.
    contours = [[(-(1 << 30), 3), ((1 << 30) - 7, 9), (5, 1 << 30)]]
    fast = kernel("flood-fill", contours, (40, 30), seed=(20, 20))
    check_oracles(fast, contours, (40, 30), (20, 20))
    # Only the first edge crosses the grid, at row 3 + round(6 * 2^30 / (2^31 - 7)) = 6 for x = 0.
    assert fast[6, 0] == 1 and fast[20, 20] == 2 and fast[0, 0] == 0


def test_bad_seeds_are_input_errors_as_in_the_generator():
    with pytest.raises(InputError, match="boundary"):
        kernel("flood-fill", TRIANGLE, (24, 20), seed=(2, 2))
    with pytest.raises(InputError, match="outside the 24x20 grid"):
        kernel("flood-fill", TRIANGLE, (24, 20), seed=(30, 2))
    with pytest.raises(InputError, match="no free pixel"):
        kernel("flood-fill", [[(0, 0), (1, 0), (0, 1)]], (24, 20))


@pytest.mark.parametrize("options", [{}, {"connectivity": "8"}, {"outline": "4"},
                                     {"seed": (5, 5), "mode": "region"},
                                     {"seed": (9, 6), "mode": "region", "connectivity": "8"},
                                     {"seed": (1, 1)}, {"radius": 0}, {"radius": 0, "seed": (2, 2)}])
def test_circle_fill(options):
    centre = ((9, 6),)
    options = {"radius": 5, **options}
    assert_kernel_is_generator("flood-fill-circle", centre, (16, 12), **options)


# ------------------------------------------------------------ random scenes
@st.composite
def scenes(draw):
    contours = draw(st.lists(st.lists(st.tuples(st.integers(-4, 23), st.integers(-4, 19)),
                                      min_size=3, max_size=6), min_size=1, max_size=2))
    seed = draw(st.tuples(st.integers(0, 19), st.integers(0, 15)))
    options = draw(st.fixed_dictionaries({"connectivity": st.sampled_from(["4", "8"]),
                                          "outline": st.sampled_from(["4", "8"]),
                                          "mode": st.sampled_from(["boundary", "region"])}))
    return contours, seed, options


@settings(max_examples=120)
@given(scenes())
def test_random_scenes(scene):
    contours, seed, options = scene
    grid = (20, 16)
    states = outline_states(contours, grid, options["outline"] == "4")
    if options["mode"] == "boundary" and states[seed[1], seed[0]] == 1:
        with pytest.raises(InputError, match="boundary"):
            kernel("flood-fill", contours, grid, seed=seed, **options)
        return
    fast = assert_kernel_is_generator("flood-fill", contours, grid, seed=seed, **options)
    check_oracles(fast, contours, grid, seed, options["connectivity"], options["outline"])


def test_a_1024_square_fills():
    box = [[(0, 0), (1025, 0), (1025, 1025), (0, 1025)]]
    fast = kernel("flood-fill", box, (1026, 1026), seed=(600, 3), connectivity="8")
    assert (fast == 2).sum() == 1024 * 1024 and (fast == 1).sum() == 4 * 1025
