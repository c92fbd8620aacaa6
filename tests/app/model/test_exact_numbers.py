"""Exact fractions where the lecture notes print them: the edge table's 1/m,
Bresenham's m and barycentric weights, each against fractions worked out by
hand here, and the decimal form left as it was."""
from fractions import Fraction

import pytest

from algorithms.core.steps import Table
from app.model import shipped, step_output
from app.model import scene as scenes
from app.model.exact import exact_values, shown_rows
from app.model.notation import number
from app.model.steptable import StepTable
from app.model.tables import TableIndex, cell_text
from tests.support import record


def scene_trace(name):
    scene = scenes.load(shipped.scene_path(name))
    return scene, record(scene.algorithm, scene.points, options=scene.options,
                         grid=(scene.width, scene.height))


def first_table(trace, name) -> tuple[int, Table]:
    return next((i, t) for i, t in trace.records_of(Table) if t.name == name)


def test_the_et_of_a_shipped_scene_shows_1_over_m_as_fractions():
    # polygon-xlow-half-pixel: P1 (3, 2), P2 (28, 6), P3 (14, 21).
    # P1P2: dx 25, dy 4; P2P3: dx -14, dy 15; P3P1 from (3, 2) up to (14, 21): dx 11, dy 19.
    _scene, trace = scene_trace("polygon-xlow-half-pixel")
    index, _table = first_table(trace, "ET")
    exact = {row[1]: row[4] for row in TableIndex(trace, "exact").at(index)[0].rows}
    assert exact == {"P1P2": "25/4", "P2P3": "-14/15", "P3P1": "11/19"}
    decimal = {row[1]: row[4] for row in TableIndex(trace, "decimal").at(index)[0].rows}
    assert decimal == {"P1P2": "6.25", "P2P3": "\u2248-0.93333", "P3P1": "\u22480.57895"}
    text = StepTable(trace, "exact").text_row(index)
    assert any("1/m=-14/15" in cell for cell in text)


def test_the_notes_1_over_m_reads_minus_5_over_2():
    # An edge from (8, 1) up to (3, 3): x changes by -5 over 2 rows.
    trace = record("polygon-scanline", [[(8, 1), (10, 6), (3, 3)]], options={}, grid=(16, 8))
    index, table = first_table(trace, "ET")
    row = next(r for r in table.rows if r[1] == "P3P1")
    assert row[4] == Fraction(-5, 2)
    assert cell_text(row[4], "exact") == "-5/2" and cell_text(row[4]) == "-2.5"
    table = StepTable(trace, "exact")
    assert "1/m=-5/2" in table.text_row(index)[table.keys.index("ET")]


@pytest.mark.parametrize("name, end, m", [("line-bresenham", (25, 12), "11/24"),
                                          ("line-midpoint", (7, 20), "6/19"),
                                          ("line-bresenham-textbook", (-9, 4), "3/10")])
def test_bresenham_m_is_dy_over_dx_of_the_first_octant(name, end, m):
    # (1, 1) -> (25, 12): 11/24; (1, 1) -> (7, 20) is steep: 6/19 after the swap;
    # (1, 1) -> (-9, 4) runs left: mirrored, 3/10.
    trace = record(name, [(1, 1), end])
    assert exact_values(trace, 0)["m"] == Fraction(m)
    table = StepTable(trace, "exact")
    assert table.constants["m"] == Fraction(m)
    assert "m" not in StepTable(trace).constants  # decimal: the table as it was
    from algorithms.core.registry import get
    assert ("m", m) in shown_rows(get(name), trace, 1, "exact")
    assert "m" not in dict(shown_rows(get(name), trace, 1))


def weights(a, b, c, p):
    """alpha, beta, gamma of p, as ratios of signed areas, in Fractions."""
    def area(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])
    whole = area(a, b, c)
    return area(p, b, c) / whole, area(a, p, c) / whole, area(a, b, p) / whole


