"""One bound for the step cap and one syntax for numbers on the command line."""
import json

import pytest

from algorithms.core.registry import InputError, parse_number
from algorithms.core.trace import MAX_STEP_CAP
from app import cli
from app.cli import main
from app.gui import preferences


def test_the_step_cap_has_the_windows_bound():
    assert MAX_STEP_CAP == 50_000_000
    assert preferences.STEP_CAP_RANGE[1] == MAX_STEP_CAP


@pytest.mark.parametrize("cap", ["50000001", "1000000000000"])
def test_a_step_cap_over_the_bound_is_refused(run_cli, cap):
    status, out, err = run_cli("run", "line-bresenham", "--points", "0,0", "6,3",
                               "--step-cap", cap)
    assert (status, out) == (2, "")
    assert err == f"rasterlab: --step-cap must be 1 .. 50,000,000, got '{cap}'\n"


def test_the_step_cap_at_the_bound_is_taken(run_cli):
    status, _, err = run_cli("run", "line-bresenham", "--points", "0,0", "6,3",
                             "--step-cap", "50000000")
    assert (status, err) == (0, "")


def test_help_states_the_bound(capsys):
    with pytest.raises(SystemExit):
        main(["run", "--help"])
    assert "1 .. 50,000,000" in " ".join(capsys.readouterr().out.split())


@pytest.mark.parametrize("text", ["\u0661\u0662", "\uff11\uff12", "1_0", "\u0967", "1\u00a0",
                                  "0x10", "1e", "- 1"])
def test_numbers_are_ascii_digits_only(text):
    with pytest.raises(InputError, match="is not a number"):
        parse_number(text, "n")


@pytest.mark.parametrize("text, value", [("12", 12), (" -3 ", -3), ("+2.5", 2.5), ("1e3", 1000),
                                         (".5", 0.5), ("5.", 5), ("1E-2", 0.01)])
def test_ascii_numbers_are_taken(text, value):
    assert parse_number(text, "n") == value


@pytest.mark.parametrize("argv", [
    ["run", "line-bresenham", "--points", "\u0661,\u0662", "6,3"],
    ["run", "line-bresenham", "--points", "0,0", "6,3", "--grid", "\uff13\uff12,24"],
    ["run", "circle-midpoint", "--points", "10,10", "--set", "radius=1_0"],
    ["run", "line-bresenham", "--points", "0,0", "6,3", "--step-cap", "1_000"],
])
def test_the_command_line_refuses_other_digits(run_cli, argv):
    status, out, err = run_cli(*argv)
    assert (status, out) == (2, "")
    assert "is not a number" in err and len(err.splitlines()) == 1


@pytest.mark.parametrize("extra", [["--json"], []])
def test_pixels_are_printed_in_parts_and_read_the_same(run_cli, monkeypatch, extra):
    # A full grid's pixels as one list of Python objects took gigabytes
    # beyond the trace; in parts they print the same text.
    argv = ["run", "flood-fill-circle", "--points", "20,20", "--set", "radius=9",
            "--grid", "41,41", *extra]
    whole = run_cli(*argv)
    monkeypatch.setattr(cli.Rows, "PART", 7)
    parts = run_cli(*argv)
    assert parts == whole and whole[0] == 0
    if extra:
        result = json.loads(whole[1])
        assert len(result["pixels"]) == len(result["values"]) > 7 * 3
