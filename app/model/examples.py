"""Example inputs: what an algorithm shows before a person has drawn
anything, or when it refuses what was drawn."""
from __future__ import annotations

import math

from app.model.inputs import clamp, runnable_input

# A concave hexagon with a notch on its right (fractions of the grid): the
# example shape of polygon fills and flood fill.
_CONCAVE = ((0.12, 0.14), (0.86, 0.1), (0.6, 0.46), (0.88, 0.86), (0.42, 0.7), (0.14, 0.88))


def default_scene(spec, grid) -> tuple[list[tuple], tuple[int, ...], dict]:
    """A pleasant first scene for an algorithm: (points, breaks, options).

    Polygon and fill algorithms get a concave shape; one that only takes a
    convex polygon gets a convex one instead (tried, not looked up by name).
    """
    width, height = grid
    if spec.inputs.contours:
        points = [_grid_point(spec, fx * width, fy * height, grid) for fx, fy in _CONCAVE]
        try:
            spec.record(runnable_input(spec, points, ()), spec.resolve(), grid, step_cap=100_000)
        except Exception:  # noqa: BLE001 - any refusal: fall back to the convex shape
            points = default_points(spec, grid, vertices=6)
        return points, (), {}
    points = default_points(spec, grid)
    if spec.inputs.multiple and len(points) == 1:
        # Inputs of any number of points (a shape of 3k points, say): one
        # point may not be a shape; a triangle is (tried, not looked up).
        try:
            spec.record(runnable_input(spec, points, ()), spec.resolve(), grid, step_cap=100_000)
        except Exception:  # noqa: BLE001 - any refusal: a triangle instead
            points = default_points(spec, grid, vertices=3)
    return points, (), {}


def _grid_point(spec, x: float, y: float, grid):
    if spec.inputs.integer:
        return clamp((math.floor(x), math.floor(y)), *grid, True)
    return clamp((round(x * 4) / 4, round(y * 4) / 4), *grid, False)


def default_points(spec, grid, vertices: int | None = None) -> list[tuple]:
    """A pleasant first input for an algorithm on a grid: the centre for one
    point, a shallow segment for two, a slightly irregular polygon for more."""
    width, height = grid
    count = max(1, vertices or spec.inputs.count)
    integer = spec.inputs.integer
    if count == 1:
        raw = [(width / 2, height / 2)]
    elif count == 2:
        raw = [(width * 0.125, height * 0.21), (width * 0.875, height * 0.625)]
    else:
        raw = []
        for k in range(count):
            angle = math.radians(100 + 360 * k / count + (12 if k % 2 else 0))
            raw.append((width / 2 + 0.4 * width * math.cos(angle),
                        height / 2 + 0.4 * height * math.sin(angle)))
    if integer:
        return [clamp((math.floor(x), math.floor(y)), width, height, True) for x, y in raw]
    # Real inputs: quarter pixels, clear of the pixel centres.
    return [clamp((round(x * 4) / 4, round(y * 4) / 4), width, height, False) for x, y in raw]
