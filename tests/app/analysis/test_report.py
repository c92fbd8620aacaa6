"""`rasterlab report --quick`: the files it writes, their columns and the known orderings."""
from __future__ import annotations

import csv
import json
import math
from collections import defaultdict

import pytest
from PIL import Image

from app.analysis import measure
from app.cli import main

PICTURES = ("lines", "circles", "polygons", "fill", "triangles", "interpolation", "textures")


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    """One quick report for the whole module: (folder, status, stdout, stderr)."""
    folder = tmp_path_factory.mktemp("report") / "out"
    capture = pytest.MonkeyPatch()
    import io
    import sys
    out, err = io.StringIO(), io.StringIO()
    capture.setattr(sys, "stdout", out)
    capture.setattr(sys, "stderr", err)
    try:
        status = main(["report", "--quick", "--out", str(folder)])
    finally:
        capture.undo()
    return folder, status, out.getvalue(), err.getvalue()


@pytest.fixture(scope="module")
def rows(report):
    folder = report[0]
    with open(folder / "measurements.csv", newline="", encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


@pytest.fixture(scope="module")
def table(rows):
    """(family, experiment, variant, parameter value, metric) -> value."""
    found = {}
    for row in rows:
        found[(row["family"], row["experiment"], row["variant"], row["parameter_value"],
               row["metric"])] = float(row["value"])
    return found


def families_expected():
    names = list(measure.FAMILIES)
    if not measure.antialias_available():
        return names
    return [n for n in names if n != "antialiasing"]


def test_the_run_succeeds_quietly_off_a_terminal(report):
    folder, status, out, err = report
    assert status == 0
    assert err == ""  # no progress bar when stderr is not a terminal
    assert str(folder) in out and "measurements" in out


def test_every_file_is_written(report):
    folder = report[0]
    names = {p.name for p in folder.iterdir()}
    expected = {"report.md", "measurements.csv", "measurements.json", ".rasterlab-report.json"}
    expected |= {f"{name}.png" for name in PICTURES}
    if measure.antialias_available() == "":
        expected.add("antialiasing.png")
    assert names == expected  # no temporary files left behind
    assert json.loads((folder / ".rasterlab-report.json").read_text()) == sorted(
        expected - {".rasterlab-report.json"})  # the manifest lists what the report wrote
    for name in expected - {"report.md", "measurements.csv", "measurements.json",
                            ".rasterlab-report.json"}:
        with Image.open(folder / name) as image:
            image.verify()
        with Image.open(folder / name) as image:
            assert image.width >= 800 and image.height >= 400


def test_csv_columns_and_finite_numbers(report, rows):
    folder = report[0]
    header = (folder / "measurements.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header.split(",") == list(measure.COLUMNS)
    assert len(rows) > 1000
    for row in rows:
        for column in ("family", "experiment", "algorithm", "variant", "parameter",
                       "parameter_value", "metric"):
            assert row[column] != "", (column, row)
        assert math.isfinite(float(row["value"])), row


def test_every_family_is_present(rows, report):
    present = {row["family"] for row in rows}
    assert present == set(families_expected())
    text = (report[0] / "report.md").read_text(encoding="utf-8")
    assert "## Headline findings" in text
    for heading in ("## Lines", "## Circles", "## Polygons", "## Triangles", "## Seed fill",
                    "## Interpolation and depth", "## Antialiasing", "## Textures"):
        assert heading in text
    for name in PICTURES:
        assert f"({name}.png)" in text


def test_every_figure_has_alt_text(report):
    folder = report[0]
    text = (folder / "report.md").read_text(encoding="utf-8")
    for name in PICTURES:
        alt = f"Cost against error of the {name} algorithms"
        assert f"![{alt}" in text
        with Image.open(folder / f"{name}.png") as image:
            assert image.text["Title"].startswith(alt)


def test_every_algorithm_family_has_operation_counts(rows):
    counted = defaultdict(set)
    for row in rows:
        if row["metric"] == "ops":
            counted[row["family"]].add(row["algorithm"])
            assert float(row["value"]) > 0, row
    for family in ("lines", "circles", "polygons", "fill", "triangles", "interpolation"):
        assert counted[family], family
    for metric in ("ops int_add", "ops float_add", "ops mul", "ops div", "ops sqrt", "ops round",
                   "ops compare", "ops pixels_tested", "ops samples", "generator time"):
        assert any(row["metric"] == metric for row in rows), metric


def test_json_holds_every_row_and_the_findings(report, rows):
    data = json.loads((report[0] / "measurements.json").read_text(encoding="utf-8"))
    assert data["quick"] is True
    assert data["columns"] == list(measure.COLUMNS)
    assert len(data["rows"]) == len(rows)
    assert data["findings"] and all(set(f) == {"topic", "finding", "measured"}
                                    for f in data["findings"])


def _series(table, family, experiment, variant, metric):
    found = [(float(key[3]), value) for key, value in table.items()
             if key[:3] == (family, experiment, variant) and key[4] == metric
             and key[3] != "all"]
    return [value for _, value in sorted(found)]


def test_float32_dda_error_grows_with_length(table):
    errors = _series(table, "lines", "length sweep", "DDA float32", "differing pixels")
    assert len(errors) >= 3
    assert all(a <= b for a, b in zip(errors, errors[1:])), errors
    assert errors[-1] > errors[0]
    share = _series(table, "lines", "DDA precision", "DDA float32", "segments wrong")
    assert share[0] == 0 and share[-1] == 1
    assert max(_series(table, "lines", "DDA precision", "DDA float64", "segments wrong")) == 0
    first = table[("lines", "DDA precision", "DDA float32", "all", "first wrong length")]
    assert first > 0


def test_exact_line_algorithms_stay_exact(table):
    for variant in ("Bresenham", "Bresenham symmetric", "explicit"):
        assert max(_series(table, "lines", "length sweep", variant, "differing pixels")) == 0
        assert max(_series(table, "lines", "length sweep", variant, "max deviation")) <= 0.5
    assert max(_series(table, "lines", "length sweep", "Bresenham symmetric",
                       "asymmetric pixels")) == 0


def test_more_supersamples_give_less_error_for_the_grid(table):
    problem = measure.antialias_available()  # the module ships with the program
    assert not problem, problem
    errors = _series(table, "antialiasing", "supersampling", "grid box", "rms error")
    assert len(errors) >= 3
    assert all(a > b for a, b in zip(errors, errors[1:])), errors


def test_fixed_8_bit_meshes_have_no_overlaps_or_cracks(table):
    for family in ("triangles", "polygons"):
        checked = 0
        for key, value in table.items():
            if key[:3] == (family, "precision", "fixed 8 bits") and key[4] in ("overlaps",
                                                                               "cracks"):
                if table[key[:4] + ("rejected",)] == 0:
                    assert value == 0, key
                    checked += 1
        assert checked >= 6, family
        # and snapping to 8 bits changes no pixel of a mesh whose vertices are
        # exact to the arithmetic (the arithmetic itself is exact)
        assert max(_series(table, family, "precision", "fixed 8 bits",
                           "misclassified vs snapped")) == 0


def test_float32_triangles_fail_before_float64(table):
    def first_wrong(variant):
        for magnitude, value in zip(
                sorted({float(k[3]) for k in table if k[:3] == ("triangles", "precision", variant)}),
                _series(table, "triangles", "precision", variant, "misclassified vs snapped")):
            if value > 0:
                return magnitude
        return math.inf
    assert first_wrong("float32") < first_wrong("float64")


def test_midpoint_circles_and_perspective_interpolation(table):
    assert max(_series(table, "circles", "radius sweep", "midpoint", "gaps")) == 0
    assert max(_series(table, "circles", "radius sweep", "midpoint", "max deviation")) <= 0.5
    assert max(_series(table, "circles", "radius sweep", "sqrt4 (4-way)", "gaps")) > 0
    assert max(_series(table, "interpolation", "w ratio", "perspective-correct",
                       "max error")) < 1e-9
    affine = _series(table, "interpolation", "w ratio", "affine", "max error")
    assert affine[0] < 1e-9 and affine[-1] > 0.1


@pytest.mark.parametrize("make, words", [
    (lambda tmp: tmp / "a-file.txt", "not a folder"),
    (lambda tmp: tmp / "a-file.txt" / "below", "cannot create the folder"),
])
def test_a_bad_out_folder_exits_2_with_one_line(tmp_path, capsys, make, words):
    (tmp_path / "a-file.txt").write_text("taken\n")
    status = main(["report", "--quick", "--out", str(make(tmp_path))])
    out, err = capsys.readouterr()
    assert status == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("rasterlab: ") and words in lines[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-file.txt"]


def test_an_unwritable_folder_is_refused_before_measuring(tmp_path, monkeypatch):
    from app.analysis import report as reporting

    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(reporting.tempfile, "mkstemp", refuse)
    measured = []
    monkeypatch.setattr(reporting.measure, "run", lambda *a, **k: measured.append(1))
    with pytest.raises(reporting.ReportError, match="cannot write in the folder"):
        reporting.write_report(tmp_path / "out", quick=True)
    assert not measured


@pytest.fixture
def old_report(tmp_path):
    """A report folder as an earlier run left it, and a person's file."""
    folder = tmp_path / "out"
    folder.mkdir()
    old = {name: b"old " + name.encode() for name in
           ("report.md", "measurements.csv", "measurements.json", "lines.png", "notes.txt")}
    for name, data in old.items():
        (folder / name).write_bytes(data)
    return folder, old


def test_a_full_disk_leaves_the_old_report_whole(old_report, monkeypatch):
    from app.analysis import report as reporting
    folder, old = old_report
    write = reporting.write_atomically
    calls = []

    def full_after_one(path, data, error=OSError, **kwargs):
        calls.append(path)
        if len(calls) == 2:
            raise error(f"{path}: cannot write the file (No space left on device)")
        write(path, data, error, **kwargs)

    monkeypatch.setattr(reporting, "write_atomically", full_after_one)
    with pytest.raises(reporting.ReportError, match="No space left") as caught:
        reporting.write_files(folder, measure.settings(True), [], {"lines": 0.1})
    assert str(folder) in str(caught.value) and ".rasterlab-" not in str(caught.value)
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == old


def test_a_killed_report_is_cleaned_up_by_the_next(old_report):
    from app.analysis import report as reporting
    from app.model.staging import StagedFolder
    folder, old = old_report
    # What a report killed while writing leaves: a staging folder with no
    # journal, of a process that is gone.
    leftover = folder / ".rasterlab-report-999999999-x"
    leftover.mkdir()
    (leftover / "report.md").write_text("half")
    assert StagedFolder(folder, "report").recover() == [leftover]
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == old
    reporting.write_files(folder, measure.settings(True), [], {"lines": 0.1})
    names = {p.name for p in folder.iterdir()}
    assert names == {"report.md", "measurements.csv", "measurements.json", "lines.png",
                     "notes.txt", ".rasterlab-report.json"}
    assert (folder / "report.md").read_bytes() != old["report.md"]


def test_the_cost_table_names_the_length_each_row_was_measured_at():
    from app.analysis.report_findings import View
    from app.analysis.report_sections import section_lines

    def row(variant, length, metric, value):
        return {"family": "lines", "experiment": "length sweep", "variant": variant,
                "parameter_value": length, "metric": metric, "value": value}

    rows = [row("Bresenham", n, "differing pixels", 0) for n in (100, 10000)]
    rows += [row("implicit", 100, "differing pixels", 0)]
    rows += [row("Bresenham", 100, "ops", 5.0), row("Bresenham", 10000, "ops", 4.0),
             row("implicit", 100, "ops", 77.0)]
    text = section_lines(View(rows))
    cost = [line for line in text.splitlines() if line.startswith("| implicit") and "77" in line]
    assert len(cost) == 1 and "| 100 px |" in cost[0]
    bresenham = [line for line in text.splitlines() if line.startswith("| Bresenham")
                 and "| 4" in line]
    assert len(bresenham) == 1 and "| 10 000 px |" in bresenham[0]
