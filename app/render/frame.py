"""What one frame of a run shows, worked out once for the window and for export.

The window's grid view and the exporter must agree on what a step looks
like: which cells are outlined as the step's own, which as the decision's
candidates, where the ideal primitive runs and what the caption says. This
module holds that logic. It needs no Qt: it works on the replayed
``FrameState`` and on ``app.render``.

``compose_frame`` draws a frame as ``app.render.compose`` does. An
``Overlay`` there holds one current cell and one path; a span (a whole run
of a row written at once) has many current cells, and k triangles have k
paths, so the rest are drawn by render's own outline and path helpers on
the same image, which keeps the look identical. ``compose_region`` draws
a part of the same frame, for an exporter that redraws only the cells that
changed since the frame before.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Callable, Sequence

import numpy as np

from algorithms.core import registry
from algorithms.core.steps import PLOT, VISIT, Span, Vars

from app.model.geometry import final_coverage
from app.model.exact import exact_values
from app.model.notation import colour, colour_names, number
from app.render import compose as render
from app.render.compose import PALETTE, Overlay, Palette, compose


# ------------------------------------------------------------ highlights
def current_cells(state) -> list:
    """The cells the step works on: its pixel, or every pixel of a span."""
    record = state.step.record
    if isinstance(record, Span):
        return [(x, record.y) for x in range(record.x_start, record.x_end)]
    return [] if state.pixel is None else [state.pixel]


def step_cells(state) -> tuple[list, list]:
    """The cells the step works on, and the runs (x_start, x_end, y) of a
    span step, which the grid outlines as one box each."""
    record = state.step.record
    if isinstance(record, Span):
        return [], [(record.x_start, record.x_end, record.y)]
    return current_cells(state), []


@dataclass(frozen=True)
class FrameMarks:
    """Everything drawn over the pixels of one frame.

    ``current`` and ``candidates`` are cells (x, y); ``spans`` runs
    (x_start, x_end, y) outlined as one box each; ``differences`` an (n, 2)
    array of cells; ``paths`` the ideal primitive as [(points, closed), ...]
    in grid units.
    """

    current: Sequence[tuple[int, int]] = ()
    candidates: Sequence[tuple[int, int]] = ()
    differences: np.ndarray | None = None
    paths: Sequence = field(default_factory=list)
    spans: Sequence[tuple[int, int, int]] = ()

    def moved(self, dx: int, dy: int, box=None) -> "FrameMarks":
        """The marks shifted by (-dx, -dy) cells, without the paths; with
        ``box`` (x0, y0, x1, y1) only the cells inside it are kept, and the
        spans that reach into it (whole)."""
        def keep(cells):
            cells = [(int(x), int(y)) for x, y in cells]
            if box is not None:
                x0, y0, x1, y1 = box
                cells = [(x, y) for x, y in cells if x0 <= x < x1 and y0 <= y < y1]
            return [(x - dx, y - dy) for x, y in cells]

        spans = [(int(a), int(b), int(y)) for a, b, y in self.spans]
        if box is not None:
            x0, y0, x1, y1 = box
            spans = [(a, b, y) for a, b, y in spans if y0 <= y < y1 and a < x1 and b > x0]
        differences = None
        if self.differences is not None and len(self.differences):
            differences = np.array(keep(self.differences), dtype=np.int64).reshape(-1, 2)
        return FrameMarks(keep(self.current), keep(self.candidates), differences, [],
                          [(a - dx, b - dx, y - dy) for a, b, y in spans])

    def cells(self) -> dict[str, set]:
        """The cells of each kind of highlight, as sets."""
        differences = () if self.differences is None else self.differences
        return {"current": {(int(x), int(y)) for x, y in self.current},
                "candidate": {(int(x), int(y)) for x, y in self.candidates},
                "difference": {(int(x), int(y)) for x, y in differences},
                "span": {(x, int(y)) for a, b, y in self.spans for x in range(int(a), int(b))}}

    def outline_overlays(self) -> list[Overlay]:
        """The highlights as render Overlays: the first carries the
        candidates, the differences, the spans and the first current cell;
        each further one a further current cell."""
        current = list(self.current)
        first = Overlay(current=current[0] if current else None,
                        candidates=list(self.candidates), differences=self.differences)
        if self.spans:
            first = replace(first, spans=list(self.spans))
        return [first] + [Overlay(current=cell) for cell in current[1:]]

    def path_overlays(self) -> list[Overlay]:
        """The ideal primitive as render Overlays, one per path."""
        return [Overlay(primitive=list(points), closed=bool(closed))
                for points, closed in self.paths]


def frame_marks(state, paths=(), differences=None, highlight: bool = True,
                primitive: bool = True) -> FrameMarks:
    """The marks the grid view draws for ``state``: the step's cells or
    span and the decision's candidates (``highlight``), the cells that
    differ from a compared run, and the ideal primitive (``primitive``)."""
    cells, spans = step_cells(state) if highlight else ((), ())
    return FrameMarks(
        current=cells,
        candidates=[tuple(c) for c in state.candidates] if highlight else (),
        differences=differences if highlight else None,
        paths=list(paths) if primitive else [],
        spans=spans)


def compose_frame(raster, marks: FrameMarks | None, palette: Palette = PALETTE,
                  scale: int = 1, grid_lines: bool | None = None) -> np.ndarray:
    """``render.compose`` with every mark of ``marks``: a uint8 RGBA image of
    shape (H * scale, W * scale, 4), row 0 at y = 0.

    In compose's order: cells, grid lines, the ideal primitive, then the
    outlines (below scale 3: tinted cells, and no primitive).
    """
    if marks is None:
        return compose(raster, None, palette, scale, grid_lines)
    outlines = marks.outline_overlays()
    if scale < 3:
        image = compose(raster, outlines[0], palette, scale, grid_lines)
        packed = image.view(render._RGBA).reshape(image.shape[:2])
        for layer in outlines[1:]:
            _tint_cells(packed, layer, palette, scale)
        return image
    paths = marks.path_overlays()
    image = compose(raster, paths[0] if paths else None, palette, scale, grid_lines)
    packed = image.view(render._RGBA).reshape(image.shape[:2])
    for layer in paths[1:]:
        render.draw_primitive(packed, layer, palette, scale)
    for layer in outlines:
        render.draw_outlines(packed, layer, palette, scale)
    return image


class _Window:
    """Part of a raster, cells [x0, x1) x [y0, y1), as compose reads it."""

    def __init__(self, raster, x0, y0, x1, y1):
        self.counts = raster.counts[y0:y1, x0:x1]
        self.colors = None if raster.colors is None else raster.colors[y0:y1, x0:x1]


def primitive_mask(width: int, height: int, paths, palette: Palette = PALETTE,
                   scale: int = 1) -> np.ndarray | None:
    """Where ``compose_frame`` draws the ideal primitive: a bool array of
    the image's shape, or None when it draws none (no paths, or scale < 3)."""
    if scale < 3 or not paths:
        return None
    from algorithms.core.raster import Raster
    empty = Raster(width, height)
    plain = compose_frame(empty, None, palette, scale, False)
    drawn = compose_frame(empty, FrameMarks(paths=list(paths)), palette, scale, False)
    return (plain != drawn).any(axis=2)


