"""The staging journal cannot be steered: recovery moves and removes only
plain file names inside the output folder, named by a journal of this
program's own; any other journal is left alone, with one line on stderr."""
import json
import os
import subprocess
import sys

import pytest

from app.model import staging
from app.model.staging import JOURNAL, StagedFolder


@pytest.fixture(scope="module")
def dead_pid():
    """The id of a process that has ended."""
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    assert not staging.process_alive(child.pid)
    return child.pid


@pytest.fixture
def planted(tmp_path, dead_pid):
    """The issue's case: victims outside the output folder and, in a staging
    folder of a process that is gone, a journal naming them."""
    victim = tmp_path / "abs" / "victim.txt"
    victim.parent.mkdir()
    victim.write_text("keep me")
    victim2 = tmp_path / "work" / "victim2.txt"
    victim2.parent.mkdir()
    victim2.write_text("keep me too")
    out = tmp_path / "work" / "out"
    out.mkdir()

    def plant(kind):
        stage = out / f".rasterlab-{kind}-{dead_pid}-abc"
        stage.mkdir()
        (stage / JOURNAL).write_text(json.dumps(
            {"names": ["../../victim2.txt"], "remove": [str(victim)]}))
        return stage
    return out, plant, [victim, victim2]


def untouched(victims, tmp_path):
    assert [v.read_text() for v in victims] == ["keep me", "keep me too"]
    assert not (tmp_path / "victim2.txt").exists()  # where the move would have put it


def test_export_frames_dir_leaves_the_victims_and_the_planted_folder(planted, tmp_path,
                                                                      run_cli):
    out, plant, victims = planted
    stage = plant("frames")
    status, _, err = run_cli("export", "demo-bresenham", "--frames-dir", out, "--to", "2")
    assert status == 0, err
    untouched(victims, tmp_path)
    assert (stage / JOURNAL).is_file()  # left as it was
    assert err.count("foreign or damaged") == 1 and stage.name in err
    assert sorted(p.name for p in out.glob("frame_*.png")) == [
        "frame_0000.png", "frame_0001.png", "frame_0002.png"]


def test_report_out_leaves_the_victims(planted, tmp_path, run_cli, monkeypatch):
    from app.analysis import measure

    class NoRows:
        rows = []
    # The measuring is not what is tested: the report is written from no rows.
    monkeypatch.setattr(measure, "run", lambda config, progress=None: (NoRows, {}))
    out, plant, victims = planted
    stage = plant("report")
    status, _, err = run_cli("report", "--quick", "--out", out)
    assert status == 0, err
    untouched(victims, tmp_path)
    assert (stage / JOURNAL).is_file() and (out / "report.md").is_file()
    assert "foreign or damaged" in err


@pytest.mark.parametrize("plan", [
    {"names": ["../x.png"], "remove": []},
    {"names": [], "remove": ["/abs/victim.txt"]},
    {"names": ["..", ], "remove": []},
    {"names": ["sub/x.png"], "remove": []},
    {"names": ["sub\\x.png"], "remove": []},
    {"names": [], "remove": ["C:victim.txt"]},
    {"names": [], "remove": [""]},
    {"names": [JOURNAL], "remove": []},
    {"names": "frame_0000.png", "remove": []},
    {"names": [1], "remove": []},
    {"names": ["frame_0000.png"]},
], ids=repr)
def test_a_journal_naming_what_it_may_not_is_left_alone(tmp_path, dead_pid, plan, capsys):
    out = tmp_path / "out"
    stage = out / f".rasterlab-frames-{dead_pid}-x"
    stage.mkdir(parents=True)
    (stage / "frame_0000.png").write_text("staged")
    (out / "victim.txt").write_text("keep")
    (stage / JOURNAL).write_text(json.dumps({**staging.MARKER, **plan}))
    assert StagedFolder(out, "frames").recover() == []
    assert sorted(p.name for p in stage.iterdir()) == [JOURNAL, "frame_0000.png"]
    assert sorted(p.name for p in out.iterdir()) == [stage.name, "victim.txt"]
    assert capsys.readouterr().err.count("\n") == 1


@pytest.mark.parametrize("journal", [
    json.dumps({"names": ["frame_0000.png"], "remove": []}),           # no marker
    json.dumps({"rasterlab": "staging", "version": 2, "names": [], "remove": []}),
    "{not json",
    b"\xff\xfe".decode("latin-1"),
], ids=["no marker", "another version", "not JSON", "not UTF-8"])
def test_a_foreign_or_damaged_journal_is_left_alone(tmp_path, dead_pid, journal, capsys):
    out = tmp_path / "out"
    stage = out / f".rasterlab-frames-{dead_pid}-x"
    stage.mkdir(parents=True)
    (stage / "frame_0000.png").write_text("staged")
    (stage / JOURNAL).write_text(journal, encoding="latin-1")
    assert StagedFolder(out, "frames").recover() == []
    assert (stage / "frame_0000.png").read_text() == "staged"
    assert not (out / "frame_0000.png").exists()
    assert "foreign or damaged" in capsys.readouterr().err


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")
def test_a_journal_that_is_a_fifo_or_a_link_is_not_read(tmp_path, dead_pid):
    out = tmp_path / "out"
    elsewhere = tmp_path / "elsewhere.json"
    elsewhere.write_text(json.dumps({**staging.MARKER, "names": [], "remove": ["keep.txt"]}))
    (out / "keep.txt").parent.mkdir()
    (out / "keep.txt").write_text("keep")
    fifo = out / f".rasterlab-frames-{dead_pid}-fifo"
    fifo.mkdir()
    os.mkfifo(fifo / JOURNAL)  # reading it would wait for a writer for ever
    link = out / f".rasterlab-frames-{dead_pid}-link"
    link.mkdir()
    (link / JOURNAL).symlink_to(elsewhere)
    assert StagedFolder(out, "frames").recover() == []
    assert (out / "keep.txt").read_text() == "keep"


def test_a_journal_of_ours_is_finished(tmp_path, dead_pid, capsys):
    out = tmp_path / "out"
    out.mkdir()
    (out / "frame_0001.png").write_text("old")
    (out / "notes.txt").write_text("keep")
    stage = out / f".rasterlab-frames-{dead_pid}-x"
    stage.mkdir()
    (stage / "frame_0000.png").write_text("new")
    (stage / JOURNAL).write_text(json.dumps({"rasterlab": "staging", "version": 1,
                                             "names": ["frame_0000.png"],
                                             "remove": ["frame_0001.png"]}))
    assert StagedFolder(out, "frames").recover() == [stage]
    assert sorted(p.name for p in out.iterdir()) == ["frame_0000.png", "notes.txt"]
    assert (out / "frame_0000.png").read_text() == "new"
    assert capsys.readouterr().err == ""


def test_commit_writes_the_marker_and_refuses_names_recovery_would_refuse(tmp_path):
    staged = StagedFolder(tmp_path, "frames")
    stage = staged.open()
    for name in ("..", "", "a:b", "sub\\x", JOURNAL):
        with pytest.raises(ValueError, match="not a plain file name"):
            staged.commit([name])
    (stage / "a.png").write_text("a")
    written = []
    move = staged._move

    def record(stage_folder, names, remove):
        written.append(json.loads((stage_folder / JOURNAL).read_text()))
        move(stage_folder, names, remove)
    staged._move = record
    staged.commit(["a.png"])
    assert written == [{"rasterlab": "staging", "version": 1, "names": ["a.png"], "remove": []}]
    assert (tmp_path / "a.png").read_text() == "a"
