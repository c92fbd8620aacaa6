"""What one exported frame stands for: a step, a decision, a pixel written,
a scan line, a primitive; and the automatic choice for a long run.

A unit's frame is the step that ends it, so each frame shows the unit done.
The first and the last step of the range are always frames: the set-up and
the result are on every export.
"""
from __future__ import annotations

import numpy as np

from algorithms.core.steps import Vars

UNITS = ("auto", "step", "decision", "pixel", "scanline", "primitive")
# The automatic choice keeps an export at most this many frames long (a
# minute at the default 4 frames per second): a slide's worth.
AUTO_FRAMES = 240
NAMES = {"step": "step", "decision": "decision", "pixel": "pixel written",
         "scanline": "scan line", "primitive": "primitive"}


def unit_ends(trace, unit: str, lo: int, hi: int) -> np.ndarray:
    """Ascending steps in lo .. hi - 1 that end a ``unit``, with lo and hi - 1."""
    if unit == "step":
        return np.arange(lo, hi, dtype=np.int64)
    if unit == "decision":
        branchy = np.array([bool(line.branch) for line in trace.code], dtype=bool)
        ends = lo + np.flatnonzero(branchy[trace.line[lo:hi]])
    elif unit == "pixel":
        ends = np.unique(trace.written(lo, hi).steps)
    elif unit == "scanline":
        ends = _row_ends(trace, lo, hi)
    elif unit == "primitive":
        starts = [step for step, record in trace.records_of(Vars, lo=lo, hi=hi)
                  if "triangle" in record.values]
        ends = np.array([step - 1 for step in starts if step > lo], dtype=np.int64)
    else:
        raise ValueError(f"unknown unit {unit!r}")
    return np.unique(np.concatenate([[lo], np.asarray(ends, dtype=np.int64), [hi - 1]]))


def _row_ends(trace, lo: int, hi: int) -> np.ndarray:
    """The last write of each run of writes on one row."""
    written = trace.written(lo, hi)
    if not len(written.steps):
        return np.zeros(0, dtype=np.int64)
    rows = written.pixels[:, 1]
    last = np.append(rows[1:] != rows[:-1], True)
    return np.unique(written.steps[last])


def choose_frames(trace, unit: str, lo: int, hi: int) -> tuple[list[int], str]:
    """The frames of steps lo .. hi - 1 and one line saying what was chosen.

    ``auto``: a frame per step while the range is short; else the finest of
    decision, pixel, scan line and primitive that stays within AUTO_FRAMES;
    else the coarsest that shows more than the two ends, thinned evenly.
    """
    count = hi - lo
    if unit != "auto":
        ends = unit_ends(trace, unit, lo, hi)
        return ends.tolist(), _said(unit, len(ends), count)
    if count <= AUTO_FRAMES:
        return list(range(lo, hi)), _said("step", count, count)
    best = None
    for candidate in ("decision", "pixel", "scanline", "primitive"):
        ends = unit_ends(trace, candidate, lo, hi)
        if 2 < len(ends) <= AUTO_FRAMES:
            return ends.tolist(), _said(candidate, len(ends), count, automatic=True)
        if len(ends) > 2 and (best is None or len(ends) < len(best[1])):
            best = (candidate, ends)
    if best is None:
        best = ("step", np.arange(lo, hi, dtype=np.int64))
    name, ends = best
    # Evenly spread over the units, the first and the last kept.
    picks = np.unique(np.round(np.linspace(0, len(ends) - 1, AUTO_FRAMES)).astype(np.int64))
    thinned = ends[picks]
    every = round((len(ends) - 1) / max(1, len(thinned) - 1))
    return thinned.tolist(), _said(name, len(thinned), count, automatic=True, every=every)


def _said(unit: str, frames: int, steps: int, automatic: bool = False, every: int = 1) -> str:
    what = NAMES[unit] if every == 1 else f"about every {_ordinal(every)} {NAMES[unit]}"
    how = " (chosen for a long run)" if automatic else ""
    return f"one frame per {what}{how}: {frames:,} frames for {steps:,} steps"


def _ordinal(n: int) -> str:
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"
