"""What a run will cost, estimated from its inputs before it starts.

Plain functions of (spec, points, options, grid, step_cap), so the command
line, the window and export can all refuse a request that would not fit
before anything is allocated. The figures are upper estimates: measured
peaks of small runs of each family (tests/app/model/test_budget.py) and of
fresh processes (benchmarks/bench_budget.py --peaks) stay under them. Memory
counts what the run keeps per step: the trace's columns, the scan line's
table snapshots (the ET and AET at every row: rows kept grow as edges x
steps), sample buffers. Time is the steps the run will record times a cost
per step of its family (or of the algorithm, where ``spec.step_seconds``
says it is well above), with the work a step cap cannot stop on top (a
tessellation's simplicity check, the images of an animation's frames, a
seed fill's search for its seed); the per-step costs come from
benchmarks/bench_budget.py --steps.
"""
from __future__ import annotations

import math
import os

import numpy as np

from algorithms.antialias.temporal import SAMPLES_PER_BAND
from algorithms.core.trace_store import BATCH, CACHED_BATCHES
from algorithms.core.errors import InputError
from algorithms.core.registry import parse_number

DEFAULT_MEMORY_LIMIT = 2 * 1024 ** 3
# A run estimated to take longer than this is refused on the command line
# (--time-limit); the window shows progress and Cancel instead.
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
# Bytes per row of a table snapshot: the records are kept pickled in batches
# (about 30 bytes a row measured on the scan line's ET and AET, with Fractions),
# and a batch being filled or read back (algorithms/core/trace_store.py: one
# pending, CACHED_BATCHES unpickled) holds its rows as Python tuples.
TABLE_ROW_BYTES = 48
TABLE_OBJECT_BYTES = 200
# Seconds per recorded step, per family: about the slower common members'
# figures on their examples at 1024 x 1024 (benchmarks/bench_budget.py --steps,
# setup included: lines 0.6-20 us, circles 2-13, polygons 12-25, triangles
# 3-22 with a few exact ones at 90-670, antialias 6-15, visibility 33-450);
# a seed fill of a whole 1024 x 1024 square: 1.3 us a step over 2.1M steps.
STEP_SECONDS = {"lines": 2e-5, "circles": 1.5e-5, "polygons": 2.5e-5, "fill": 5e-6,
                "triangles": 3e-5, "antialias": 3e-5, "visibility": 2e-4,
                "pipeline": 1.2e-4, "textures": 2e-4}
# Seconds per row of a table snapshot (made and pickled).
TABLE_ROW_SECONDS = 1e-6
# Seconds per sample test of an antialiasing run (one sample against one shape).
SAMPLE_SECONDS = 5e-8

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


def _temporal_frame_steps(options, points, pixels: int) -> int:
    """Steps of one animation frame at most: a pixel frame per pixel, and
    with motion blur one per instant and pixel the primitive reaches then
    (the square around it that any turn of it fits in), added to the
    accumulation buffer."""
    if options["mode"] != "motion-blur":
        return pixels
    if len(points) == 1:
        reach = 2 * options["radius"] + options["spoke_width"] + 2
    else:
        cx = sum(float(p[0]) for p in points) / max(1, len(points))
        cy = sum(float(p[1]) for p in points) / max(1, len(points))
        reach = 2 * max((math.hypot(float(p[0]) - cx, float(p[1]) - cy) for p in points),
                        default=0.0) + 2
    return pixels + options["time_samples"] * min(pixels, math.ceil(min(reach, pixels)) ** 2)


def step_bound(spec, points, options, grid, step_cap: int) -> int:
    """Steps the run records at most: the cap, or less where the grid bounds the run."""
    width, height = int(grid[0]), int(grid[1])
    options = _options(spec, options)
    if spec.name == "aa-temporal":
        per_frame = _temporal_frame_steps(options, spec.inputs.flat(points), width * height)
        bound = options["frames"] * (per_frame + 1) + 2
    elif spec.family == "lines":
        # a few steps per pixel of each segment, and one per pixel of the
        # box or grid an algorithm tests pixel by pixel
        bound = 8 * _outline_length(spec, points) + 1024 + _visited(spec, points, grid)
    elif spec.name == "flood-fill":
        # two steps a pixel of the grid (measured: 2.0 for a whole square),
        # and the outline drawn pixel by pixel
        bound = 3 * width * height + 2 * _outline_length(spec, points) + 1024
    elif spec.family == "polygons" and spec.name != "polygon-tessellate":
        # a few steps per scan line and a span per pair of edges
        bound = height * (8 + len(spec.inputs.flat(points))) + 1024
    elif spec.family in ("triangles", "visibility") and spec.inputs.multiple:
        # each triangle walks its own box, however many overlap: up to 4
        # steps a pixel of it (measured: scan conversion 2.2-3.9, the
        # others below 2)
        count = len(spec.inputs.flat(points))
        boxes = sum(_box_pixels(group, grid) for group in _groups(spec, points))
        bound = 4 * boxes + 4 * count + 1024
    else:
        count = len(spec.inputs.flat(points))
        bound = 16 * width * height + 4 * count + 1024
    return min(int(step_cap), bound)


