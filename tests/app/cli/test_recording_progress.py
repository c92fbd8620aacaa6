"""A recording that runs longer than two seconds shows a bar on a terminal
(and nothing where stderr is a file or a pipe); the bar is wiped when the
run ends, so the command's own output reads as before."""
from __future__ import annotations

import io

import pytest

from app import progress
from app.progress import RecordingBar
from tests.support import ROOT

# A flood fill of 296 x 296 pixels: more steps than one monitor report (65,536).
FILL = ["flood-fill", "--points", "1,1", "298,1", "298,298", "1,298", "--grid", "300,300"]


class Terminal(io.StringIO):
    def isatty(self):
        return True


class Clock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def test_the_bar_waits_two_seconds_then_shows_steps_and_time_left():
    stream, clock = Terminal(), Clock()
    bar = RecordingBar(1000, stream, clock)
    clock.now += 1.9
    bar(100)
    assert stream.getvalue() == ""
    clock.now += 0.1  # 2 s after the start, 250 of at most 1,000 steps
    bar(250)
    assert "recording [" in stream.getvalue() and "250/1000" in stream.getvalue()
    assert "at most 6 s left" in stream.getvalue()  # 750 steps more at 125 steps a second
    bar.clear()
    assert stream.getvalue().endswith("\r\033[K")


def test_a_bar_on_a_file_or_pipe_draws_nothing():
    stream, clock = io.StringIO(), Clock()
    bar = RecordingBar(10, stream, clock)
    clock.now += 60
    bar(5)
    bar.clear()
    assert stream.getvalue() == ""


@pytest.mark.parametrize("argv", [["run", *FILL, "--ascii"]])
def test_a_long_run_on_a_terminal_shows_the_bar_and_wipes_it(argv, run_cli, monkeypatch):
    from app import cli
    terminal = Terminal()
    monkeypatch.setattr(RecordingBar, "AFTER", 0.0)  # every report draws, however fast the machine
    monkeypatch.setattr(progress.sys, "stderr", terminal)
    assert cli.main(argv) == 0
    shown = terminal.getvalue()
    assert "recording [" in shown and "steps, at most" in shown
    assert shown.endswith("\r\033[K")


def test_the_worksheet_and_export_record_with_the_bar(tmp_path, monkeypatch):
    from app import cli
    from app.model import scene as scenes
    scene = scenes.Scene(algorithm="flood-fill",
                         points=(((1, 1), (298, 1), (298, 298), (1, 298)),),
                         width=300, height=300)
    path = tmp_path / "fill.json"
    scenes.save(scene, path)
    terminal = Terminal()
    monkeypatch.setattr(RecordingBar, "AFTER", 0.0)
    monkeypatch.setattr(progress.sys, "stderr", terminal)
    assert cli.main(["worksheet", str(path), "--out", str(tmp_path / "sheet"),
                     "--format", "csv"]) == 0
    assert "recording [" in terminal.getvalue() and terminal.getvalue().endswith("\r\033[K")
    terminal.seek(0), terminal.truncate()
    assert cli.main(["export", str(path), "--html", str(tmp_path / "fill.html")]) == 0
    assert "recording [" in terminal.getvalue() and terminal.getvalue().endswith("\r\033[K")


def test_a_long_check_shows_its_cases_on_a_terminal(monkeypatch):
    from app import cli
    from app.progress import CasesBar
    terminal = Terminal()
    monkeypatch.setattr(CasesBar, "AFTER", 0.0)
    monkeypatch.setattr(progress.sys, "stderr", terminal)
    sample = ROOT / "resources" / "students" / "bresenham_correct.py"
    assert cli.main(["check", str(sample), "--against", "line-bresenham"]) == 0
    shown = terminal.getvalue()
    assert "checking [" in shown and "cases, about" in shown
    assert shown.endswith("\r\033[K")


def test_the_cases_bar_waits_two_seconds():
    stream, clock = Terminal(), Clock()
    bar = progress.CasesBar(stream, clock)
    clock.now += 1.0
    bar(1, 4)
    assert stream.getvalue() == ""
    clock.now += 1.0  # 2 s for 2 of 4 cases: about 2 s left
    bar(2, 4)
    assert "2/4 cases, about 2 s left" in stream.getvalue()


def test_the_grading_bar_counts_cases_and_submissions():
    stream, clock = Terminal(), Clock()
    bar = progress.GradingBar(3, 4, stream, clock)  # 3 submissions of 4 cases
    for _ in range(4):
        bar.case_done()
    assert stream.getvalue() == ""  # under 2 s
    clock.now += 4.0  # 4 s for 4 of 12 cases: about 8 s left
    bar.submission_done()
    assert "grading [" in stream.getvalue()
    assert "4/12 cases, 1 of 3 submissions, about 8 s left" in stream.getvalue()
