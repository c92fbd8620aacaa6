"""Lecture export: a run as an animated GIF and as numbered PNG frames.

One renderer draws every exported frame. Its grid part is what the window's
grid view shows for the step: ``app.render.compose`` with the marks of
``app.frame_view`` (the step's cells, the decision's candidates, the ideal
primitive). Text (a caption under the grid, a side panel with the
pseudo-code or the variables) is drawn with QPainter on a QImage, which
works without a display: the offscreen platform is chosen when there is
none.

Palette
-------
A GIF frame holds at most 256 colours. Every frame of an export uses one
palette, fixed before the first frame is drawn, so no colour shifts from
frame to frame: the theme's colours, a few shades between each text colour
and the background it sits on (for antialiased text), and, for runs that
write colours, those colours (reduced by median cut if there are too many).
Each drawn pixel is looked up in that palette; a colour it lacks (the edge
of a glyph, say) takes the nearest entry, without dithering. The PNG frames
use the same palette.

Timing
------
GIF stores frame durations in hundredths of a second. Frame k is shown
from round(k * 100 / fps) to round((k + 1) * 100 / fps) hundredths, so
every frame lasts 1000 / fps ms to within 10 ms and the whole animation
keeps time: at 30 fps frames last 30, 40, 30, 30, 40, ... ms. The last
frame is held ``hold`` seconds longer. Frames per second go up to 50:
viewers slow down frames shorter than 20 ms. Pillow writes the file and
joins a frame identical to the one before it into that frame, adding the
durations (so a range where nothing visible changes takes fewer frames, and
the same time); with the caption on, every frame differs from the one
before it, because the step number does.

Safety
------
The GIF is written to a temporary file beside the target and renamed over
it at the end; PNG frames are written into a temporary folder inside the
target folder and moved into place at the end. A failed or cancelled export
leaves neither a partial GIF nor a partial set of frames.
"""
from __future__ import annotations

import math
import os
import re
import shutil
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable, Iterable

import numpy as np
from PIL import Image
from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import (QColor, QFont, QFontDatabase, QFontMetrics, QGuiApplication, QImage,
                           QPainter)

from algorithms import registry
from algorithms.antialias import animation_frame_steps
from algorithms.registry import InputError
from algorithms.trace import DEFAULT_STEP_CAP, FrameState

from app.render import frame as frame_view
from app.render.frame import (compose_frame, compose_region, frame_marks, key_values,
                              primitive_mask, scene_paths, step_caption)
from app.render.compose import DARK_PALETTE, PALETTE, Palette
from app.model.scene import one_line

MIN_FPS = 0.1
MAX_FPS = 50.0
MAX_SCALE = 64
MAX_HOLD = 600.0   # seconds; GIF's longest frame is 655.35 s
MAX_SIDE = 4096    # pixels, each side of a frame
AUTO_EXTENT = 640  # pixels the grid's longer side takes at the automatic scale
# Pillow holds every frame of a GIF in memory until it writes the file.
MAX_GIF_PIXELS = 2 ** 30
PANELS = ("code", "variables", "both", "none")
# One exported frame per step, or per animation frame of a run that has
# them (aa-temporal); auto picks animation frames where there are some.
PER = ("auto", "step", "animation")
FRAME_NAME = "frame_{:0{width}d}.png"
_FRAME_FILE = re.compile(r"^frame_\d{4,}\.png$")
# A palette index meaning "not looked up yet", so never a colour: drawn
# colours take at most 253 entries, and the spare entry (see ColourIndex) one.
_MISSING = 255


class ExportError(ValueError):
    """An export that cannot be made; the message is one line."""

    def __init__(self, message: str):
        super().__init__(one_line(message))


class ExportCancelled(Exception):
    """The export was cancelled; nothing was written."""


# ------------------------------------------------------------------ themes
@dataclass(frozen=True)
class Theme:
    """Colours of an exported frame: the grid's palette and the text parts."""

    name: str
    palette: Palette
    panel: str          # side panel background
    caption: str        # caption strip background
    border: str         # lines between the grid, the panel and the caption
    text: str
    muted: str          # titles and secondary text
    line_number: str
    current_line: str   # background of the pseudo-code line being run
    current_edge: str   # its marker and number
    changed: str        # a value that changed at this step

    def text_pairs(self) -> list[tuple[str, str]]:
        """(text colour, background) pairs that occur, for antialiasing shades."""
        return [(self.text, self.caption), (self.muted, self.caption),
                (self.text, self.panel), (self.muted, self.panel),
                (self.line_number, self.panel), (self.changed, self.panel),
                (self.text, self.current_line), (self.current_edge, self.current_line)]


LIGHT = Theme("light", PALETTE, panel="#ffffff", caption="#f3f5f8", border="#d5dbe2",
              text="#1d2733", muted="#55606d", line_number="#8a94a1",
              current_line="#ffe8b3", current_edge="#f08c00", changed="#b35900")

