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

from algorithms.core.steps import Vars

# Columns whose values are whole numbers, and the packed colour.
WHOLE = ("level", "fetches", "@triangle")
COLOURS = ("rgb", "src", "dst")
WEIGHTS = {"@weights": ("alpha", "beta", "gamma"), "@weights_p": ("alpha_p", "beta_p", "gamma_p")}
# The Vars text of a triangle whose P1 and P2 the run swapped (see triangles/run.py).
SWAPPED = "clockwise: P1, P2 swapped"


def fragment_table(trace, pairs) -> tuple[list[tuple[str, str, int]], "FragmentTable"]:
    """(layout, table): layout lists (key, column, width) of the keys this run has;
    table holds, per written pixel in emission order, those columns side by side."""
    table = FragmentTable(trace, pairs)
    return table.layout, table


class FragmentTable:
    """The fragment columns of a run, made a slice of pixels at a time: a whole
    table beside a step-capped trace would cost as much again."""

    def __init__(self, trace, pairs):
        self.steps = trace.written().steps
        names = set(trace.value_names)
        self.layout, self.sources = [], []
        for key, column in pairs:
            source = _source(trace, column, names)
            if source is not None:
                self.layout.append((key, column, _width(column)))
                self.sources.append(source)

    def __len__(self) -> int:
        return len(self.steps)

    def __getitem__(self, part: slice) -> np.ndarray:
        steps = self.steps[part]
        blocks = [source(steps).reshape(len(steps), -1).astype(np.float64)
                  for source in self.sources]
        return np.concatenate(blocks, axis=1) if blocks else np.zeros((len(steps), 0))


def fragment_objects(layout, rows: np.ndarray) -> list[dict]:
    """JSON objects of fragment_table's rows: null for NaN, #rrggbb for a colour,
    a list for a column several wide. Built a column at a time (fast on big runs)."""
    if isinstance(rows, FragmentTable):
        rows = rows[:]
    keys, columns, start = [], [], 0
    for key, column, width in layout:
        parts = [_values(column, rows[:, start + k]) for k in range(width)]
        columns.append(parts[0] if width == 1 else [list(v) for v in zip(*parts)])
        keys.append(key)
        start += width
    return [dict(zip(keys, values)) for values in zip(*columns)]


def _width(column: str) -> int:
    return 3 if column in WEIGHTS else 1


def _source(trace, column, names):
    """A function of written steps giving the column there, or None when the run lacks it."""
    if column == "@triangle":
        return _vars_source(trace, "triangle")
    if column in WEIGHTS:
        return _weights_source(trace, column, names)
    if column not in names:
        return None
    series = trace.series(column)
    return lambda steps: series[steps]


def _weights_source(trace, column, names):
    own = WEIGHTS[column]
    if all(name in names for name in own):
        columns = [trace.series(name) for name in own]
    elif column == "@weights" and {"e0", "e1", "e2"} <= names:
        area2 = _vars_source(trace, "2A")
        edges = [trace.series(f"e{k}") for k in range(3)]
        columns = None
    else:
        return None
    winding = _vars_source(trace, "winding", dtype=object)

    def weights(steps):
        if columns is not None:
            found = np.stack([series[steps] for series in columns], axis=1)
        else:
            with np.errstate(divide="ignore", invalid="ignore"):
                found = np.stack([series[steps] for series in edges], axis=1) \
                    / area2(steps)[:, None]
        # Weights follow the run's vertex order; a swapped triangle's P1 and P2
        # are the input's P2 and P1, so swap those weights back.
        swapped = winding(steps) == SWAPPED
        found[swapped] = found[swapped][:, [0, 2, 1]]
        return found
    return weights


def _vars_source(trace, name, dtype=np.float64):
    """A function of steps giving the value of the Vars ``name`` in effect at each
    (NaN or None before any)."""
    found = [(i, record.values[name]) for i, record in trace.records_of(Vars)
             if name in record.values]
    empty = np.nan if dtype is np.float64 else None
    at = np.array([i for i, _ in found], dtype=np.int64)
    values = np.array([empty] + [v for _, v in found], dtype=dtype)
    return lambda steps: values[np.searchsorted(at, steps, side="right")]


def _values(column: str, values: np.ndarray) -> list:
    finite = np.isfinite(values)
    if column in COLOURS:
        ok = finite & (values >= 0) & (values <= 0xFFFFFF)
        return [f"#{int(v):06x}" if good else None for v, good in zip(values.tolist(), ok)]
    plain = (np.where(finite, values, 0).astype(np.int64).tolist() if column in WHOLE
             else values.tolist())
    return [v if good else None for v, good in zip(plain, finite.tolist())]

