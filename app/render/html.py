"""The interactive page: one self-contained HTML file that replays a run in
any current browser, with no network, no install and nothing beside it.

The page holds the recorded trace, not pictures: per step its pseudo-code
line, pixel and values, and every write (step, cell, colour), as typed
arrays, delta-coded where neighbours are alike, split into byte planes,
compressed with zlib and written in base64; the rich records (variables, tables, notes, spans) as
JSON, compressed the same way. The browser inflates them with its own DecompressionStream and
replays the writes onto a canvas, as ``Trace.replay`` and
``app.render.compose`` do: the count of writes per cell picks background,
ink or overdraw, a written colour wins, darkened where written again. So a
100,000-step run stays small, and the page shows what the GIF shows.

The player itself (``player.html`` beside this module) is plain JavaScript
and CSS in one template; ``write_page`` puts the data into it as JSON that
cannot end or comment out its script element (``app.model.escape.script_json``);
the player sets every text of the scene (title, bookmark names) as text, never
as HTML.

Each step is also put in words (``step_words``): the caption under the grid
shows them and, being an ``aria-live`` region, a screen reader reads them
when a person moves to another step.

A run with animation frames plays at no more than
``flashes.playback_cap`` steps a second whatever speed is chosen (the
page's data carries the cap and the line saying so, shown beside the speed
list when the speed chosen is above it).
"""
from __future__ import annotations

import base64
import json
import math
import zlib
from dataclasses import asdict
from fractions import Fraction
from pathlib import Path

import numpy as np

from algorithms.core import registry
from algorithms.core.steps import NO_PIXEL, Note, Span, Table, Vars

from app.model.escape import script_json
from app.model.files import write_atomically
from app.model.geometry import scene_paths
from app.model.notation import fraction
from app.model.step_words import describe
from app.render.flashes import cap_note, playback_cap
from app.render.frame import colour_name
from app.render.palette import THEMES
from app.render.settings import ExportError, frame_range

TEMPLATE = Path(__file__).with_name("player.html")
DATA_MARK = "/*RASTERLAB-DATA*/null"
# Size budgets of a page, as the README states them: at most 2 MB for a run
# of up to 100,000 steps, 5 MB for a longer one.
SHORT_RUN, SHORT_BUDGET, LONG_BUDGET = 100_000, 2 * 2 ** 20, 5 * 2 ** 20
# Pages of up to this many steps carry each step's words; a longer one
# builds a short caption itself. Words take about 0.12 ms a step to make
# (2.4 s for 20,000) and a million steps in words would take about 5 MB,
# the whole budget of the page.
WORDED_STEPS = 20_000


def page_budget(steps: int) -> int:
    """The most bytes a page of a run of ``steps`` steps may take."""
    return SHORT_BUDGET if steps <= SHORT_RUN else LONG_BUDGET


def write_page(scene, trace, path, settings, force: bool = False) -> int:
    """Write the page for ``scene``'s run ``trace`` to ``path`` (atomically);
    its size in bytes. A page over its size budget is refused unless
    ``force``."""
    page = page_bytes(scene, trace, settings, force)
    write_atomically(Path(path), page, ExportError)
    return len(page)


def page_bytes(scene, trace, settings, force: bool = False) -> bytes:
    """The page for ``scene``'s run ``trace``, UTF-8 (see ``write_page``)."""
    data = page_data(scene, trace, settings)
    text = TEMPLATE.read_text(encoding="utf-8")
    page = text.replace(DATA_MARK, script_json(data), 1).encode("utf-8")
    budget = page_budget(len(trace))
    if not force and len(page) > budget:
        raise ExportError(f"the page would take {len(page) / 2 ** 20:.1f} MB for {len(trace):,} "
                          f"steps, over its budget of {budget / 2 ** 20:g} MB: export a shorter "
                          "run, or give --force")
    return page