def compose_region(raster, marks: FrameMarks | None, box, palette: Palette = PALETTE,
                   scale: int = 1, grid_lines: bool | None = None,
                   primitive: np.ndarray | None = None) -> np.ndarray:
    """The pixels ``compose_frame`` draws for the cells in ``box`` =
    (x0, y0, x1, y1), exactly, without composing the rest of the grid.

    ``primitive`` is ``primitive_mask`` for the marks' paths (the paths of
    ``marks`` are ignored here: the primitive is the same in every frame).
    Every mark lies inside its cell, and so does everything compose draws
    for a cell except a grid line, which compose draws along the first
    row and column of every cell but the grid's first; the region is
    therefore composed with one cell more before it, and that cell cut off.
    """
    x0, y0, x1, y1 = box
    mx, my = int(x0 > 0), int(y0 > 0)
    ox, oy, ex = x0 - mx, y0 - my, x1
    if marks is not None:
        # A span's box is drawn around the whole run: compose the whole run
        # of any span reaching into the region, then cut the region out.
        width = raster.counts.shape[1]
        for start, end, y in marks.spans:
            if y0 <= y < y1 and start < x1 and end > x0:
                ox, ex = min(ox, max(0, start)), max(ex, min(width, end))
    window = _Window(raster, ox, oy, ex, y1)
    moved = marks.moved(ox, oy, (ox, oy, ex, y1)) if marks is not None else None
    if scale < 3:
        image = compose_frame(window, moved, palette, scale, grid_lines)
    else:
        image = compose(window, None, palette, scale, grid_lines)
        packed = image.view(render._RGBA).reshape(image.shape[:2])
        if primitive is not None:
            inside = primitive[oy * scale:y1 * scale, ox * scale:ex * scale]
            packed[inside] = render.packed_rgba(palette.primitive)
        if moved is not None:
            for layer in moved.outline_overlays():
                render.draw_outlines(packed, layer, palette, scale)
    left = (x0 - ox) * scale
    return image[my * scale:, left:left + (x1 - x0) * scale]


def _tint_cells(packed, layer, palette, scale) -> None:
    # Below scale 3 compose tints highlighted cells instead of outlining
    # them. A further layer tints its cells the same way, one scale x scale
    # block at a time; a block's last pixel is never on a grid line, and
    # grid-line pixels keep their colour.
    height, width = packed.shape[0] // scale, packed.shape[1] // scale
    for name, cells in render.overlay_layers(layer):
        color = getattr(palette, name)
        for x, y in cells:
            if 0 <= x < width and 0 <= y < height:
                block = packed[y * scale:(y + 1) * scale, x * scale:(x + 1) * scale]
                cell = block[-1, -1]
                block[block == cell] = render.mix(cell, color, render.TINT[name])


