"""`run --json`'s "fragments": per written pixel, the attributes the algorithm computed there.

A spec names its fragment keys as (key, column) pairs. A column is one of the
trace's per-step values, or a derived column starting with "@", put together
from values the run recorded (never recomputed another way):

- "@triangle": the number of the triangle being drawn (its last Vars).
- "@weights": the barycentric weights of the triangle's vertices in input
  order, from the run's alpha, beta, gamma where it recorded them, otherwise
  e_k / 2A (the edge values at the pixel over the triangle's doubled area).
- "@weights_p": the perspective-correct weights alpha_p, beta_p, gamma_p.

Columns a run did not record (an attribute option not given) are left out.
"""
from __future__ import annotations

import numpy as np

from algorithms.steps import Vars

# Columns whose values are whole numbers, and the packed colour.
WHOLE = ("level", "fetches", "@triangle")
COLOURS = ("rgb", "src", "dst")
WEIGHTS = {"@weights": ("alpha", "beta", "gamma"), "@weights_p": ("alpha_p", "beta_p", "gamma_p")}
# The Vars text of a triangle whose P1 and P2 the run swapped (see triangles/run.py).
SWAPPED = "clockwise: P1, P2 swapped"


def fragment_table(trace, pairs) -> tuple[list[tuple[str, str, int]], np.ndarray]:
    """(layout, table): layout lists (key, column, width) of the keys this run has;
    table holds, per written pixel in emission order, those columns side by side."""
    steps = trace.written().steps
    names = set(trace.value_names)
    layout, blocks = [], []
    for key, column in pairs:
        block = _column(trace, column, steps, names)
        if block is not None:
            block = block.reshape(len(steps), -1)
            layout.append((key, column, block.shape[1]))
            blocks.append(block.astype(np.float64))
    table = np.concatenate(blocks, axis=1) if blocks else np.zeros((len(steps), 0))
    return layout, table


def fragment_objects(layout, rows: np.ndarray) -> list[dict]:
    """JSON objects of fragment_table's rows: null for NaN, #rrggbb for a colour,
    a list for a column several wide. Built a column at a time (fast on big runs)."""
    keys, columns, start = [], [], 0
    for key, column, width in layout:
        parts = [_values(column, rows[:, start + k]) for k in range(width)]
        columns.append(parts[0] if width == 1 else [list(v) for v in zip(*parts)])
        keys.append(key)
        start += width
    return [dict(zip(keys, values)) for values in zip(*columns)]


def _column(trace, column, steps, names):
    if column == "@triangle":
        return _vars_at(trace, "triangle", steps)
    if column in WEIGHTS:
        return _weights(trace, column, steps, names)
    return trace.series(column)[steps] if column in names else None


def _weights(trace, column, steps, names):
    own = WEIGHTS[column]
    if all(name in names for name in own):
        weights = np.stack([trace.series(name)[steps] for name in own], axis=1)
    elif column == "@weights" and {"e0", "e1", "e2"} <= names:
        area2 = _vars_at(trace, "2A", steps)
        edges = np.stack([trace.series(f"e{k}")[steps] for k in range(3)], axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            weights = edges / area2[:, None]
    else:
        return None
    # Weights follow the run's vertex order; a swapped triangle's P1 and P2 are
    # the input's P2 and P1, so swap those weights back.
    winding = _vars_at(trace, "winding", steps, dtype=object)
    swapped = winding == SWAPPED
    weights[swapped] = weights[swapped][:, [0, 2, 1]]
    return weights


def _vars_at(trace, name, steps, dtype=np.float64):
    """The value of the Vars ``name`` in effect at each of ``steps`` (NaN before any)."""
    found = [(i, record.values[name]) for i, record in trace.records_of(Vars)
             if name in record.values]
    if not found:
        return np.full(len(steps), np.nan if dtype is np.float64 else None, dtype=dtype)
    at = np.array([i for i, _ in found], dtype=np.int64)
    values = np.array([np.nan if dtype is np.float64 else None] + [v for _, v in found],
                      dtype=dtype)
    return values[np.searchsorted(at, steps, side="right")]


def _values(column: str, values: np.ndarray) -> list:
    finite = np.isfinite(values)
    if column in COLOURS:
        ok = finite & (values >= 0) & (values <= 0xFFFFFF)
        return [f"#{int(v):06x}" if good else None for v, good in zip(values.tolist(), ok)]
    plain = (np.where(finite, values, 0).astype(np.int64).tolist() if column in WHOLE
             else values.tolist())
    return [v if good else None for v, good in zip(plain, finite.tolist())]

