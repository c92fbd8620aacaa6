"""Vector frames: SVG parsed back (filled cells, outlines, text), the PDF's
pages and text read back with pypdf, and the Beamer snippet."""
import xml.etree.ElementTree as ET

import pytest
from pypdf import PdfReader

from app import cli
from app.model.scene import Scene, save
from app.render import export as ex
from app.render.vector import PdfWriter, SvgFolderWriter
from tests.support import record
from tests.support.bresenham import bresenham_pixels

SVG = "{http://www.w3.org/2000/svg}"
P, Q = (1, 1), (12, 6)
SCENE = Scene(algorithm="line-bresenham", points=(P, Q), width=14, height=8)
CELL = 20  # the export's scale: units per cell, as pixels in the GIF


def filled_cells(svg_root, background) -> set:
    """Cells covered by the filled rectangles that are not background, from their geometry."""
    cells = set()
    for rect in svg_root.iter(f"{SVG}rect"):
        fill = rect.get("fill")
        if fill in (None, "none", background) or rect.get("width") == "100%":
            continue
        x, y = float(rect.get("x")), float(rect.get("y"))
        w, h = float(rect.get("width")), float(rect.get("height"))
        if h != CELL or x % CELL or y % CELL:
            continue  # panels and outlines are not cells
        row = int(y // CELL)
        cells |= {(int(x // CELL) + k, SCENE.height - 1 - row) for k in range(int(w // CELL))}
    return cells


def test_each_svg_frame_shows_the_cells_written_so_far_and_its_caption(tmp_path):
    settings = ex.ExportSettings(panel="code", scale=CELL)
    result = ex.export(SCENE, settings, writers=[SvgFolderWriter(tmp_path / "svg")])
    names = sorted(p.name for p in (tmp_path / "svg").glob("*.svg"))
    assert len(names) == result.frames == len(record("line-bresenham", [P, Q], grid=(14, 8)))
    expected = bresenham_pixels(P, Q)
    background = ex.LIGHT.palette.background
    for k in (0, 5, result.frames - 1):
        root = ET.parse(tmp_path / "svg" / names[k]).getroot()
        texts = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
        # The caption's first line, its bold parts written as texts of their own.
        assert f"Step {k} of {result.frames - 1}" in "".join(texts)
        trace = record("line-bresenham", [P, Q], grid=(14, 8))
        plotted = {tuple(p) for p in trace.written(0, k + 1).pixels.tolist()}
        assert plotted <= set(expected)
        assert filled_cells(root, background) == plotted
        assert any("plot(x, y)" in text for text in texts)


def test_the_pdf_has_a_page_per_frame_with_its_text(tmp_path):
    pdf = tmp_path / "a.pdf"
    writer = PdfWriter(pdf)
    result = ex.export(SCENE, ex.ExportSettings(last=4), writers=[writer])
    reader = PdfReader(pdf)
    assert len(reader.pages) == result.frames == writer.pages == 5
    for k, page in enumerate(reader.pages):
        text = page.extract_text()
        assert f"Step {k} of" in text and "incrNE" in text


def test_export_writes_svg_pdf_and_a_beamer_frame_from_the_command_line(tmp_path, run_cli):
    scene = tmp_path / "s.json"
    save(SCENE, scene)
    status, out, err = run_cli("export", scene, "--svg-dir", tmp_path / "svg", "--pdf",
                               tmp_path / "a.pdf", "--beamer", tmp_path / "a.tex", "--to", "3")
    assert status == 0, err
    tex = (tmp_path / "a.tex").read_text()
    assert tex.count("\\includegraphics[page=") == 4 and "{a.pdf}" in tex
    assert "\\only<4>" in tex and "\\only<5>" not in tex
    assert len(list((tmp_path / "svg").glob("frame_*.svg"))) == 4


@pytest.mark.parametrize("argv, message", [
    (["--beamer", "x.tex"], "give --pdf"),
    (["--pdf", "/no/such/folder/a.pdf"], "does not exist"),
])
def test_bad_vector_requests_get_one_line(tmp_path, run_cli, argv, message):
    scene = tmp_path / "s.json"
    save(SCENE, scene)
    status, out, err = run_cli("export", scene, *argv)
    assert status == 2 and out == "" and err.count("\n") == 1 and message in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.json"]


def test_pages_per_bookmark_and_the_variables_panel(tmp_path, run_cli):
    scene = tmp_path / "s.json"
    marked = Scene(algorithm="line-bresenham", points=(P, Q), width=14, height=8,
                   bookmarks=({"name": "start", "step": 1}, {"name": "tie", "step": 6}))
    save(marked, scene)
    status, _, err = run_cli("export", scene, "--pdf", tmp_path / "b.pdf", "--pages", "bookmarks",
                             "--panel", "both")
    assert status == 0, err
    pages = PdfReader(tmp_path / "b.pdf").pages
    trace = record("line-bresenham", [P, Q], grid=(14, 8))
    assert len(pages) == 2
    for page, step in zip(pages, (1, 6)):
        text = page.extract_text()
        assert f"Step {step} of" in text and "Variables" in text
        d = trace.variables_at(step)["d"]
        assert f"{int(d)}" in text


def test_pages_per_bookmark_without_bookmarks_is_refused(tmp_path, run_cli):
    scene = tmp_path / "s.json"
    save(SCENE, scene)
    status, out, err = run_cli("export", scene, "--pdf", tmp_path / "b.pdf", "--pages", "bookmarks")
    assert status == 2 and "no bookmarks" in err and not (tmp_path / "b.pdf").exists()
