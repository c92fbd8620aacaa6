"""The report's budget: refused before anything is made when over the memory
limit, and an estimate not below the peak a report is measured to reach."""
import os
import subprocess
import sys

import pytest

from app.analysis import measure
from app.analysis.report_budget import estimate_report_memory
from app.model.budget import parse_size
from tests.support import ROOT

MB = 1024 ** 2


def test_a_report_over_the_memory_limit_is_refused_in_one_line(run_cli, tmp_path):
    out = tmp_path / "report"
    status, text, err = run_cli("report", "--quick", "--memory-limit", "50M", "--out", out)
    assert status == 2 and text == ""
    assert err.count("\n") == 1 and "--memory-limit" in err and "MB" in err
    assert not out.exists()  # refused before the folder is made


def test_the_full_report_is_refused_where_the_quick_one_would_fit(run_cli, tmp_path):
    quick = estimate_report_memory(measure.settings(True))
    full = estimate_report_memory(measure.settings(False))
    assert quick < full
    limit = (quick + full) // 2
    status, _, err = run_cli("report", "--memory-limit", str(limit), "--out", tmp_path / "r")
    assert status == 2 and "--quick" in err


@pytest.mark.parametrize("limit", ["", "1x", "-5M", "\u0665M"])
def test_a_bad_memory_limit_is_refused(run_cli, tmp_path, limit):
    status, _, err = run_cli("report", "--quick", "--memory-limit", limit, "--out", tmp_path)
    assert status == 2 and err.count("\n") == 1 and "--memory-limit" in err


def test_the_default_limit_takes_both_reports():
    default = parse_size("2G")
    assert estimate_report_memory(measure.settings(False)) < default


PEAK = """
import sys
from app.analysis import report
report.write_report(sys.argv[1], quick=True)
"""


@pytest.mark.slow
@pytest.mark.skipif(not hasattr(os, "wait4"), reason="os.wait4 gives a child's own rusage")
def test_the_estimate_covers_the_measured_peak_of_a_quick_report(tmp_path, capsys):
    # the resident peak of a fresh child alone (interpreter and libraries
    # included), from wait4's rusage of that child: not this process's
    # ru_maxrss, which Linux carries across fork and exec
    child = subprocess.Popen([sys.executable, "-c", PEAK, str(tmp_path / "r")], cwd=ROOT,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    err = child.stderr.read().decode(errors="replace")
    child.stderr.close()
    assert os.waitstatus_to_exitcode(status) == 0, err
    peak = usage.ru_maxrss * (1 if sys.platform == "darwin" else 1024)
    estimate = estimate_report_memory(measure.settings(True))
    with capsys.disabled():
        print(f"\nquick report: peak {peak / MB:.0f} MB, estimate {estimate / MB:.0f} MB")
    assert peak <= estimate
