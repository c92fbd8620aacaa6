"""The export command asks the run's budget and the frames' disk limit before
writing anything, and both limits can be set."""
from tests.support import ROOT

SCENE = ROOT / "resources" / "scenes" / "circle-radius-2.json"


def test_an_export_over_the_memory_limit_is_refused_and_writes_nothing(run_cli, tmp_path):
    gif = tmp_path / "out.gif"
    status, out, err = run_cli("export", SCENE, "--gif", gif, "--memory-limit", "1K")
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "over the limit of" in err
    assert list(tmp_path.iterdir()) == []
    status, _out, err = run_cli("export", SCENE, "--gif", gif, "--memory-limit", "1G")
    assert status == 0, err
    assert gif.is_file()


def test_frames_over_the_disk_limit_are_refused_and_the_limit_can_be_raised(run_cli, tmp_path):
    frames = tmp_path / "frames"
    status, out, err = run_cli("export", SCENE, "--frames-dir", frames, "--frames-limit", "4K")
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "limit" in err
    assert not frames.exists() or not any(frames.iterdir())
    status, _out, err = run_cli("export", SCENE, "--frames-dir", frames, "--frames-limit", "1G")
    assert status == 0, err
    assert len(list(frames.glob("frame_*.png"))) == 19


def test_a_bad_limit_is_one_line(run_cli, tmp_path):
    for option in ("--memory-limit", "--frames-limit"):
        status, out, err = run_cli("export", SCENE, "--gif", tmp_path / "x.gif", option, "lots")
        assert status == 2 and out == "" and len(err.strip().splitlines()) == 1
        assert option in err
