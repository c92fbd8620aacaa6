"""What a run will cost, estimated from its inputs before it starts.

Plain functions of (spec, points, options, grid, step_cap), so the command
line, the window and export can all refuse a request that would not fit
before anything is allocated. The figures are upper estimates: measured
peaks of small runs of each family (tests/app/model/test_budget.py) stay
under them. Time is estimated only for the work a step cap cannot stop: the
work before a step (a tessellation's simplicity check, a band of an animation
frame's image, a row of a seed fill's search for its seed).
"""
from __future__ import annotations

import math

from algorithms.antialias.temporal import SAMPLES_PER_BAND
from algorithms.core.errors import InputError

DEFAULT_MEMORY_LIMIT = 2 * 1024 ** 3
# Work between two steps longer than this cannot be stopped by the cap or a
# cancel in reasonable time, so such a request is refused up front.
DEFAULT_TIME_LIMIT = 120.0

# Bytes per recorded step: the trace's columns and rich records, with the
# generator's own state per step (its stack or queue) on top.
STEP_BYTES = 256
# Bytes per grid pixel: masks and padded regions the runs keep.
PIXEL_BYTES = 8
# Bytes per entry of a seed fill's stack or queue (a Python tuple and its slot).
PENDING_BYTES = 100
# Bytes per input point, and per outline pixel or crossing kept as Python objects.
POINT_BYTES = 512
OBJECT_BYTES = 200
BASE_BYTES = 1 << 20

UNITS = {"": 1, "b": 1, "k": 1024, "kb": 1024, "m": 1024 ** 2, "mb": 1024 ** 2,
         "g": 1024 ** 3, "gb": 1024 ** 3}


class BudgetError(InputError):
    """A request would need more memory or time than the budget allows."""


def parse_size(text: str, what: str = "--memory-limit") -> int:
    """A size such as 2G, 512M, 300000000 (bytes); ASCII digits only."""
    value = str(text).strip().lower()
    digits = value.rstrip("bkmg")
    unit = value[len(digits):]
    if not digits or not digits.isascii() or not digits.isdigit() or unit not in UNITS:
        raise InputError(f"{what} must be a size such as 2G, 512M or a number of bytes, "
                         f"got {text!r}")
    size = int(digits) * UNITS[unit]
    if size < 1:
        raise InputError(f"{what} must be at least 1 byte, got {text!r}")
    return size


def _options(spec, options) -> dict:
    return {**{option.name: option.default for option in spec.options}, **(options or {})}


def _contours(spec, points) -> list:
    if spec.inputs.contours:
        return [list(contour) for contour in points]
    return [list(points)]


def _edges(spec, points):
    """Every closed-polygon edge of the points as (p, q)."""
    for contour in _contours(spec, points):
        for k, p in enumerate(contour):
            yield p, contour[(k + 1) % len(contour)]


def _box_pixels(points, grid) -> int:
    """Pixels of the grid the points' bounding box covers."""
    xs = [float(p[0]) for p in points] or [0.0]
    ys = [float(p[1]) for p in points] or [0.0]
    width = min(int(grid[0]), math.ceil(max(xs))) - max(0, math.floor(min(xs))) + 1
    height = min(int(grid[1]), math.ceil(max(ys))) - max(0, math.floor(min(ys))) + 1
    return max(0, width) * max(0, height)


def _outline_length(spec, points) -> int:
    """Pixels of the drawn outline, summed over edges."""
    return sum(max(abs(int(q[0]) - int(p[0])), abs(int(q[1]) - int(p[1]))) + 1
               for p, q in _edges(spec, points))


def step_bound(spec, points, options, grid, step_cap: int) -> int:
    """Steps the run records at most: the cap, or less where the grid bounds the run."""
    width, height = int(grid[0]), int(grid[1])
    options = _options(spec, options)
    if spec.name == "aa-temporal":
        bound = options["frames"] * (width * height + 1) + 2
    else:
        count = len(spec.inputs.flat(points))
        bound = 16 * width * height + 4 * count + 1024
    return min(int(step_cap), bound)


