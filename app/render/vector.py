"""Vector frames for LaTeX and slides: SVG files, a PDF with a page per
frame, and a Beamer snippet that shows the PDF's pages as overlays.

A frame is described once as a list of shapes (``Drawing``): the cells
(runs of equal colour per row, so a grid of a million cells stays small),
the grid lines, the ideal primitive, the outlines of the step's pixel and
its candidates, the caption and the pseudo-code with the current line
marked. The SVG and PDF backends draw the same shapes, so the two agree,
and the colours and marks are those of the raster frames (the same
palette, ``frame_marks`` and ``step_caption``). One unit is one raster
pixel at CELL units per cell; text is text, not pixels.

The writers take part in the export's writer protocol: instead of the
raster image they are given the step (``grab_step(renderer, index)``),
because a vector frame is drawn from the state, not from pixels.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
import numpy as np

from app.model.escape import latex_comment, latex_file_name, latex_text, xml_text
from app.model.exact import shown_rows
from app.render.compose import OUTLINE_STYLE, compose
from app.render.frame import frame_marks, key_values, step_caption
from app.render.reasoning import step_guides
from app.render.settings import ExportError
from app.render.text import font_path
from app.model.files import target_of
from app.render.writers import PngFolderWriter, temporary_beside

CELL = 20        # units per cell
FONT = 12        # units, caption and pseudo-code
PAD = 8          # units around the text parts
MONO_WIDTH = 0.6  # a monospaced character's advance, in font sizes


@dataclass
class Drawing:
    """One frame as shapes, in units with y down (see the module text)."""

    width: float
    height: float
    background: str
    shapes: list = field(default_factory=list)
    title: str = ""  # the scene's title: the SVG's <title>

    def rect(self, x, y, w, h, fill=None, stroke=None, width=0.0):
        self.shapes.append(("rect", x, y, w, h, fill, stroke, width))

    def line(self, points, stroke, width, closed=False):
        self.shapes.append(("line", [tuple(map(float, p)) for p in points], stroke, width, closed))

    def text(self, x, y, text, colour, mono=False, bold=False, size=FONT):
        self.shapes.append(("text", x, y, text, colour, mono, bold, size))

    def texts(self) -> list[str]:
        return [shape[3] for shape in self.shapes if shape[0] == "text"]


# ------------------------------------------------------------------ drawing
def draw_frame(renderer, index: int) -> Drawing:
    """Frame ``index`` of the renderer's export as a Drawing."""
    trace, settings, theme = renderer.trace, renderer.settings, renderer.theme
    palette = theme.palette
    state = trace.state_at(index)
    code = settings.panel in ("code", "both")
    rows = (shown_rows(renderer.spec, trace, index, settings.numbers)
            if settings.panel in ("variables", "both") else [])
    panel_width = _code_width(trace) if code else (_rows_width(rows) if rows else 0)
    grid_w, grid_h = trace.width * CELL, trace.height * CELL
    caption_h = 3 * (FONT + 4) + 2 * PAD if settings.caption else 0
    code_h = len(trace.code) * (FONT + 4) + 2 * PAD if code else 0
    rows_h = (len(rows) + 1) * (FONT + 4) + 2 * PAD if rows else 0
    body_h = max(grid_h, code_h + rows_h)
    drawing = Drawing(grid_w + panel_width, body_h + caption_h, palette.outside,
                      title=renderer.scene.title)
    y_of = (lambda y: y) if renderer.y_down else (lambda y: trace.height - y)
    _cells(drawing, state.raster, palette, y_of, trace.height)
    if renderer.grid_lines:
        _grid_lines(drawing, trace.width, trace.height, palette.grid)
    marks = frame_marks(state, renderer.paths, renderer.differences, settings.highlight,
                        settings.primitive)
    for points, closed in marks.paths:
        drawing.line([(x * CELL, y_of(y) * CELL) for x, y in points], palette.primitive,
                     2.0, closed)
    _outlines(drawing, marks, palette, y_of)
    if settings.reasoning and settings.highlight:
        _guides(drawing, step_guides(trace, state, renderer.ideal, renderer.y_down), palette, y_of)
    if panel_width:
        drawing.rect(grid_w, 0, panel_width, body_h, fill=theme.panel)
    if code:
        _code_panel(drawing, trace, state.step.line, grid_w, panel_width, theme)
    if rows:
        before = dict(shown_rows(renderer.spec, trace, index - 1, settings.numbers)) if index else {}
        _variables(drawing, rows, before, grid_w, code_h, theme)
    if caption_h:
        _caption(drawing, trace, state, body_h, theme, settings.numbers)
    return drawing


