"""`rasterlab worksheet`: the PDF read back with pypdf (pages and text), the
CSV and LaTeX tables against the step table, blanks where asked, bad input."""
from __future__ import annotations

import csv
import math
import re

import pytest
from pypdf import PdfReader

from algorithms.core.steps import Span
from app.model import scene as scenes
from app.model.steptable import StepTable
from tests.support import ROOT

SCENES = ROOT / "resources" / "scenes"
LINE_SCENE = SCENES / "demo-bresenham.json"


def expected_table(path):
    """The step table's rows for the steps that plot, branch or fill a run."""
    scene = scenes.load(path)
    trace = scene.spec.record(scene.points, scene.options, grid=(scene.width, scene.height))
    table = StepTable(trace)
    keep = [k for k, c in enumerate(table.columns)
            if c.key in ("step", "line", "pixel", "choice")
            or (c.kind == "variable" and c.key not in trace.start.constants)]
    steps = []
    for i in range(len(trace)):
        step = trace.step(i)
        run = step.record if isinstance(step.record, Span) else None
        if step.writes or step.branch or (run is not None and run.x_end > run.x_start):
            steps.append(i)
    heading = [table.columns[k].title for k in keep]
    return heading, [[table.text_row(i)[k] for k in keep] for i in steps], trace


def test_csv_matches_the_step_table_with_blanks(run_cli, tmp_path):
    status, out, err = run_cli("worksheet", LINE_SCENE, "--out", tmp_path, "--format", "csv",
                               "--blank", "pixel,d")
    assert status == 0, err
    heading, rows, _ = expected_table(LINE_SCENE)
    answers = list(csv.reader(open(tmp_path / "answers.csv")))
    sheet = list(csv.reader(open(tmp_path / "worksheet.csv")))
    assert answers[0] == sheet[0] == heading and answers[1:] == rows
    blank = [heading.index("pixel"), heading.index("d")]
    for row, full in zip(sheet[1:], rows):
        assert [row[k] for k in blank] == ["", ""]
        assert [c for k, c in enumerate(row) if k not in blank] == \
               [c for k, c in enumerate(full) if k not in blank]


def unescape(cell: str) -> str:
    return re.sub(r"\\([&%$#_{}])", r"\1", cell.strip())


def test_latex_tabular_matches_the_step_table(run_cli, tmp_path):
    assert run_cli("worksheet", LINE_SCENE, "--out", tmp_path, "--format", "tex")[0] == 0
    heading, rows, _ = expected_table(LINE_SCENE)
    text = (tmp_path / "answers.tex").read_text()
    assert text.count(r"\begin{tabular}") == 1 and r"\end{tabular}" in text
    body = [line[:-len(r" \\")] for line in text.splitlines() if line.endswith(r" \\")]
    parsed = [[unescape(cell) for cell in line.split(" & ")] for line in body]
    assert parsed[0] == heading and parsed[1:] == rows
    blank_sheet = (tmp_path / "worksheet.tex").read_text()
    assert "NE" not in blank_sheet.split(r"\hline", 2)[2]  # the choice column is blank


def test_pdf_pages_and_text(run_cli, tmp_path):
    from app.gui.worksheet_pdf import ROWS_PER_PAGE
    assert run_cli("worksheet", LINE_SCENE, "--out", tmp_path)[0] == 0
    heading, rows, trace = expected_table(LINE_SCENE)
    pages = math.ceil(len(rows) / ROWS_PER_PAGE) + 1
    sheet, key = (PdfReader(tmp_path / name) for name in ("worksheet.pdf", "answers.pdf"))
    assert len(sheet.pages) == len(key.pages) == pages

    def text(reader):
        return re.sub(r"\s+", "", "".join(page.extract_text() for page in reader.pages))
    sheet_text, key_text = text(sheet), text(key)
    assert "Worksheet:" in sheet_text and "Answerkey:" in key_text
    assert all(title in key_text for title in heading)
    pixels = {f"({x},{y})" for x, y in trace.written_pixels().tolist()}
    assert all(pixel in key_text for pixel in pixels)
    assert not any(pixel in sheet_text for pixel in pixels)  # the pixel column is blank
    assert "Shadethepixels" in sheet_text


def test_markdown_links_its_grids(run_cli, tmp_path):
    assert run_cli("worksheet", SCENES / "circle-radius-2.json", "--out", tmp_path,
                   "--format", "md")[0] == 0
    for stem in ("worksheet", "answers"):
        text = (tmp_path / f"{stem}.md").read_text()
        assert f"![grid]({stem}-grid.png)" in text
        assert (tmp_path / f"{stem}-grid.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("argv, words", [
    ([LINE_SCENE, "--blank", "pixel,nope"], "no column nope"),
    ([SCENES / "missing.json"], "missing.json"),
    ([LINE_SCENE, "--format", "doc"], "invalid choice"),
])
def test_bad_input_exits_2(run_cli, tmp_path, argv, words):
    status, out, err = run_cli("worksheet", *argv, "--out", tmp_path / "out")
    assert status == 2 and words in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


def test_a_long_run_lists_its_first_steps_and_says_so(run_cli, tmp_path, monkeypatch):
    from app.teaching import worksheet
    monkeypatch.setattr(worksheet, "MAX_ROWS", 5)
    assert run_cli("worksheet", LINE_SCENE, "--out", tmp_path, "--format", "md")[0] == 0
    heading, rows, _ = expected_table(LINE_SCENE)
    text = (tmp_path / "answers.md").read_text()
    table = [line for line in text.splitlines() if line.startswith("| ")]
    assert len(table) == 1 + 5 and table[-1] == "| " + " | ".join(rows[4]) + " |"
    assert f"the run goes on after step {rows[4][0]}" in text
