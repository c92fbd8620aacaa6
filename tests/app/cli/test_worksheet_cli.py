"""`rasterlab worksheet`: the PDF read back with pypdf (pages and text), the
CSV and LaTeX tables against the step table, blanks where asked, bad input;
the inputs stated, every scan line kept, the ET and AET to fill in, empty
columns left out, the decision variable after its update, name and date."""
from __future__ import annotations

import csv
import json
import re

import pytest
from pypdf import PdfReader

from algorithms.core.steps import Span, Table
from app.model import scene as scenes
from app.model.steptable import StepTable
from tests.support import ROOT

SCENES = ROOT / "resources" / "scenes"
LINE_SCENE = SCENES / "demo-bresenham.json"


POLYGON_SCENE = SCENES / "polygon-star-evenodd.json"


def expected_table(path):
    """The step table's rows for the steps that plot, branch or fill a run
    (an empty run too), without the columns empty on every row, with the
    decision variable d after the step's update beside it."""
    scene = scenes.load(path)
    trace = scene.spec.record(scene.points, scene.options, grid=(scene.width, scene.height))
    table = StepTable(trace)
    keep = [k for k, c in enumerate(table.columns)
            if c.key in ("step", "line", "pixel", "choice")
            or (c.kind == "variable" and c.key not in trace.start.constants)]
    steps = []
    for i in range(len(trace)):
        step = trace.step(i)
        if step.writes or step.branch or (isinstance(step.record, Span) and step.kind == "plot"):
            steps.append(i)
    heading = [table.columns[k].title for k in keep]
    rows = [[table.text_row(i)[k] for k in keep] for i in steps]
    if "d" in heading:
        at = heading.index("d") + 1
        heading.insert(at, "d after")
        for row, i in zip(rows, steps):
            after = trace.variables_at(i + 1) if i + 1 < len(trace) else trace.final_variables()
            row.insert(at, f"{after['d']:g}")
    filled = [k for k in range(len(heading)) if k == 0 or any(row[k] for row in rows)]
    return ([heading[k] for k in filled], [[row[k] for k in filled] for row in rows], trace)


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
    assert run_cli("worksheet", LINE_SCENE, "--out", tmp_path)[0] == 0
    heading, rows, trace = expected_table(LINE_SCENE)
    sheet, key = (PdfReader(tmp_path / name) for name in ("worksheet.pdf", "answers.pdf"))
    assert len(sheet.pages) == len(key.pages) == 2  # 25 rows fit on the first page

    def text(reader):
        return re.sub(r"\s+", "", "".join(page.extract_text() for page in reader.pages))
    sheet_text, key_text = text(sheet), text(key)
    assert "Worksheet:" in sheet_text and "Answerkey:" in key_text
    assert all(title.replace(" ", "") in key_text for title in heading)
    pixels = {f"({x},{y})" for x, y in trace.written_pixels().tolist()}
    assert all(pixel in key_text for pixel in pixels)
    ends = {f"({x},{y})" for x, y in points_of(LINE_SCENE)[0]}  # P and Q: the inputs, stated
    assert not any(pixel in sheet_text for pixel in pixels - ends)  # the pixel column is blank
    assert "Shadethepixels" in sheet_text
    assert "Name:" in sheet_text and "Date:" in sheet_text and "Name:" not in key_text
    assert "Inputs:P=(3,4),Q=(27,15)" in sheet_text  # the scene file's two points


def test_the_default_blanks_give_nothing_away(run_cli, tmp_path):
    assert run_cli("worksheet", LINE_SCENE, "--out", tmp_path, "--format", "csv")[0] == 0
    heading, rows, _ = expected_table(LINE_SCENE)
    sheet = list(csv.reader(open(tmp_path / "worksheet.csv")))
    assert sheet[0] == heading and "line" in heading and "d" in heading
    # Only the step numbers are given: the line names the branch, d decides it.
    assert [row[0] for row in sheet[1:]] == [row[0] for row in rows]
    assert all(cell == "" for row in sheet[1:] for cell in row[1:])


