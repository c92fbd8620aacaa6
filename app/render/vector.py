"""Vector frames for LaTeX and slides: SVG files, a PDF with a page per
frame, and a Beamer snippet that shows the PDF's pages as overlays.

A frame is described once as a list of shapes (``Drawing``): the cells
(runs of equal colour per row, so a grid of a million cells stays small),
the grid lines, the ideal primitive, the outlines of the step's pixel and
its candidates, the reasoning, and the text. The SVG and PDF backends draw
the same shapes, so the two agree. The frame is the raster frame's
(app/render/export.py): one unit is one pixel of the GIF, at the same
size, and the axes, the side panel and the caption are painted by the same
code that paints them with Pillow (app/render/text.py, app/render/axes.py),
here onto ``_Canvas``, which records text as text in the shipped DejaVu
fonts at the raster's sizes: the same lines, with ≤ and subscripts.

The writers take part in the export's writer protocol: instead of the
raster image they are given the step (``grab_step(renderer, index)``),
because a vector frame is drawn from the state, not from pixels.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
import numpy as np

from app.render.alt_text import LANGUAGE
from app.model.escape import latex_comment, latex_file_name, latex_text, xml_text
from app.render.compose import OUTLINE_STYLE, compose
from app.render.frame import frame_marks
from app.render.reasoning import step_guides
from app.render.settings import ExportError
from app.render.text import FONT_FILES, font_path
from app.model.files import target_of
from app.render.writers import PngFolderWriter, temporary_beside

_KINDS = {name: kind for kind, name in FONT_FILES.items()}  # font file -> sans, mono_bold, ...
# Where a Pillow text anchor puts the text: its horizontal offset as a share
# of the width, and the vertical one in ascents and descents from the baseline.
_ACROSS = {"l": 0.0, "m": 0.5, "r": 1.0}
_DOWN = {"a": (1, 0), "t": (1, 0), "m": (0.5, -0.5), "s": (0, 0), "d": (0, -1), "b": (0, -1)}


@dataclass
class Drawing:
    """One frame as shapes, in units with y down (see the module text)."""

    width: float
    height: float
    background: str
    shapes: list = field(default_factory=list)
    title: str = ""  # the scene's title: the SVG's <title>
    description: str = ""  # the frame in words (app/render/alt_text.py): the SVG's <desc>

    def rect(self, x, y, w, h, fill=None, stroke=None, width=0.0):
        self.shapes.append(("rect", x, y, w, h, fill, stroke, width))

    def line(self, points, stroke, width, closed=False):
        self.shapes.append(("line", [tuple(map(float, p)) for p in points], stroke, width, closed))

    def text(self, x, y, text, colour, mono=False, bold=False, size=12):
        """Text with its baseline's left end at (x, y)."""
        self.shapes.append(("text", x, y, text, colour, mono, bold, size))

    def texts(self) -> list[str]:
        return [shape[3] for shape in self.shapes if shape[0] == "text"]


class _Canvas:
    """The part of Pillow's ImageDraw that the text parts use (text,
    rectangle, line), recorded into a Drawing at an offset."""

    def __init__(self, drawing: Drawing, left: float, top: float):
        self.drawing, self.left, self.top = drawing, left, top

    def text(self, xy, text, font, fill, anchor="la") -> None:
        kind = _KINDS[os.path.basename(font.path)]
        ascent, descent = font.getmetrics()
        across, (ascents, descents) = _ACROSS[anchor[0]], _DOWN[anchor[1]]
        x = xy[0] - across * font.getlength(text)
        y = xy[1] + ascents * ascent - descents * descent
        self.drawing.text(self.left + x, self.top + y, text, fill, mono=kind.startswith("mono"),
                          bold=kind.endswith("bold"), size=font.size)

    def rectangle(self, box, fill=None, outline=None, width=1) -> None:
        x0, y0, x1, y1 = box  # Pillow's corners are inclusive
        self.drawing.rect(self.left + x0, self.top + y0, x1 - x0 + 1, y1 - y0 + 1, fill=fill,
                          stroke=outline, width=width if outline else 0.0)

    def line(self, xy, fill=None, width=1) -> None:
        x0, y0, x1, y1 = xy
        self.drawing.line([(self.left + x0, self.top + y0), (self.left + x1, self.top + y1)],
                          fill, width)


# ------------------------------------------------------------------ drawing
def draw_frame(renderer, index: int) -> Drawing:
    """Frame ``index`` of the renderer's export as a Drawing, the size of the
    raster frame."""
    trace, settings, theme = renderer.trace, renderer.settings, renderer.theme
    palette = theme.palette
    state = trace.state_at(index)
    width, height = renderer.size
    alt = renderer.alt_text
    drawing = Drawing(width, height, palette.outside, title=alt.title,
                      description=alt.description(index))
    at = _Place(renderer)
    _cells(drawing, state.raster, palette, at)
    if renderer.grid_lines:
        _grid_lines(drawing, at, palette.grid)
    marks = frame_marks(state, renderer.paths, renderer.differences, settings.highlight,
                        settings.primitive)
    for points, closed in marks.paths:
        drawing.line([at(x, y) for x, y in points], palette.primitive, 2.0, closed)
    _outlines(drawing, marks, palette, at)
    text = renderer.text_parts
    if settings.reasoning and settings.highlight:
        guides = step_guides(trace, state, renderer.ideal, renderer.y_down)
        _guides(drawing, guides, palette, at)
        if settings.grid_text:
            _labels(drawing, text, text.label_places(guides.labels, at), palette.guide)
    if renderer.vertex_labels:
        _labels(drawing, text, text.label_places(renderer.vertex_labels, at),
                palette.handle_edge)
    if renderer.axes is not None:
        renderer.axes.paint(_Canvas(drawing, 0, 0), _Canvas(drawing, at.left, at.height))
    grid_right = at.left + at.width
    if renderer.panel_width:
        drawing.rect(grid_right, 0, renderer.panel_width, renderer.body_height, fill=theme.panel)
        text.paint_panel(_Canvas(drawing, grid_right, 0), state)
    if renderer.caption_height:
        drawing.rect(0, renderer.body_height, width, renderer.caption_height, fill=theme.caption)
        text.paint_caption(_Canvas(drawing, 0, renderer.body_height), state)
    return drawing


