"""`run --steps`: every step as an aligned table, CSV or JSON; and the
command line of the printed line variants."""
from __future__ import annotations

import csv
import io
import json
from fractions import Fraction

import pytest

from tests.support.bresenham import bresenham_run

LINE = ("run", "line-bresenham", "--points", "0,0", "8,3")


def test_csv_has_a_row_per_step_with_the_decision_of_each(run_cli):
    status, out, err = run_cli(*LINE, "--steps", "--csv")
    assert status == 0 and err == ""
    rows = list(csv.DictReader(io.StringIO(out)))
    _, json_out, _ = run_cli(*LINE, "--json")
    result = json.loads(json_out)
    assert len(rows) == result["steps"]
    assert [int(r["step"]) for r in rows] == list(range(len(rows)))
    plotted = [r for r in rows if r["pixel"]]
    assert [r["pixel"] for r in plotted] == [f"({x}, {y})" for x, y in result["pixels"]]
    decisions = bresenham_run((0, 0), (8, 3))[1]
    previous_y = 0
    for k, row in enumerate(plotted[1:], start=1):
        assert int(row["d"]) == decisions[k - 1]
        y = int(row["pixel"].strip("()").split(",")[1])
        # The nearest row to y = 3k/8, halves down (ties go to E).
        exact = Fraction(3 * k, 8)
        assert y == (exact - Fraction(1, 2)).__ceil__()
        assert row["choice"] == ("NE" if y > previous_y else "E")
        previous_y = y


def test_aligned_table_lines_up_and_names_the_code(run_cli):
    status, out, _ = run_cli(*LINE, "--steps")
    lines = out.splitlines()
    assert status == 0 and lines[0].split()[:5] == ["step", "line", "pseudo-code", "pixel", "choice"]
    assert len(lines) == 1 + json.loads(run_cli(*LINE, "--json")[1])["steps"]
    start = lines[0].index("pseudo-code")
    assert all(line[start - 2:start] == "  " for line in lines[1:] if len(line) > start)
    assert "plot(x, y)" in out


def test_json_carries_columns_and_rows_beside_the_run(run_cli):
    status, out, _ = run_cli(*LINE, "--steps", "--json")
    result = json.loads(out)
    keys = [column["key"] for column in result["columns"]]
    assert keys[:5] == ["step", "line", "code", "pixel", "choice"] and "d" in keys
    assert len(result["rows"]) == result["steps"]
    pixel = keys.index("pixel")
    assert [row[pixel] for row in result["rows"] if row[pixel]] == result["pixels"]


def test_polygon_steps_carry_the_tables(run_cli):
    status, out, _ = run_cli("run", "polygon-scanline", "--points", "2,2", "12,3", "8,9",
                             "--steps", "--json")
    result = json.loads(out)
    kinds = {column["key"]: column["kind"] for column in result["columns"]}
    assert "table" in kinds.values()
    table = [key for key, kind in kinds.items() if kind == "table"][0]
    at = list(kinds).index(table)
    assert any(isinstance(row[at], list) and row[at] for row in result["rows"])


@pytest.mark.parametrize("argv, words", [
    ((*LINE, "--csv"), "--steps"),
    ((*LINE, "--steps", "--ascii"), "--steps"),
    (("run", "line-bresenham-textbook", "--points", "0,0", "5,2", "--set", "variant=nope"),
     "variant"),
    (("run", "line-supercover", "--points", "0,0", "nan,2"), "finite"),
    (("run", "line-dda-printed", "--points", "0,0", "1.5,2"), "whole"),
])
def test_bad_input_is_one_line_and_status_2(run_cli, argv, words):
    status, out, err = run_cli(*argv)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and words in err


@pytest.mark.parametrize("name, options", [
    ("line-dda-printed", ["variant=x-only"]), ("line-bresenham-textbook", ["variant=as-printed"]),
    ("line-midpoint", []), ("line-implicit-infinite", []), ("line-parametric-printed", ["dt=0.1"]),
])
def test_printed_variants_run_with_every_output(run_cli, name, options):
    sets = [arg for option in options for arg in ("--set", option)]
    base = ("run", name, "--points", "1,1", "9,4", *sets)
    for extra in ((), ("--json",), ("--ascii",), ("--steps",), ("--steps", "--csv")):
        status, out, err = run_cli(*base, *extra)
        assert status == 0 and out and err == "", (name, extra)


def test_traversals_take_real_points(run_cli):
    status, out, _ = run_cli("run", "line-amanatides-woo", "--points", "0.5,0.25", "6.75,3.5",
                             "--json")
    pixels = json.loads(out)["pixels"]
    assert status == 0 and pixels[0] == [0, 0] and pixels[-1] == [6, 3]
