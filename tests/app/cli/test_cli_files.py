"""The command line never traces back on files and Ctrl+C: one line, a status."""
import os

import pytest

from algorithms.core import registry
from app.analysis import report


def _one_line(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


def test_report_out_with_a_name_too_long_is_one_line(run_cli, tmp_path):
    status, out, err = run_cli("report", "--quick", "--out", tmp_path / ("a" * 300))
    assert status == 2 and out == ""
    line = _one_line(err)
    assert line.startswith("rasterlab: ") and "too long" in line


def test_report_folder_without_permission_is_one_line(run_cli, tmp_path, monkeypatch):
    # Tests may run as root, which no folder refuses: the system's refusal is made here.
    def refused(out, **_):
        raise PermissionError(13, "Permission denied", str(tmp_path / "locked" / "report.md"))
    monkeypatch.setattr(report, "write_report", refused)
    status, _, err = run_cli("report", "--quick", "--out", tmp_path / "locked")
    line = _one_line(err)
    assert status == 2
    assert line.endswith("report.md: Permission denied")


def test_ctrl_c_during_run_is_one_line_and_130(run_cli, monkeypatch):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt
    monkeypatch.setattr(registry.AlgorithmSpec, "record", interrupted)
    status, out, err = run_cli("run", "line-bresenham", "--points", "0,0", "6,3")
    assert status == 130 and out == ""
    assert _one_line(err) == "rasterlab: run interrupted"


def test_a_long_message_keeps_its_reason_at_the_end():
    # Lines were cut at 300 characters, so a long path hid what went wrong.
    from app.model.scene import MAX_MESSAGE, one_line
    path = "/" + "/".join("folder%03d" % k for k in range(80)) + "/scene.json"
    reason = "cannot read the file (Permission denied)"
    line = one_line(f"{path}: {reason}")
    assert len(line) <= MAX_MESSAGE and line.endswith(": " + reason)
    assert line.startswith("/folder000")  # where the path starts, too


def test_a_long_value_in_a_command_line_error_keeps_the_reason(run_cli):
    status, _, err = run_cli("run", "line-dda", "--points", "0,0", "3," + "9" * 2000)
    line = _one_line(err)
    assert status == 2 and len(line) < 400
    assert line.endswith("is not a finite number") and "9" * 70 not in line
