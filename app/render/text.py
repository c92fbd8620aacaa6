"""The text of an exported frame, drawn with Pillow: the caption strip under
the grid and the side panel with the pseudo-code and the variables.

The fonts are DejaVu Sans and DejaVu Sans Mono, shipped with RasterLab
(resources/fonts/), so a frame's text is the same on every system and has
every glyph the frames draw (≤, dᵢ₊₁, ▶).
Text is antialiased; its edge colours take the nearest entry of the
export's palette, which holds shades between each text colour and its
background.
"""
from __future__ import annotations

import re
from functools import lru_cache

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from algorithms.core.trace import FrameState

from app.model.notation import shown
from app.model.shipped import FONTS
from app.model.exact import shown_rows
from app.model.tables import TableIndex
from app.render.frame import key_values, step_caption

ELLIPSIS = "\u2026"
VALUE_SEPARATOR = "   \u00b7   "
VALUE_SAMPLES = 512   # steps looked at to size the caption
MAX_VALUE_LINES = 6   # the caption's value lines at most
FONT_FILES = {"sans": "DejaVuSans.ttf", "sans_bold": "DejaVuSans-Bold.ttf",
              "mono": "DejaVuSansMono.ttf", "mono_bold": "DejaVuSansMono-Bold.ttf"}


def font_path(kind: str) -> str:
    """The shipped font file of ``kind`` (sans, sans_bold, mono, mono_bold)."""
    return str(FONTS / FONT_FILES[kind])


@lru_cache(maxsize=None)
def font(kind: str, pixels: int) -> ImageFont.FreeTypeFont:
    """The shipped font of ``kind``, ``pixels`` high."""
    return ImageFont.truetype(font_path(kind), pixels)


class _Font:
    """A font with the measures layout needs."""

    def __init__(self, kind: str, pixels: int):
        self.face = font(kind, pixels)
        self.ascent, self.descent = self.face.getmetrics()

    def width(self, text: str) -> int:
        return round(self.face.getlength(text))

    def elided(self, text: str, width: float) -> str:
        """``text`` cut with an ellipsis to fit ``width`` pixels."""
        if self.width(text) <= width:
            return text
        low, high = 0, len(text)
        while low < high:  # the longest prefix that fits with the ellipsis
            middle = (low + high + 1) // 2
            if self.width(text[:middle] + ELLIPSIS) <= width:
                low = middle
            else:
                high = middle - 1
        return text[:low] + ELLIPSIS if low or self.width(ELLIPSIS) <= width else ""


BASE_TEXT = 13  # pixels: the caption's text at ui = 1; every other measure follows it
PANEL_WIDTH = 360  # pixels at ui = 1
MIN_CODE_ROWS = 6  # rows of pseudo-code a side panel shows at least


def text_pixels(grid_extent: int) -> int:
    """The default text size: about a thirtieth of the grid's longer side,
    16 to 48 pixels, so that a frame shown on a slide reads at about the
    size of the slide's own text."""
    return max(16, min(48, round(grid_extent / 30)))


def panel_width(text_size: int) -> int:
    """Width of the side panel for text of ``text_size`` pixels."""
    return round(PANEL_WIDTH * text_size / BASE_TEXT)


