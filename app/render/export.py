"""Lecture export: a scene's run drawn frame by frame, into GIF and PNG writers.

One renderer draws every exported frame. Its grid part is what the window's
grid view shows for the step: ``app.render.compose`` with the marks of
``app.render.frame`` (the step's cells, the decision's candidates, the
ideal primitive). Its text (a caption under the grid, a side panel with the
pseudo-code or the variables) is drawn with Pillow (``app.render.text``);
nothing here needs Qt.

The parts: ``settings`` (what is asked for, the steps, the timing),
``palette`` (themes and the one palette of an export), ``text``,
``writers`` (GIF, PNG folder, null), and this module, which draws the
frames and hands them to the writers.
"""
from __future__ import annotations

import io
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Callable, Sequence

import numpy as np
from PIL import Image

from algorithms.core import registry

from app.model.geometry import run_paths
from app.render.alt_text import AltText
from app.render.derivation import draw_distances
from app.render.octant_overlay import line_on_grid
from app.render.overlays import draw_shapes, overlay_colours, overlay_shapes
from app.render.frame import compose_frame, compose_region, frame_marks, primitive_mask
from app.render.axes import Axes
from app.render.reasoning import NONE, draw_guides, step_guides, vertex_labels
from app.render.palette import DARK, LIGHT, THEMES, ColourIndex, Theme, build_palette
from app.render.settings import (MAX_FPS, MAX_HOLD, MAX_SCALE, MAX_TEXT, MIN_FPS, MIN_TEXT,
                                 NAMES, ExportCancelled, ExportError, ExportSettings, auto_scale, chosen_frames,
                                 frame_durations, frame_range, frame_steps, record)
from app.render.text import TextParts, panel_width, text_pixels
from app.render.writers import (MANIFEST, FrameWriter, GifWriter, NullWriter, PngFolderWriter,
                                saving)

# Callers take every export name from here, whichever part defines it.
__all__ = ["DARK", "LIGHT", "THEMES", "ColourIndex", "Theme", "build_palette", "MAX_FPS",
           "MAX_HOLD", "MAX_SCALE", "MIN_FPS", "MAX_TEXT", "MIN_TEXT", "chosen_frames", "ExportCancelled", "ExportError", "ExportSettings",
           "auto_scale", "frame_durations", "frame_range", "frame_steps", "record",
           "FrameWriter", "GifWriter", "NullWriter", "PngFolderWriter", "FrameRenderer",
           "ExportResult", "export", "check_frames_size", "MAX_FRAMES_BYTES",
           "MANIFEST"]

MAX_SIDE = 4096    # pixels, each side of a frame
# The default limit of a frames folder on disk, as the GIF's above.
MAX_FRAMES_BYTES = 2 ** 30
BLOCK = 4096       # bytes a file takes on disk at least
SAMPLES = 9        # frames drawn to estimate the size of PNG frames
MARGIN = 1.25      # the estimate's allowance for frames larger than the samples


# ---------------------------------------------------------------- renderer
def _recorded(scene, settings: ExportSettings):
    return record(scene, memory_limit=settings.memory_limit, time_limit=settings.time_limit,
                  progress=settings.recording)