def _visited(spec, points, grid) -> int:
    """Pixels an algorithm tests one by one beyond its path (``spec.visits``)."""
    if spec.visits == "grid":
        return int(grid[0]) * int(grid[1])
    if spec.visits == "box":
        return _box_pixels(list(spec.inputs.flat(points)), grid)
    return 0


def _groups(spec, points) -> list:
    """The points of each primitive of a scene of several (three per triangle)."""
    flat = list(spec.inputs.flat(points))
    size = max(1, spec.inputs.count or 1)
    return [flat[k:k + size] for k in range(0, len(flat), size)]


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
        # this frame's hits and image, the last image, the mask, the pixel
        # list, with motion blur the accumulation buffer and an instant's
        # hits, and one band of samples (coordinates, owners, tests)
        band = min(SAMPLES_PER_BAND, pixels * options["n"] ** 2)
        total += 88 * pixels + 100 * band
    elif spec.name == "flood-fill":
        # drawn segments, and outline pixels off the grid (each one a step)
        total += OBJECT_BYTES * (count + min(_outline_length(spec, points), steps))
    elif spec.name == "flood-fill-circle":
        total += OBJECT_BYTES * 8 * (int(options.get("radius", 0)) + 1)
    kept, live = table_rows(spec, points, options, steps)
    total += TABLE_ROW_BYTES * kept + TABLE_OBJECT_BYTES * live
    return int(total)


# The scan-line algorithms that show the ET at every row and the AET twice.
SCANLINE_TABLES = ("polygon-scanline", "polygon-scanline-xlow", "polygon-scanline-integer")


def _active(first, last, size: int):
    """Per row, the edges with first <= row < last (negative spans count none)."""
    keep = first < last
    starts = np.bincount(np.clip(first[keep], 0, size - 1), minlength=size)
    ends = np.bincount(np.clip(last[keep], 0, size - 1), minlength=size)
    return np.cumsum(starts) - np.cumsum(ends)


def table_rows(spec, points, options, steps: int) -> tuple[int, int]:
    """Rows of the table snapshots the first ``steps`` steps keep, and the
    most of them held as Python objects at once (upper estimates).

    Only the scan-line algorithms keep tables that grow with the input: the
    ET at every row (the edges not yet reached) and the AET twice. Rows are
    counted scan line by scan line from the edges' extents, up to the step
    where the cap stops the run; a scan line is taken to record the fewest
    steps it can (so that no fewer scan lines are counted than the run reaches)."""
    if spec.name not in SCANLINE_TABLES:
        return 0, 0
    ys = np.array([(p[1], q[1]) for p, q in _edges(spec, points)], dtype=float).reshape(-1, 2)
    ys = ys[np.ceil(ys.min(axis=1) - 0.5) < np.ceil(ys.max(axis=1) - 0.5)]  # edges met
    if not len(ys):
        return 0, 0
    first = np.floor(ys.min(axis=1)).astype(np.int64)
    last = np.ceil(ys.max(axis=1)).astype(np.int64) + 1
    low = int(first.min())
    size = int(last.max()) - low + 1
    active = _active(first - low, last - low, size)
    # the fewest steps a scan line takes: the loop, ET, leave, AET, next row,
    # AET, and under even-odd a span per pair of the edges it surely meets
    met = _active(np.ceil(ys.min(axis=1) - 0.5).astype(np.int64) - low + 1,
                  np.ceil(ys.max(axis=1) - 0.5).astype(np.int64) - low, size)
    spans = met // 2 if _options(spec, options)["fill_rule"] == "evenodd" else 0
    reached = int(np.searchsorted(np.cumsum(6 + spans), steps)) + 1
    row_rows = (len(ys) - np.cumsum(np.bincount(first - low, minlength=size))) + 2 * active
    kept = len(ys) + int(row_rows[:reached].sum())
    # a batch of records as objects: BATCH records, of which one in six an ET
    batch = int(row_rows[:reached].max()) * (BATCH // 6)
    return kept, min(kept, (1 + CACHED_BATCHES) * batch)


def estimate_seconds(spec, points, options, grid, step_cap: int) -> float:
    """Seconds the run takes (an upper estimate): its steps at its family's
    cost per step, the table rows it snapshots, and the work no step
    measures (an edge table, a simplicity check, the images of an
    animation's frames, a seed fill's search for its seed)."""
    steps = step_bound(spec, points, options, grid, step_cap)
    seconds = (spec.step_seconds or STEP_SECONDS.get(spec.family, 2e-4)) * steps
    seconds += TABLE_ROW_SECONDS * table_rows(spec, points, options, steps)[0]
    return seconds + _unstepped_seconds(spec, points, options, grid, steps)


def _unstepped_seconds(spec, points, options, grid, steps: int) -> float:
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
        # each frame reached: every pixel's samples, at every instant, against every shape
        frames = min(options["frames"],
                     steps // (_temporal_frame_steps(options, spec.inputs.flat(points),
                                                     width * height) + 1) + 1)
        return SAMPLE_SECONDS * frames * width * height * options["n"] ** 2 * instants * shapes
    if spec.name == "aa-supersample":
        # n x n samples per pixel reached, each against the shape's edges
        # (one binary search in a crossing table for a polygon)
        edges = max(1, math.ceil(math.log2(count + 1))) if options.get("shape") == "polygon" \
            else max(1, count)
        return SAMPLE_SECONDS * steps * options["n"] ** 2 * edges + 3e-8 * count * height
    if spec.name == "polygon-tessellate-any":
        # every pixel of the box is tested in exact fractions by the
        # trapezoids' triangles (measured 25-40 us a pixel of the box)
        return 8e-5 * _box_pixels([p for c in _contours(spec, points) for p in c], grid)
    if spec.name in SCANLINE_TABLES:
        return 1e-4 * count  # the edge table, in exact fractions
    if spec.name == "flood-fill":
        # the seed is looked for a row at a time (each row tests every edge)
        return 1.5e-6 * count * height
    return 0.0


