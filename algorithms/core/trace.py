"""Record a step generator once; give random access to every step.

Frames are stored as columns (pseudo-code line, x, y and one float64
column per named value), about 10 + 8k bytes a step for k values, instead
of one Python object per step. ``state_at(i)`` copies the nearest keyframe
before i and replays the frames in between with numpy, so scrubbing and
stepping backward never replay from step 0 on long traces.

The rich records (``Start``, ``Vars``, ``Table``, ``Note``, ``Span``) are
kept by step, with a sorted array of steps per record type, and read
through the queries below rather than by walking them:

``record_at(i)``                 the rich record of step i, or None
``steps_of(*types, lo, hi)``     the steps holding records of those types
``records_of(*types, lo, hi)``   (step, record) pairs of those types
``last_of(*types, at)``          the latest such pair at or before a step
``spans(lo, hi)``                the Spans of a step range, one table row each
``written(lo, hi)``              the pixels steps lo..hi-1 write, with values
``replay(lo, hi, raster)``       apply steps lo..hi-1 to a raster; the one
                                 replay, which ``state_at`` uses from a keyframe
"""
from __future__ import annotations

import functools
import math
import struct
import time
from dataclasses import dataclass
from itertools import groupby, islice
from typing import Iterable, NamedTuple, Sequence

import numpy as np

from algorithms.core.monitor import (  # noqa: F401 (the trace's API)
    DEFAULT_STEP_CAP, Cancelled, RecordMonitor, checkpoint, watching, work_allowance)
from algorithms.core.keyframes import Keyframes, color_dtype, smallest_unsigned
from algorithms.core.trace_store import Columns, Records, frame_dtype, frame_rows
from algorithms.core.raster import Raster
from algorithms.core.steps import NO_PIXEL, PLOT, RICH_RECORDS, CodeLine, Span, Start, Step, Vars

NO_PIXELS = (NO_PIXEL, NO_PIXEL)  # x and y of a rich record without a pixel
# The most steps any recording keeps, in the window and on the command line:
# at about 22 bytes a step (README, "Performance") a trace stays near 1.1 GB.
MAX_STEP_CAP = 50_000_000
KEYFRAME_BUDGET = 64 * 2 ** 20  # bytes the dense keyframes of one trace may take
KEYFRAME_BYTES_PER_STEP = 16  # or this per recorded step, when that is more
MIN_KEYFRAME_GAP = 1024
LIST_ROWS = 1024  # frames listed and converted together (a list that stays in cache)
# While frames come slowly, the list shortens so that a cancel is heard
# within about this many seconds, however long each frame takes.
PACE = 0.02
FIRST_LIST_ROWS = 64  # a watched recording's first list
# Steps between keyframes on long runs: a replay of this many steps takes a
# few milliseconds, so any step of any run is that far from a keyframe.
MAX_KEYFRAME_GAP = 1 << 16


class TraceError(ValueError):
    """A generator broke the frame protocol of steps.py."""


@dataclass
class FrameState:
    """Everything known at one step: what panels and the grid display."""

    index: int
    step: Step
    raster: Raster
    variables: dict
    candidates: list

    @property
    def pixel(self):
        return self.step.pixel


class Writes(NamedTuple):
    """The pixels some steps write, in emission order, duplicates kept.

    A Span on a PLOT line counts as one write per pixel of its run.
    ``steps`` (n,) int64: the step of each write; ``pixels`` (n, 2) int64:
    (x, y), outside the grid included; ``values`` (n,) float64: the run's
    ``Start.pixel_value`` written (NaN from a span without one), or None
    when the run writes no values.
    """

    steps: np.ndarray
    pixels: np.ndarray
    values: np.ndarray | None


# One row per Span record: its step, code line, row and run; value NaN for none.
SPAN_DTYPE = np.dtype([("step", "i8"), ("line", "i8"), ("y", "i8"), ("x_start", "i8"),
                       ("x_end", "i8"), ("value", "f8")])


