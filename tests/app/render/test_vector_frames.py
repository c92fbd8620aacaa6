"""Vector frames are the GIF's frames: the same size, the same text sizes and
the same caption lines (the decision and update, with ≤), in SVG and PDF."""
import re
import xml.etree.ElementTree as ET

from PIL import Image
from pypdf import PdfReader

from app.model import scene as scenes
from app.model import shipped
from app.render import export as ex
from app.render.vector import PdfWriter, SvgFolderWriter

SVG = "{http://www.w3.org/2000/svg}"
STEPS = (0, 13, 26)  # first, middle and last of demo-bresenham's 27 steps


def _export(tmp_path):
    scene = scenes.load(shipped.scene_path("demo-bresenham"))
    gif = tmp_path / "a.gif"
    ex.export(scene, ex.ExportSettings(), gif=gif,
              writers=[SvgFolderWriter(tmp_path / "svg"), PdfWriter(tmp_path / "a.pdf")])
    renderer = ex.FrameRenderer(scene, ex.ExportSettings())
    return renderer, Image.open(gif)


def _caption_lines(renderer, index):
    """The caption's lines as the raster composer makes them: step, code, values."""
    parts = renderer.text_parts
    state = renderer.trace.state_at(index)
    line = state.step.line
    code = f"{line + 1}: ", parts.code[line].strip()
    return code, parts.value_texts(state)


def test_svg_frames_have_the_gif_size_text_size_and_caption_lines(tmp_path):
    renderer, gif = _export(tmp_path)
    width, height = gif.size
    parts = renderer.text_parts
    assert parts.sans.face.size == renderer.text_size > 12  # the GIF's text: 21 px here
    seen_le = False
    for k in STEPS:
        root = ET.parse(tmp_path / "svg" / f"frame_{k:04d}.svg").getroot()
        assert root.get("viewBox") == f"0 0 {width} {height}"
        texts = {"".join(t.itertext()): t for t in root.iter(f"{SVG}text")}
        assert not any("<=" in text for text in texts)
        code, values = _caption_lines(renderer, k)
        assert code[1] in texts and code[0] in texts
        for line in values:
            assert line in texts
            assert float(texts[line].get("font-size")) == parts.mono.face.size
        if k == 13:  # a step of the loop: the decision and its update
            assert any("decision" in line and "update" in line for line in values)
        seen_le |= "\u2264" in code[1]
        step = next(t for text, t in texts.items() if text.startswith("Step"))
        assert float(step.get("font-size")) == renderer.text_size
    assert seen_le  # the decision line "if d ≤ 0" is written with ≤


def test_pdf_pages_have_the_gif_size_and_the_caption_lines(tmp_path):
    renderer, gif = _export(tmp_path)
    pages = PdfReader(tmp_path / "a.pdf").pages
    assert len(pages) == gif.n_frames
    for k in STEPS:
        page = pages[k]
        assert (float(page.mediabox.width), float(page.mediabox.height)) == gif.size
        sizes = {}

        def visit(text, cm, tm, font, size, sizes=sizes):
            if text.strip():
                sizes[text.strip()] = size * tm[0]

        text = page.extract_text(visitor_text=visit)
        code, values = _caption_lines(renderer, k)
        flat = re.sub(r"\s+", " ", text)
        for line in (code[1], *values):
            assert re.sub(r"\s+", " ", line) in flat
        assert "<=" not in text
        step = next(size for piece, size in sizes.items() if piece.startswith("Step"))
        assert step == renderer.text_size
    assert "\u2264" in pages[13].extract_text()