DARK = Theme("dark", DARK_PALETTE, panel="#181c21", caption="#101317", border="#2d343c",
             text="#e6eaef", muted="#9aa4b0", line_number="#6b7683", current_line="#4a3a12",
             current_edge="#ffa23e", changed="#ffb15c")

THEMES = {"light": LIGHT, "dark": DARK}


# ---------------------------------------------------------------- settings
@dataclass(frozen=True)
class ExportSettings:
    """How to export. ``first`` and ``last`` are steps (inclusive) or
    bookmark names; None means the first and the last step of the run."""

    first: int | str | None = None
    last: int | str | None = None
    fps: float = 4.0
    hold: float = 2.0        # extra seconds on the last frame
    scale: int | None = None  # image pixels per grid cell; None: auto_scale
    grid_lines: bool = True  # drawn when a cell is 4 or more pixels wide
    primitive: bool = True
    highlight: bool = True
    caption: bool = True
    panel: str = "code"
    theme: str = "light"
    loop: bool = True        # False: play once
    per: str = "auto"        # one of PER

    def checked(self) -> "ExportSettings":
        fps = _real(self.fps, "frames per second")
        if not MIN_FPS <= fps <= MAX_FPS:
            raise ExportError(f"frames per second must be {MIN_FPS:g} .. {MAX_FPS:g}, got {fps:g} "
                              "(GIF times frames in hundredths of a second)")
        hold = _real(self.hold, "hold")
        if not 0 <= hold <= MAX_HOLD:
            raise ExportError(f"hold must be 0 .. {MAX_HOLD:g} seconds, got {hold:g}")
        scale = self.scale
        if scale is not None and (isinstance(scale, bool)
                                  or not isinstance(scale, (int, np.integer))
                                  or not 1 <= scale <= MAX_SCALE):
            raise ExportError(f"scale must be a whole number 1 .. {MAX_SCALE} "
                              f"(pixels per grid cell), got {scale!r}")
        if self.panel not in PANELS:
            raise ExportError(f"panel must be one of {', '.join(PANELS)}, got {self.panel!r}")
        if self.theme not in THEMES:
            raise ExportError(f"theme must be one of {', '.join(THEMES)}, got {self.theme!r}")
        if self.per not in PER:
            raise ExportError(f"frames per must be one of {', '.join(PER)}, got {self.per!r}")
        return replace(self, fps=fps, hold=hold, scale=None if scale is None else int(scale))

    def for_grid(self, width: int, height: int) -> "ExportSettings":
        """Checked, with the scale chosen for the grid when it is automatic."""
        settings = self.checked()
        if settings.scale is None:
            settings = replace(settings, scale=auto_scale(width, height))
        return settings


