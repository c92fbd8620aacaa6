"""`run --json`'s "fragments": per written pixel, the attributes the algorithm computed there."""
from __future__ import annotations

import math

import numpy as np

# Columns whose values are whole numbers, and the packed colour.
WHOLE = ("level", "fetches")
COLOURS = ("rgb", "src", "dst")


def fragment_columns(trace, pairs) -> np.ndarray:
    """(n, k) array: for each written pixel (emission order) the k columns named by
    ``pairs`` ((key, column) each); NaN where a pixel has no value."""
    steps = trace.written().steps
    names = set(trace.value_names)
    columns = [trace.series(column)[steps] if column in names else np.full(len(steps), np.nan)
               for _, column in pairs]
    return np.stack(columns, axis=1) if columns else np.zeros((len(steps), 0))


def fragment_objects(pairs, rows: np.ndarray) -> list[dict]:
    """JSON objects of fragment_columns' rows: null for NaN, #rrggbb for a colour."""
    return [{key: _value(column, float(value)) for (key, column), value in zip(pairs, row)}
            for row in rows]


def _value(column: str, value: float):
    if not math.isfinite(value):
        return None
    if column in COLOURS:
        return f"#{int(value):06x}" if 0 <= value <= 0xFFFFFF else None
    if column in WHOLE:
        return int(value)
    return value
