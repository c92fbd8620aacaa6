"""Breakpoints and step units over a recorded run (no Qt).

A *condition* holds at some frames of a trace; ``next_stop`` finds the
nearest such frame after (or before) the current one. A *step unit* says
how far one step forward or back goes. Both come down to one sorted array
of frame indices per trace and condition, worked out once with numpy over
the trace's columns and kept while the trace lives, so a search on a run of
a million steps is a binary search.

What each condition means
-------------------------
``sign``      the run's decision variable (``Start.decision``, Bresenham's
              d) has a different sign (-, 0 or +) from the last frame
              before that carries it. A tie (d = 0) counts as its own sign.
``branch``    the frame's pseudo-code line stands for a branch
              (``CodeLine.branch``, E or NE) other than the one of the last
              frame before it on a branch line.
``aet``       an active edge table snapshot (a Table named "AET") lists
              other edges, or the same edges in another order, than the
              snapshot before it (none before the first). The x of each
              edge moves on every scan line and is not counted.
``scanline``  the frame works on another row than the last frame before it
              that works on a row. A frame's row is the y of its pixel, or
              of its span. Runs whose frames have no pixel of their own but
              spans (the polygon fills) carry the scan line as the value
              ``y``: there the frame where y changes (``y += 1``) starts it.
``pixel``     the frame visits or plots pixel (x, y): a visit or plot line
              at that pixel, or a span on such a line that covers it.
``depth``     a depth test fails: the frame runs the z-buffer's "fail"
              branch (runs that keep a depth buffer).

Step units: ``frame`` (every frame), ``decision`` (frames on a branch
line), ``scanline`` (frames where a new scan line starts, as above) and
``primitive`` (frames where the next primitive starts: the Vars record
naming a new ``triangle``, or a triangle's edge-function table in the
ear-clipping fill).

A condition or unit a run does not offer (no decision variable, no active
edge table, ...) is *unavailable*: ``unavailable`` names why, and the
searches simply find nothing.
"""
from __future__ import annotations

import bisect
import weakref
from dataclasses import dataclass

import numpy as np

from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Table, Vars

SIGN, BRANCH, AET, SCANLINE, PIXEL, DEPTH = "sign", "branch", "aet", "scanline", "pixel", "depth"
CONDITIONS = (SIGN, BRANCH, AET, SCANLINE, PIXEL, DEPTH)
CONDITION_TITLES = {
    SIGN: "decision variable changes sign",
    BRANCH: "branch taken changes",
    AET: "active edge table changes",
    SCANLINE: "new scanline starts",
    PIXEL: "pixel reached",
    DEPTH: "depth test fails",
}
FRAME, DECISION, PRIMITIVE = "frame", "decision", "primitive"
UNITS = (FRAME, DECISION, SCANLINE, PRIMITIVE)
UNIT_TITLES = {FRAME: "frame", DECISION: "decision", SCANLINE: "scanline",
               PRIMITIVE: "primitive"}

AET_NAME = "AET"  # the scan-line fill's active edge table (algorithms/polygons.py)
FAIL_BRANCH = "fail"
PRIMITIVE_KEYS = ("triangle",)
PRIMITIVE_TABLE = "edge functions of triangle"


@dataclass(frozen=True)
class Condition:
    """A breakpoint condition: a kind from CONDITIONS, and the pixel for PIXEL."""

    kind: str
    pixel: tuple[int, int] | None = None

    def __post_init__(self):
        if self.kind not in CONDITIONS:
            raise ValueError(f"unknown breakpoint condition {self.kind!r}; "
                             f"use one of {', '.join(CONDITIONS)}")
        if self.kind == PIXEL and self.pixel is None:
            raise ValueError("the pixel condition needs a pixel (x, y)")

    @property
    def title(self) -> str:
        if self.kind == PIXEL:
            return f"pixel ({self.pixel[0]}, {self.pixel[1]}) reached"
        return CONDITION_TITLES[self.kind]


@dataclass(frozen=True)
class Stop:
    """Where a search stopped, and the condition that holds there."""

    index: int
    condition: Condition


