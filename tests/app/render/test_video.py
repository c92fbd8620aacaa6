"""MP4 and WebM exports, decoded again with PyAV: frame count, size,
duration and the colours of cells against the GIF's frames."""
import av
import numpy as np
import pytest
from PIL import Image, ImageSequence

from app.model.scene import Scene
from app.render import export as ex
from app.render.video import VideoWriter

SCENE = Scene(algorithm="line-bresenham", points=((1, 1), (12, 6)), width=15, height=9)
# Flat cells (no primitive, no outlines), so a cell's colour survives 4:2:0 chroma.
SETTINGS = ex.ExportSettings(fps=5, hold=1.0, scale=16, panel="none", primitive=False,
                             highlight=False)


def decoded(path):
    with av.open(str(path)) as container:
        stream = container.streams.video[0]
        frames = [(float(f.time), f.to_ndarray(format="rgb24")) for f in container.decode(stream)]
        return stream.codec_context.name, container.duration / 1e6, frames


@pytest.mark.parametrize("kind, codec", [("mp4", "h264"), ("webm", "vp9")])
def test_a_video_has_the_gifs_frames_timing_and_colours(tmp_path, kind, codec):
    gif, video = tmp_path / "a.gif", tmp_path / f"a.{kind}"
    result = ex.export(SCENE, SETTINGS, gif=gif,
                       writers=[VideoWriter(video, kind, SETTINGS.fps, SETTINGS.hold)])
    name, duration, frames = decoded(video)
    assert name == codec
    # Every frame of the GIF, and the last one again where the hold ends.
    assert len(frames) == result.frames + 1
    assert duration == pytest.approx(sum(result.durations) / 1000, abs=0.011)
    assert [round(t, 3) for t, _ in frames[:-1]] == [k / SETTINGS.fps for k in range(result.frames)]
    height, width = frames[0][1].shape[:2]
    assert width % 2 == 0 and height % 2 == 0
    assert (width - result.size[0], height - result.size[1]) in {(0, 0), (1, 0), (0, 1), (1, 1)}
    gif_frames = [np.asarray(f.convert("RGB")) for f in ImageSequence.Iterator(Image.open(gif))]
    scale = SETTINGS.scale
    for k in (0, result.frames // 2, result.frames - 1):
        for x, y in ((1, 1), (6, 4), (12, 6), (3, 7)):
            row, col = (SCENE.height - 1 - y) * scale + scale // 2, x * scale + scale // 2
            want = gif_frames[k][row, col].astype(int)
            got = frames[k][1][row, col].astype(int)
            assert np.abs(want - got).max() <= 12, (k, x, y, want, got)


def test_an_odd_frame_is_padded_to_even_sides(tmp_path):
    scene = Scene(algorithm="line-bresenham", points=((0, 0), (4, 2)), width=5, height=3)
    video = tmp_path / "odd.mp4"
    result = ex.export(scene, ex.ExportSettings(scale=5, panel="none", caption=False),
                       writers=[VideoWriter(video, "mp4", 4, 0)])
    assert result.size == (25, 15)
    _, _, frames = decoded(video)
    assert frames[0][1].shape[:2] == (16, 26) and len(frames) == result.frames


def test_a_frame_too_large_for_h264_is_refused_before_anything_is_written(tmp_path):
    scene = Scene(algorithm="line-bresenham", points=((0, 0), (190, 90)), width=200, height=120)
    video = tmp_path / "big.mp4"
    with pytest.raises(ex.ExportError, match="too large for a video"):
        ex.export(scene, ex.ExportSettings(scale=20, panel="none", last=3),
                  writers=[VideoWriter(video, "mp4", 4, 0)])
    assert list(tmp_path.iterdir()) == []


def test_a_cancelled_video_leaves_nothing(tmp_path):
    video = tmp_path / "c.webm"
    calls = []

    def cancelled():
        calls.append(1)
        return len(calls) > 3
    with pytest.raises(ex.ExportCancelled):
        ex.export(SCENE, SETTINGS, writers=[VideoWriter(video, "webm", 5, 0)], cancelled=cancelled)
    assert list(tmp_path.iterdir()) == []