class TextParts:
    """The caption strip and the side panel of one export, as palette indices."""

    def __init__(self, renderer, text_size: int):
        self.r = renderer
        settings = renderer.settings
        ui = text_size / BASE_TEXT
        self.ui = ui
        sans, mono = round(13 * ui), round(12 * ui)
        self.sans, self.sans_bold = _Font("sans", sans), _Font("sans_bold", sans)
        self.mono, self.mono_bold = _Font("mono", mono), _Font("mono_bold", mono)
        self.line = round(18 * ui)
        self.pad = round(8 * ui)
        self.panel_width = panel_width(text_size)
        trace = renderer.trace
        self.last = len(trace) - 1
        # Step, pseudo-code line, and as many lines for the step's values as
        # the steps need (two at least), so that no value is cut.
        self.value_lines = self._value_lines(renderer)
        self.caption_height = (2 + self.value_lines) * self.line + 2 * round(5 * ui)
        self.code = [shown(line.text) for line in trace.code]
        self.number_width = self.mono_bold.width("\u25b6 " + str(len(self.code))) + round(6 * ui)
        text_width = self.panel_width - 2 * self.pad - self.number_width
        self.wrapped = [_wrap(text, self.mono_bold, text_width) for text in self.code]
        code_height = self.pad + self.line + sum(len(rows) for rows in self.wrapped) * self.line \
            + self.pad
        variables_height = self.pad + self.line * (1 + 10) + self.pad  # title and 10 rows
        # The panel takes the grid's height (no band under the grid): the
        # pseudo-code scrolls to keep the current line in view where it is
        # longer, as the window's panel does; at least MIN_CODE_ROWS show.
        shortest = self.pad + self.line * (1 + MIN_CODE_ROWS) + self.pad
        grid_height = renderer.grid_size[1]
        if settings.panel == "both":  # the variables take what the code leaves, 4 rows at least
            self.code_height = max(shortest, min(code_height, grid_height // 2))
            variables_height = max(self.pad + self.line * 5 + self.pad,
                                   grid_height - self.code_height)
        else:
            self.code_height = max(shortest, min(code_height, grid_height))
        self.panel_height = {"code": self.code_height, "variables": variables_height,
                             "both": self.code_height + variables_height, "none": 0,
                             "tables": shortest}[settings.panel]
        self._tables = (TableIndex(renderer.trace, settings.numbers) if settings.panel == "tables"
                        else None)
        self._code_cache: dict[int | None, np.ndarray] = {}
        self._code_rows: dict[int, Image.Image] = {}

    def _value_lines(self, renderer) -> int:
        """The lines the caption's values take at the most crowded of up to
        VALUE_SAMPLES steps spread over the run (at least 2, at most
        MAX_VALUE_LINES); the frame keeps one size for every step."""
        trace, settings = renderer.trace, renderer.settings
        if not settings.caption:
            return 2
        room = renderer.grid_size[0] + (self.panel_width if settings.panel != "none" else 0) \
            - 2 * self.pad
        count = len(trace)
        steps = range(count) if count <= VALUE_SAMPLES else sorted(
            {round(k * (count - 1) / (VALUE_SAMPLES - 1)) for k in range(VALUE_SAMPLES)})
        needed = 2
        for index in steps:
            state = FrameState(index, trace.step(index), None, trace.variables_at(index), [])
            needed = max(needed, len(_pack(self.caption_parts(state), VALUE_SEPARATOR, self.mono,
                                           room, MAX_VALUE_LINES)))
        return min(needed, MAX_VALUE_LINES)

    def allocate(self) -> None:
        r = self.r
        width, _ = r.size
        self.caption_size = (width, max(1, r.caption_height))
        self.panel_size = (max(1, r.panel_width), r.body_height)

    # ------------------------------------------------------------ drawing
    def _canvas(self, size, background: str):
        image = Image.new("RGBA", size, background)
        return image, ImageDraw.Draw(image)

    def _indices(self, image: Image.Image) -> np.ndarray:
        return self.r.colours.indices(np.asarray(image))

    def _text(self, draw, x, baseline, text, face: _Font, color, width=None) -> int:
        """Draw ``text`` (cut with an ellipsis to ``width``); its width."""
        if width is not None:
            text = face.elided(text, max(0, int(width)))
        if text:
            draw.text((int(x), int(baseline)), text, font=face.face, fill=color, anchor="ls")
        return face.width(text)

    def _baseline(self, top: int, face: _Font) -> int:
        return top + (self.line + face.ascent - face.descent) // 2

    # ------------------------------------------------------------ caption
    def caption(self, state) -> np.ndarray:
        """Three lines under the grid: what the step does, the line of
        pseudo-code it runs, and the values it changes."""
        image, draw = self._canvas(self.caption_size, self.r.theme.caption)
        # Line 2 (first, so that no other line's glyphs are covered): the
        # pseudo-code line, drawn once per line and pasted.
        image.paste(self._code_row(state.step.line), (0, round(5 * self.ui) + self.line))
        self.paint_caption(draw, state, code_row=False)
        return self._indices(image)

    def paint_caption(self, draw, state, code_row: bool = True) -> None:
        """The caption's lines onto ``draw`` (Pillow's, or a vector frame's:
        app/render/vector.py), its top left at (0, 0); ``code_row`` false
        leaves out line 2, which ``caption`` pastes."""
        theme = self.r.theme
        width = self.caption_size[0]
        draw.rectangle((0, 0, width - 1, 0), fill=theme.border)
        top = round(5 * self.ui)
        x0, room = self.pad, width - 2 * self.pad
        if code_row:  # line 2: the pseudo-code line, numbered as in the panel
            self._paint_code_row(draw, state.step.line, top + self.line)
        # Line 1: "Step 12 of 40 · plots (5, 3) · branch NE", bold parts bold.
        text = step_caption(state, self.last, bold=lambda part: f"\x01{part}\x02")
        x, baseline = x0, self._baseline(top, self.sans)
        for k, piece in enumerate(re.split(r"[\x01\x02]", text)):
            if not piece or x >= x0 + room:
                continue
            face = self.sans_bold if k % 2 == 1 else self.sans
            x += self._text(draw, x, baseline, piece, face, theme.text, x0 + room - x)
        # Lines 3 and on: the values of this step, then what the algorithm
        # explains (its decision and update), each labelled; whole parts
        # wrap to the next line.
        for k, line in enumerate(self.value_texts(state)):
            baseline = self._baseline(top + (2 + k) * self.line, self.mono)
            self._text(draw, x0, baseline, line, self.mono, theme.text, room)

    def value_texts(self, state) -> list[str]:
        """The caption's value lines at this step, before any cut to width."""
        room = self.caption_size[0] - 2 * self.pad
        return _pack(self.caption_parts(state), VALUE_SEPARATOR, self.mono, room,
                     self.value_lines)

    def caption_parts(self, state) -> list[str]:
        """The caption's values, each labelled: "name = value" for the
        step's values, "name: text" for what the algorithm explains."""
        rows = key_values(self.r.trace, state, self.r.settings.numbers)
        names = {name for name, _ in rows}
        extra = [(n, t) for n, t in self._rows(state.index)[len(state.variables):]
                 if n not in names]
        return [shown(f"{name} = {text}") for name, text in rows] \
            + [f"{name}: {text}" for name, text in extra]

    def _code_row(self, line: int) -> Image.Image:
        """The caption's second line for pseudo-code line ``line``, drawn
        once per line (it is the same at every step that runs the line)."""
        row = self._code_rows.get(line)
        if row is None:
            row, draw = self._canvas((self.caption_size[0], self.line), self.r.theme.caption)
            self._paint_code_row(draw, line, 0)
            self._code_rows[line] = row
        return row

    def _paint_code_row(self, draw, line: int, top: int) -> None:
        theme = self.r.theme
        x0, baseline = self.pad, self._baseline(top, self.mono)
        if 0 <= line < len(self.code):
            x = x0 + self._text(draw, x0, baseline, f"{line + 1}: ", self.mono, theme.muted)
            self._text(draw, x, baseline, self.code[line].strip(), self.mono, theme.text,
                       self.caption_size[0] - self.pad - x)

    def grid_labels(self, frame: np.ndarray, labels, to_pixel, colour: str | None = None) -> None:
        """Write labels (x, y, text in grid units) onto the grid part of
        ``frame`` (palette indices), in ``colour`` (the guide colour by
        default), just right of and above their point."""
        colours = self.r.colours
        face = self.sans_bold
        for left, top, text in self.label_places(labels, to_pixel):
            width, height = face.width(text) + 2, face.ascent + face.descent
            region = frame[top:top + height, left:left + width]
            patch = Image.fromarray(colours.rgb[region], "RGB")
            ImageDraw.Draw(patch).text((1, 0), text, font=face.face,
                                       fill=colour or self.r.theme.palette.guide, anchor="la")
            rgba = np.dstack([np.asarray(patch), np.full(region.shape, 255, np.uint8)])
            frame[top:top + height, left:left + width] = colours.indices(rgba)

    def label_places(self, labels, to_pixel) -> list[tuple[int, int, str]]:
        """(left, top, text) of each label written on the grid (in the bold
        sans face): right of and above its point, kept within the grid; a
        label that would cover one already placed is left out."""
        gw, gh = self.r.grid_size
        x0 = self.r.grid_left
        face = self.sans_bold
        placed, boxes = [], []
        for x, y, text in labels:
            left, top = to_pixel(x, y)
            width, height = face.width(text) + 2, face.ascent + face.descent
            left = int(min(max(x0, left + 4), x0 + gw - width))
            top = int(min(max(0, top - height - 2), gh - height))
            box = (left, top, left + width, top + height)
            if left < 0 or top < 0 or any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3]
                                          and b[1] < box[3] for b in boxes):
                continue
            boxes.append(box)
            placed.append((left, top, text))
        return placed

    def _rows(self, index: int) -> list:
        """The variables panel's rows at step ``index``, as a person reads
        them (app/model/notation.py)."""
        return [(shown(name), shown(text)) for name, text in
                shown_rows(self.r.spec, self.r.trace, index, self.r.settings.numbers)]

    # -------------------------------------------------------------- panel
    def panel(self, state) -> np.ndarray:
        if self.r.settings.panel == "code":
            return self._code_panel(state.step.line)
        image, draw = self._canvas(self.panel_size, self.r.theme.panel)
        self.paint_panel(draw, state)
        return self._indices(image)

    def paint_panel(self, draw, state) -> None:
        """The side panel onto ``draw`` (Pillow's or a vector frame's), its
        top left at (0, 0): pseudo-code, variables, both, or the tables."""
        kind = self.r.settings.panel
        if kind == "tables":
            self._paint_tables(draw, state.index)
        else:
            top = 0
            if kind in ("code", "both"):
                self._paint_code(draw, state.step.line)
                top = self.code_height
            if kind != "code":
                self._paint_variables(draw, state, top)
        self._paint_border(draw)

    def _code_panel(self, line) -> np.ndarray:
        cached = self._code_cache.get(line)
        if cached is None:
            image, draw = self._canvas(self.panel_size, self.r.theme.panel)
            self._paint_code(draw, line)
            self._paint_border(draw)
            cached = self._code_cache[line] = self._indices(image)
        return cached

    def _paint_border(self, draw) -> None:
        draw.rectangle((0, 0, 0, self.panel_size[1] - 1), fill=self.r.theme.border)

    def _paint_code(self, draw, current) -> None:
        theme = self.r.theme
        width = self.panel_size[0]
        top = self.pad
        self._text(draw, self.pad, self._baseline(top, self.sans_bold), self.r.spec.title,
                   self.sans_bold, theme.muted, width - 2 * self.pad)
        top += self.line
        room = (self.code_height - top - self.pad) // self.line
        skip = self._first_row(current, room)
        for number, rows in enumerate(self.wrapped):
            if skip >= len(rows):
                skip -= len(rows)
                continue
            rows, skip = rows[skip:], 0
            if room <= 0:
                break
            rows, room = rows[:room], room - len(rows[:room])
            here = number == current
            if here:
                draw.rectangle((1, top, width - 1, top + len(rows) * self.line - 1),
                               fill=theme.current_line)
            face = self.mono_bold if here else self.mono
            label = ("\u25b6 " if here else "") + str(number + 1)
            label_x = self.pad + self.number_width - round(6 * self.ui) - face.width(label)
            self._text(draw, label_x, self._baseline(top, face), label, face,
                       theme.current_edge if here else theme.line_number)
            for row in rows:
                self._text(draw, self.pad + self.number_width, self._baseline(top, face), row,
                           face, theme.text)
                top += self.line

    def _paint_tables(self, draw, index: int) -> None:
        """The run's tables as of step ``index`` (the scan line's ET and
        AET), one under the other; a table taken at this very step is
        titled in the colour of a changed value."""
        theme = self.r.theme
        width, height = self.panel_size
        top = self.pad
        tables = self._tables.at(index) if self._tables else []
        if not tables:
            self._text(draw, self.pad, self._baseline(top, self.sans), "No table at this step",
                       self.sans, theme.muted)
        for table in tables:
            if top + 2 * self.line > height - self.pad:
                break
            title = f"{table.name}  ({len(table.rows)} row{'s' if len(table.rows) != 1 else ''})"
            self._text(draw, self.pad, self._baseline(top, self.sans_bold), title,
                       self.sans_bold, theme.changed if table.fresh else theme.muted)
            top += self.line
            widths = [max([self.mono.width(str(c)) for c in [name] + [r[k] for r in table.rows]])
                      + self.mono.width("  ") for k, name in enumerate(table.columns)]
            rows = [table.columns] + list(table.rows)
            fits = max(1, (height - top - self.pad) // self.line - 1)
            for r, row in enumerate(rows[:fits]):
                x = self.pad
                face = self.mono_bold if r == 0 or (r - 1) in table.changed_rows else self.mono
                colour = theme.muted if r == 0 else (
                    theme.changed if (r - 1) in table.changed_rows else theme.text)
                for k, cell in enumerate(row):
                    self._text(draw, x, self._baseline(top, face), str(cell), face, colour,
                               width - self.pad - x)
                    x += widths[k]
                top += self.line
            if len(rows) > fits:
                self._text(draw, self.pad, self._baseline(top, self.sans),
                           f"{ELLIPSIS} {len(rows) - fits} more", self.sans, theme.muted)
                top += self.line
            top += self.pad

    def _first_row(self, current, room: int) -> int:
        """The first wrapped row shown: 0 when all fit, else the row that
        puts the current line a third of the way down."""
        total = sum(len(rows) for rows in self.wrapped)
        if total <= room or current is None or not 0 <= current < len(self.wrapped):
            return 0
        before = sum(len(rows) for rows in self.wrapped[:current])
        wanted = max(0, min(before - room // 3, total - room))
        # Start at the first row of a line, never on a continuation row: the
        # line start at or before ``wanted`` when the current line still
        # fits below it, else the next line start (never past the current line).
        starts = [0]
        for rows in self.wrapped:
            starts.append(starts[-1] + len(rows))
        down = max(start for start in starts if start <= wanted)
        up = min(start for start in starts if start >= wanted)
        if down + room >= before + len(self.wrapped[current]):
            return down
        return up if up <= before else wanted

    def _paint_variables(self, draw, state, top: int) -> None:
        theme = self.r.theme
        width, height = self.panel_size
        top += self.pad
        self._text(draw, self.pad, self._baseline(top, self.sans_bold), "Variables",
                   self.sans_bold, theme.muted)
        top += self.line
        rows = self._rows(state.index)
        # The rows of the step before: values that changed are marked.
        before = dict(self._rows(state.index - 1)) if state.index else {}
        fits = max(0, (height - top - self.pad) // self.line)
        shown = rows if len(rows) <= fits else rows[:max(0, fits - 1)]
        name_width = round(110 * self.ui)
        for name, text in shown:
            changed = name in before and before[name] != text
            baseline = self._baseline(top, self.mono)
            self._text(draw, self.pad, baseline, name, self.sans, theme.muted, name_width - 6)
            self._text(draw, self.pad + name_width, baseline, text,
                       self.mono_bold if changed else self.mono,
                       theme.changed if changed else theme.text,
                       width - 2 * self.pad - name_width)
            top += self.line
        if len(shown) < len(rows):
            self._text(draw, self.pad, self._baseline(top, self.sans),
                       f"{ELLIPSIS} {len(rows) - len(shown)} more", self.sans, theme.muted)


def _pack(parts: list[str], separator: str, face: _Font, width: int, lines: int) -> list[str]:
    """``parts`` joined by ``separator`` into at most ``lines`` lines of
    ``width`` pixels, a part never split between lines (only a part
    too long for a line of its own, or the last line's overflow, is
    cut by the caller)."""
    result, line = [], ""
    for part in parts:
        candidate = f"{line}{separator}{part}" if line else part
        if line and face.width(candidate) > width and len(result) < lines - 1:
            result.append(line)
            line = part
        else:
            line = candidate
    if line:
        result.append(line)
    return result


def _wrap(text: str, face: _Font, width: int) -> list[str]:
    """A line of code broken at spaces to fit ``width`` pixels; continuation
    rows are indented past the line's own indent."""
    if face.width(text) <= width:
        return [text]
    indent = text[:len(text) - len(text.lstrip())] + "    "
    rows, row = [], ""
    for word in re.split(r"(?<= )", text):
        candidate = row + word
        if row and face.width(candidate.rstrip()) > width:
            rows.append(row.rstrip())
            row = indent + word.lstrip()
        else:
            row = candidate
        while face.width(row) > width and len(row) > len(indent) + 1:
            # A single word longer than the row: cut it.
            cut = len(row)
            while cut > len(indent) + 1 and face.width(row[:cut]) > width:
                cut -= 1
            rows.append(row[:cut])
            row = indent + row[cut:]
    if row.strip():
        rows.append(row.rstrip())
    return rows or [text]
