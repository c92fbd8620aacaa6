"""Transcripts written beside an export, so that a person who cannot see the
pictures can follow them: the description of each exported step in words
(``app/model/step_words.py``).

* Beside a GIF, ``NAME.txt``: one description a line, a line for each
  exported step.
* Beside an MP4 or WebM, ``NAME.vtt``: WebVTT captions, one cue a frame,
  timed as the frames are (the export's fps, the hold on the last frame),
  which video players show under the picture.

Each is a writer of the export's protocol (``app/render/writers.py``)
that takes the step rather than the picture, and writes its file whole
at the end (``write_atomically``); the command line and the dialog check
its path with the other outputs (``check_outputs``), so a transcript never
replaces a file RasterLab did not write unless --force says so.
"""
from __future__ import annotations

import re
from pathlib import Path

from app.model.files import Output, write_atomically
from app.model.step_words import describe
from app.render.settings import ExportError, frame_durations

VTT_HEADER = "WEBVTT - RasterLab transcript"
_DESCRIPTION = re.compile(r"^step \d+ of \d+: ")


def transcript_paths(gif=None, mp4=None, webm=None) -> list[tuple[str, Path]]:
    """(option, path) of each transcript the picture outputs call for: a
    .txt beside the GIF, a .vtt beside each video (one for both when an
    MP4 and a WebM share a name)."""
    found: dict[Path, str] = {}
    for option, picture, suffix in (("--gif", gif, ".txt"), ("--mp4", mp4, ".vtt"),
                                    ("--webm", webm, ".vtt")):
        if picture is not None:
            found.setdefault(Path(picture).with_suffix(suffix), option)
    return [(f"{option} transcript", path) for path, option in found.items()]


def outputs(gif=None, mp4=None, webm=None) -> list[Output]:
    """The transcripts as outputs of the output policy."""
    return [Output(option, path, foreign=_not_a_transcript)
            for option, path in transcript_paths(gif, mp4, webm)]


def _not_a_transcript(path: Path) -> str | None:
    """Why an existing file is not a transcript RasterLab wrote (None: it is, or is empty)."""
    with open(path, "rb") as stream:
        head = stream.read(len(VTT_HEADER) + 64).decode("utf-8", "replace")
    if not head or head.startswith(VTT_HEADER) or _DESCRIPTION.match(head):
        return None
    return "is not a transcript RasterLab wrote"


def writers(gif=None, mp4=None, webm=None, settings=None) -> list:
    """A TranscriptWriter for each transcript the picture outputs call for."""
    return [TranscriptWriter(path, settings.fps, settings.hold, settings.numbers)
            for _option, path in transcript_paths(gif, mp4, webm)]


def text(lines: list[str]) -> str:
    """The .txt transcript: one description a line."""
    return "".join(f"{line}\n" for line in lines)


def webvtt(lines: list[str], durations_ms: list[int]) -> str:
    """WebVTT captions: a cue per line, each lasting its frame's duration."""
    cues, start = [VTT_HEADER, ""], 0
    for number, (line, duration) in enumerate(zip(lines, durations_ms), 1):
        end = start + duration
        cues += [str(number), f"{_timestamp(start)} --> {_timestamp(end)}", line, ""]
        start = end
    return "\n".join(cues)


def _timestamp(ms: int) -> str:
    hours, rest = divmod(ms, 3_600_000)
    minutes, rest = divmod(rest, 60_000)
    seconds, millis = divmod(rest, 1000)
    return f"{hours:02d}:{minutes:02d}:{seconds:02d}.{millis:03d}"


class TranscriptWriter:
    """Writes the exported steps' descriptions to ``path``: a .vtt as
    captions timed by ``fps`` and ``hold``, anything else as lines."""

    def __init__(self, path, fps: float, hold: float, numbers: str = "decimal"):
        self.path = Path(path)
        self.fps, self.hold, self.numbers = fps, hold, numbers
        self.lines: list[str] = []

    def setup(self, size, count, palette, transparent) -> None:
        self.lines = []  # the words need no picture: nothing to get ready

    def grab_step(self, renderer, index: int) -> None:
        self.lines.append(describe(renderer.trace, index, self.numbers))

    def finish(self) -> None:
        if self.path.suffix.lower() == ".vtt":
            body = webvtt(self.lines, frame_durations(len(self.lines), self.fps, self.hold))
        else:
            body = text(self.lines)
        write_atomically(self.path, body.encode("utf-8"), ExportError)

    def abort(self) -> None:
        self.lines = []  # nothing was written: the file appears only in finish