class Trace:
    """A recorded run: columns of frames plus the sparse rich records."""

    def __init__(self, code: Sequence[CodeLine], width: int, height: int,
                 step_cap: int = DEFAULT_STEP_CAP):
        if step_cap < 1:
            raise ValueError("the step cap must be at least 1")
        self.code = tuple(code)
        self.width, self.height = width, height
        self.step_cap = step_cap
        self.start: Start | None = None
        self._store = Records()  # the rich records, by step
        self.truncated = False
        self.message = ""
        # Steps of the rich records, per record type and of all types: lists
        # while recording, read-only int64 arrays once it is finished.
        self._steps_by_type: dict[type, list[int] | np.ndarray] = {}
        self._rich_steps: list[int] | np.ndarray = []
        self._span_table: np.ndarray | None = None
        self._vars_index: dict | None = None  # name -> (steps, values) of its Vars updates
        self._keyframes: Keyframes | None = None
        self._dtypes = (np.int32, np.int64)  # of the rasters raster_at gives
        self._flat: np.ndarray | None = None
        self._monitor: RecordMonitor | None = None
        self._next_report = math.inf
        self._list_rows = LIST_ROWS

    @functools.cached_property
    def _plot_lines(self) -> np.ndarray:
        """Whether each pseudo-code line plots (made when first asked for)."""
        return np.array([line.kind == PLOT for line in self.code], dtype=bool)

    # ----------------------------------------------------------- recording
    @classmethod
    def record(cls, frames: Iterable, code: Sequence[CodeLine], width: int,
               height: int, step_cap: int = DEFAULT_STEP_CAP,
               monitor: RecordMonitor | None = None) -> "Trace":
        """Record the frames; a ``monitor`` hears the progress and may cancel
        (``Cancelled`` is raised then)."""
        trace = cls(code, width, height, step_cap)
        trace._monitor = monitor
        trace._next_report = monitor.every if monitor is not None else math.inf
        # Watched, the first list is short and grows while frames come fast.
        trace._list_rows = LIST_ROWS if monitor is None else FIRST_LIST_ROWS
        with watching(monitor, step_cap):
            trace._record(iter(frames))
        trace._monitor = None
        return trace

    def _report(self) -> None:
        """Called when the count passes the next report mark (rarely)."""
        self._monitor.report(self._count)
        self._next_report = self._count + self._monitor.every

    def _record(self, frames) -> None:
        start = next(frames, None)
        if not isinstance(start, Start):
            raise TraceError("the first frame of a run must be a Start record")
        self.start = start
        self._nans = (math.nan,) * len(start.values)
        # Every frame goes to this list first (a rich record as its line and
        # pixel) and into the columns a list at a time (see frame_rows).
        self._pending = [(start.line, NO_PIXEL, NO_PIXEL) + self._nans]
        self._columns = Columns(frame_dtype(len(start.values)).names[3:], self._list_rows)
        self._listed_at = time.perf_counter()
        self._store_rich(0, start)
        # groupby sets the rich records aside without a Python-level test
        # per frame; its key (a C-level isinstance) puts consecutive rich
        # records of any types in one run.
        capped = islice(frames, self.step_cap - 1)
        for plain, group in groupby(capped, tuple.__instancecheck__):
            if plain:
                self._record_plain(group)
            else:
                self._record_rich(group)
        self._flush()
        if self._count >= self.step_cap and next(frames, None) is not None:
            self.truncated = True
            self.message = (f"Recording stopped at the step cap of {self.step_cap:,} steps; "
                            "the run goes on beyond it. Raise the cap or use a smaller input.")
        self._finish()

    @property
    def _count(self) -> int:
        """Frames recorded so far, converted or waiting."""
        return self._columns.count + len(self._pending)

    def _list_size(self) -> int:
        """Frames the list takes before it goes into the columns: never past
        the next report, so that progress keeps its interval."""
        return min(self._list_rows, self._next_report - self._columns.count)

    def _record_plain(self, group) -> None:
        """A run of tuples, listed as many at a time as the list has room for."""
        while True:
            size = self._list_size()
            self._pending.extend(islice(group, size - len(self._pending)))
            if len(self._pending) < size:
                return  # the run has ended
            self._flush()

    def _record_rich(self, group) -> None:
        """A run of rich records; a record type is checked at its first record."""
        by_type = self._steps_by_type
        add, steps = self._store.add, self._rich_steps
        monitor = self._monitor
        size = self._list_size()
        for record in group:
            index = self._count
            kind = type(record)
            of_kind = by_type.get(kind)
            if of_kind is None or kind is Start:
                if not issubclass(kind, RICH_RECORDS) or issubclass(kind, Start):
                    self._flush()  # a bad frame listed before it is reported first
                    raise TraceError(f"step {index}: {record!r} is not a frame "
                                     "steps.py allows here")
                of_kind = by_type[kind] = []
            x, y = record.pixel or NO_PIXELS
            self._pending.append((record.line, x, y, *self._nans))
            add(record)
            steps.append(index)
            of_kind.append(index)
            if len(self._pending) >= size:
                self._flush()
                size = self._list_size()
            if monitor is not None and monitor.cancelled:
                self._report()  # raises Cancelled: heard after any record

    def _flush(self) -> None:
        """The listed frames into the columns; report progress."""
        if not self._pending:
            return
        first = self._columns.count
        try:
            rows = frame_rows(self._pending, len(self._nans))
        except struct.error as error:
            raise self._frame_error(first, error) from None
        self._check_rows(rows, first)
        self._columns.append(rows)
        self._pending = []
        if self._monitor is not None:
            self._pace()
        if self._count >= self._next_report:
            self._report()

    def _pace(self) -> None:
        """Fit the list to the frames' speed: a list that took longer than
        PACE to fill and convert is followed by a shorter one, fast lists
        grow back to LIST_ROWS, and a cancel is heard after every list."""
        now = time.perf_counter()
        took, self._listed_at = now - self._listed_at, now
        if took > PACE:
            self._list_rows = max(1, int(self._list_rows * PACE / took))
        elif took < PACE / 4:
            self._list_rows = min(LIST_ROWS, 2 * self._list_rows)
        if self._monitor.cancelled:
            self._report()  # raises Cancelled; progress keeps its interval

    def _frame_error(self, first: int, error) -> TraceError:
        return TraceError(f"near step {first}: a frame is not (line, x, y"
                          f"{', value' * len(self.start.values)}): {error}")

    def _check_rows(self, rows: np.ndarray, first_index: int) -> None:
        bad = rows["line"] >= len(self.code)
        if bad.any():
            index = first_index + int(np.argmax(bad))
            raise TraceError(f"step {index}: pseudo-code line {rows['line'][index - first_index]} "
                             f"does not exist")

    def _store_rich(self, index: int, record) -> None:
        self._store.add(record)
        self._rich_steps.append(index)
        self._steps_by_type.setdefault(type(record), []).append(index)

    def _finish(self) -> None:
        columns = self._columns
        columns.finish()
        self.line, self.x, self.y, self.values = columns.line, columns.x, columns.y, columns.values
        self._columns = None
        self._rich_steps = _frozen_steps(self._rich_steps)
        self._store.finish(self._rich_steps)
        self._steps_by_type = {kind: _frozen_steps(steps)
                               for kind, steps in self._steps_by_type.items()}

    # ------------------------------------------------------------ queries
    def __len__(self) -> int:
        return len(self.line)

    @property
    def value_names(self) -> tuple[str, ...]:
        return self.start.values

    def nbytes(self) -> int:
        """Bytes held by the recorded frames (not counting replay caches)."""
        return self.line.nbytes + self.x.nbytes + self.y.nbytes + self.values.nbytes

    def cache_nbytes(self) -> int:
        """Bytes held by the replay caches: keyframes, the pixel index, the span table."""
        keyframes = 0 if self._keyframes is None else self._keyframes.nbytes()
        spans = 0 if self._span_table is None else self._span_table.nbytes
        return keyframes + spans + (0 if self._flat is None else self._flat.nbytes)

    def series(self, name: str) -> np.ndarray:
        """One named value over all steps; NaN where a step lacks it."""
        return self.values[:, self.value_names.index(name)]

    # ------------------------------------------------------- rich records
    def record_at(self, i: int):
        """The rich record of step i (a Start, Vars, Table, Note or Span), or None."""
        i = self._index(i)
        return self.start if i == 0 else self._store.get(i)

    def steps_of(self, *types: type, lo: int = 0, hi: int | None = None) -> np.ndarray:
        """Ascending steps in lo..hi-1 that hold a rich record of one of
        ``types`` (of any type when none is named): a read-only int64 array,
        found by binary search in the steps kept per type."""
        if not types:
            return _between(self._rich_steps, lo, hi)
        parts = [_between(self._steps_by_type.get(kind, _NO_STEPS), lo, hi) for kind in types]
        return parts[0] if len(parts) == 1 else np.sort(np.concatenate(parts))

    def records_of(self, *types: type, lo: int = 0, hi: int | None = None) -> list:
        """(step, record) pairs of the rich records ``steps_of`` finds, in step order."""
        steps = self.steps_of(*types, lo=lo, hi=hi)
        records = self._store.at_positions(self._store.position(steps))
        if len(steps) and steps[0] == 0:
            records[0] = self.start
        return list(zip(steps.tolist(), records))

    def last_of(self, *types: type, at: int):
        """The (step, record) pair of the latest record of one of ``types``
        at or before step ``at``, or None when there is none."""
        latest = -1
        for kind in types:
            steps = self._steps_by_type.get(kind, _NO_STEPS)
            k = int(np.searchsorted(steps, at, side="right")) - 1
            if k >= 0:
                latest = max(latest, int(steps[k]))
        return None if latest < 0 else (latest, self.record_at(latest))

    def spans(self, lo: int = 0, hi: int | None = None) -> np.ndarray:
        """The Span records of steps lo..hi-1, on lines of any kind, one row
        each (fields of ``SPAN_DTYPE``; ``value`` NaN where a span has none),
        in step order; read-only."""
        if self._span_table is None:
            spans = self.records_of(Span)
            table = np.array([(step, r.line, r.y, r.x_start, r.x_end,
                               math.nan if r.value is None else float(r.value))
                              for step, r in spans], SPAN_DTYPE)
            table.flags.writeable = False
            self._span_table = table
        first, last = _bounds(self._span_table["step"], lo, hi)
        return self._span_table[first:last]

    # ------------------------------------------------------------- writes
    def writes(self) -> np.ndarray:
        """Per step: does it write a single pixel? (A Span step writes a run
        and is not counted here; ``written`` gives every write.)"""
        return self._single_writes(0, len(self))

    def written(self, lo: int = 0, hi: int | None = None) -> Writes:
        """The pixels steps lo..hi-1 write, spans expanded, in emission order
        (see ``Writes``); ``written(0, i + 1)`` is everything up to step i."""
        lo, hi = self._range(lo, hi)
        steps = lo + np.flatnonzero(self._single_writes(lo, hi))
        pixels = np.stack([self.x[steps], self.y[steps]], axis=1).astype(np.int64)
        name = self.start.pixel_value
        values = None if name is None else self.series(name)[steps]
        span_steps, span_pixels, span_values = self._span_writes(lo, hi)
        if len(span_steps):
            # Stable, so that the pixels of one span keep their order.
            order = np.argsort(np.concatenate([steps, span_steps]), kind="stable")
            steps = np.concatenate([steps, span_steps])[order]
            pixels = np.concatenate([pixels, span_pixels])[order]
            if values is not None:
                values = np.concatenate([values, span_values])[order]
        return Writes(steps, pixels, values)

    def written_pixels(self) -> np.ndarray:
        """(n, 2) array of the written pixels, in emission order, duplicates kept."""
        return self.written().pixels

    def pixel_values(self) -> np.ndarray | None:
        """The value written with each written pixel (spans included), in emission order."""
        return self.written().values

    def _single_writes(self, lo: int, hi: int) -> np.ndarray:
        mask = self._plot_lines[self.line[lo:hi]] & (self.x[lo:hi] != NO_PIXEL)
        # Rich records never write a single pixel (a Span writes its run).
        mask[self.steps_of(lo=lo, hi=hi) - lo] = False
        return mask

    def _span_writes(self, lo: int, hi: int):
        """Steps, pixels and values (NaN for none) of the pixels written by
        the spans on PLOT lines among steps lo..hi-1, in order."""
        if Span not in self._steps_by_type:  # most runs have none: skip the work
            return np.zeros(0, np.int64), np.zeros((0, 2), np.int64), np.zeros(0)
        spans = self.spans(lo, hi)
        spans = spans[self._plot_lines[spans["line"]]]
        lengths = np.maximum(spans["x_end"] - spans["x_start"], 0)
        steps = np.repeat(spans["step"], lengths)
        # x = the span's x_start plus the write's place within its span.
        offsets = np.repeat(spans["x_start"] - (np.cumsum(lengths) - lengths), lengths)
        pixels = np.stack([offsets + np.arange(len(steps)), np.repeat(spans["y"], lengths)],
                          axis=1)
        return steps, pixels, np.repeat(spans["value"], lengths)

    # ------------------------------------------------------------- steps
    def step(self, i: int) -> Step:
        i = self._index(i)
        line = int(self.line[i])
        code = self.code[line]
        x, y = int(self.x[i]), int(self.y[i])
        pixel = None if x == NO_PIXEL else (x, y)
        values = {name: float(v) for name, v in zip(self.value_names, self.values[i])
                  if not math.isnan(v)}
        return Step(i, line, code.kind, pixel, values, code.branch, self.record_at(i))

    def variables_at(self, i: int) -> dict:
        """Constants, every Vars update up to step i, and step i's own values."""
        i = self._index(i)
        result = dict(self.start.constants)
        # Each name's latest update by binary search, names in the order
        # they first appear: the same dict as applying every Vars record in
        # turn, without walking them (a flood fill has one per pop).
        for name, (steps, values) in self._variable_updates().items():
            k = int(np.searchsorted(steps, i, side="right")) - 1
            if k < 0:
                continue
            result[name] = values[k]
        result.update(self.step(i).values)
        branch = self.code[int(self.line[i])].branch
        if branch:
            result["choice"] = branch
        return result

    def _variable_updates(self) -> dict:
        """name -> (ascending steps, values) of the Vars records that set it,
        names in the order they first appear (built once)."""
        if self._vars_index is None:
            index: dict = {}
            for step, record in self.records_of(Vars):
                for name, value in record.values.items():
                    steps, values = index.setdefault(name, ([], []))
                    steps.append(step)
                    values.append(value)
            self._vars_index = {name: (np.array(steps, np.int64), values)
                                for name, (steps, values) in index.items()}
        return self._vars_index

    def final_variables(self) -> dict:
        """The named variables at the end of the run: for each name, the
        value set last, whether by a Vars record or by a frame's value."""
        updates = [(index, name, value) for index, record in self.records_of(Vars)
                   for name, value in record.values.items()]
        for column, name in enumerate(self.value_names):
            known = np.flatnonzero(~np.isnan(self.values[:, column]))
            if known.size:
                last = int(known[-1])
                updates.append((last, name, _plain_number(self.values[last, column])))
        result = dict(self.start.constants)
        for _, name, value in sorted(updates, key=lambda update: update[0]):
            result[name] = value
        return result

    def candidates_at(self, i: int) -> list[tuple[int, int]]:
        i = self._index(i)
        line = self.code[int(self.line[i])]
        offsets = line.candidates or self.start.candidates
        if not offsets or i == 0 or not line.branch:
            return []
        px, py = int(self.x[i - 1]), int(self.y[i - 1])
        if px == NO_PIXEL:
            return []
        found = [(px + dx, py + dy) for dx, dy in offsets]
        here = (int(self.x[i]), int(self.y[i]))
        if here in found or here[0] == NO_PIXEL:
            return found
        # Frames came between the pixel decided from and this one (mirrors
        # plotted before the decision): this step's pixel is the candidate
        # its branch names, so the pixel decided from is found from it.
        names = [other.branch for other in self.code if other.branch
                 and (other.candidates or self.start.candidates) == offsets]
        names = list(dict.fromkeys(names))
        if line.branch not in names or names.index(line.branch) >= len(offsets):
            return found
        dx, dy = offsets[names.index(line.branch)]
        bx, by = here[0] - dx, here[1] - dy
        return [(bx + ox, by + oy) for ox, oy in offsets]

    def state_at(self, i: int, compact: bool = False) -> FrameState:
        i = self._index(i)
        return self.state_on(i, self.raster_at(i, compact))

    def state_on(self, i: int, raster: Raster) -> FrameState:
        """Step i's state shown on ``raster``, which the caller made (and
        which should be the raster after step i)."""
        return FrameState(i, self.step(i), raster, self.variables_at(i), self.candidates_at(i))

    def raster_at(self, i: int, compact: bool = False) -> Raster:
        """The framebuffer after step i: nearest keyframe plus a numpy replay.

        ``compact``: counts and colours in the smallest dtypes this run
        needs (uint8 counts, say, rather than int32), which is what makes a
        large grid quick to show; otherwise int32 counts and int64 colours.
        """
        i = self._index(i)
        keyframes = self._ensure_keyframes()
        slot = min((i + 1) // keyframes.gap, len(keyframes) - 1)
        raster = keyframes.restore(slot, *(self._dtypes if compact else (np.int32, np.int64)))
        self.replay(slot * keyframes.gap, i + 1, raster)
        return raster

    def replay(self, lo: int, hi: int, raster: Raster) -> None:
        """Apply steps lo..hi-1 to ``raster``, in step order, vectorised: the
        one replay behind ``state_at`` and every frame-by-frame renderer.

        Each write adds one to the pixel's count, sets its colour from the
        run's colour value (``Start.color_value``, else ``pixel_value``; a
        span's own value) and its depth (``Start.depth_value``; spans carry
        none). Pixels outside the grid are clipped.
        """
        lo, hi = self._range(lo, hi)
        if hi > lo:
            raster.write_many(*self._replay_writes(lo, hi))

    def _replay_writes(self, lo: int, hi: int):
        """Flat pixels (-1: none), colours and depths steps lo..hi-1 write, in order."""
        column = self._value_column()
        values = None if column is None else self.values[lo:hi, column]
        depth_column = self._depth_column()
        depths = None if depth_column is None else self.values[lo:hi, depth_column]
        flat = self._flat_pixels()[lo:hi]
        orders, pixels, span_values = self._span_writes(lo, hi)
        if len(orders):
            x, y = pixels[:, 0], pixels[:, 1]
            inside = (x >= 0) & (x < self.width) & (y >= 0) & (y < self.height)
            # Spans and single pixels merged in step order, so that the last
            # write to a pixel sets its colour.
            order = np.argsort(np.concatenate([np.arange(lo, hi), orders]), kind="stable")
            flat = np.concatenate([flat, np.where(inside, y * self.width + x, -1)])[order]
            if values is not None:
                values = np.concatenate([values, span_values])[order]
            if depths is not None:
                depths = np.concatenate([depths, np.full(len(orders), math.nan)])[order]
        return flat, values, depths

    # ---------------------------------------------------------- internals
    def _range(self, lo: int, hi: int | None) -> tuple[int, int]:
        """lo..hi clipped to the trace; hi None stands for its end."""
        n = len(self)
        return min(max(lo, 0), n), n if hi is None else min(max(hi, 0), n)

    def _index(self, i: int) -> int:
        n = len(self)
        if not -n <= i < n:
            raise IndexError(f"step {i} is outside 0..{n - 1}")
        return i % n

    def _value_column(self):
        """The column of packed colours for the colour buffer, if the run writes any."""
        name = self.start.color_value or self.start.pixel_value
        return None if name is None else self.value_names.index(name)

    def _depth_column(self):
        name = self.start.depth_value
        return None if name is None else self.value_names.index(name)

    def _empty_raster(self) -> Raster:
        with_colors = (self.start.color_value or self.start.pixel_value) is not None
        raster = Raster(self.width, self.height, with_colors, self.start.depth_value is not None)
        raster.replaces = self.start.replaces
        return raster

    def _flat_pixels(self) -> np.ndarray:
        """Per step, y * W + x of the pixel it writes, or -1 (no write, or clipped)."""
        if self._flat is None:
            x, y = self.x.astype(np.int64), self.y.astype(np.int64)
            inside = self.writes() & (x >= 0) & (x < self.width) & (y >= 0) & (y < self.height)
            self._flat = np.where(inside, y * self.width + x, -1).astype(np.int32)
        return self._flat

    def _ensure_keyframes(self) -> Keyframes:
        """Keyframes every gap steps (see keyframes.py), built in one replay;
        it also finds the smallest dtypes the run's rasters need."""
        if self._keyframes is not None:
            return self._keyframes
        empty = self._empty_raster()
        colors = np.int64
        if empty.colors is not None:
            colors = color_dtype(np.concatenate([self.values[:, self._value_column()],
                                                 self.spans()["value"]]))
            empty.colors = empty.colors.astype(colors)
        budget = max(KEYFRAME_BUDGET, KEYFRAME_BYTES_PER_STEP * len(self))
        gap = max(MIN_KEYFRAME_GAP, min(MAX_KEYFRAME_GAP, math.ceil(len(self) / 64)))
        keyframes = Keyframes(empty, gap, budget)
        raster = empty.copy()
        for lo in range(0, len(self), gap):
            writes = self._replay_writes(lo, min(lo + gap, len(self)))
            raster.write_many(*writes)
            if lo + gap < len(self):
                keyframes.add(writes[0], raster)
        self._dtypes = (smallest_unsigned(int(raster.counts.max(initial=0))), colors)
        self._keyframes = keyframes
        return keyframes


_NO_STEPS = np.zeros(0, np.int64)
_NO_STEPS.flags.writeable = False


def _frozen_steps(steps: list[int]) -> np.ndarray:
    array = np.array(steps, np.int64)
    array.flags.writeable = False
    return array


def _bounds(steps: np.ndarray, lo: int, hi: int | None) -> tuple[int, int]:
    """Where steps lo..hi-1 begin and end in the sorted ``steps``."""
    first = 0 if lo <= 0 else int(np.searchsorted(steps, lo))
    return first, len(steps) if hi is None else int(np.searchsorted(steps, hi))


def _between(steps: np.ndarray, lo: int, hi: int | None) -> np.ndarray:
    """The part of the sorted ``steps`` in lo..hi-1."""
    first, last = _bounds(steps, lo, hi)
    return steps[first:last]


def _plain_number(value: float):
    return int(value) if float(value).is_integer() else float(value)