def _cells(drawing, raster, palette, y_of, height) -> None:
    colours = compose(raster, None, palette, 1, False)[..., :3]  # (H, W, 3), row 0 at y = 0
    background = tuple(int(palette.background[i:i + 2], 16) for i in (1, 3, 5))
    drawing.rect(0, 0, colours.shape[1] * CELL, height * CELL, fill=palette.background)
    for y in range(colours.shape[0]):
        row = colours[y]
        change = np.flatnonzero(np.any(row[1:] != row[:-1], axis=1)) + 1
        starts = np.concatenate(([0], change))
        ends = np.concatenate((change, [len(row)]))
        top = min(y_of(y), y_of(y + 1)) * CELL
        for a, b in zip(starts.tolist(), ends.tolist()):
            colour = tuple(int(c) for c in row[a])
            if colour != background:
                drawing.rect(a * CELL, top, (b - a) * CELL, CELL, fill="#%02x%02x%02x" % colour)


def _grid_lines(drawing, width, height, colour) -> None:
    for x in range(width + 1):
        drawing.line([(x * CELL, 0), (x * CELL, height * CELL)], colour, 0.5)
    for y in range(height + 1):
        drawing.line([(0, y * CELL), (width * CELL, y * CELL)], colour, 0.5)


def _outlines(drawing, marks, palette, y_of) -> None:
    def box(x0, x1, y, kind, colour):
        style = OUTLINE_STYLE[kind]
        inset = style.inset * CELL + style.width / 2
        top = min(y_of(y), y_of(y + 1)) * CELL
        drawing.rect(x0 * CELL + inset, top + inset, (x1 - x0) * CELL - 2 * inset,
                     CELL - 2 * inset, stroke=colour, width=style.width)

    for x, y in ([] if marks.differences is None else marks.differences.tolist()):
        box(x, x + 1, y, "difference", palette.difference)
    for a, b, y in marks.spans:
        box(a, b, y, "span", palette.current)
    for x, y in marks.current:
        box(x, x + 1, y, "current", palette.current)
    for x, y in marks.candidates:
        box(x, x + 1, y, "candidate", palette.candidate)


def _guides(drawing, guides, palette, y_of) -> None:
    """The step's reasoning (app/render/reasoning.py), as the GIF draws it:
    lines, dots (as small squares) and labels in the guide colour."""
    widths = {"pair": 4.0, "drop": 1.5}
    for x0, y0, x1, y1, role in guides.lines:
        drawing.line([(x0 * CELL, y_of(y0) * CELL), (x1 * CELL, y_of(y1) * CELL)],
                     palette.guide, widths.get(role, 1.0))
    for x, y, role in guides.dots:
        size = CELL * (0.3 if role in ("crossing", "midpoint", "sample") else 0.18)
        colour = palette.current if role == "sample" else palette.guide
        drawing.rect(x * CELL - size / 2, y_of(y) * CELL - size / 2, size, size,
                     fill=None if role == "miss" else colour, stroke=colour, width=0.5)
    for x, y, text in guides.labels:
        drawing.text(x * CELL + 3, y_of(y) * CELL - 3, text, palette.guide, bold=True)


def _code_width(trace) -> float:
    longest = max((len(line.text) for line in trace.code), default=0) + 6
    return longest * FONT * MONO_WIDTH + 2 * PAD


def _rows_width(rows) -> float:
    longest = max((len(f"{name}  {text}") for name, text in rows), default=0) + 4
    return max(longest * FONT * MONO_WIDTH, 160) + 2 * PAD


