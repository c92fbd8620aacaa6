"""The text of an exported frame, drawn with Pillow: the caption strip under
the grid and the side panel with the pseudo-code and the variables.

The fonts are DejaVu Sans and DejaVu Sans Mono (the system's, from
fonts-dejavu-core); where they are missing, Pillow's own font stands in.
Text is antialiased; its edge colours take the nearest entry of the
export's palette, which holds shades between each text colour and its
background.
"""
from __future__ import annotations

import re
from functools import lru_cache

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from app.render.frame import key_values, step_caption

ELLIPSIS = "\u2026"
_FONT_FILES = {"sans": "DejaVuSans.ttf", "sans_bold": "DejaVuSans-Bold.ttf",
               "mono": "DejaVuSansMono.ttf", "mono_bold": "DejaVuSansMono-Bold.ttf"}
_FONT_FOLDERS = ("/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/TTF",
                 "/usr/share/fonts/dejavu", "/usr/local/share/fonts")


@lru_cache(maxsize=None)
def font(kind: str, pixels: int) -> ImageFont.FreeTypeFont:
    """The font of ``kind`` (sans, sans_bold, mono, mono_bold), ``pixels`` high."""
    name = _FONT_FILES[kind]
    for candidate in (name, *(f"{folder}/{name}" for folder in _FONT_FOLDERS)):
        try:
            return ImageFont.truetype(candidate, pixels)
        except OSError:
            continue
    return ImageFont.load_default(pixels)


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


class TextParts:
    """The caption strip and the side panel of one export, as palette indices."""

    def __init__(self, renderer, grid_extent: int):
        self.r = renderer
        settings = renderer.settings
        # Text grows with large frames so that it keeps its size on a slide.
        ui = max(1.0, min(3.0, grid_extent / 640))
        self.ui = ui
        sans, mono = round(13 * ui), round(12 * ui)
        self.sans, self.sans_bold = _Font("sans", sans), _Font("sans_bold", sans)
        self.mono, self.mono_bold = _Font("mono", mono), _Font("mono_bold", mono)
        self.line = round(18 * ui)
        self.pad = round(8 * ui)
        self.caption_height = 3 * self.line + 2 * round(5 * ui)
        self.panel_width = round(360 * ui)

        trace = renderer.trace
        self.last = len(trace) - 1
        self.code = [line.text for line in trace.code]
        self.number_width = self.mono_bold.width("\u25b6 " + str(len(self.code))) + round(6 * ui)
        text_width = self.panel_width - 2 * self.pad - self.number_width
        self.wrapped = [_wrap(text, self.mono_bold, text_width) for text in self.code]
        code_height = self.pad + self.line + sum(len(rows) for rows in self.wrapped) * self.line \
            + self.pad
        variables_height = self.pad + self.line * (1 + 10) + self.pad  # title and 10 rows
        self.code_height = code_height
        self.panel_height = {"code": code_height, "variables": variables_height,
                             "both": code_height + variables_height, "none": 0}[settings.panel]
        self._code_cache: dict[int | None, np.ndarray] = {}
        self._code_rows: dict[int, Image.Image] = {}

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
        theme = self.r.theme
        image, draw = self._canvas(self.caption_size, theme.caption)
        width = image.width
        draw.rectangle((0, 0, width - 1, 0), fill=theme.border)
        top = round(5 * self.ui)
        x0, room = self.pad, width - 2 * self.pad
        # Line 2 (first, so that no other line's glyphs are covered): the
        # pseudo-code line, numbered as in the panel.
        image.paste(self._code_row(state.step.line), (0, top + self.line))
        # Line 1: "Step 12 of 40 · plots (5, 3) · branch NE", bold parts bold.
        text = step_caption(state, self.last, bold=lambda part: f"\x01{part}\x02")
        x, baseline = x0, self._baseline(top, self.sans)
        for k, piece in enumerate(re.split(r"[\x01\x02]", text)):
            if not piece or x >= x0 + room:
                continue
            face = self.sans_bold if k % 2 == 1 else self.sans
            x += self._text(draw, x, baseline, piece, face, theme.text, x0 + room - x)
        # Line 3: the values of this step, then what the algorithm explains.
        rows = key_values(self.r.trace, state)
        names = {name for name, _ in rows}
        extra = [(n, t) for n, t in self._rows(state.index)[len(state.variables):]
                 if n not in names]
        parts = [f"{name} = {text}" for name, text in rows] + [text for _, text in extra]
        baseline = self._baseline(top + 2 * self.line, self.mono)
        self._text(draw, x0, baseline, "   \u00b7   ".join(parts), self.mono, theme.text, room)
        return self._indices(image)

    def _code_row(self, line: int) -> Image.Image:
        """The caption's second line for pseudo-code line ``line``, drawn
        once per line (it is the same at every step that runs the line)."""
        row = self._code_rows.get(line)
        if row is None:
            theme = self.r.theme
            row, draw = self._canvas((self.caption_size[0], self.line), theme.caption)
            x0, baseline = self.pad, self._baseline(0, self.mono)
            if 0 <= line < len(self.code):
                x = x0 + self._text(draw, x0, baseline, f"{line + 1}: ", self.mono, theme.muted)
                self._text(draw, x, baseline, self.code[line].strip(), self.mono, theme.text,
                           row.width - self.pad - x)
            self._code_rows[line] = row
        return row

    def grid_labels(self, frame: np.ndarray, labels, to_pixel) -> None:
        """Write the guides' labels (x, y, text in grid units) onto the
        grid part of ``frame`` (palette indices), in the guide colour, just
        right of and above their point."""
        colours = self.r.colours
        gw, gh = self.r.grid_size
        face = self.sans_bold
        for x, y, text in labels:
            left, top = to_pixel(x, y)
            width, height = face.width(text) + 2, face.ascent + face.descent
            left = int(min(max(0, left + 4), gw - width))
            top = int(min(max(0, top - height - 2), gh - height))
            if left < 0 or top < 0:
                continue
            region = frame[top:top + height, left:left + width]
            patch = Image.fromarray(colours.rgb[region], "RGB")
            ImageDraw.Draw(patch).text((1, 0), text, font=face.face,
                                       fill=self.r.theme.palette.guide, anchor="la")
            rgba = np.dstack([np.asarray(patch), np.full(region.shape, 255, np.uint8)])
            frame[top:top + height, left:left + width] = colours.indices(rgba)

    def _rows(self, index: int) -> list:
        """The variables panel's rows at step ``index``."""
        return self.r.spec.panel_rows(self.r.trace, index)

    # -------------------------------------------------------------- panel
    def panel(self, state) -> np.ndarray:
        kind = self.r.settings.panel
        if kind == "code":
            return self._code_panel(state.step.line)
        image, draw = self._canvas(self.panel_size, self.r.theme.panel)
        top = 0
        if kind == "both":
            self._paint_code(draw, state.step.line)
            top = self.code_height
        self._paint_variables(draw, state, top)
        self._paint_border(draw)
        return self._indices(image)

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
        for number, rows in enumerate(self.wrapped):
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
