"""The polygon algorithms through the command line: contours, options, refusals."""
import json

from algorithms.exact import polygons as oracle

SQUARE_WITH_HOLE = ["--points", "1,1", "15,1", "15,15", "1,15",
                    "--points", "5,5", "11,5", "11,11", "5,11"]


def test_run_takes_one_points_list_per_contour(run_cli):
    for rule in ("evenodd", "nonzero"):
        status, out, err = run_cli("run", "polygon-scanline", *SQUARE_WITH_HOLE,
                                   "--set", f"fill_rule={rule}", "--json")
        assert status == 0 and err == ""
        result = json.loads(out)
        contours = [[(1, 1), (15, 1), (15, 15), (1, 15)], [(5, 5), (11, 5), (11, 11), (5, 11)]]
        assert {tuple(p) for p in result["pixels"]} == oracle.covered_pixels(contours, rule)
        assert result["options"] == {"fill_rule": rule, "arithmetic": "exact"}
        assert result["final"]["pixels"] == len(result["pixels"])


def test_run_accepts_real_coordinates_and_the_arithmetic_option(run_cli):
    status, out, _ = run_cli("run", "polygon-scanline", "--points", "0.5,1.25", "9.75,3", "5,9.5",
                             "--grid", "12,12", "--set", "arithmetic=float32", "--json")
    assert status == 0
    pixels = {tuple(p) for p in json.loads(out)["pixels"]}
    assert pixels == oracle.covered_pixels([[(0.5, 1.25), (9.75, 3), (5, 9.5)]])


def test_ascii_output_of_tessellation(run_cli):
    status, out, _ = run_cli("run", "polygon-tessellate", "--points", "1,1", "9,1", "5,5", "9,9",
                             "1,9", "--ascii")
    assert status == 0
    assert "+" not in out  # no pixel written twice
    assert out.count("#") == len(oracle.covered_pixels([[(1, 1), (9, 1), (5, 5), (9, 9), (1, 9)]]))


def test_refusals_are_one_line_with_status_2(run_cli):
    status, out, err = run_cli("run", "polygon-convex", "--points", "1,1", "9,1", "5,4", "5,9")
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and "not convex" not in err and "convex polygon" in err
    status, _, err = run_cli("run", "polygon-tessellate", *SQUARE_WITH_HOLE)
    assert status == 2 and "fills one contour, got 2" in err
    status, _, err = run_cli("run", "polygon-scanline", "--points", "1,1", "2,2")
    assert status == 2 and "at least 3 points" in err