def as_condition(condition) -> Condition:
    """A Condition from a Condition, a kind name, or (PIXEL, (x, y))."""
    if isinstance(condition, Condition):
        return condition
    if isinstance(condition, str):
        return Condition(condition)
    kind, pixel = condition
    return Condition(kind, (int(pixel[0]), int(pixel[1])))


# ------------------------------------------------------------ availability
def unavailable(trace, what) -> str:
    """Why a condition or unit cannot be used on this run; "" when it can.
    Worked out once per run: stepping and playback ask at every step."""
    key = what if isinstance(what, str) else as_condition(what).kind
    known = _cache(trace).setdefault("unavailable", {})
    if key not in known:
        known[key] = _why_unavailable(trace, key)
    return known[key]


def _why_unavailable(trace, key: str) -> str:
    if key in (FRAME, PIXEL):
        return ""
    if key == SIGN:
        name = trace.start.decision
        if name is None or name not in trace.value_names:
            return "the run has no decision variable"
        return ""
    if key in (BRANCH, DECISION):
        return "" if any(line.branch for line in trace.code) else "the run takes no branches"
    if key == AET:
        return "" if _aet_records(trace) else "the run keeps no active edge table"
    if key == SCANLINE:
        return "" if np.isfinite(_rows(trace)).any() else "the run works on no rows"
    if key == DEPTH:
        if trace.start.depth_value is None or not _fail_lines(trace):
            return "the run makes no depth test"
        return ""
    if key == PRIMITIVE:
        return "" if len(_primitive_starts(trace)) else "the run draws a single primitive"
    raise ValueError(f"unknown condition or step unit {key!r}")


# ----------------------------------------------------------------- search
def stops(trace, condition) -> np.ndarray:
    """Sorted frame indices where the condition holds (empty if unavailable)."""
    condition = as_condition(condition)
    key = (condition.kind, condition.pixel)
    cache = _cache(trace)
    if key not in cache:
        if unavailable(trace, condition):
            found = np.zeros(0, np.int64)
        else:
            found = _FINDERS[condition.kind](trace, condition)
        cache[key] = np.asarray(found, np.int64)
    return cache[key]


def next_stop(trace, index: int, condition, direction: int = +1) -> int | None:
    """The first frame after ``index`` (before it, for direction -1) where
    the condition holds; None when there is none or it is unavailable."""
    return _nearest(stops(trace, condition), index, direction)


def first_stop(trace, index: int, conditions, direction: int = +1,
               bound: int | None = None) -> Stop | None:
    """The nearest stop of any of ``conditions`` in the direction given, not
    beyond ``bound`` when one is given. Ties go to the first condition."""
    best = None
    for condition in map(as_condition, conditions):
        found = next_stop(trace, index, condition, direction)
        if found is None or (bound is not None and (found - bound) * direction > 0):
            continue
        if best is None or (found - best.index) * direction < 0:
            best = Stop(found, condition)
    return best


def unit_frames(trace, unit: str) -> np.ndarray | None:
    """Sorted frames a step of ``unit`` lands on; None for FRAME (all of them)."""
    if unit == FRAME:
        return None
    if unit not in UNITS:
        raise ValueError(f"unknown step unit {unit!r}; use one of {', '.join(UNITS)}")
    if unit == SCANLINE:
        return stops(trace, SCANLINE)
    cache = _cache(trace)
    key = ("unit", unit)
    if key not in cache:
        if unavailable(trace, unit):
            cache[key] = np.zeros(0, np.int64)
        elif unit == DECISION:
            cache[key] = np.flatnonzero(_branch_ids(trace))
        else:
            cache[key] = _primitive_starts(trace)
    return cache[key]


def step_target(trace, index: int, unit: str, count: int = 1) -> int | None:
    """Where ``count`` steps of ``unit`` go from ``index`` (back for a
    negative count); None when not even one such step is left."""
    if count == 0:
        return index
    frames = unit_frames(trace, unit)
    if frames is None:
        target = index + count
        if (count > 0 and index >= len(trace) - 1) or (count < 0 and index <= 0):
            return None
        return min(max(target, 0), len(trace) - 1)
    if count > 0:
        k = bisect.bisect_right(frames, index) + count - 1
        if k >= len(frames):
            k = len(frames) - 1  # as far as there are stops
        return int(frames[k]) if k >= 0 and frames[k] > index else None
    k = bisect.bisect_left(frames, index) + count
    if k < 0:
        k = 0
    return int(frames[k]) if k < len(frames) and frames[k] < index else None