def page_data(scene, trace, settings) -> dict:
    """Everything the page replays, as JSON-ready values (see the module text)."""
    spec = registry.get(scene.algorithm)
    steps = frame_range(scene, trace, settings.first, settings.last)
    first, last = steps.start, steps.stop - 1
    start = trace.start
    cap = playback_cap(spec, trace)
    return {
        "version": 1,
        "title": scene.title or spec.name,
        "algorithm": spec.name, "summary": spec.summary,
        "width": trace.width, "height": trace.height,
        "yDown": scene.origin == "top-left",
        "steps": len(trace), "first": first, "last": last,
        "fps": settings.fps, "theme": settings.theme, "loop": bool(settings.loop),
        # Play held to SAFE_FPS animation frames a second (None: not held).
        "playCap": cap, "playCapNote": None if cap is None else cap_note(cap),
        "code": [{"text": c.text, "kind": c.kind, "branch": c.branch,
                  "candidates": [list(o) for o in c.candidates]} for c in trace.code],
        "startCandidates": [list(o) for o in start.candidates],
        "decision": start.decision,
        "replaces": bool(getattr(start, "replaces", False)),
        "constants": {**{str(k): _json_value(v) for k, v in start.constants.items()},
                      **_implied(trace, settings.numbers)},
        "valueNames": list(trace.value_names),
        "exactValues": _exact_values(trace, settings.numbers),
        "arrays": _arrays(trace),
        "rich": _pack_json(_rich(trace, settings.numbers)),
        "paths": [[[list(map(float, p)) for p in points], bool(closed)]
                  for points, closed in scene_paths(spec, scene.points, spec.resolve(scene.options))],
        "bookmarks": [{"name": b["name"], "step": int(b["step"])} for b in scene.bookmarks],
        "themes": {name: _theme(theme) for name, theme in THEMES.items()},
        "words": (_pack_json(step_words(trace, first, last, settings.numbers))
                  if last - first < WORDED_STEPS else None),
    }


def step_words(trace, first: int, last: int, numbers: str = "decimal") -> list[str]:
    """Steps ``first`` .. ``last`` of ``trace`` in words, as the page's
    caption shows them and its live region reads them: "step 5 of 26: d =
    -4, at most 0, so E: plot (5, 2)" (app/model/step_words.py, the words of
    the window's announcements and of the transcripts)."""
    return [describe(trace, i, numbers) for i in range(first, last + 1)]


def _arrays(trace) -> dict:
    n = len(trace)
    lines = _column(trace, "line").astype(np.uint16)
    x = _column(trace, "x").astype(np.int32)
    y = _column(trace, "y").astype(np.int32)
    values = np.array(trace.values, dtype=np.float64).reshape(n, -1)
    writes = trace.written()
    width = trace.width
    px, py = writes.pixels[:, 0], writes.pixels[:, 1]
    inside = (px >= 0) & (px < width) & (py >= 0) & (py < trace.height)
    flat = np.where(inside, py * width + px, -1).astype(np.int64)
    colours = _write_colours(trace, writes)
    return {
        "noPixel": NO_PIXEL,
        "line": _pack(lines),
        "x": _pack(_delta(x)), "y": _pack(_delta(y)),
        "values": _pack(values.T.copy()),  # column after column: alike values side by side
        "writeStep": _pack(_delta(writes.steps.astype(np.int64)).astype(np.int32)),
        "writeCell": _pack(_delta(flat).astype(np.int32)),
        "writeColour": None if colours is None else _pack(colours.astype(np.int32)),
    }


def _column(trace, name: str) -> np.ndarray:
    # The trace's per-step columns (line, x, y) in step order.
    return np.asarray(getattr(trace, name))


def _write_colours(trace, writes) -> np.ndarray | None:
    """The packed colour each write sets (-1: none), as Trace.replay sets it."""
    name = colour_name(trace.start)
    if name is None:
        return None
    series = trace.series(name)
    colours = series[writes.steps].astype(np.float64)
    span_steps = trace.spans()["step"] if len(trace.spans()) else np.empty(0, np.int64)
    from_span = np.isin(writes.steps, span_steps)
    if from_span.any() and writes.values is not None:
        colours[from_span] = writes.values[from_span]
    return np.where(np.isnan(colours), -1, np.nan_to_num(colours)).astype(np.int64)