def auto_scale(width: int, height: int) -> int:
    """Cells as large as fit a grid into 640 pixels, from 1 to 32 pixels."""
    return max(1, min(32, AUTO_EXTENT // max(width, height)))


def _real(value, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.number)):
        raise ExportError(f"{what} must be a number, got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ExportError(f"{what} must be a finite number, got {value!r}")
    return value


def frame_durations(count: int, fps: float, hold: float = 0.0) -> list[int]:
    """Milliseconds per frame, whole hundredths of a second (see Timing)."""
    ends = [round(k * 100 / fps) * 10 for k in range(count + 1)]
    durations = [b - a for a, b in zip(ends, ends[1:])]
    if durations:
        durations[-1] += round(hold * 100) * 10
    return durations


# -------------------------------------------------------------------- runs
@dataclass
class Run:
    """What is exported: a recorded run and how its grid is shown."""

    spec: object
    trace: object
    points: list
    options: dict
    y_down: bool = False
    differences: np.ndarray | None = None
    title: str = ""
    bookmarks: list = field(default_factory=list)

    @classmethod
    def from_scene(cls, scene, step_cap: int = DEFAULT_STEP_CAP) -> "Run":
        spec = scene.spec
        try:
            trace = spec.record(scene.points, scene.options, grid=(scene.width, scene.height),
                                step_cap=step_cap)
        except InputError as error:
            raise ExportError(f"the scene cannot run: {error}") from None
        return cls(spec, trace, scene.points, spec.resolve(scene.options),
                   y_down=scene.origin == "top-left", title=scene.title,
                   bookmarks=list(scene.bookmarks))

    @classmethod
    def from_player(cls, player, y_down: bool = False, title: str = "") -> "Run":
        """The player's run as it stands (the window's scene)."""
        if player.trace is None:
            raise ExportError("there is no run to export: place the points first")
        if player.recording:
            raise ExportError("the new run is still recording: export when it has finished, "
                              "or cancel it to export the run on show")
        # Build the replay caches now, so that a export running beside the
        # window never builds them at the same time as the window does.
        player.trace.raster_at(len(player.trace) - 1)
        differences = player.differences if len(player.differences) else None
        # The points the run was recorded from: a polygon's contours, the
        # whole triangles; not a shape still being drawn.
        return cls(player.spec, player.trace, player.input_points(), dict(player.options),
                   y_down=y_down, differences=differences, title=title)

    def paths(self):
        return scene_paths(self.spec, self.points, self.options)

    def step_of(self, value, what: str) -> int:
        """A step given as a number or a bookmark name, checked against the run."""
        last = len(self.trace) - 1
        if isinstance(value, str):
            text = value.strip()
            marks = {mark["name"]: mark["step"] for mark in self.bookmarks}
            if text in marks:
                step = marks[text]
                if step > last:
                    raise ExportError(f"{what} {value!r}: the bookmark is step {step}, past the "
                                      f"last step of the run ({last})")
                return step
            try:
                number = registry.parse_number(text, what, integer=True)
            except InputError:
                known = ", ".join(repr(name) for name in marks) or "none in this scene"
                raise ExportError(f"{what} {value!r}: not a step number or a bookmark "
                                  f"(bookmarks: {known})") from None
            value = number
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
            raise ExportError(f"{what}: expected a step number, got {value!r}")
        if not 0 <= value <= last:
            raise ExportError(f"{what} {value}: the run has steps 0 .. {last}")
        return int(value)

    def frame_range(self, first=None, last=None,
                    names: tuple[str, str] = ("the first step", "the last step")) -> range:
        """Steps ``first`` .. ``last`` (inclusive; numbers or bookmark names)."""
        start = 0 if first is None else self.step_of(first, names[0])
        end = len(self.trace) - 1 if last is None else self.step_of(last, names[1])
        if end < start:
            raise ExportError(f"the range ends (step {end}) before it starts (step {start})")
        return range(start, end + 1)

    def frame_steps(self, settings: "ExportSettings",
                    names: tuple[str, str] = ("the first step", "the last step")):
        """The steps drawn as frames: every step of the range, or the step
        that completes each animation frame inside it."""
        steps = self.frame_range(settings.first, settings.last, names)
        if settings.per == "step":
            return steps
        ends = animation_frame_steps(self.spec, self.trace)
        if not ends:
            if settings.per == "animation":
                raise ExportError(f"{self.spec.name} has no animation frames: export one frame "
                                  "per step instead")
            return steps
        chosen = [end for end in ends if steps.start <= end < steps.stop]
        if not chosen:
            raise ExportError(f"no animation frame ends between steps {steps.start} and "
                              f"{steps.stop - 1}: widen the range")
        return chosen


# --------------------------------------------------------------- Qt set-up
_APPLICATION = None


def ensure_qt():
    """A QGuiApplication for painting text; the offscreen platform is chosen
    when there is no display. Returns the application."""
    global _APPLICATION
    app = QCoreApplication.instance()
    if app is None:
        if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
            os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
        app = _APPLICATION = QGuiApplication(["rasterlab"])
    elif not isinstance(app, QGuiApplication):
        raise ExportError("export needs Qt's GUI module, but a console-only Qt application runs")
    return app


# ----------------------------------------------------------------- palette
def _rgb(color: str) -> tuple[int, int, int]:
    value = int(color.lstrip("#"), 16)
    return (value >> 16) & 255, (value >> 8) & 255, value & 255


def _shades(fg: str, bg: str, count: int = 6) -> list[tuple[int, int, int]]:
    a, b = np.array(_rgb(fg), float), np.array(_rgb(bg), float)
    return [tuple(int(v) for v in np.round(b + (a - b) * k / (count + 1)))
            for k in range(1, count + 1)]


class ColourIndex:
    """A fixed palette of at most 253 colours and a lookup from RGBA pixels
    to palette indices; a colour not in the palette maps to its nearest
    entry, remembered for the next frame.

    The palette written to files has one more entry, ``transparent``, that
    no drawn pixel uses: the GIF writer marks with it the pixels a frame
    leaves as they were in the frame before, which keeps files small.
    """

    def __init__(self, colours: Iterable[tuple[int, int, int]]):
        unique = list(dict.fromkeys(tuple(int(v) for v in c) for c in colours))
        if not 1 <= len(unique) < _MISSING - 1:
            raise ValueError(f"a palette holds 1 .. {_MISSING - 2} colours, got {len(unique)}")
        self.rgb = np.array(unique, dtype=np.uint8)
        self.transparent = len(unique)
        self._spare = _spare_colour(unique)
        self._table = np.full(1 << 24, _MISSING, dtype=np.uint8)
        self._table[self._keys(self.rgb)] = np.arange(len(unique), dtype=np.uint8)

    def __len__(self) -> int:
        return len(self.rgb)

    @staticmethod
    def _keys(rgb: np.ndarray) -> np.ndarray:
        rgb = rgb.astype(np.int64)
        return rgb[:, 0] | (rgb[:, 1] << 8) | (rgb[:, 2] << 16)

    def palette_bytes(self) -> bytes:
        """The palette as files store it: the colours, then the spare entry."""
        return self.rgb.tobytes() + bytes(self._spare)

    def index_of(self, color: str) -> int:
        return int(self._table[self._keys(np.array([_rgb(color)]))[0]])

    def indices(self, rgba: np.ndarray) -> np.ndarray:
        """(h, w) palette indices of an (h, w, 4) uint8 image (R, G, B, A)."""
        keys = rgba.view("<u4").reshape(rgba.shape[:2]) & np.uint32(0xFFFFFF)
        out = self._table[keys]
        missing = out == _MISSING
        if missing.any():
            self._learn(np.unique(keys[missing]))
            out[missing] = self._table[keys[missing]]
        return out

    def _learn(self, keys: np.ndarray) -> None:
        keys = keys.astype(np.int64)
        rgb = np.stack([keys & 255, (keys >> 8) & 255, (keys >> 16) & 255], axis=1)
        distance = ((rgb[:, None, :] - self.rgb[None, :, :].astype(np.int64)) ** 2).sum(axis=2)
        self._table[keys] = distance.argmin(axis=1).astype(np.uint8)


def _spare_colour(colours) -> tuple[int, int, int]:
    """A colour not among ``colours`` (for the palette's unused entry)."""
    taken = set(colours)
    for value in range(0xFF00FF, -1, -1):
        colour = ((value >> 16) & 255, (value >> 8) & 255, value & 255)
        if colour not in taken:
            return colour
    raise ValueError("no spare colour")


def build_palette(theme: Theme, trace=None) -> ColourIndex:
    """The export's one palette: theme colours, text shades and the run's
    own colours (see Palette in the module notes)."""
    p = theme.palette
    named = [p.background, p.ink, p.overdraw, p.grid, p.outside, p.current, p.candidate,
             p.difference, p.primitive, theme.panel, theme.caption, theme.border, theme.text,
             theme.muted, theme.line_number, theme.current_line, theme.current_edge,
             theme.changed]
    colours = list(dict.fromkeys(_rgb(c) for c in named))
    for fg, bg in theme.text_pairs():
        colours += _shades(fg, bg)
    colours = list(dict.fromkeys(colours))
    room = _MISSING - 2 - len(colours)
    run_colours = _run_colours(trace)
    run_colours = [c for c in run_colours if c not in set(colours)]
    if len(run_colours) > room:
        run_colours = _reduce(run_colours, room)
    return ColourIndex(colours + run_colours)


def _run_colours(trace) -> list[tuple[int, int, int]]:
    """Colours a run writes, and their darker shade for pixels written twice."""
    if trace is None:
        return []
    values = frame_view.written_colours(trace)
    if values is None or not len(values):
        return []
    values = values[np.isfinite(values)]
    values = values[(values >= 0) & (values <= 0xFFFFFF)].astype(np.int64)
    values = np.unique(values)
    rgb = np.stack([(values >> 16) & 255, (values >> 8) & 255, values & 255], axis=1)
    # render darkens a coloured pixel written more than once to 60%.
    darker = (rgb.astype(np.float32) * 0.6).astype(np.int64)
    both = np.unique(np.concatenate([rgb, darker]), axis=0)
    return [tuple(int(v) for v in row) for row in both]


def _reduce(colours: list, count: int) -> list:
    """At most ``count`` colours standing for ``colours`` (median cut)."""
    if count <= 0:
        return []
    strip = Image.fromarray(np.array(colours, dtype=np.uint8).reshape(1, -1, 3), "RGB")
    reduced = strip.quantize(colors=count, method=Image.Quantize.MEDIANCUT,
                             dither=Image.Dither.NONE)
    palette = reduced.getpalette()[:3 * count]
    used = np.unique(np.asarray(reduced)).tolist()
    return [tuple(palette[3 * i:3 * i + 3]) for i in used]


# ---------------------------------------------------------------- renderer
class FrameRenderer:
    """Draws exported frames of one run as palette-index arrays.

    ``size`` is (width, height) in pixels: the grid (cells x scale), plus the
    side panel's width when there is a panel, plus the caption's height when
    there is a caption. Frames come out top row first.
    """

    def __init__(self, run: Run, settings: ExportSettings = ExportSettings(),
                 incremental: bool = True):
        self.run = run
        self.settings = settings = settings.for_grid(run.trace.width, run.trace.height)
        self.theme = THEMES[settings.theme]
        trace = run.trace
        scale = settings.scale
        self.grid_size = (trace.width * scale, trace.height * scale)
        gw, gh = self.grid_size
        if gw > MAX_SIDE or gh > MAX_SIDE:
            raise ExportError(f"the grid would be {gw}x{gh} pixels at scale {scale}; a frame is "
                              f"at most {MAX_SIDE}x{MAX_SIDE}: choose a smaller scale")
        ensure_qt()
        self.paths = run.paths() if settings.primitive else []
        self._text = _TextParts(self, max(gw, gh))
        self.panel_width = self._text.panel_width if settings.panel != "none" else 0
        self.caption_height = self._text.caption_height if settings.caption else 0
        panel_height = self._text.panel_height if settings.panel != "none" else 0
        self.body_height = max(gh, panel_height)
        self.size = (gw + self.panel_width, self.body_height + self.caption_height)
        width, height = self.size
        if width > MAX_SIDE or height > MAX_SIDE:
            raise ExportError(f"a frame would be {width}x{height} pixels, more than "
                              f"{MAX_SIDE}x{MAX_SIDE}: choose a smaller scale or no side panel")
        self.colours = build_palette(self.theme, trace)
        self._outside = self.colours.index_of(self.theme.palette.outside)
        self._grid_lines = settings.grid_lines and scale >= 4
        self._grid = _GridPart(self, incremental)
        self._states = _States(trace, incremental)
        self._text.allocate()

    @property
    def palette_bytes(self) -> bytes:
        return self.colours.palette_bytes()

    def render(self, index: int) -> np.ndarray:
        """Frame ``index`` as a (height, width) uint8 array of palette indices."""
        run, settings = self.run, self.settings
        state, written = self._states.at(index)
        marks = frame_marks(state, self.paths, run.differences, settings.highlight,
                            settings.primitive)
        grid = self._grid.draw(state.raster, marks, written)
        if not run.y_down:
            grid = grid[::-1]  # row 0 is y = 0, the bottom of the picture
        width, height = self.size
        gw, gh = self.grid_size
        frame = np.empty((height, width), dtype=np.uint8)
        frame[:gh, :gw] = grid
        if self.body_height > gh:
            frame[gh:self.body_height, :gw] = self._outside
        if self.panel_width:
            frame[:self.body_height, gw:] = self._text.panel(state)
        if self.caption_height:
            frame[self.body_height:, :] = self._text.caption(state)
        return frame

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
        step = trace.step(index)
        if self.incremental and self.index is not None and index == self.index + 1:
            trace.replay(index, index + 1, self.raster)
            written = [tuple(cell) for cell in trace.written(index, index + 1).pixels.tolist()]
        else:
            self.raster, written = trace.raster_at(index), None
        self.index = index
        state = FrameState(index, step, self.raster, trace.variables_at(index),
                           trace.candidates_at(index))
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
        trace = renderer.run.trace
        self.width, self.height = trace.width, trace.height
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
            rgba = compose_frame(raster, marks, palette, scale, r._grid_lines)
            self.indices = r.colours.indices(rgba)
        elif box is not None:
            x0, y0, x1, y1 = box
            rgba = compose_region(raster, marks, box, palette, scale, r._grid_lines,
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


class _TextParts:
    """The caption strip and the side panel, painted with Qt on QImages
    that are reused from frame to frame."""

    def __init__(self, renderer: FrameRenderer, grid_extent: int):
        self.r = renderer
        settings = renderer.settings
        # Text grows with large frames so that it keeps its size on a slide.
        ui = max(1.0, min(3.0, grid_extent / 640))
        self.ui = ui
        sans = QFont("DejaVu Sans")
        sans.setStyleHint(QFont.StyleHint.SansSerif)
        mono = QFont("DejaVu Sans Mono")
        mono.setStyleHint(QFont.StyleHint.Monospace)
        if not QFontDatabase.hasFamily("DejaVu Sans Mono"):
            mono = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        for font, pixels in ((sans, 13), (mono, 12)):
            font.setPixelSize(round(pixels * ui))
            font.setStyleStrategy(QFont.StyleStrategy.PreferAntialias)
        self.sans, self.mono = sans, mono
        self._metrics_of: dict[int, QFontMetrics] = {}
        self.sans_bold, self.mono_bold = QFont(sans), QFont(mono)
        self.sans_bold.setBold(True)
        self.mono_bold.setBold(True)
        self.line = round(18 * ui)
        self.pad = round(8 * ui)
        self.caption_height = 3 * self.line + 2 * round(5 * ui)
        self.panel_width = round(360 * ui)

        trace = renderer.run.trace
        self.last = len(trace) - 1
        self.code = [line.text for line in trace.code]
        mono_metrics = QFontMetrics(self.mono_bold)
        self.number_width = mono_metrics.horizontalAdvance("\u25b6 " + str(len(self.code))) \
            + round(6 * ui)
        text_width = self.panel_width - 2 * self.pad - self.number_width
        self.wrapped = [_wrap(text, mono_metrics, text_width) for text in self.code]
        code_height = self.pad + self.line + sum(len(rows) for rows in self.wrapped) * self.line \
            + self.pad
        variables_height = self.pad + self.line * (1 + 10) + self.pad  # title and 10 rows
        self.code_height = code_height
        self.panel_height = {"code": code_height, "variables": variables_height,
                             "both": code_height + variables_height, "none": 0}[settings.panel]
        self._code_cache: dict[int | None, np.ndarray] = {}
        self._previous_rows: tuple[int, list] | None = None

    def allocate(self) -> None:
        r = self.r
        width, _ = r.size
        fmt = QImage.Format.Format_RGBX8888
        self.caption_image = QImage(width, max(1, r.caption_height), fmt)
        self.panel_image = QImage(max(1, r.panel_width), r.body_height, fmt)

    # ------------------------------------------------------------ drawing
    def _painter(self, image, background: str):
        image.fill(QColor(background))
        painter = QPainter(image)
        painter.setRenderHint(QPainter.RenderHint.TextAntialiasing, True)
        return painter

    def _indices(self, image) -> np.ndarray:
        height, width = image.height(), image.width()
        data = np.frombuffer(image.constBits(), dtype=np.uint8, count=image.sizeInBytes())
        rows = data.reshape(height, image.bytesPerLine())[:, :width * 4]
        return self.r.colours.indices(np.ascontiguousarray(rows).reshape(height, width, 4))

    def _metrics(self, font) -> QFontMetrics:
        metrics = self._metrics_of.get(id(font))
        if metrics is None:
            metrics = self._metrics_of[id(font)] = QFontMetrics(font)
        return metrics

    def _text(self, painter, x, baseline, text, font, color, width=None):
        """Draw ``text`` (cut with an ellipsis to ``width``); its width."""
        painter.setFont(font)
        painter.setPen(QColor(color))
        metrics = self._metrics(font)
        advance = metrics.horizontalAdvance(text)
        if width is not None and advance > width:
            text = metrics.elidedText(text, Qt.TextElideMode.ElideRight, max(0, int(width)))
            advance = metrics.horizontalAdvance(text)
        painter.drawText(int(x), int(baseline), text)
        return advance

    def _baseline(self, top: int, font) -> int:
        metrics = self._metrics(font)
        return top + (self.line + metrics.ascent() - metrics.descent()) // 2

    # ------------------------------------------------------------ caption
    def caption(self, state) -> np.ndarray:
        """Three lines under the grid: what the step does, the line of
        pseudo-code it runs, and the values it changes."""
        theme, r = self.r.theme, self.r
        image = self.caption_image
        width = image.width()
        painter = self._painter(image, theme.caption)
        try:
            # Rules are filled rectangles: QPainter draws lines on this
            # image format far more slowly.
            painter.fillRect(0, 0, width, 1, QColor(theme.border))
            top = round(5 * self.ui)
            x0, room = self.pad, width - 2 * self.pad
            # Line 1: "Step 12 of 40 · plots (5, 3) · branch NE", bold parts bold.
            text = step_caption(state, self.last, bold=lambda part: f"\x01{part}\x02")
            x, baseline = x0, self._baseline(top, self.sans)
            for k, piece in enumerate(re.split(r"[\x01\x02]", text)):
                if not piece or x >= x0 + room:
                    continue
                bold = k % 2 == 1
                x += self._text(painter, x, baseline, piece, self.sans_bold if bold else self.sans,
                                theme.text, x0 + room - x)
            # Line 2: the pseudo-code line, numbered as in the panel.
            line = state.step.line
            baseline = self._baseline(top + self.line, self.mono)
            if 0 <= line < len(self.code):
                number = f"{line + 1}: "
                x = x0 + self._text(painter, x0, baseline, number, self.mono, theme.muted)
                self._text(painter, x, baseline, self.code[line].strip(), self.mono, theme.text,
                           x0 + room - x)
            # Line 3: the values of this step, then what the algorithm explains.
            rows = key_values(r.run.trace, state)
            names = {name for name, _ in rows}
            extra = [(n, t) for n, t in self._rows(state)[len(state.variables):]
                     if n not in names]
            parts = [f"{name} = {text}" for name, text in rows] + [text for _, text in extra]
            baseline = self._baseline(top + 2 * self.line, self.mono)
            self._text(painter, x0, baseline, "   \u00b7   ".join(parts), self.mono, theme.text,
                       room)
        finally:
            painter.end()
        return self._indices(image)

    def _rows(self, state) -> list:
        run = self.r.run
        return run.spec.panel_rows(run.trace, state.index)

    # -------------------------------------------------------------- panel
    def panel(self, state) -> np.ndarray:
        kind = self.r.settings.panel
        if kind == "code":
            return self._code_panel(state.step.line)
        image = self.panel_image
        painter = self._painter(image, self.r.theme.panel)
        try:
            top = 0
            if kind == "both":
                self._paint_code(painter, state.step.line)
                top = self.code_height
            self._paint_variables(painter, state, top)
            self._paint_border(painter)
        finally:
            painter.end()
        return self._indices(image)

    def _code_panel(self, line) -> np.ndarray:
        cached = self._code_cache.get(line)
        if cached is None:
            image = self.panel_image
            painter = self._painter(image, self.r.theme.panel)
            try:
                self._paint_code(painter, line)
                self._paint_border(painter)
            finally:
                painter.end()
            cached = self._code_cache[line] = self._indices(image)
        return cached

    def _paint_border(self, painter) -> None:
        painter.fillRect(0, 0, 1, self.panel_image.height(), QColor(self.r.theme.border))

    def _paint_code(self, painter, current) -> None:
        theme = self.r.theme
        width = self.panel_image.width()
        top = self.pad
        title = self.r.run.spec.title
        self._text(painter, self.pad, self._baseline(top, self.sans_bold), title,
                   self.sans_bold, theme.muted, width - 2 * self.pad)
        top += self.line
        for number, rows in enumerate(self.wrapped):
            here = number == current
            if here:
                painter.fillRect(1, top, width - 1, len(rows) * self.line,
                                 QColor(theme.current_line))
            font = self.mono_bold if here else self.mono
            label = ("\u25b6 " if here else "") + str(number + 1)
            label_x = self.pad + self.number_width - round(6 * self.ui) \
                - self._metrics(font).horizontalAdvance(label)
            baseline = self._baseline(top, font)
            self._text(painter, label_x, baseline, label, font,
                       theme.current_edge if here else theme.line_number)
            for row in rows:
                self._text(painter, self.pad + self.number_width, self._baseline(top, font), row,
                           font, theme.text)
                top += self.line

    def _paint_variables(self, painter, state, top: int) -> None:
        theme = self.r.theme
        width = self.panel_image.width()
        height = self.panel_image.height()
        top += self.pad
        self._text(painter, self.pad, self._baseline(top, self.sans_bold), "Variables",
                   self.sans_bold, theme.muted)
        top += self.line
        rows = self._rows(state)
        before = dict(self._rows_before(state.index))
        fits = max(0, (height - top - self.pad) // self.line)
        shown = rows if len(rows) <= fits else rows[:max(0, fits - 1)]
        name_width = round(110 * self.ui)
        for name, text in shown:
            changed = name in before and before[name] != text
            baseline = self._baseline(top, self.mono)
            self._text(painter, self.pad, baseline, name, self.sans, theme.muted, name_width - 6)
            self._text(painter, self.pad + name_width, baseline, text,
                       self.mono_bold if changed else self.mono,
                       theme.changed if changed else theme.text,
                       width - 2 * self.pad - name_width)
            top += self.line
        if len(shown) < len(rows):
            self._text(painter, self.pad, self._baseline(top, self.sans),
                       f"\u2026 {len(rows) - len(shown)} more", self.sans, theme.muted)

    def _rows_before(self, index: int) -> list:
        """The panel rows of the step before (values that changed are marked)."""
        if index == 0:
            return []
        run = self.r.run
        return run.spec.panel_rows(run.trace, index - 1)


def _wrap(text: str, metrics, width: int) -> list[str]:
    """A line of code broken at spaces to fit ``width`` pixels; continuation
    rows are indented past the line's own indent."""
    if metrics.horizontalAdvance(text) <= width:
        return [text]
    indent = text[:len(text) - len(text.lstrip())] + "    "
    rows, row = [], ""
    for word in re.split(r"(?<= )", text):
        candidate = row + word
        if row and metrics.horizontalAdvance(candidate.rstrip()) > width:
            rows.append(row.rstrip())
            row = indent + word.lstrip()
        else:
            row = candidate
        while metrics.horizontalAdvance(row) > width and len(row) > len(indent) + 1:
            # A single word longer than the row: cut it.
            cut = len(row)
            while cut > len(indent) + 1 and metrics.horizontalAdvance(row[:cut]) > width:
                cut -= 1
            rows.append(row[:cut])
            row = indent + row[cut:]
    if row.strip():
        rows.append(row.rstrip())
    return rows or [text]


# ----------------------------------------------------------------- outputs
class _GifFile:
    """A GIF written to a temporary file beside ``path``, renamed at the end."""

    def __init__(self, path):
        self.path = Path(path)
        directory = _folder_of(self.path)
        if self.path.is_dir():
            raise ExportError(f"{self.path}: is a folder, not a file name")
        try:
            handle, name = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=".tmp",
                                            dir=directory)
        except OSError as error:
            raise ExportError(f"cannot write {self.path}: the folder {directory} is not writable "
                              f"({error.strerror or error})") from None
        os.close(handle)
        self.temporary = Path(name)
        _readable_by_all(self.temporary)

    def write(self, frames: Iterable[Image.Image], durations, loop: bool, palette: bytes,
              transparent: int) -> None:
        frames = iter(frames)
        first = next(frames)
        extra = {"loop": 0} if loop else {}
        with open(self.temporary, "wb") as stream:
            # One global palette (no frame carries its own). With
            # ``optimize`` Pillow writes each frame after the first as the
            # box that changed, its unchanged pixels set to ``transparent``.
            first.save(stream, format="GIF", save_all=True, append_images=frames,
                       duration=list(durations), palette=palette, optimize=True,
                       transparency=transparent, disposal=1, **extra)
            stream.flush()
            os.fsync(stream.fileno())

    def commit(self) -> None:
        os.replace(self.temporary, self.path)

    def abort(self) -> None:
        self.temporary.unlink(missing_ok=True)


class _FrameFolder:
    """PNG frames written into a temporary folder inside ``directory`` and
    moved into place at the end. Frames of an earlier export to the same
    folder (frame_NNNN.png beyond this export's last) are removed then, so
    the folder holds one export."""

    def __init__(self, directory, count: int):
        self.directory = Path(directory)
        self.width = max(4, len(str(max(0, count - 1))))
        self.names: list[str] = []
        self.created = False
        if self.directory.exists() and not self.directory.is_dir():
            raise ExportError(f"{self.directory}: is a file, not a folder")
        if not self.directory.exists():
            parent = _folder_of(self.directory)
            try:
                self.directory.mkdir()
            except OSError as error:
                raise ExportError(f"cannot make the folder {self.directory} in {parent} "
                                  f"({error.strerror or error})") from None
            self.created = True
        try:
            self.temporary = Path(tempfile.mkdtemp(prefix=".rasterlab-frames-",
                                                   dir=self.directory))
        except OSError as error:
            self._remove_created()
            raise ExportError(f"cannot write in the folder {self.directory} "
                              f"({error.strerror or error})") from None

    def add(self, image: Image.Image) -> None:
        name = FRAME_NAME.format(len(self.names), width=self.width)
        image.save(self.temporary / name, format="PNG", compress_level=3)
        self.names.append(name)

    def commit(self) -> None:
        for name in self.names:
            os.replace(self.temporary / name, self.directory / name)
        keep = set(self.names)
        for old in self.directory.iterdir():
            if _FRAME_FILE.match(old.name) and old.name not in keep and old.is_file():
                old.unlink()
        self.temporary.rmdir()

    def abort(self) -> None:
        shutil.rmtree(self.temporary, ignore_errors=True)
        self._remove_created()

    def _remove_created(self) -> None:
        if self.created:
            try:
                self.directory.rmdir()
            except OSError:
                pass


def _readable_by_all(path: Path) -> None:
    # mkstemp makes files only their owner may read; an exported file gets
    # the permissions any new file gets.
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(path, 0o666 & ~umask)


def _folder_of(path: Path) -> Path:
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise ExportError(f"cannot write {path}: the folder {directory} does not exist")
    return directory


# ------------------------------------------------------------------ export
@dataclass
class ExportResult:
    frames: int
    size: tuple[int, int]
    durations: list[int]
    gif: Path | None = None
    frames_dir: Path | None = None


def export(run: Run, settings: ExportSettings = ExportSettings(), gif=None, frames_dir=None,
           progress: Callable[[int, int], None] | None = None,
           cancelled: Callable[[], bool] | None = None,
           names: tuple[str, str] = ("the first step", "the last step")) -> ExportResult:
    """Export the run's frames as a GIF at ``gif``, as PNGs in ``frames_dir``,
    or both (each frame is drawn once).

    ``progress(done, total)`` is called after each frame; when
    ``cancelled()`` turns true the export stops with ExportCancelled and
    leaves nothing behind. Bad settings, sizes and paths raise ExportError;
    ``names`` are what its messages call the range's ends.
    """
    if gif is None and frames_dir is None:
        raise ExportError("nothing to write: give a GIF file, a folder for frames, or both")
    settings = settings.for_grid(run.trace.width, run.trace.height)
    steps = run.frame_steps(settings, names)
    renderer = FrameRenderer(run, settings)
    width, height = renderer.size
    if gif is not None and len(steps) * width * height > MAX_GIF_PIXELS:
        raise ExportError(f"the GIF would hold {len(steps):,} frames of {width}x{height} pixels, "
                          f"more than {MAX_GIF_PIXELS // 2 ** 20:,} MiB: export a shorter range "
                          "or at a smaller scale")
    durations = frame_durations(len(steps), settings.fps, settings.hold)
    outputs = []
    try:
        gif_file = _GifFile(gif) if gif is not None else None
        if gif_file:
            outputs.append(gif_file)
        folder = _FrameFolder(frames_dir, len(steps)) if frames_dir is not None else None
        if folder:
            outputs.append(folder)

        def frames():
            for done, index in enumerate(steps, 1):
                if cancelled is not None and cancelled():
                    raise ExportCancelled("the export was cancelled")
                image = renderer.image(index)
                if folder is not None:
                    folder.add(image)
                if progress is not None:
                    progress(done, len(steps))
                yield image

        if gif_file is not None:
            gif_file.write(frames(), durations, settings.loop, renderer.palette_bytes,
                           renderer.colours.transparent)
        else:
            for _ in frames():
                pass
        if cancelled is not None and cancelled():
            raise ExportCancelled("the export was cancelled")
        for output in outputs:
            output.commit()
    except BaseException as error:
        for output in outputs:
            output.abort()
        if isinstance(error, OSError):
            target = gif if gif is not None else frames_dir
            raise ExportError(f"cannot write {target} ({error.strerror or error})") from None
        raise
    return ExportResult(len(steps), renderer.size, durations,
                        Path(gif) if gif is not None else None,
                        Path(frames_dir) if frames_dir is not None else None)
