"""One bound for the step cap and one syntax for numbers on the command line."""
import pytest

from algorithms.registry import InputError, parse_number
from algorithms.trace import MAX_STEP_CAP
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