def _delta(values: np.ndarray) -> np.ndarray:
    out = values.astype(np.int64).copy()
    out[1:] = np.diff(values.astype(np.int64))
    return out


def _pack(array: np.ndarray) -> dict:
    kinds = {np.dtype(np.uint16): "u16", np.dtype(np.int32): "i32", np.dtype(np.float64): "f64"}
    array = np.ascontiguousarray(array)
    if array.dtype == np.int64:
        array = array.astype(np.int32)
    little = array.astype(array.dtype.newbyteorder("<"))
    # Byte planes: all first bytes, then all second bytes, ...: small deltas
    # leave whole planes of zeros, which deflate shrinks to almost nothing.
    planes = little.view(np.uint8).reshape(-1, array.itemsize).T.tobytes()
    return {"type": kinds[array.dtype], "length": int(array.size),
            "data": base64.b64encode(zlib.compress(planes, 9)).decode("ascii")}


def _pack_json(value) -> dict:
    """JSON, compressed: table snapshots repeat most of the one before."""
    text = json.dumps(value, separators=(",", ":"), allow_nan=False).encode("utf-8")
    return {"type": "json", "data": base64.b64encode(zlib.compress(text, 9)).decode("ascii")}


def _rich(trace, numbers: str = "decimal") -> list:
    """[step, kind, payload] for every Vars, Table, Note and Span record;
    table cells as ``numbers`` (decimal or exact) shows them."""
    out = []
    for index, record in trace.records_of(Vars, Table, Note, Span):
        if isinstance(record, Vars):
            out.append([index, "vars", {str(k): _json_value(v) for k, v in record.values.items()}])
        elif isinstance(record, Table):
            out.append([index, "table", {"name": record.name, "columns": list(record.columns),
                                         "rows": [[_cell(v, numbers) for v in row]
                                                  for row in record.rows]}])
        elif isinstance(record, Note):
            out.append([index, "note", record.text])
        else:
            out.append([index, "span", [record.x_start, record.x_end, record.y]])
    return out


def _implied(trace, numbers: str) -> dict:
    """With "exact": what the run implies without recording it (Bresenham's
    m), as p/q text, shown among the constants as the window shows it."""
    if numbers != "exact":
        return {}
    from app.model.steptable import implied
    return {name: fraction(value) for name, value in implied(trace).items()}


def _exact_values(trace, numbers: str) -> dict | None:
    """With "exact": {name: [p/q text, or None, per step]} for the run's
    values that have an exact form (barycentric weights at lattice points,
    app/model/exact.py), which the page shows in place of the floats."""
    from app.model.exact import EXACT_NAMES
    from app.model.steptable import StepTable
    names = [name for name in EXACT_NAMES if name in trace.value_names]
    if numbers != "exact" or not names:
        return None
    table = StepTable(trace, "exact")
    found = {name: [None] * len(trace) for name in names}
    for i in range(len(trace)):
        for name, value in table.exact_cells(i).items():
            if name in found:
                found[name][i] = fraction(value)
    return found


def _json_value(value):
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        value = float(value)
        return value if math.isfinite(value) else str(value)
    return _cell(value)


def _cell(value, numbers: str = "decimal") -> str:
    from app.model.tables import cell_text
    return cell_text(value, numbers) if not isinstance(value, Fraction) or value.denominator != 1 \
        else str(value.numerator)


def _theme(theme) -> dict:
    colours = asdict(theme.palette)
    for unused in ("coverage", "diff"):  # the page shows neither coverage counts nor a diff
        colours.pop(unused, None)
    return {**colours, "panel": theme.panel, "caption": theme.caption, "border": theme.border,
            "text": theme.text, "muted": theme.muted, "lineNumber": theme.line_number,
            "currentLine": theme.current_line, "currentEdge": theme.current_edge}