class _Place:
    """Grid units to frame units, as the raster frame places the grid."""

    def __init__(self, renderer):
        self.scale = renderer.settings.scale
        self.left = renderer.grid_left
        self.width, self.height = renderer.grid_size
        self.y_down = renderer.y_down
        self.cells = renderer.trace.height

    def __call__(self, x: float, y: float) -> tuple[float, float]:
        return (self.left + x * self.scale,
                (y if self.y_down else self.cells - y) * self.scale)

    def row_top(self, y: int) -> float:
        """The top of cell row ``y``."""
        return (y if self.y_down else self.cells - y - 1) * self.scale


def _cells(drawing, raster, palette, at: _Place) -> None:
    colours = compose(raster, None, palette, 1, False)[..., :3]  # (H, W, 3), row 0 at y = 0
    background = tuple(int(palette.background[i:i + 2], 16) for i in (1, 3, 5))
    drawing.rect(at.left, 0, at.width, at.height, fill=palette.background)
    for y in range(colours.shape[0]):
        row = colours[y]
        change = np.flatnonzero(np.any(row[1:] != row[:-1], axis=1)) + 1
        starts = np.concatenate(([0], change))
        ends = np.concatenate((change, [len(row)]))
        for a, b in zip(starts.tolist(), ends.tolist()):
            colour = tuple(int(c) for c in row[a])
            if colour != background:
                drawing.rect(at.left + a * at.scale, at.row_top(y), (b - a) * at.scale, at.scale,
                             fill="#%02x%02x%02x" % colour)


def _grid_lines(drawing, at: _Place, colour) -> None:
    for x in range(at.width // at.scale + 1):
        drawing.line([(at.left + x * at.scale, 0), (at.left + x * at.scale, at.height)],
                     colour, 1.0)
    for y in range(at.height // at.scale + 1):
        drawing.line([(at.left, y * at.scale), (at.left + at.width, y * at.scale)], colour, 1.0)


def _outlines(drawing, marks, palette, at: _Place) -> None:
    def box(x0, x1, y, kind, colour):
        style = OUTLINE_STYLE[kind]
        inset = style.inset * at.scale + style.width / 2
        drawing.rect(at.left + x0 * at.scale + inset, at.row_top(y) + inset,
                     (x1 - x0) * at.scale - 2 * inset, at.scale - 2 * inset, stroke=colour,
                     width=style.width)

    for x, y in ([] if marks.differences is None else marks.differences.tolist()):
        box(x, x + 1, y, "difference", palette.difference)
    for a, b, y in marks.spans:
        box(a, b, y, "span", palette.current)
    for x, y in marks.current:
        box(x, x + 1, y, "current", palette.current)
    for x, y in marks.candidates:
        box(x, x + 1, y, "candidate", palette.candidate)


def _guides(drawing, guides, palette, at: _Place) -> None:
    """The step's reasoning (app/render/reasoning.py), as the GIF draws it:
    lines and dots (as small squares) in the guide colour."""
    widths = {"pair": 4.0, "drop": 1.5}
    for x0, y0, x1, y1, role in guides.lines:
        drawing.line([at(x0, y0), at(x1, y1)], palette.guide, widths.get(role, 1.0))
    for x, y, role in guides.dots:
        size = at.scale * (0.3 if role in ("crossing", "midpoint", "sample") else 0.18)
        colour = palette.current if role == "sample" else palette.guide
        cx, cy = at(x, y)
        drawing.rect(cx - size / 2, cy - size / 2, size, size,
                     fill=None if role == "miss" else colour, stroke=colour, width=0.5)


def _labels(drawing, text, places, colour) -> None:
    """Labels on the grid where the raster frame writes them (``label_places``)."""
    face = text.sans_bold
    for left, top, label in places:
        drawing.text(left + 1, top + face.ascent, label, colour, bold=True, size=face.face.size)


# ---------------------------------------------------------------------- SVG
def to_svg(drawing: Drawing) -> str:
    """The drawing as a standalone SVG document."""
    # role="img" with its title and description: what screen readers read of an image.
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{drawing.width:g}" '
           f'height="{drawing.height:g}" viewBox="0 0 {drawing.width:g} {drawing.height:g}" '
           f'role="img" aria-labelledby="title" aria-describedby="desc" xml:lang="en">']
    out.append(f'<title id="title">{xml_text(drawing.title)}</title>')
    out.append(f'<desc id="desc">{xml_text(drawing.description)}</desc>')
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
        self.described = False
        self.target = target_of(self.path, ExportError)
        self.temporary = temporary_beside(self.target)

    def grab_step(self, renderer, index: int) -> None:
        if self.only is not None and index not in self.only:
            return
        if not self.described:   # the document's title, subject and language
            alt = renderer.alt_text
            self.pdf.set_title(alt.title)
            self.pdf.set_subject(alt.subject)
            self.pdf.set_lang(LANGUAGE)
            self.described = True
        _pdf_page(self.pdf, draw_frame(renderer, index))
        self.pdf.start_section(renderer.alt_text.words(index))   # the reader's page list
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

