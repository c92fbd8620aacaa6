"""A run made without the window: the grid fitted to the points, the run
recorded within its budget, and its result as plain data.

``rasterlab run`` prints ``run_result`` as JSON and the Python API
(app/api.py) returns the same values as Python lists and dicts, so the two
cannot drift apart. Nothing here imports Qt.
"""
from __future__ import annotations

import math
from pathlib import Path

from algorithms.core.monitor import RecordMonitor
from algorithms.core.raster import MAX_GRID
from algorithms.core.registry import InputError

from app.model import budget
from app.model.fragments import fragment_objects, fragment_table

DEFAULT_GRID = (32, 24)


def check_grid(width: int, height: int) -> tuple[int, int]:
    """A grid size within 1x1 .. MAX_GRID x MAX_GRID, or InputError."""
    if not (1 <= width <= MAX_GRID and 1 <= height <= MAX_GRID):
        raise InputError(f"grid {width}x{height} is outside 1x1 .. {MAX_GRID}x{MAX_GRID}")
    return width, height


def fit_grid(points, grid: tuple[int, int] | None, integer: bool = True) -> tuple[int, int]:
    """The given grid, or the smallest default-or-larger grid holding the points.

    Integer points name pixels, so they lie in 0..W-1; real points are
    positions, which may lie anywhere in [0, W] x [0, H].
    """
    def extent(v):
        return math.floor(v) + 1 if integer else math.ceil(v)

    if grid is not None:
        width, height = check_grid(*grid)
    else:
        width = max([DEFAULT_GRID[0]] + [extent(x) for x, _ in points])
        height = max([DEFAULT_GRID[1]] + [extent(y) for _, y in points])
        if width > MAX_GRID or height > MAX_GRID:
            raise InputError(f"the points need a grid larger than {MAX_GRID}x{MAX_GRID}")
    for x, y in points:
        inside_x = 0 <= x < width if integer else 0 <= x <= width
        inside_y = 0 <= y < height if integer else 0 <= y <= height
        if not (inside_x and inside_y):
            raise InputError(f"point ({_plain(x)}, {_plain(y)}) lies outside the "
                             f"{width}x{height} grid")
    return width, height


def _plain(value: float):
    return int(value) if float(value).is_integer() else value


def record(spec, points, options: dict, grid: tuple[int, int], step_cap: int,
           memory_limit: int = budget.DEFAULT_MEMORY_LIMIT,
           time_limit: float = budget.DEFAULT_TIME_LIMIT, progress=None):
    """The run's trace; a run over the memory or time budget is refused
    (BudgetError, an InputError) before it starts. ``progress`` (if given)
    is called with the steps recorded so far, every RecordMonitor chunk."""
    budget.check_budget(spec, points, options, grid, step_cap, memory_limit=memory_limit,
                        time_limit=time_limit)
    monitor = None if progress is None else RecordMonitor(progress)
    return spec.record(points, options, grid=grid, step_cap=step_cap, monitor=monitor)



def save_new(scene, path, replace: bool, hint: str) -> None:
    """Save ``scene`` to ``path`` atomically; an existing file is refused
    (InputError ending with ``hint``) unless ``replace``: a scene may hold a
    title, notes and bookmarks written by hand."""
    from app.model import scene as scenes
    path = Path(path)
    if not replace and (path.exists() or path.is_symlink()):
        raise InputError(f"{path}: the file exists; {hint}")
    try:
        scenes.save(scene, path)
    except scenes.SceneError as error:
        raise InputError(str(error)) from None


# ------------------------------------------------------------------ results
def run_result(spec, trace, options) -> dict:
    """The JSON object of `run --json`; its per-pixel lists are Rows, which
    the command line prints in parts and the API turns into lists."""
    result = {
        "algorithm": spec.name,
        "grid": [trace.width, trace.height],
        "pixels": Rows(trace.written_pixels(), lambda part: part.tolist()),
        "steps": len(trace),
        "final": jsonable(trace.final_variables()),
        "options": jsonable(spec.resolve(options)),
    }
    values = trace.pixel_values()
    if values is not None:
        name = trace.start.pixel_value
        result["values"] = Rows(values, lambda part: _pixel_values(name, part))
    if spec.fragments:
        layout, table = fragment_table(trace, spec.fragments)
        result["fragments"] = Rows(table, lambda part: fragment_objects(layout, part))
    if trace.truncated:
        result["truncated"] = True
        result["message"] = trace.message
    return result


class Rows:
    """A per-pixel array that is printed a part at a time: as one list of
    Python objects, a full grid's pixels took gigabytes beside the trace,
    which the step cap bounds."""

    PART = 1 << 16

    def __init__(self, array, convert):
        self.array, self.convert = array, convert

    def tolist(self) -> list:
        return self.convert(self.array)

    def parts(self):
        for start in range(0, len(self.array), self.PART):
            yield self.convert(self.array[start:start + self.PART])


def _pixel_values(name: str, values) -> list:
    # A pixel written without a value (NaN) or with a value that is not a
    # colour gets null: strict JSON has no NaN, and "#-00001" is no colour.
    if name == "rgb":
        return [f"#{int(v):06x}" if 0 <= v <= 0xFFFFFF else None for v in values]
    return [jsonable(float(v)) for v in values]


def jsonable(value):
    """The value as strict JSON takes it: lists for tuples and arrays, plain
    numbers for numpy scalars, null for NaN and infinities, at any depth."""
    if isinstance(value, dict):
        return {str(key): jsonable(item) for key, item in value.items()}
    if isinstance(value, (tuple, list)):
        return [jsonable(item) for item in value]
    if hasattr(value, "tolist"):  # numpy scalars and arrays
        return jsonable(value.tolist())
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    return str(value)