def points_of(path):
    """The contours, read from the scene file itself."""
    return [primitive["points"] for primitive in json.loads(path.read_text())["primitives"]]


def test_the_polygon_sheet_states_its_vertices_and_keeps_every_scan_line(run_cli, tmp_path):
    assert run_cli("worksheet", POLYGON_SCENE, "--out", tmp_path, "--format", "md")[0] == 0
    heading, rows, trace = expected_table(POLYGON_SCENE)
    text, blank = ((tmp_path / name).read_text() for name in ("answers.md", "worksheet.md"))
    vertices = [tuple(p) for contour in points_of(POLYGON_SCENE) for p in contour]
    assert "Inputs: vertices: " + " ".join(f"({x:g}, {y:g})" for x, y in vertices) in blank
    table = [line.split(" | ") for line in text.split("## ET")[0].splitlines()
             if line.startswith("| ") and not line.startswith("| step")]
    spans = [trace.step(i).record for i in range(len(trace))
             if isinstance(trace.step(i).record, Span) and trace.step(i).kind == "plot"]
    assert len(table) == len(rows) == len(spans)  # an empty run keeps its row (y = 10)
    assert "spans" not in heading and "pixels" not in heading  # empty on every row
    assert "| step | line | pixel | y | active |" in text
    # The ET to fill in: the edges given, their numbers blank on the sheet.
    et = text.split("## ET")[1].split("##")[0]
    et_rows = [line for line in et.splitlines() if line.startswith("| ") and "ymin" not in line]
    first = next(record for _, record in trace.records_of(Table) if record.name == "ET")
    assert len(et_rows) == len(first.rows)
    for line, row in zip(et_rows, first.rows):
        assert f"| {row[0]} | {row[1]} | {row[2]} |" in line
    sheet_et = blank.split("## ET")[1].split("##")[0]
    assert all(f"| {row[0]} | {row[1]} |  |  |  |" in sheet_et for row in first.rows)
    # The AET: a row per active edge at each scan line the run fills.
    aet = text.split("## AET")[1]
    ys = {record.y for record in spans}
    assert {int(line.split(" | ")[0][2:]) for line in aet.splitlines()
            if line.startswith("| ") and line[2].isdigit()} == ys


def test_a_long_pseudo_code_line_is_wrapped_not_cut(run_cli, tmp_path):
    assert run_cli("worksheet", POLYGON_SCENE, "--out", tmp_path)[0] == 0
    scene = scenes.load(POLYGON_SCENE)
    code = scene.spec.code(scene.spec.inputs.check(scene.points), scene.spec.resolve(scene.options))
    lines = PdfReader(tmp_path / "worksheet.pdf").pages[0].extract_text().splitlines()
    first = next(n for n, line in enumerate(lines) if line.startswith("2") and "ET:" in line)
    wanted, joined = re.sub(r"\s+", "", "2" + code[1].text), ""
    for last in range(first, len(lines)):
        joined += re.sub(r"\s+", "", lines[last])
        if len(joined) >= len(wanted):
            break
    # Every word of the line is on the page, on two lines or more (A4 is too narrow for one).
    assert joined == wanted and last > first


def test_circle_rows_show_d_after_the_update_beside_x(run_cli, tmp_path):
    path = SCENES / "circle-midpoint-printed.json"
    assert run_cli("worksheet", path, "--out", tmp_path, "--format", "csv")[0] == 0
    rows = list(csv.DictReader(open(tmp_path / "answers.csv")))
    branches = [(row, after) for row, after in zip(rows, rows[1:]) if row["choice"]]
    assert branches
    for row, following in branches:
        # The mirrors plotted right after the decision hold the updated d and the same x.
        assert row["d after"] == following["d"] and row["x"] == following["x"]


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
