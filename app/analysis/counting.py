"""The measurements' rows, their operation counts and timings, and the Pareto front.

How the counts are made is told in ``app/analysis/measure.py``.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable, Iterable

import numpy as np

from algorithms.core.steps import OP_NAMES, PER_PIXEL, PER_ROW, Note, Table, Vars

ARITHMETIC = ("int_add", "float_add", "mul", "div", "sqrt", "round", "compare")
COLUMNS = ("family", "experiment", "algorithm", "variant", "parameter", "parameter_value",
           "metric", "value", "unit")
SEED = 20240607


# ============================================================== rows
@dataclass
class Rows:
    """The measurements of a report, one dict per value (see COLUMNS)."""

    rows: list = field(default_factory=list)

    def add(self, family, experiment, algorithm, variant, parameter, parameter_value,
            metric, value, unit=""):
        value = float(value)
        if not math.isfinite(value):
            raise ValueError(f"{family}/{experiment}/{variant}/{metric}: {value} is not finite")
        self.rows.append({"family": family, "experiment": experiment, "algorithm": algorithm,
                          "variant": variant, "parameter": parameter,
                          "parameter_value": parameter_value, "metric": metric,
                          "value": value, "unit": unit})

    def select(self, **where) -> list[dict]:
        return [row for row in self.rows if all(row[k] == v for k, v in where.items())]

    def value(self, **where) -> float:
        found = self.select(**where)
        if len(found) != 1:
            raise KeyError(f"{len(found)} rows match {where}")
        return found[0]["value"]


# =================================================== operation counts
def op_counts(trace) -> dict[str, int]:
    """Operations the run performed, by name (OP_NAMES), from its code lines."""
    code = trace.code
    executions = np.bincount(trace.line, minlength=len(code)).astype(np.int64)
    notes = trace.steps_of(Note)
    if len(notes):
        executions -= np.bincount(trace.line[notes], minlength=len(code))
    counts = dict.fromkeys(OP_NAMES, 0)
    for k, line in enumerate(code):
        for name, count in line.ops.items():
            counts[name] += count * int(executions[k])
        for quantity, ops in line.per.items():
            amount = _quantity(trace, k, quantity, int(executions[k]))
            for name, count in ops.items():
                counts[name] += count * amount
    return counts


def _quantity(trace, line: int, quantity: str, executions: int) -> int:
    """How much of ``quantity`` the frames on ``line`` carry, summed."""
    if quantity == PER_PIXEL:
        spans = trace.spans()
        lengths = np.maximum(spans["x_end"] - spans["x_start"], 0)
        return int(lengths[spans["line"] == line].sum())
    if quantity == PER_ROW:
        return sum(len(table.rows) for _, table in trace.records_of(Table) if table.line == line)
    if quantity in trace.value_names:
        values = trace.series(quantity)[trace.line == line]
        return int(np.nansum(values))
    constants = trace.start.constants
    if quantity in constants:
        return int(constants[quantity]) * executions
    carried = [record.values[quantity] for _, record in trace.records_of(Vars)
               if record.line == line and quantity in record.values]
    if carried:  # a quantity the run keeps as a Vars update on this line
        return int(sum(carried))
    raise KeyError(f"code line {line} scales by {quantity!r}, which the run does not name")


def total_ops(counts: dict) -> int:
    return sum(counts[name] for name in ARITHMETIC)


def written_count(trace) -> int:
    """Pixels the run wrote (duplicates included, spans counted pixel by pixel)."""
    return int(len(trace.written_pixels()))


def add_costs(rows, family, experiment, name, variant, parameter, value, counts, written,
              seconds=None, per="px") -> None:
    """The cost rows of one run: ops per pixel (or per ``per``), each op, the time."""
    written = max(written, 1)
    add = lambda metric, v, unit="": rows.add(family, experiment, name, variant,  # noqa: E731
                                               parameter, value, metric, v, unit)
    add("ops", total_ops(counts) / written, f"per {per}")
    for op in OP_NAMES:
        add(f"ops {op}", counts[op] / written, f"per {per}")
    if seconds is not None:
        add("generator time", 1e6 * seconds / written, f"us/{per}")


def pixel_keys(pixels: np.ndarray) -> np.ndarray:
    """One int64 per pixel, for set operations on pixel lists."""
    pixels = np.asarray(pixels, np.int64).reshape(-1, 2)
    return ((pixels[:, 0] + (1 << 30)) << 32) | (pixels[:, 1] + (1 << 30))


# ============================================================= timing
def median_seconds(call: Callable[[], object], repeats: int = 5, least: float = 0.002,
                   once: float | None = None) -> float:
    """Median time of one call, over ``repeats`` samples.

    A sample repeats the call until it has run ``least`` seconds (for
    calls far shorter than the clock's resolution) and divides. ``once``
    is the time of a call already made (the run whose counts were taken,
    say), which then stands for the warm-up call that sizes the samples.
    The measures time one call over all the inputs of a sweep (a pass
    over its segments or shapes) rather than each input alone, so that
    short inputs do not each pay ``least`` seconds per sample.
    """
    if once is None:
        start = time.perf_counter()
        call()
        once = time.perf_counter() - start
    inner = max(1, min(1000, int(least / max(once, 1e-9))))
    samples = []
    for _ in range(max(1, repeats)):
        start = time.perf_counter()
        for _ in range(inner):
            call()
        samples.append((time.perf_counter() - start) / inner)
    return float(np.median(samples))


def timed(call: Callable[[], object]) -> tuple[object, float]:
    """What ``call()`` returns, and the seconds it took."""
    start = time.perf_counter()
    result = call()
    return result, time.perf_counter() - start


def pareto_front(points: Iterable[tuple[float, float, object]]) -> list:
    """The (cost, error, label) points no other point beats on both cost and error."""
    ordered = sorted(points, key=lambda p: (p[0], p[1]))
    front, best = [], math.inf
    for point in ordered:
        if point[1] < best:
            front.append(point)
            best = point[1]
    return front
