"""The step table: one row per step, the same variables the panel shows,
Bresenham's d as exact integer arithmetic gives it, CSV that reads back."""
import csv
import io

import pytest

from algorithms.core.steps import Table
from app.model import steptable
from app.model.steptable import StepTable, aligned_text, cell_to_json, write_csv
from tests.support import record
from tests.support.bresenham import bresenham_run


@pytest.mark.parametrize("end", [(9, 4), (13, 13), (20, 1), (17, 5)])
def test_bresenham_rows_carry_the_exact_decision_variable(end):
    table = StepTable(record("line-bresenham", [(1, 1), end]))
    rows = [row for row in table.rows() if row["choice"] in ("E", "NE")]
    pixels, decisions = bresenham_run((1, 1), end)
    expected = [(x, y, d) for (x, y), d in zip(pixels[1:], decisions)]
    assert [(r["pixel"][0], r["pixel"][1], r["d"]) for r in rows] == expected
    assert [r["choice"] for r in rows] == ["E" if d <= 0 else "NE" for _, _, d in expected]


@pytest.mark.parametrize("name, points", [
    ("polygon-scanline", [[(2, 2), (12, 4), (6, 12)]]),
    ("triangle-bbox", [(1, 1), (9, 2), (4, 8)]),
    ("circle-midpoint", [(10, 10)]),
    ("flood-fill", [[(2, 2), (10, 2), (6, 9)]]),
])
def test_every_row_matches_the_variables_panel(monkeypatch, name, points):
    monkeypatch.setattr(steptable, "CHECKPOINT", 5)  # many checkpoints on a small run
    trace = record(name, points)
    table = StepTable(trace)
    assert len(table) == len(trace)
    keys = {c.key for c in table.columns if c.kind == "variable"}
    for i in range(len(trace)):
        row = table.row(i)
        step = trace.step(i)
        assert row["step"] == i and row["line"] == step.line + 1
        assert row["code"] == trace.code[step.line].text
        panel = trace.variables_at(i)
        shown = {k: v for k, v in row.items() if k in keys}
        assert shown == {k: v for k, v in panel.items() if k in keys}


def test_tables_are_the_latest_snapshot_at_or_before_the_step():
    trace = record("polygon-scanline", [[(2, 2), (12, 4), (6, 12)]])
    table = StepTable(trace)
    snapshots = trace.records_of(Table)
    assert {c.key for c in table.columns if c.kind == "table"} == {r.name for _, r in snapshots}
    for i in range(len(trace)):
        row = table.row(i)
        for name in ("ET", "AET"):
            before = [r for at, r in snapshots if r.name == name and at <= i]
            assert row.get(name) == (before[-1] if before else None)


def test_csv_reads_back_with_one_row_per_step():
    trace = record("line-bresenham", [(0, 0), (7, 3)])
    table = StepTable(trace)
    stream = io.StringIO()
    assert write_csv(table, stream) == len(trace)
    rows = list(csv.reader(io.StringIO(stream.getvalue())))
    assert rows[0] == [c.title for c in table.columns]
    assert len(rows) == len(trace) + 1
    assert all(len(r) == len(rows[0]) for r in rows)
    assert [r[0] for r in rows[1:]] == [str(i) for i in range(len(trace))]


def test_aligned_text_lines_up_and_json_cells_are_plain():
    table = StepTable(record("polygon-scanline", [[(2, 2), (12, 4), (6, 12)]]))
    lines = aligned_text(table, 0, 10).splitlines()
    assert len(lines) == 11
    column = lines[0].index("pseudo-code")
    assert all(line[column - 2:column] == "  " for line in lines[1:] if len(line) > column)
    for row in table.rows(0, 10):
        for value in row.values():
            assert isinstance(cell_to_json(value), (int, float, str, list, dict, type(None)))


def test_a_step_outside_the_run_is_refused():
    table = StepTable(record("line-bresenham", [(0, 0), (3, 1)]))
    with pytest.raises(IndexError):
        table.row(len(table))
