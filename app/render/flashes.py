"""Flashes in an animation, measured as WCAG 2.1 defines them (2.3.1, "Three
Flashes or Below Threshold").

A *transition* of a pixel is a change of its relative luminance by at least
0.1 (10% of the largest, 1.0) where the darker of the two is below 0.80; a
*flash* is a pair of opposing transitions (brighter then darker, or darker
then brighter), so a pixel that turns black to white and back five times a
second flashes five times a second. A slow ramp is one transition, however
many frames it takes: a pixel's transition is measured from the furthest
value it reached since its last one.

Area: WCAG's *general flash threshold* counts flashes that take, together,
25% of any 10-degree field of vision, and its note gives a 341 x 256 pixel
rectangle of a 1024 x 768 screen as that field. A frame is taken to fill the
screen (the largest it can be shown), so the field is a third of the frame's
width by a third of its height, and flashes count when they cover at least a
quarter of that rectangle, anywhere in the frame (2.8% of the frame).

``flash_rate`` gives the most flashes in any one second, over such an area,
with the frames shown for the export's durations and looped as a GIF loops.
WCAG allows at most ``LIMIT`` (three) a second. No Qt here: the command line
and the window measure with the same code.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from algorithms.antialias import animation_frame_steps

LIMIT = 3               # flashes in any one second, WCAG 2.3.1
# A flash takes two changes of picture: at this many pictures a second or
# fewer, nothing can flash more than LIMIT times in any second.
SAFE_FPS = 2 * LIMIT + 1
CHANGE = 0.1            # a transition: this much relative luminance ...
DARKER_BELOW = 0.8      # ... where the darker state is below this
FIELD = (256 / 768, 341 / 1024)   # the 10-degree field, as a fraction of (height, width)
AREA = 0.25             # of the field, flashing together


@dataclass(frozen=True)
class Flashes:
    """How much an animation flashes: ``per_second`` flashes in its worst
    second over a large area, at ``second`` seconds from its start."""

    per_second: int
    second: float

    @property
    def safe(self) -> bool:
        return self.per_second <= LIMIT


def relative_luminance(rgb: np.ndarray) -> np.ndarray:
    """WCAG's relative luminance of sRGB pixels (..., 3) as 8-bit values."""
    c = np.asarray(rgb, dtype=np.float32)[..., :3] / np.float32(255)
    linear = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return linear @ np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)


def transitions(luminance: np.ndarray) -> np.ndarray:
    """(frames, h, w) int8: +1 where a pixel's transition (up) or -1
    (down) completes at that frame, 0 elsewhere; frame 0 has none."""
    out = np.zeros(luminance.shape, dtype=np.int8)
    extreme = luminance[0].copy()   # the furthest value since the last transition
    last = np.zeros(luminance.shape[1:], dtype=np.int8)
    for t in range(1, len(luminance)):
        value = luminance[t]
        change = value - extreme
        darker = np.minimum(value, extreme)
        sign = np.sign(change).astype(np.int8)
        turned = (np.abs(change) >= CHANGE) & (darker < DARKER_BELOW) & (sign != last)
        out[t][turned] = sign[turned]
        last[turned] = sign[turned]
        # Further the same way as the last transition: the extreme moves on.
        onward = ~turned & (sign == last) & (last != 0)
        extreme = np.where(turned | onward, value, extreme)
    return out


def flash_rate(frames, durations_ms, loop: bool = True) -> Flashes:
    """The flashes of ``frames`` (each (h, w, 3), 8-bit RGB) shown for
    ``durations_ms`` each; with ``loop`` the animation plays over again
    for long enough that its turns from the last frame back to the first
    count too."""
    frames = [relative_luminance(frame) for frame in frames]
    durations = list(durations_ms)
    starts = len(frames)   # the seconds that begin at these frames cover them all
    if loop and len(frames) > 1:
        # Rounds enough that a second starting in the first two is whole;
        # later rounds only repeat the second.
        rounds = 3 + int(1000 // max(1, sum(durations)))
        frames, durations, starts = frames * rounds, durations * rounds, 2 * len(frames)
    if len(frames) < 3:
        return Flashes(0, 0.0)   # two frames make one transition at most: no pair
    turns = transitions(np.stack(frames)) != 0
    shown = np.concatenate([[0.0], np.cumsum(durations[:-1], dtype=np.float64) / 1000.0])
    worst = Flashes(0, 0.0)
    for start in range(1, starts):
        # The transitions into the frames shown within one second of this
        # one (a microsecond's allowance for the sums of fractional times).
        end = int(np.searchsorted(shown, shown[start] + 1.0 - 1e-6, side="left"))
        per_pixel = turns[start:end].sum(axis=0, dtype=np.int32) // 2
        count = worst.per_second
        while count < per_pixel.max() and _covers(per_pixel >= count + 1):
            count += 1
        if count > worst.per_second:
            worst = Flashes(count, float(shown[start]))
    return worst


def _covers(mask: np.ndarray) -> bool:
    """Whether some FIELD-sized rectangle of ``mask`` is AREA true."""
    h, w = mask.shape
    bh, bw = max(1, round(h * FIELD[0])), max(1, round(w * FIELD[1]))
    table = np.zeros((h + 1, w + 1), dtype=np.int64)
    table[1:, 1:] = mask.cumsum(0).cumsum(1)
    sums = table[bh:, bw:] - table[:-bh, bw:] - table[bh:, :-bw] + table[:-bh, :-bw]
    return bool(sums.max() >= AREA * bh * bw)


def playback_cap(spec, trace) -> float | None:
    """The most steps a second a run may be played at so that it shows no
    more than SAFE_FPS pictures a second: SAFE_FPS times the fewest steps
    between two consecutive pictures, the empty grid at step 0 and each
    complete animation frame. None when the run has no animation frames."""
    ends = animation_frame_steps(spec, trace)
    if not ends:
        return None
    pictures = [0, *ends]
    return float(SAFE_FPS * min(b - a for a, b in zip(pictures, pictures[1:])))


def cap_note(cap: float) -> str:
    """The line saying play is held to ``cap`` steps a second, and why."""
    return (f"Playing at most {cap:g} steps/s: faster, this animation could flash more "
            f"than {LIMIT} times a second")