def estimate_memory(spec, points, options, grid, step_cap: int) -> int:
    """Bytes the run's recording needs at its peak (an upper estimate)."""
    width, height = int(grid[0]), int(grid[1])
    options = _options(spec, options)
    pixels = width * height
    count = len(spec.inputs.flat(points))
    steps = step_bound(spec, points, options, grid, step_cap)
    total = BASE_BYTES + STEP_BYTES * steps + PIXEL_BYTES * pixels + POINT_BYTES * count
    if spec.family == "fill":
        # each step pushes up to four neighbours
        total += PENDING_BYTES * 4 * min(pixels, steps)
    if spec.name == "aa-temporal":
        # this frame's hits and image, the last image, the mask and the
        # pixel list, and one band of samples (coordinates, owners, tests)
        band = min(SAMPLES_PER_BAND, pixels * options["n"] ** 2)
        total += 72 * pixels + 100 * band
    elif spec.name == "flood-fill":
        # drawn segments, and outline pixels off the grid (each one a step)
        total += OBJECT_BYTES * (count + min(_outline_length(spec, points), steps))
    elif spec.name == "flood-fill-circle":
        total += OBJECT_BYTES * 8 * (int(options.get("radius", 0)) + 1)
    return int(total)


def estimate_seconds(spec, points, options, grid, step_cap: int) -> float:
    """Seconds of work the step cap and a cancel cannot cut short (an upper estimate)."""
    width, height = int(grid[0]), int(grid[1])
    options = _options(spec, options)
    count = len(spec.inputs.flat(points))
    if spec.name == "polygon-tessellate":
        # the simplicity check tests every pair of edges (in numpy, one edge
        # against the rest at a time)
        return 5e-8 * count * count + 1e-4 * count
    if spec.name == "aa-temporal":
        instants = options["time_samples"] if options["mode"] == "motion-blur" else 1
        shapes = options["spokes"] if count == 1 else 1
        # the image is made in bands of rows between steps: one band's samples,
        # at every instant, against every shape
        row = width * options["n"] ** 2 * instants
        band = max(row, min(SAMPLES_PER_BAND, row * height))
        return 5e-8 * band * shapes
    if spec.name == "aa-supersample" and options.get("shape") == "polygon":
        # a sample is one binary search in its row's crossing table; the
        # longest work between two steps is making one table (numpy, every edge)
        return 3e-8 * count
    if spec.name == "polygon-scanline":
        return 1e-4 * count  # the edge table, in exact fractions
    if spec.name == "flood-fill":
        # the outline is drawn in the frames, so the cap stops it; before
        # the first frame the seed is looked for a row at a time (each row
        # tests every edge, and a cancel is heard between rows)
        return 1.5e-6 * count
    return 0.0


def check_budget(spec, points, options, grid, step_cap: int,
                 memory_limit: int = DEFAULT_MEMORY_LIMIT,
                 time_limit: float = DEFAULT_TIME_LIMIT) -> None:
    """Raise BudgetError (one line) when the run would not fit the budget."""
    memory = estimate_memory(spec, points, options, grid, step_cap)
    if memory > memory_limit:
        raise BudgetError(f"{spec.name} on a {grid[0]}x{grid[1]} grid would need about "
                          f"{size_text(memory)} of memory, over the limit of "
                          f"{size_text(memory_limit)}; "
                          "use a smaller grid, fewer points or samples, or a lower step cap")
    seconds = estimate_seconds(spec, points, options, grid, step_cap)
    if seconds > time_limit:
        raise BudgetError(f"{spec.name} would work about {_duration(seconds)} where the step "
                          f"cap and a cancel cannot cut it short (limit {_duration(time_limit)}); "
                          "use fewer points or samples, a smaller grid or a lower step cap")


def size_text(count: float) -> str:
    for unit, scale in (("GB", 1024 ** 3), ("MB", 1024 ** 2), ("KB", 1024)):
        if count >= scale:
            return f"{count / scale:.1f} {unit}"
    return f"{int(count)} bytes"


def _duration(seconds: float) -> str:
    if seconds >= 3600:
        return f"{seconds / 3600:.1f} h"
    if seconds >= 60:
        return f"{math.ceil(seconds / 60)} min"
    return f"{seconds:.0f} s"