def _variables(drawing, rows, before, left, top, theme) -> None:
    step = FONT + 4
    drawing.text(left + PAD, top + PAD + FONT, "Variables", theme.muted, bold=True)
    name_width = max(len(name) for name, _ in rows) * FONT * MONO_WIDTH + FONT
    for k, (name, text) in enumerate(rows, 1):
        baseline = top + PAD + k * step + FONT
        changed = name in before and before[name] != text
        drawing.text(left + PAD, baseline, name, theme.muted, mono=True)
        drawing.text(left + PAD + name_width, baseline, text,
                     theme.changed if changed else theme.text, mono=True, bold=changed)


def _code_panel(drawing, trace, current, left, width, theme) -> None:
    step = FONT + 4
    for number, line in enumerate(trace.code):
        top = PAD + number * step
        if number == current:
            drawing.rect(left, top, width, step, fill=theme.current_line)
        colour = theme.current_edge if number == current else theme.line_number
        drawing.text(left + PAD, top + FONT, f"{number + 1:>2}", colour, mono=True)
        drawing.text(left + PAD + 3 * FONT * MONO_WIDTH, top + FONT, line.text, theme.text,
                     mono=True, bold=number == current)


def _caption(drawing, trace, state, top, theme, numbers: str) -> None:
    drawing.rect(0, top, drawing.width, drawing.height - top, fill=theme.caption)
    drawing.text(PAD, top + PAD + FONT, step_caption(state, len(trace) - 1), theme.text, bold=True)
    values = "   ".join(f"{name} = {text}" for name, text in key_values(trace, state, numbers))
    if values:
        drawing.text(PAD, top + PAD + 2 * FONT + 4, values, theme.muted)
    line = trace.code[state.step.line].text.strip()
    drawing.text(PAD, top + PAD + 3 * FONT + 8, line, theme.muted, mono=True)


# ---------------------------------------------------------------------- SVG
def to_svg(drawing: Drawing) -> str:
    """The drawing as a standalone SVG document."""
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{drawing.width:g}" '
           f'height="{drawing.height:g}" viewBox="0 0 {drawing.width:g} {drawing.height:g}">']
    if drawing.title:
        out.append(f"<title>{xml_text(drawing.title)}</title>")
    out.append(f'<rect width="100%" height="100%" fill="{drawing.background}"/>')
    for shape in drawing.shapes:
        out.append(_svg_shape(shape))
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _svg_shape(shape) -> str:
    kind = shape[0]
    if kind == "rect":
        _, x, y, w, h, fill, stroke, width = shape
        paint = f'fill="{fill}"' if fill else 'fill="none"'
        if stroke:
            paint += f' stroke="{stroke}" stroke-width="{width:g}"'
        return f'<rect x="{x:g}" y="{y:g}" width="{w:g}" height="{h:g}" {paint}/>'
    if kind == "line":
        _, points, stroke, width, closed = shape
        tag = "polygon" if closed else "polyline"
        coords = " ".join(f"{x:g},{y:g}" for x, y in points)
        return (f'<{tag} points="{coords}" fill="none" stroke="{stroke}" '
                f'stroke-width="{width:g}" stroke-linejoin="round"/>')
    _, x, y, text, colour, mono, bold, size = shape
    # An SVG names its fonts: a viewer without DejaVu uses its own sans-serif or monospace.
    family = "DejaVu Sans Mono, monospace" if mono else "DejaVu Sans, sans-serif"
    weight = ' font-weight="bold"' if bold else ""
    return (f'<text x="{x:g}" y="{y:g}" font-family="{xml_text(family)}" font-size="{size:g}" '
            f'fill="{colour}" xml:space="preserve"{weight}>{xml_text(text)}</text>')


