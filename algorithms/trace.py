"""Record a step generator once; give random access to every step.

Frames are stored as columns (pseudo-code line, x, y and one float64
column per named value), about 10 + 8k bytes a step for k values, instead
of one Python object per step. ``state_at(i)`` copies the nearest keyframe
before i and replays the frames in between with numpy, so scrubbing and
stepping backward never replay from step 0 on long traces.
"""
from __future__ import annotations

import bisect
import math
import threading
from dataclasses import dataclass
from itertools import groupby, islice
from typing import Iterable, Sequence

import numpy as np

from .errors import InputError
from .raster import Raster
from .steps import NO_PIXEL, PLOT, RICH_RECORDS, CodeLine, Span, Start, Step, Vars

DEFAULT_STEP_CAP = 5_000_000
CHUNK = 1 << 16
KEYFRAME_BUDGET = 64 * 2 ** 20  # bytes all keyframes of one trace may take
KEYFRAME_BYTES_PER_STEP = 16  # and no more than this per recorded step
MIN_KEYFRAME_GAP = 1024


class TraceError(ValueError):
    """A generator broke the frame protocol of steps.py."""


class Cancelled(Exception):
    """A recording was stopped through its monitor before the run ended."""


class RecordMonitor:
    """Progress and cancellation of one recording, safe to share between threads.

    ``Trace.record`` calls ``report(steps)`` about every ``every`` steps (at
    the end of a bulk chunk, so the check costs nothing per frame);
    ``report`` raises ``Cancelled`` once ``cancel()`` has been called, from
    any thread, and otherwise passes the count to ``progress``.
    """

    def __init__(self, progress=None, every: int = CHUNK):
        self.progress = progress
        self.every = max(1, int(every))
        self._cancelled = threading.Event()

    def cancel(self) -> None:
        self._cancelled.set()

    @property
    def cancelled(self) -> bool:
        return self._cancelled.is_set()

    def report(self, steps: int) -> None:
        if self._cancelled.is_set():
            raise Cancelled(f"recording cancelled after {steps:,} steps")
        if self.progress is not None:
            self.progress(steps)


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
        self.records: dict[int, object] = {}
        self.truncated = False
        self.message = ""
        self._vars_at: list[int] = []
        self._spans: list[int] = []  # indices of Span records on PLOT lines
        self._chunks: list[np.ndarray] = []
        self._keyframes: list[Raster] | None = None
        self._gap = 0
        self._flat: np.ndarray | None = None
        self._monitor: RecordMonitor | None = None
        self._next_report = math.inf
        self._chunk = CHUNK
        kinds = np.array([line.kind == PLOT for line in self.code], dtype=bool)
        self._line_plots = kinds

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
        # Bulk chunks no longer than the report interval, so reports keep time.
        trace._chunk = CHUNK if monitor is None else min(CHUNK, monitor.every)
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
        self._dtype = np.dtype([("line", "u2"), ("x", "i4"), ("y", "i4")]
                               + [(f"v{k}", "f8") for k in range(len(start.values))])
        self._chunks.append(self._rich_row(start))
        self._count = 1
        self._store_rich(0, start)
        capped = islice(frames, self.step_cap - 1)
        # Lean tuples go to numpy in bulk; groupby(type) sets the rare rich
        # records aside without a Python-level test per frame.
        for kind, group in groupby(capped, type):
            if kind is tuple:
                self._record_lean(group)
            else:
                for record in group:
                    self._record_rich(record)
            if self._count >= self._next_report:
                self._report()
        if self._count >= self.step_cap and next(frames, None) is not None:
            self.truncated = True
            self.message = (f"Recording stopped at the step cap of {self.step_cap:,} steps; "
                            "the run goes on beyond it. Raise the cap or use a smaller input.")
        self._finish()

    def _record_lean(self, group) -> None:
        while True:
            first = self._count
            try:
                rows = np.fromiter(islice(group, self._chunk), self._dtype)
            except InputError:
                raise  # the generator refused its input: not a protocol fault
            except (ValueError, TypeError, OverflowError) as error:
                raise TraceError(f"near step {first}: a frame is not (line, x, y"
                                 f"{', value' * len(self.start.values)}): {error}") from None
            if not len(rows):
                return
            self._check_rows(rows, first)
            self._chunks.append(rows)
            self._count += len(rows)
            if self._count >= self._next_report:
                self._report()

    def _record_rich(self, record) -> None:
        index = self._count
        if not isinstance(record, RICH_RECORDS) or isinstance(record, Start):
            raise TraceError(f"step {index}: {record!r} is not a frame steps.py allows here")
        row = self._rich_row(record)
        self._check_rows(row, index)
        self._store_rich(index, record)
        self._chunks.append(row)
        self._count += 1

    def _rich_row(self, record) -> np.ndarray:
        row = np.zeros(1, self._dtype)
        pixel = getattr(record, "pixel", None) or (NO_PIXEL, NO_PIXEL)
        row["line"], row["x"], row["y"] = record.line, pixel[0], pixel[1]
        for name in self._dtype.names[3:]:
            row[name] = math.nan
        return row

    def _check_rows(self, rows: np.ndarray, first_index: int) -> None:
        bad = rows["line"] >= len(self.code)
        if bad.any():
            index = first_index + int(np.argmax(bad))
            raise TraceError(f"step {index}: pseudo-code line {rows['line'][index - first_index]} "
                             f"does not exist")

    def _store_rich(self, index: int, record) -> None:
        self.records[index] = record
        if isinstance(record, Vars):
            self._vars_at.append(index)
        elif isinstance(record, Span) and self.code[record.line].kind == PLOT:
            self._spans.append(index)

    def _finish(self) -> None:
        # Chunk by chunk into the columns rather than one concatenate: each
        # copy is short, so a recording in a worker thread hands the
        # interpreter lock back often (and one copy of the frames is saved).
        count = sum(len(chunk) for chunk in self._chunks)
        names = self._dtype.names[3:]
        self.line = np.empty(count, "u2")
        self.x = np.empty(count, "i4")
        self.y = np.empty(count, "i4")
        self.values = np.empty((count, len(names)))
        at = 0
        for block in _blocks(self._chunks):
            end = at + len(block)
            self.line[at:end], self.x[at:end], self.y[at:end] = \
                block["line"], block["x"], block["y"]
            for column, name in enumerate(names):
                self.values[at:end, column] = block[name]
            at = end
        self._chunks = []

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
        """Bytes held by the replay caches: keyframes and the pixel index."""
        keyframes = sum(raster.bytes() for raster in self._keyframes or () if raster)
        return keyframes + (0 if self._flat is None else self._flat.nbytes)

    def series(self, name: str) -> np.ndarray:
        """One named value over all steps; NaN where a step lacks it."""
        return self.values[:, self.value_names.index(name)]

    def writes(self) -> np.ndarray:
        """Per step: does it write a single pixel? (Span steps are not counted.)"""
        mask = self._line_plots[self.line] & (self.x != NO_PIXEL)
        # Rich records never write a single pixel (a Span writes its run).
        mask[list(self.records)] = False
        return mask

    def written_pixels(self) -> np.ndarray:
        """(n, 2) array of the written pixels, in emission order, duplicates kept."""
        mask = self.writes()
        order = np.flatnonzero(mask)
        pixels = np.stack([self.x[mask], self.y[mask]], axis=1).astype(np.int64)
        if not self._spans:
            return pixels
        span_order, span_pixels, _ = self._span_pixels(0, len(self))
        order = np.concatenate([order, span_order])
        pixels = np.concatenate([pixels, span_pixels])
        return pixels[np.argsort(order, kind="stable")]

    def _span_pixels(self, lo: int, hi: int):
        """Step indices, pixels and values of the spans recorded in steps lo..hi-1.

        A span without a value gives NaN values.
        """
        chosen = self._spans[bisect.bisect_left(self._spans, lo):bisect.bisect_left(self._spans, hi)]
        orders, pixels = [np.zeros(0, np.int64)], [np.zeros((0, 2), np.int64)]
        values = [np.zeros(0)]
        for index in chosen:
            span = self.records[index]
            xs = np.arange(span.x_start, span.x_end, dtype=np.int64)
            orders.append(np.full(len(xs), index, np.int64))
            pixels.append(np.stack([xs, np.full(len(xs), span.y, np.int64)], axis=1))
            values.append(np.full(len(xs), math.nan if span.value is None else float(span.value)))
        return np.concatenate(orders), np.concatenate(pixels), np.concatenate(values)

    def pixel_values(self) -> np.ndarray | None:
        """The value written with each written pixel (spans included), in emission order."""
        if self.start.pixel_value is None:
            return None
        mask = self.writes()
        values = self.series(self.start.pixel_value)[mask]
        if not self._spans:
            return values
        span_order, _, span_values = self._span_pixels(0, len(self))
        order = np.concatenate([np.flatnonzero(mask), span_order])
        values = np.concatenate([values, span_values])
        return values[np.argsort(order, kind="stable")]

    def step(self, i: int) -> Step:
        i = self._index(i)
        line = int(self.line[i])
        code = self.code[line]
        x, y = int(self.x[i]), int(self.y[i])
        pixel = None if x == NO_PIXEL else (x, y)
        values = {name: float(v) for name, v in zip(self.value_names, self.values[i])
                  if not math.isnan(v)}
        return Step(i, line, code.kind, pixel, values, code.branch, self.records.get(i))

    def variables_at(self, i: int) -> dict:
        """Constants, every Vars update up to step i, and step i's own values."""
        i = self._index(i)
        result = dict(self.start.constants)
        for index in self._vars_at[:bisect.bisect_right(self._vars_at, i)]:
            result.update(self.records[index].values)
        result.update(self.step(i).values)
        branch = self.code[int(self.line[i])].branch
        if branch:
            result["choice"] = branch
        return result

    def final_variables(self) -> dict:
        """The named variables at the end of the run: for each name, the
        value set last, whether by a Vars record or by a frame's value."""
        updates = [(index, name, value) for index in self._vars_at
                   for name, value in self.records[index].values.items()]
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
        return [(px + dx, py + dy) for dx, dy in offsets]

    def state_at(self, i: int) -> FrameState:
        i = self._index(i)
        raster = self.raster_at(i)
        return FrameState(i, self.step(i), raster, self.variables_at(i), self.candidates_at(i))

    def raster_at(self, i: int) -> Raster:
        """The framebuffer after step i: nearest keyframe plus a numpy replay."""
        i = self._index(i)
        keyframes = self._ensure_keyframes()
        slot = min((i + 1) // self._gap, len(keyframes) - 1)
        raster = keyframes[slot].copy() if slot else self._empty_raster()
        self._apply(raster, slot * self._gap, i + 1)
        return raster

    def replay_slowly(self, i: int) -> Raster:
        """Step-by-step replay from step 0, one pixel at a time (for checks)."""
        raster = self._empty_raster()
        column = self._value_column()
        depth_column = self._depth_column()
        for k in range(self._index(i) + 1):
            step = self.step(k)
            if isinstance(step.record, Span):
                for x in range(step.record.x_start, step.record.x_end):
                    if step.kind == PLOT:
                        raster.write(x, step.record.y, step.record.value)
            elif step.writes:
                value = None if column is None else self.values[k, column]
                depth = None if depth_column is None else self.values[k, depth_column]
                raster.write(*step.pixel, value, depth)
        return raster

    # ---------------------------------------------------------- internals
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

    def _apply(self, raster: Raster, lo: int, hi: int) -> None:
        """Apply steps lo..hi-1 to the raster, vectorised."""
        if hi <= lo:
            return
        column = self._value_column()
        values = None if column is None else self.values[lo:hi, column]
        depth_column = self._depth_column()
        depths = None if depth_column is None else self.values[lo:hi, depth_column]
        flat = self._flat_pixels()[lo:hi]
        orders, pixels, span_values = self._span_pixels(lo, hi) if self._spans else ((),) * 3
        if len(orders):
            x, y = pixels[:, 0], pixels[:, 1]
            inside = (x >= 0) & (x < self.width) & (y >= 0) & (y < self.height)
            # Spans and single pixels merged in step order, so that the last
            # write to a pixel sets its colour.
            order = np.argsort(np.concatenate([np.arange(lo, hi), orders]), kind="stable")
            flat = np.concatenate([flat, np.where(inside, y * self.width + x, -1)])[order]
            if values is not None:
                values = np.concatenate([values, span_values])[order]
            if depths is not None:  # spans carry no depth
                depths = np.concatenate([depths, np.full(len(orders), math.nan)])[order]
        raster.write_many(flat, values, depths)

    def _flat_pixels(self) -> np.ndarray:
        """Per step, y * W + x of the pixel it writes, or -1 (no write, or clipped)."""
        if self._flat is None:
            x, y = self.x.astype(np.int64), self.y.astype(np.int64)
            inside = self.writes() & (x >= 0) & (x < self.width) & (y >= 0) & (y < self.height)
            self._flat = np.where(inside, y * self.width + x, -1).astype(np.int32)
        return self._flat

    def _ensure_keyframes(self) -> list[Raster]:
        if self._keyframes is not None:
            return self._keyframes
        empty = self._empty_raster()
        budget = min(KEYFRAME_BUDGET, KEYFRAME_BYTES_PER_STEP * len(self))
        most = max(1, budget // max(1, empty.bytes()))
        self._gap = max(MIN_KEYFRAME_GAP, math.ceil(len(self) / most))
        # Slot 0 is the empty raster, made afresh when needed (np.zeros is
        # cheaper than a copy and holds no memory until written).
        keyframes = [None]
        for lo in range(0, len(self) - self._gap, self._gap):
            raster = keyframes[-1].copy() if keyframes[-1] else self._empty_raster()
            self._apply(raster, lo, lo + self._gap)
            keyframes.append(raster)
        self._keyframes = keyframes
        return keyframes


def _blocks(chunks):
    """The chunks joined into blocks of about CHUNK rows: one-row chunks
    (rich records) are not copied one by one, long ones are not joined."""
    batch, rows = [], 0
    for chunk in chunks:
        batch.append(chunk)
        rows += len(chunk)
        if rows >= CHUNK:
            yield batch[0] if len(batch) == 1 else np.concatenate(batch)
            batch, rows = [], 0
    if batch:
        yield batch[0] if len(batch) == 1 else np.concatenate(batch)


def _plain_number(value: float):
    return int(value) if float(value).is_integer() else float(value)