# ------------------------------------------------------------- internals
_CACHES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _cache(trace) -> dict:
    try:
        return _CACHES.setdefault(trace, {})
    except TypeError:  # an object that takes no weak reference: no cache
        return {}


def _nearest(frames: np.ndarray, index: int, direction: int) -> int | None:
    if direction >= 0:
        k = bisect.bisect_right(frames, index)
        return int(frames[k]) if k < len(frames) else None
    k = bisect.bisect_left(frames, index) - 1
    return int(frames[k]) if k >= 0 else None


def _changes(values: np.ndarray, known: np.ndarray) -> np.ndarray:
    """Frames (of ``known``) whose value differs from the previous known one."""
    picked = values[known]
    return known[1:][picked[1:] != picked[:-1]]


def _sign_changes(trace, _condition) -> np.ndarray:
    decision = trace.series(trace.start.decision)
    known = np.flatnonzero(np.isfinite(decision))
    return _changes(np.sign(decision), known)


def _branch_ids(trace) -> np.ndarray:
    """Per frame: 0 off a branch line, else a number per branch name."""
    names = sorted({line.branch for line in trace.code if line.branch})
    number = {name: k + 1 for k, name in enumerate(names)}
    table = np.array([number.get(line.branch, 0) for line in trace.code], np.int32)
    return table[trace.line]


def _branch_changes(trace, _condition) -> np.ndarray:
    ids = _branch_ids(trace)
    return _changes(ids, np.flatnonzero(ids))


def _aet_records(trace) -> list:
    return [(index, table) for index, table in trace.records_of(Table)
            if table.name == AET_NAME]


def _aet_changes(trace, _condition) -> list:
    found, previous = [], ()
    for index, table in _aet_records(trace):
        column = table.columns.index("edge") if "edge" in table.columns else None
        edges = tuple(row[column] for row in table.rows) if column is not None else table.rows
        if edges != previous:
            found.append(index)
        previous = edges
    return found


def _rows(trace) -> np.ndarray:
    """Per frame, the row it works on (see the module's notes); NaN for none."""
    cache = _cache(trace)
    if "rows" in cache:
        return cache["rows"]
    rows = np.where(trace.x != NO_PIXEL, trace.y, np.nan).astype(float)
    spans = trace.spans()
    rows[spans["step"]] = np.nan
    if "y" in trace.value_names and len(spans) and not np.isfinite(rows).any():
        rows = trace.series("y").copy()
    rows[spans["step"]] = spans["y"]
    cache["rows"] = rows
    return rows


def _row_changes(trace, _condition) -> np.ndarray:
    rows = _rows(trace)
    return _changes(rows, np.flatnonzero(np.isfinite(rows)))


def _pixel_frames(trace, condition) -> np.ndarray:
    x, y = condition.pixel
    looks = np.array([line.kind in (PLOT, VISIT) for line in trace.code], bool)
    hit = (trace.x == x) & (trace.y == y) & looks[trace.line]
    spans = trace.spans()
    covered = spans["step"][(spans["y"] == y) & (spans["x_start"] <= x) & (x < spans["x_end"])
                            & looks[spans["line"]]]
    hit[spans["step"]] = False
    hit[covered] = True
    return np.flatnonzero(hit)


def _fail_lines(trace) -> list[int]:
    return [k for k, line in enumerate(trace.code) if line.branch == FAIL_BRANCH]


def _depth_fails(trace, _condition) -> np.ndarray:
    return np.flatnonzero(np.isin(trace.line, _fail_lines(trace)))


def _primitive_starts(trace) -> np.ndarray:
    found = [index for index, record in trace.records_of(Vars)
             if any(key in record.values for key in PRIMITIVE_KEYS)]
    found += [index for index, table in trace.records_of(Table)
              if table.name.startswith(PRIMITIVE_TABLE)]
    return np.array(sorted(found), np.int64)


_FINDERS = {SIGN: _sign_changes, BRANCH: _branch_changes, AET: _aet_changes,
            SCANLINE: _row_changes, PIXEL: _pixel_frames, DEPTH: _depth_fails}