# ---------------------------------------------------------------------- PDF
def _pdf_page(pdf, drawing: Drawing) -> None:
    pdf.add_page(format=(drawing.width, drawing.height))
    pdf.set_fill_color(drawing.background)
    pdf.rect(0, 0, drawing.width, drawing.height, style="F")
    for shape in drawing.shapes:
        kind = shape[0]
        if kind == "rect":
            _, x, y, w, h, fill, stroke, width = shape
            if fill:
                pdf.set_fill_color(fill)
            if stroke:
                pdf.set_draw_color(stroke)
                pdf.set_line_width(width)
            pdf.rect(x, y, w, h, style=("F" if fill else "") + ("D" if stroke else ""))
        elif kind == "line":
            _, points, stroke, width, closed = shape
            pdf.set_draw_color(stroke)
            pdf.set_line_width(width)
            pdf.polyline(points, style="D") if not closed else pdf.polygon(points, style="D")
        else:
            _, x, y, text, colour, mono, bold, size = shape
            pdf.set_font("mono" if mono else "sans", "B" if bold else "", size)
            pdf.set_text_color(colour)
            pdf.text(x, y, text)


def _new_pdf():
    from fpdf import FPDF  # loaded only when a PDF is written

    pdf = FPDF(unit="pt")
    pdf.set_auto_page_break(False)
    pdf.set_margins(0, 0, 0)
    for family, style, kind in (("sans", "", "sans"), ("sans", "B", "sans_bold"),
                                ("mono", "", "mono"), ("mono", "B", "mono_bold")):
        pdf.add_font(family, style, font_path(kind))  # shipped: no system font is asked for
    return pdf


# ------------------------------------------------------------------ writers
class SvgFolderWriter(PngFolderWriter):
    """SVG frames frame_0000.svg, ... in a folder, staged and moved into
    place together as the PNG frames are (see PngFolderWriter). With
    ``only``, just the frames of those steps (the scene's bookmarks, say)."""

    SUFFIX = ".svg"

    def __init__(self, directory, only=None, replace: bool = False):
        super().__init__(directory, replace)
        self.only = None if only is None else set(only)

    def grab_step(self, renderer, index: int) -> None:
        if self.only is not None and index not in self.only:
            return
        name = f"frame_{len(self.names):0{self.width}d}.svg"
        try:
            (self.temporary / name).write_text(to_svg(draw_frame(renderer, index)),
                                               encoding="utf-8")
        except OSError as error:
            raise self._failed(error) from None
        self.names.append(name)


class PdfWriter:
    """A PDF with one page per exported frame (or per step of ``only``),
    written to a temporary file beside ``path`` and renamed over it at the end."""

    def __init__(self, path, only=None):
        self.path = Path(path)
        self.only = None if only is None else set(only)
        self.temporary: Path | None = None
        self.pages = 0

    def setup(self, size, count, palette, transparent) -> None:
        self.pdf = _new_pdf()
        self.target = target_of(self.path, ExportError)
        self.temporary = temporary_beside(self.target)

    def grab_step(self, renderer, index: int) -> None:
        if self.only is not None and index not in self.only:
            return
        _pdf_page(self.pdf, draw_frame(renderer, index))
        self.pages += 1

    def finish(self) -> None:
        try:
            self.pdf.output(str(self.temporary))
            os.replace(self.temporary, self.target)
        except OSError as error:
            self.abort()
            raise ExportError(f"cannot write {self.path} ({error.strerror or error})") from None

    def abort(self) -> None:
        if self.temporary is not None:
            self.temporary.unlink(missing_ok=True)


def beamer_snippet(pdf_name: str, pages: int, title: str) -> str:
    """A Beamer frame showing page k of the PDF on overlay k. ``pdf_name``
    must be one LaTeX can read (``latex_file_name``): ValueError if not."""
    pdf_name = latex_file_name(pdf_name)
    lines = [latex_comment(f"RasterLab: {pages} frames of {pdf_name}; "
                           "needs \\usepackage{graphicx}"),
             f"\\begin{{frame}}{{{latex_text(title)}}}", "  \\centering"]
    for page in range(1, pages + 1):
        lines.append(f"  \\only<{page}>{{\\includegraphics[page={page},width=\\linewidth,"
                     f"height=0.85\\textheight,keepaspectratio]{{{pdf_name}}}}}")
    lines.append("\\end{frame}")
    return "\n".join(lines) + "\n"