# ------------------------------------------------------------ caption
def step_caption(state, last: int, bold: Callable[[str], str] = lambda text: text) -> str:
    """One line saying what the step does: "Step 12 of 40 · plots (5, 3) ·
    branch NE". ``bold`` marks up the parts the window sets in bold."""
    step = state.step
    parts = [f"{bold(f'Step {state.index:,}')} of {last:,}"]
    if isinstance(step.record, Span) and step.pixel is not None:
        verb = "fills" if step.kind == PLOT else "scans"
        parts.append(f"{verb} row {step.record.y}, x {step.record.x_start}\u2013{step.record.x_end - 1}")
    elif step.pixel is not None and step.kind == PLOT:
        parts.append(f"plots ({step.pixel[0]}, {step.pixel[1]})")
    elif step.pixel is not None and step.kind == VISIT:
        parts.append(f"visits ({step.pixel[0]}, {step.pixel[1]})")
    elif state.index == 0:
        parts.append("set-up")
    else:
        parts.append("updates variables")
    if step.branch:
        parts.append(f"branch {bold(step.branch)}")
    return " \u00b7 ".join(parts)


def html_caption(state, last: int) -> str:
    """The caption as the window's rich-text label shows it."""
    return step_caption(state, last, bold=lambda text: f"<b>{text}</b>")


def key_values(trace, state, numbers: str = "decimal") -> list[tuple[str, str]]:
    """The values that change from step to step (the decision variable d_i,
    say), as (name, text), decision variable first. Constants of the run
    (dx, incrE, ...) are left to the variables panel. ``numbers`` "exact":
    a value with an exact form (app/model/exact.py) reads as p/q."""
    start = trace.start
    names = list(trace.value_names)
    record = state.step.record
    if isinstance(record, Vars):  # values a run keeps as Vars (the scan line's y)
        names += [name for name in record.values if name not in names]
    decision = getattr(start, "decision", None)
    if decision in names:
        names.remove(decision)
        names.insert(0, decision)
    colours = colour_names(start)
    exact = exact_values(trace, state.index, state.variables) if numbers == "exact" else {}
    rows = []
    for name in names:
        if name not in state.variables:
            continue
        value = exact.get(name, state.variables[name])
        packed = colour(value) if name in colours and isinstance(value, (int, float)) else None
        rows.append((name, packed or number(value, numbers=numbers)))
    return rows


# ------------------------------------------------------------ values
def colour_name(start) -> str | None:
    """The value holding a run's packed 0xRRGGBB colours: ``color_value``,
    else ``pixel_value``. (An antialiasing run's pixel value is a coverage
    in 0..1, a number, never a colour.)"""
    return getattr(start, "color_value", None) or getattr(start, "pixel_value", None)


def written_colours(trace) -> np.ndarray | None:
    """The packed colour written with each written pixel, in emission order."""
    name = colour_name(trace.start)
    if name is None:
        return None
    if name == trace.start.pixel_value:
        return trace.pixel_values()
    return trace.series(name)[trace.writes()]


# ------------------------------------------------------------ samples
@dataclass(frozen=True)
class PixelSamples:
    """The samples tested so far in the current step's pixel: positions
    ``xs``, ``ys`` in grid units, ``hits`` (bool), and ``current`` the
    index among them of the step's own sample (-1: the step is no sample)."""

    pixel: tuple[int, int]
    xs: np.ndarray
    ys: np.ndarray
    hits: np.ndarray
    current: int = -1


def pixel_samples(trace, index: int, limit: int = 4096) -> PixelSamples | None:
    """The samples of the pixel of step ``index`` (a run whose frames name
    values ``sx``, ``sy``), found by scanning back from the step while the
    pixel stays the same; None when the step tests no sample and follows none."""
    if trace is None:
        return None
    names = trace.value_names
    if "sx" not in names or "sy" not in names:
        return None
    step = trace.step(index)
    if step.pixel is None or step.record is not None:
        return None
    cx, cy = step.pixel
    sx = trace.values[:, names.index("sx")]
    sy = trace.values[:, names.index("sy")]
    hit = trace.values[:, names.index("hit")] if "hit" in names else None
    first = index
    while first > 0 and index - first < limit and int(trace.x[first - 1]) == cx \
            and int(trace.y[first - 1]) == cy:
        first -= 1
    rows = np.arange(first, index + 1)
    rows = rows[np.isfinite(sx[rows]) & np.isfinite(sy[rows])]
    if not len(rows):
        return None
    hits = np.ones(len(rows), bool) if hit is None else hit[rows] > 0
    current = len(rows) - 1 if rows[-1] == index else -1
    return PixelSamples((cx, cy), sx[rows].copy(), sy[rows].copy(), hits, current)


def run_coverage(trace) -> np.ndarray | None:
    """(H, W) coverage a run ends with (its ``pixel_value`` written last to
    each pixel, 0 elsewhere), or None for a run that writes no values."""
    if trace is None or trace.start.pixel_value is None:
        return None
    values = trace.pixel_values()
    return final_coverage(trace.width, trace.height, trace.written_pixels(), values)
