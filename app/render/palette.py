"""The colours of an exported frame: the themes, and the one palette every
frame of an export uses.

A GIF frame holds at most 256 colours. Every frame of an export uses one
palette, fixed before the first frame is drawn, so no colour shifts from
frame to frame: the theme's colours, a few shades between each text colour
and the background it sits on (for antialiased text), and, for runs that
write colours, those colours (reduced by median cut if there are too many).
Each drawn pixel is looked up in that palette; a colour it lacks (the edge
of a glyph, say) takes the nearest entry, without dithering. The PNG frames
use the same palette.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable

import numpy as np
from PIL import Image

from app.render import frame as frame_view
from app.render.compose import DARK_PALETTE, PALETTE, Palette

# A palette index meaning "not looked up yet", so never a colour: drawn
# colours take at most 253 entries, and the spare entry (see ColourIndex) one.
_MISSING = 255


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


def build_palette(theme: Theme, trace=None, extra=()) -> ColourIndex:
    """The export's one palette: theme colours, text shades, ``extra``
    (r, g, b) colours (an overlay's) and the run's own colours (see Palette
    in the module notes)."""
    p = theme.palette
    named = [p.background, p.ink, p.overdraw, p.grid, p.outside, p.current, p.candidate,
             p.difference, p.primitive, p.guide, theme.panel, theme.caption, theme.border, theme.text,
             theme.muted, theme.line_number, theme.current_line, theme.current_edge,
             theme.changed]
    colours = list(dict.fromkeys([_rgb(c) for c in named] + [tuple(c) for c in extra]))
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