@pytest.mark.parametrize("name", ["triangle-cramer", "triangle-trilinear"])
def test_barycentric_weights_at_pixel_centres_are_exact(name):
    vertices = [(1, 1), (13, 4), (4, 11)]
    trace = record(name, vertices, options={}, grid=(16, 12))
    table = StepTable(trace, "exact")
    checked = 0
    for i in range(len(trace)):
        found = exact_values(trace, i)
        if "alpha" not in found:
            continue
        x, y = trace.step(i).pixel
        centre = (Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2))
        assert (found["alpha"], found["beta"], found["gamma"]) == weights(*vertices, centre)
        text = dict(zip(table.keys, table.text_row(i)))
        assert text["alpha"] == f"{found['alpha'].numerator}/{found['alpha'].denominator}" \
            or found["alpha"].denominator == 1
        checked += 1
    assert checked > 20


def test_weights_of_one_pixel_by_hand():
    # Triangle (0, 0), (4, 0), (0, 4); pixel (1, 0) has its centre at (3/2, 1/2):
    # 2A = 16; beta = 2 * (3/2) * 4 / 16 = 3/8, gamma = 2 * (1/2) * 4 / 16 = 1/8, alpha = 1/2.
    trace = record("triangle-cramer", [(0, 0), (4, 0), (0, 4)], options={}, grid=(6, 6))
    steps = [i for i in range(len(trace)) if trace.step(i).pixel == (1, 0)
             and "alpha" in exact_values(trace, i)]
    assert steps
    found = exact_values(trace, steps[-1])
    assert (found["alpha"], found["beta"], found["gamma"]) == (Fraction(1, 2), Fraction(3, 8),
                                                               Fraction(1, 8))


def test_weights_that_are_not_ratios_of_edge_values_stay_floats():
    # The printed test's distances have no sign: its weights are not e_k / 2A.
    trace = record("triangle-barycentric-printed", [(0, 0), (8, 0), (0, 8)], options={},
                   grid=(10, 10))
    assert not any(set(exact_values(trace, i)) & {"alpha", "beta", "gamma"}
                   for i in range(len(trace)))


def test_json_keeps_its_fields_and_adds_exact_strings():
    trace = record("triangle-cramer", [(1, 1), (13, 4), (4, 11)], options={}, grid=(16, 12))
    decimal, exact = StepTable(trace), StepTable(trace, "exact")
    columns = step_output.json_columns(exact)
    assert columns[:len(decimal.columns)] == step_output.json_columns(decimal)
    assert [c["key"] for c in columns[len(decimal.columns):]] == [
        "alpha_exact", "beta_exact", "gamma_exact"]
    for i in range(len(trace)):
        plain, more = step_output.json_row(decimal, i), step_output.json_row(exact, i)
        assert more[:len(plain)] == plain
        found = exact_values(trace, i)
        if "alpha" in found:
            assert Fraction(more[len(plain)]) == found["alpha"]
            assert plain[decimal.keys.index("alpha")] == pytest.approx(float(found["alpha"]))


def test_json_table_rows_gain_exact_fields():
    _scene, trace = scene_trace("polygon-xlow-half-pixel")
    index, _table = first_table(trace, "ET")
    plain = step_output.json_step(StepTable(trace), index)["tables"]["ET"]
    more = step_output.json_step(StepTable(trace, "exact"), index)["tables"]["ET"]
    assert [{k: v for k, v in row.items() if not k.endswith("_exact")} for row in more] == plain
    assert sorted(row["1/m_exact"] for row in more) == ["-14/15", "11/19", "25/4"]


def test_number_and_a_bad_setting():
    assert number(Fraction(-5, 2), numbers="exact") == "-5/2"
    assert number(Fraction(-5, 2)) == "-5/2 (-2.5)"
    with pytest.raises(ValueError, match="numbers must be decimal or exact"):
        StepTable(record("line-bresenham", [(0, 0), (5, 2)]), "fractions")
