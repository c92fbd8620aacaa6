"""Alt text in the exports, read back with the readers others use: SVG
frames' <title> and <desc> (xml.etree), PNG frames' Title and Description
(Pillow), the frames' PDF and the worksheets' PDFs (pypdf: title, subject,
language, and the words of the page as text). The report's figures:
tests/app/analysis/test_report.py."""
from __future__ import annotations

import xml.etree.ElementTree as ET

from PIL import Image
from pypdf import PdfReader

from app.model import scene as scenes
from tests.support import ROOT

SVG = "{http://www.w3.org/2000/svg}"
DEMO = ROOT / "resources" / "scenes" / "demo-bresenham.json"


def test_every_frame_says_what_it_shows(run_cli, tmp_path):
    status, _, err = run_cli("export", DEMO, "--svg-dir", tmp_path / "svg", "--frames-dir",
                             tmp_path / "png", "--pdf", tmp_path / "frames.pdf", "--to", "3")
    assert status == 0, err
    title = scenes.load(DEMO).title
    assert title   # the shipped demo has one
    for k in range(4):
        root = ET.parse(tmp_path / "svg" / f"frame_{k:04d}.svg").getroot()
        assert root.get("role") == "img"
        assert root.find(f"{SVG}title").text == title
        desc = root.find(f"{SVG}desc").text
        assert f"step {k} of 26: " in desc and "line-bresenham" in desc and "32 x 24 grid" in desc
        with Image.open(tmp_path / "png" / f"frame_{k:04d}.png") as png:
            assert png.text["Title"] == title
            assert png.text["Description"] == desc   # the same words in both
    assert "plot (3, 4)" in ET.parse(tmp_path / "svg" / "frame_0001.svg").getroot() \
        .find(f"{SVG}desc").text   # Bresenham's first step plots P = (3, 4)
    pdf = PdfReader(tmp_path / "frames.pdf")
    assert pdf.metadata.title == title
    assert "line-bresenham" in pdf.metadata.subject
    assert pdf.trailer["/Root"]["/Lang"] == "en"
    titles = [entry.title for entry in pdf.outline]   # a bookmark per page, naming its step
    assert len(titles) == 4
    assert all(title.startswith(f"step {k} of 26: ") for k, title in enumerate(titles))
    # P = (3, 4), Q = (27, 15): dx = 24, dy = 11, d0 = 2dy - dx = -2, so E first.
    assert titles[2] == "step 2 of 26: d = -2, at most 0, so E: plot (4, 4)"
    assert "map P, Q into octant" in pdf.pages[0].extract_text()   # the pseudo-code, as text


def test_the_worksheets_have_a_title_subject_language_and_text(run_cli, tmp_path):
    status, _, err = run_cli("worksheet", DEMO, "--out", tmp_path / "sheet")
    assert status == 0, err
    for name, kind in (("worksheet.pdf", "Worksheet"), ("answers.pdf", "Answer key")):
        pdf = PdfReader(tmp_path / "sheet" / name)
        title = f"{kind}: {scenes.load(DEMO).title}"
        assert pdf.metadata.title == title
        xmp = pdf.xmp_metadata   # Qt's QPdfWriter sets no /Subject nor /Lang: XMP carries them
        assert xmp.dc_title == {"x-default": title}
        assert xmp.dc_language == ["en"]
        assert "line-bresenham" in xmp.dc_description["x-default"]
        words = " ".join(pdf.pages[0].extract_text().split())
        assert kind in words and "Inputs: P = (3, 4)" in words and "dx = x1 - x0" in words



def test_a_title_no_file_can_hold_is_written_with_replacement_characters(run_cli, tmp_path):
    """A scene file may spell lone surrogates in its title (JSON allows
    "\\ud800"); PNG chunks and PDF strings cannot hold them. Other
    characters stay as given."""
    import json
    scene = json.loads(DEMO.read_text(encoding="utf-8"))
    scene["title"] = "\ud800 wheel \x1b[31m"
    path = tmp_path / "odd.json"
    path.write_text(json.dumps(scene), encoding="utf-8")   # ensure_ascii spells \ud800
    status, _, err = run_cli("export", path, "--frames-dir", tmp_path / "png", "--pdf",
                             tmp_path / "frames.pdf", "--to", "1")
    assert status == 0, err
    with Image.open(tmp_path / "png" / "frame_0000.png") as png:
        assert png.text["Title"] == "\ufffd wheel \x1b[31m"
    assert PdfReader(tmp_path / "frames.pdf").metadata.title == "\ufffd wheel \x1b[31m"
