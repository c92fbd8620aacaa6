"""The public functions of the compiled kernels on fixed inputs, for comparing a
process without numba with one that has it (tests/algorithms/core/test_without_numba.py)."""
import numpy as np

from algorithms import triangles
from algorithms.antialias.wu_kernel import draw_wu_lines
from algorithms.core.registry import get
from algorithms.polygons import scanline_fill_many


def results() -> dict:
    """name -> the array each function returns."""
    rng = np.random.default_rng(28)
    grid = (96, 80)
    tris = rng.uniform(-10, 100, (60, 2))
    polygons = rng.uniform(0, 90, (25, 1, 2)) + rng.uniform(-12, 12, (25, 7, 2))
    starts, ends = rng.integers(-10, 100, (2, 40, 2))
    flood, circle = get("flood-fill"), get("flood-fill-circle")
    star = [(48, 2), (60, 60), (2, 30), (94, 30), (36, 60)]
    return {
        "fill_canvas": triangles.fill_canvas(tris, grid),
        "fill_canvas_uint8": triangles.fill_canvas(tris, grid, np.zeros((80, 96), np.uint8), 9,
                                                   rule="strict"),
        "scanline_fill_many": scanline_fill_many(polygons, grid, options={"fill_rule": "nonzero"}),
        "draw_wu_lines": draw_wu_lines(np.zeros((80, 96)), starts, ends, "gap"),
        "flood_fill": flood.kernel([star], flood.resolve({"connectivity": "8"}), grid),
        "flood_fill_circle": circle.kernel([(40, 35)], circle.resolve({"radius": 30}), grid),
    }
