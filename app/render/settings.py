"""What an export is asked for: its settings, the steps it draws, its timing.

Timing
------
GIF stores frame durations in hundredths of a second. Frame k is shown
from round(k * 100 / fps) to round((k + 1) * 100 / fps) hundredths, so
every frame lasts 1000 / fps ms to within 10 ms and the whole animation
keeps time: at 30 fps frames last 30, 40, 30, 30, 40, ... ms. The last
frame is held ``hold`` seconds longer. Frames per second go up to 50:
viewers slow down frames shorter than 20 ms.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from algorithms.core import registry
from algorithms.antialias import animation_frame_steps
from algorithms.core.registry import InputError
from algorithms.core.trace import DEFAULT_STEP_CAP

from app.model import runs
from app.model.budget import DEFAULT_MEMORY_LIMIT, DEFAULT_TIME_LIMIT
from app.model.notation import NUMBERS
from app.model.scene import one_line
from app.render.overlays import OVERLAYS
from app.render.palette import THEMES
from app.render.units import UNITS, choose_frames

MIN_FPS = 0.1
MAX_FPS = 50.0
MAX_SCALE = 64
MAX_HOLD = 600.0   # seconds; GIF's longest frame is 655.35 s
AUTO_EXTENT = 640  # pixels the grid's longer side takes at the automatic scale
# auto: the pseudo-code beside the grid, or no panel where the frame would
# then be wider than a frame may be (a 4096-cell-wide grid).
PANELS = ("auto", "code", "variables", "both", "tables", "none")
MIN_TEXT, MAX_TEXT = 8, 96  # pixels: the caption's text size
# One exported frame per step, or per animation frame of a run that has
# them (aa-temporal); auto picks animation frames where there are some.
PER = ("auto", "step", "animation")
NAMES = ("the first step", "the last step")


class ExportError(ValueError):
    """An export that cannot be made; the message is one line."""

    def __init__(self, message: str):
        super().__init__(one_line(message))


class ExportCancelled(Exception):
    """The export was cancelled; nothing was written."""


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
    reasoning: bool = True   # the step's reasoning on the grid (app/render/reasoning.py)
    grid_text: bool = True   # the reasoning's labels (M, y + 1/2) on the grid
    vertex_labels: bool = False  # P1, P2, ... at the scene's points
    axes: bool = False       # coordinates beside the grid: ticks at the cell boundaries
    caption: bool = True
    panel: str = "auto"
    theme: str = "light"
    loop: bool = True        # False: play once
    per: str = "auto"        # one of PER
    unit: str = "auto"       # one of units.UNITS: what a frame stands for
    text_size: int | None = None  # pixels of the caption's text; None: text_pixels()
    memory_limit: int = DEFAULT_MEMORY_LIMIT  # bytes the run may need (app/model/budget.py)
    time_limit: float = DEFAULT_TIME_LIMIT  # seconds the run may take, as estimated
    overlays: tuple = ()     # names from app/render/overlays.py's OVERLAYS
    numbers: str = "decimal"  # fractions as decimals or exact p/q (app/model/notation.py)
    # Called with the steps recorded so far while the run is recorded (the
    # command line's terminal bar); not a setting of the picture.
    recording: object = field(default=None, compare=False, repr=False)

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
        if self.unit not in UNITS:
            raise ExportError(f"unit must be one of {', '.join(UNITS)}, got {self.unit!r}")
        text = self.text_size
        if text is not None and (isinstance(text, bool) or not isinstance(text, (int, np.integer))
                                 or not MIN_TEXT <= text <= MAX_TEXT):
            raise ExportError(f"text size must be a whole number of pixels {MIN_TEXT} .. "
                              f"{MAX_TEXT}, got {text!r}")
        if self.numbers not in NUMBERS:
            raise ExportError(f"numbers must be one of {', '.join(NUMBERS)}, got {self.numbers!r}")
        if not set(self.overlays) <= set(OVERLAYS):
            raise ExportError(f"overlays must be among {', '.join(OVERLAYS)}, got "
                              f"{', '.join(map(str, self.overlays))}")
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


# ------------------------------------------------------------------ steps
def record(scene, step_cap: int = DEFAULT_STEP_CAP, memory_limit: int = DEFAULT_MEMORY_LIMIT,
           time_limit: float = DEFAULT_TIME_LIMIT, progress=None):
    """The scene's run, recorded: the trace an export draws. A run over the
    memory or time budget is refused before it starts. ``progress`` hears
    the recording's steps."""
    spec = registry.get(scene.algorithm)
    try:
        return runs.record(spec, scene.points, scene.options, (scene.width, scene.height),
                           step_cap, memory_limit, time_limit, progress)
    except InputError as error:
        raise ExportError(f"the scene cannot run: {error}") from None


def step_of(scene, trace, value, what: str) -> int:
    """A step given as a number or one of the scene's bookmarks, checked
    against the run."""
    last = len(trace) - 1
    if isinstance(value, str):
        text = value.strip()
        marks = {mark["name"]: mark["step"] for mark in scene.bookmarks}
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


def frame_range(scene, trace, first=None, last=None, names: tuple[str, str] = NAMES) -> range:
    """Steps ``first`` .. ``last`` (inclusive; numbers or bookmark names)."""
    start = 0 if first is None else step_of(scene, trace, first, names[0])
    end = len(trace) - 1 if last is None else step_of(scene, trace, last, names[1])
    if end < start:
        raise ExportError(f"the range ends (step {end}) before it starts (step {start})")
    return range(start, end + 1)


def frame_steps(scene, trace, settings: ExportSettings, names: tuple[str, str] = NAMES):
    """The steps drawn as frames (see ``chosen_frames``)."""
    return chosen_frames(scene, trace, settings, names)[0]


def chosen_frames(scene, trace, settings: ExportSettings,
                  names: tuple[str, str] = NAMES) -> tuple[list[int], str]:
    """The steps drawn as frames, and one line saying what a frame stands
    for: the step that completes each animation frame of a run that has
    them, else one frame per ``settings.unit`` (app/render/units.py)."""
    steps = frame_range(scene, trace, settings.first, settings.last, names)
    unit = "step" if settings.per == "step" and settings.unit == "auto" else settings.unit
    if settings.per == "step" or unit != "auto":
        return choose_frames(trace, unit, steps.start, steps.stop)
    spec = registry.get(scene.algorithm)
    ends = animation_frame_steps(spec, trace)
    if not ends:
        if settings.per == "animation":
            raise ExportError(f"{spec.name} has no animation frames: export one frame "
                              "per step instead")
        return choose_frames(trace, "auto", steps.start, steps.stop)
    chosen = [end for end in ends if steps.start <= end < steps.stop]
    if not chosen:
        raise ExportError(f"no animation frame ends between steps {steps.start} and "
                          f"{steps.stop - 1}: widen the range")
    return chosen, (f"one frame per animation frame: {len(chosen):,} frames for "
                    f"{len(steps):,} steps")