class FrameRenderer:
    """Draws the exported frames of a scene's run as palette-index arrays.

    ``trace`` is the scene's run when it is already recorded (the window's),
    else the scene is recorded here; ``differences`` are cells outlined as
    differing from a compared run. ``size`` is (width, height) in pixels:
    the grid (cells x scale), plus the side panel's width when there is a
    panel, plus the caption's height when there is a caption. Frames come
    out top row first.
    """

    def __init__(self, scene, settings: ExportSettings = ExportSettings(), trace=None,
                 differences: np.ndarray | None = None, incremental: bool = True):
        self.scene = scene
        self.spec = registry.get(scene.algorithm)
        self.trace = trace = _recorded(scene, settings) if trace is None else trace
        self.differences = differences
        self.y_down = scene.origin == "top-left"
        self.settings = settings = settings.for_grid(trace.width, trace.height)
        self.theme = THEMES[settings.theme]
        scale = settings.scale
        self.grid_size = (trace.width * scale, trace.height * scale)
        gw, gh = self.grid_size
        if gw > MAX_SIDE or gh > MAX_SIDE:
            raise ExportError(f"the grid would be {gw}x{gh} pixels at scale {scale}; a frame is "
                              f"at most {MAX_SIDE}x{MAX_SIDE}: choose a smaller scale")
        # The ideal primitive: drawn when asked, and always the target the
        # reasoning's guides point at (the drop from Bresenham's M).
        self.ideal = run_paths(self.spec, scene.points, self.spec.resolve(scene.options), trace)
        self.paths = self.ideal if settings.primitive else []
        text_size = settings.text_size or text_pixels(max(gw, gh))
        if settings.panel == "auto":
            fits = gw + panel_width(text_size) <= MAX_SIDE
            settings = self.settings = replace(settings, panel="code" if fits else "none")
        self.text_size = text_size
        self._text = TextParts(self, text_size)
        self.panel_width = self._text.panel_width if settings.panel != "none" else 0
        self.caption_height = self._text.caption_height if settings.caption else 0
        panel_height = self._text.panel_height if settings.panel != "none" else 0
        self.axes = Axes(self, self._text.sans, max(2, round(text_size / 4))) \
            if settings.axes else None
        self.grid_left = self.axes.left if self.axes else 0
        below = self.axes.bottom if self.axes else 0
        self.body_height = max(gh + below, panel_height)
        self.size = (self.grid_left + gw + self.panel_width,
                     self.body_height + self.caption_height)
        width, height = self.size
        if width > MAX_SIDE or height > MAX_SIDE:
            raise ExportError(f"a frame would be {width}x{height} pixels, more than "
                              f"{MAX_SIDE}x{MAX_SIDE}: choose a smaller scale or no side panel")
        self.colours = build_palette(self.theme, trace,
                                     overlay_colours(self.theme.palette.background,
                                                     self.theme.palette.ink)
                                     if settings.overlays else ())
        self._outside = self.colours.index_of(self.theme.palette.outside)
        self._guide = self.colours.index_of(self.theme.palette.guide)
        self._current = self.colours.index_of(self.theme.palette.current)
        self.grid_lines = settings.grid_lines and scale >= 4
        self._grid = _GridPart(self, incremental)
        self._states = _States(trace, incremental)
        self._text.allocate()
        self._axes = self.axes.draw() if self.axes else None
        self.vertex_labels = vertex_labels(self.spec, scene) if settings.vertex_labels else []
        self.alt_text = AltText(scene, trace, settings.numbers)   # what each frame shows, in words

    @property
    def text_parts(self) -> TextParts:
        """The caption and side panel's layout and painting (app/render/text.py)."""
        return self._text

    @property
    def palette_bytes(self) -> bytes:
        return self.colours.palette_bytes()

    def render(self, index: int) -> np.ndarray:
        """Frame ``index`` as a (height, width) uint8 array of palette indices."""
        settings = self.settings
        state, written = self._states.at(index)
        marks = frame_marks(state, self.paths, self.differences, settings.highlight,
                            settings.primitive)
        grid = self._grid.draw(state.raster, marks, written)
        guides = (step_guides(self.trace, state, self.ideal, self.y_down)
                  if settings.reasoning and settings.highlight else NONE)
        if guides:
            grid = grid.copy()  # the grid part keeps its own picture for the next frame
            draw_guides(grid, guides, settings.scale, self._guide, self._current)
        if settings.overlays:
            grid = self._overlaid(grid, index)
        if not self.y_down:
            grid = grid[::-1]  # row 0 is y = 0, the bottom of the picture
        width, height = self.size
        gw, gh = self.grid_size
        left = self.grid_left
        frame = np.empty((height, width), dtype=np.uint8)
        frame[:self.body_height, :left + gw] = self._outside
        frame[:gh, left:left + gw] = grid
        if settings.highlight:
            draw_distances(frame[:gh, left:left + gw], self, index)  # s and n, where the run has them
        if self._axes is not None:
            strip, under = self._axes
            frame[:strip.shape[0], :left] = strip
            frame[gh:gh + under.shape[0], left:left + gw] = under
        if self.panel_width:
            frame[:self.body_height, left + gw:] = self._text.panel(state)
        if self.caption_height:
            frame[self.body_height:, :] = self._text.caption(state)
        if guides.labels and settings.grid_text:
            self._text.grid_labels(frame, guides.labels, self._grid_point)
        if self.vertex_labels:
            self._text.grid_labels(frame, self.vertex_labels, self._grid_point,
                                   self.theme.palette.handle_edge)
        return frame

    def _grid_point(self, x: float, y: float) -> tuple[float, float]:
        """Grid units to the frame's pixels (left, top)."""
        scale = self.settings.scale
        return (self.grid_left + x * scale,
                y * scale if self.y_down else self.grid_size[1] - y * scale)

    def _overlaid(self, grid: np.ndarray, index: int) -> np.ndarray:
        """The grid with the step's geometric overlays drawn over it (a copy:
        the grid part keeps its own for the next frame)."""
        shapes = overlay_shapes(self.trace, index, self.settings.overlays,
                                line_on_grid(self.spec, self.scene.points))
        if not shapes:
            return grid
        halo = tuple(int(self.theme.palette.background[i:i + 2], 16) for i in (1, 3, 5))
        rgb = draw_shapes(self.colours.rgb[grid], shapes, self.settings.scale, self.y_down, halo)
        rgba = np.concatenate([rgb, np.full(rgb.shape[:2] + (1,), 255, np.uint8)], axis=2)
        return self.colours.indices(np.ascontiguousarray(rgba))

    def image(self, index: int) -> Image.Image:
        """Frame ``index`` as a Pillow palette image."""
        return self.to_image(self.render(index))

    def to_image(self, frame: np.ndarray) -> Image.Image:
        image = Image.fromarray(frame, "P")
        image.putpalette(self.palette_bytes)
        return image

    def rgb(self, index: int) -> np.ndarray:
        """Frame ``index`` as an (h, w, 3) uint8 RGB array (for tests and checks)."""
        return self.colours.rgb[self.render(index)]

    def cells(self, index: int) -> np.ndarray:
        """(H, W, 3) uint8 colours at the centres of the grid's cells in
        frame ``index``, row 0 at y = 0 (for tests and checks: grid lines,
        outlines and text never reach a centre)."""
        scale = self.settings.scale
        gw, gh = self.grid_size
        left = self.grid_left
        centres = self.rgb(index)[scale // 2:gh:scale, left + scale // 2:left + gw:scale]
        return centres if self.y_down else centres[::-1]


class _States:
    """The replayed state of each frame. Frames asked for in order are made
    from the one before by replaying one step into the same raster
    (``Trace.replay``); any other frame comes from ``Trace.raster_at``.
    ``at`` also returns the cells the step wrote, or None when the frame
    did not follow the one before."""

    def __init__(self, trace, incremental: bool = True):
        self.trace = trace
        self.incremental = incremental
        self.raster = None
        self.index: int | None = None

    def at(self, index: int):
        trace = self.trace
        if self.incremental and self.index is not None and index == self.index + 1:
            trace.replay(index, index + 1, self.raster)
            written = [tuple(cell) for cell in trace.written(index, index + 1).pixels.tolist()]
        else:
            self.raster, written = trace.raster_at(index), None
        self.index = index
        state = trace.state_on(index, self.raster)
        return state, written


class _GridPart:
    """The grid part of successive frames, as palette indices, row 0 at
    y = 0. From one frame to the next only the cells the step wrote and the
    cells whose highlight changed are composed again (``compose_region``);
    the result is the same as composing the whole grid (``compose_frame``),
    which is done for the first frame and for a frame that does not follow
    the one before."""

    def __init__(self, renderer: FrameRenderer, incremental: bool = True):
        self.r = renderer
        self.width, self.height = renderer.trace.width, renderer.trace.height
        settings = renderer.settings
        self.incremental = incremental
        self.primitive = primitive_mask(self.width, self.height, renderer.paths,
                                        renderer.theme.palette, settings.scale)
        self.indices: np.ndarray | None = None
        self.highlights: dict | None = None

    def draw(self, raster, marks, written=None) -> np.ndarray:
        """The grid of this frame; ``written`` lists the cells written since
        the frame drawn before, or is None when that is not known."""
        r = self.r
        palette, scale = r.theme.palette, r.settings.scale
        highlights = marks.cells()
        box = "all"
        if self.incremental and self.indices is not None and written is not None:
            box = self._changed(written, highlights)
        if box == "all":
            rgba = compose_frame(raster, marks, palette, scale, r.grid_lines)
            self.indices = r.colours.indices(rgba)
        elif box is not None:
            x0, y0, x1, y1 = box
            rgba = compose_region(raster, marks, box, palette, scale, r.grid_lines,
                                  self.primitive)
            self.indices[y0 * scale:y1 * scale, x0 * scale:x1 * scale] = r.colours.indices(rgba)
        self.highlights = highlights
        return self.indices

    def _changed(self, written, highlights):
        """The box (x0, y0, x1, y1) of cells that may look different from
        the frame before, None when none do, "all" when most might."""
        cells = list(written)
        for name, now in highlights.items():
            cells += now ^ self.highlights[name]
        cells = [(x, y) for x, y in cells if 0 <= x < self.width and 0 <= y < self.height]
        if not cells:
            return None
        xs, ys = [x for x, _ in cells], [y for _, y in cells]
        box = (min(xs), min(ys), max(xs) + 1, max(ys) + 1)
        if 2 * (box[2] - box[0]) * (box[3] - box[1]) > self.width * self.height:
            return "all"
        return box


# ------------------------------------------------------------------ export
@dataclass
class ExportResult:
    frames: int
    size: tuple[int, int]
    durations: list[int]
    gif: Path | None = None
    frames_dir: Path | None = None
    chosen: str = ""  # one line: what a frame stands for, the size and the panel


def export(scene, settings: ExportSettings = ExportSettings(), gif=None, frames_dir=None,
           progress: Callable[[int, int], None] | None = None,
           cancelled: Callable[[], bool] | None = None,
           names: tuple[str, str] = NAMES, trace=None,
           differences: np.ndarray | None = None,
           writers: Sequence[FrameWriter] = (),
           frames_limit: int = MAX_FRAMES_BYTES, replace: bool = False) -> ExportResult:
    """Export the scene's run as a GIF at ``gif``, as PNGs in ``frames_dir``,
    into further ``writers``, or any of them together (each frame is drawn
    once). ``trace`` and ``differences`` are as FrameRenderer takes them.

    ``progress(done, total)`` is called after each frame; when
    ``cancelled()`` turns true the export stops with ExportCancelled and
    leaves nothing behind. Bad settings, sizes and paths raise ExportError;
    ``names`` are what its messages call the range's ends. PNG frames
    estimated to take more than ``frames_limit`` bytes are refused before
    anything is written. ``replace``: frames the folder's manifest does not
    list (a user's own) may be replaced, else they are refused.
    """
    if gif is None and frames_dir is None and not writers:
        raise ExportError("nothing to write: give a GIF file, a folder for frames, or both")
    trace = _recorded(scene, settings) if trace is None else trace
    settings = settings.for_grid(trace.width, trace.height)
    steps, chosen = chosen_frames(scene, trace, settings, names)
    renderer = FrameRenderer(scene, settings, trace, differences)
    if frames_dir is not None:
        check_frames_size(renderer, steps, frames_limit)
    durations = frame_durations(len(steps), settings.fps, settings.hold)
    outputs = ([GifWriter(gif, durations, settings.loop)] if gif is not None else []) \
        + ([PngFolderWriter(frames_dir, replace)] if frames_dir is not None else []) + list(writers)
    try:
        with saving(outputs, renderer.size, len(steps), renderer.palette_bytes,
                    renderer.colours.transparent):
            for done, index in enumerate(steps, 1):
                if cancelled is not None and cancelled():
                    raise ExportCancelled("the export was cancelled")
                hand_over(outputs, renderer, index)
                if progress is not None:
                    progress(done, len(steps))
            if cancelled is not None and cancelled():
                raise ExportCancelled("the export was cancelled")
    except OSError as error:
        # The writers name their own target; this is for anything else.
        target = " and ".join(str(path) for path in (gif, frames_dir) if path is not None)
        raise ExportError(f"cannot write {target or 'the export'} "
                          f"({error.strerror or error})") from None
    chosen += (f"; {renderer.settings.scale} px per cell, text {renderer.text_size} px, "
               f"side panel: {renderer.settings.panel}")
    return ExportResult(len(steps), renderer.size, durations,
                        Path(gif) if gif is not None else None,
                        Path(frames_dir) if frames_dir is not None else None, chosen)


def hand_over(outputs, renderer: FrameRenderer, index: int) -> None:
    """Frame ``index`` to every writer: the picture, or the step itself to a
    writer that draws it (vector frames have ``grab_step``); the picture
    is drawn only when a writer takes it."""
    image = None
    for output in outputs:
        if hasattr(output, "grab_step"):
            output.grab_step(renderer, index)
            continue
        if image is None:
            image = renderer.image(index)
            image.info.update(renderer.alt_text.png_info(index))   # PNG frames keep it
        output.grab_frame(image)


def check_frames_size(renderer: FrameRenderer, steps, limit: int) -> None:
    """Refuse PNG frames whose estimated size on disk is over ``limit``.

    The estimate is the frame count times the largest of SAMPLES frames
    spread over the range, compressed as the writer compresses them,
    rounded up to whole disk blocks and given a MARGIN: frames between the
    samples can be larger (a 60,541-frame flood fill's first and last
    frames take 13 KB, frames between them up to 17 KB). A count that
    cannot fit even at one block a frame is refused without drawing.
    """
    count = len(steps)
    per_frame = BLOCK
    if count * BLOCK <= limit:
        largest = 0
        for k in sorted({round(i * (count - 1) / (SAMPLES - 1)) for i in range(SAMPLES)}):
            buffer = io.BytesIO()
            renderer.image(steps[k]).save(buffer, format="PNG", compress_level=3)
            largest = max(largest, buffer.tell())
        per_frame = -(-int(largest * MARGIN) // BLOCK) * BLOCK
    if count * per_frame > limit:
        width, height = renderer.size
        raise ExportError(f"the frames would take about {count * per_frame / 2 ** 20:,.0f} MiB "
                          f"on disk ({count:,} PNG frames of {width}x{height} pixels), more "
                          f"than the limit of {limit / 2 ** 20:,.0f} MiB: export a shorter "
                          "range or at a smaller scale")