def check_budget(spec, points, options, grid, step_cap: int,
                 memory_limit: int = DEFAULT_MEMORY_LIMIT,
                 time_limit: float = DEFAULT_TIME_LIMIT) -> None:
    """Raise BudgetError (one line) when the run would not fit the budget
    (``time_limit`` math.inf: no limit on time, as in the window)."""
    memory = estimate_memory(spec, points, options, grid, step_cap)
    if memory > memory_limit:
        raise BudgetError(f"{spec.name} on a {grid[0]}x{grid[1]} grid would need about "
                          f"{size_text(memory)} of memory, over the limit of "
                          f"{size_text(memory_limit)}; "
                          "use a smaller grid, fewer points or samples, or a lower step cap")
    seconds = estimate_seconds(spec, points, options, grid, step_cap)
    if seconds > time_limit:
        raise BudgetError(f"{spec.name} on a {grid[0]}x{grid[1]} grid would take about "
                          f"{_duration(seconds)}, over the time limit of {_duration(time_limit)}; "
                          "raise --time-limit (seconds), or use a smaller grid, fewer points "
                          "or samples, or a lower step cap")


# Room the address-space backstop leaves above the process's size when it is
# set and the run's budget: Qt for PDF pages (about 110 MB of address space),
# the threads' stacks and malloc arenas (64 MB each), a video encoder's pipes.
ADDRESS_MARGIN = 1024 ** 3


def limit_address_space(memory_limit: int, rlimits=None) -> int | None:
    """Set this process's soft address-space limit (RLIMIT_AS) to its present
    size plus ``memory_limit`` plus ADDRESS_MARGIN: a run whose estimate was
    wrong then meets MemoryError, which the command line turns into one
    line, instead of the system's out-of-memory killer. Returns the limit,
    or None where it cannot be set: no ``resource`` module (Windows), no
    /proc/self/statm to read the size from (macOS, which refuses RLIMIT_AS
    too), or a hard limit below it already."""
    if rlimits is None:
        try:
            import resource as rlimits
        except ImportError:
            return None
    try:
        with open("/proc/self/statm", encoding="ascii") as statm:
            size = int(statm.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
        limit = size + memory_limit + ADDRESS_MARGIN
        hard = rlimits.getrlimit(rlimits.RLIMIT_AS)[1]
        if hard != rlimits.RLIM_INFINITY and hard < limit:
            return None
        rlimits.setrlimit(rlimits.RLIMIT_AS, (limit, hard))
    except (OSError, ValueError, AttributeError):
        return None
    return limit


def parse_seconds(text: str) -> float:
    """--time-limit: seconds, more than 0."""
    seconds = parse_number(str(text), "--time-limit")
    if not seconds > 0:
        raise InputError(f"--time-limit must be a number of seconds above 0, got {text!r}")
    return float(seconds)


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
