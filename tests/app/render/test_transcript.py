"""Transcripts: `run --describe`, and the .txt beside a GIF and the WebVTT
captions beside a video that export writes by default, through the output
policy."""
from __future__ import annotations

import re

import pytest

from app.model import scene as scenes
from app.model import shipped
from app.model.step_words import describe_steps
from app.render.settings import record
from app.render.transcript import VTT_HEADER

SCENE = "demo-bresenham"
CUE_TIME = re.compile(r"^(\d\d):(\d\d):(\d\d)\.(\d\d\d) --> (\d\d):(\d\d):(\d\d)\.(\d\d\d)$")


@pytest.fixture(scope="module")
def words():
    """The descriptions of the scene's steps, every step exported."""
    return describe_steps(record(scenes.load(shipped.scene_path(SCENE))))


def _ms(parts) -> int:
    hours, minutes, seconds, millis = (int(part) for part in parts)
    return ((hours * 60 + minutes) * 60 + seconds) * 1000 + millis


def parse_vtt(text: str) -> list[tuple[int, int, str]]:
    """(start ms, end ms, text) of each cue; AssertionError when it is not WebVTT."""
    blocks = text.split("\n\n")
    assert blocks[0].startswith("WEBVTT")
    cues = []
    for block in blocks[1:]:
        lines = [line for line in block.split("\n") if line]
        if not lines:
            continue
        timing = CUE_TIME.match(lines[1])
        assert lines[0].isdigit() and timing, block
        cues.append((_ms(timing.groups()[:4]), _ms(timing.groups()[4:]), "\n".join(lines[2:])))
    return cues


def test_run_describe_prints_one_description_a_step(run_cli):
    status, out, err = run_cli("run", "line-bresenham", "--points", "0,0", "5,2", "--describe")
    assert status == 0 and err == ""
    lines = out.splitlines()
    assert len(lines) == 8
    # The textbook's d for (0, 0)-(5, 2): -1, 3, -3, 1, -5.
    assert lines[2:7] == ["step 2 of 7: d = -1, at most 0, so E: plot (1, 0)",
                          "step 3 of 7: d = 3, above 0, so NE: plot (2, 1)",
                          "step 4 of 7: d = -3, at most 0, so E: plot (3, 1)",
                          "step 5 of 7: d = 1, above 0, so NE: plot (4, 2)",
                          "step 6 of 7: d = -5, at most 0, so E: plot (5, 2)"]


def test_run_describe_takes_the_numbers_setting_and_refuses_another_output(run_cli):
    status, out, _ = run_cli("run", "polygon-scanline", "--points", "1,1", "8,2", "5,7",
                             "--describe", "--numbers", "exact")
    assert status == 0 and "crosses the edges at x = 4/3, 9/2;" in out
    status, out, err = run_cli("run", "line-bresenham", "--points", "0,0", "5,2", "--describe",
                               "--json")
    assert status == 2 and out == "" and len(err.splitlines()) == 1


def test_a_gif_gets_its_transcript_and_a_video_its_captions(run_cli, tmp_path, words):
    gif, mp4 = tmp_path / "run.gif", tmp_path / "run.mp4"
    status, out, err = run_cli("export", SCENE, "--gif", gif, "--mp4", mp4, "--fps", "4",
                               "--hold", "1")
    assert status == 0, err
    assert (tmp_path / "run.txt").read_text(encoding="utf-8").splitlines() == words
    cues = parse_vtt((tmp_path / "run.vtt").read_text(encoding="utf-8"))
    assert [text for _, _, text in cues] == words
    starts = [start for start, _, _ in cues]
    assert starts == sorted(set(starts)) and starts[0] == 0
    assert all(end == following for (_, end, _), following in zip(cues, starts[1:]))
    # 4 frames a second: 250 ms each, the last held 1 s more.
    assert [end - start for start, end, _ in cues] == [250] * (len(words) - 1) + [1250]


def test_no_transcript_writes_none(run_cli, tmp_path):
    status, _, err = run_cli("export", SCENE, "--gif", tmp_path / "run.gif", "--no-transcript")
    assert status == 0, err
    assert sorted(path.name for path in tmp_path.iterdir()) == ["run.gif"]


def test_a_file_in_the_transcripts_place_is_kept_unless_forced(run_cli, tmp_path, words):
    notes = tmp_path / "run.txt"
    notes.write_text("my own notes\n", encoding="utf-8")
    status, _, err = run_cli("export", SCENE, "--gif", tmp_path / "run.gif")
    assert status == 2 and "is not a transcript RasterLab wrote" in err
    assert notes.read_text(encoding="utf-8") == "my own notes\n"
    assert not (tmp_path / "run.gif").exists()  # refused before any work
    status, _, err = run_cli("export", SCENE, "--gif", tmp_path / "run.gif", "--force")
    assert status == 0, err
    assert notes.read_text(encoding="utf-8").splitlines() == words
    # A transcript RasterLab wrote is replaced as its GIF is.
    status, _, err = run_cli("export", SCENE, "--gif", tmp_path / "run.gif", "--to", "3")
    assert status == 0, err
    assert notes.read_text(encoding="utf-8").splitlines() == words[:4]


def test_a_vtt_not_ours_is_refused(run_cli, tmp_path):
    (tmp_path / "talk.vtt").write_text("WEBVTT\n\n1\n00:00.000 --> 00:01.000\nhello\n",
                                       encoding="utf-8")
    status, _, err = run_cli("export", SCENE, "--webm", tmp_path / "talk.webm")
    assert status == 2 and "talk.vtt" in err
    assert VTT_HEADER.startswith("WEBVTT ")


def test_the_python_api_can_leave_the_transcript_out(tmp_path):
    import rasterlab
    rasterlab.export(SCENE, tmp_path / "a.gif", transcript=False, last=3)
    rasterlab.export(SCENE, tmp_path / "b.gif", last=3)
    assert sorted(path.name for path in tmp_path.iterdir()) == ["a.gif", "b.gif", "b.txt"]
