"""The streamed GIF decodes, frame for frame, to what was given to it."""
import io

import numpy as np
from PIL import Image, ImageSequence

from app.render.gif_stream import GifStream


def frames_of(data: bytes):
    with Image.open(io.BytesIO(data)) as gif:
        return [(np.asarray(frame.convert("RGB")).copy(), frame.info.get("duration"))
                for frame in ImageSequence.Iterator(gif)], gif.info.get("loop")


def test_frames_come_back_as_given_and_repeats_are_joined():
    rng = np.random.default_rng(7)
    colours = rng.integers(0, 256, (12, 3), dtype=np.uint8)
    palette = colours.tobytes() + bytes((255, 0, 255))  # entry 12: transparent, never drawn
    frames = [rng.integers(0, 12, (20, 30), dtype=np.uint8)]
    for k in range(7):
        frame = frames[-1].copy()
        if k != 3:  # frame 4 repeats frame 3
            frame[k:k + 4, 2 * k:2 * k + 5] = rng.integers(0, 12, (4, 5))
        frames.append(frame)
    stream = io.BytesIO()
    gif = GifStream(stream, (30, 20), palette, 12, loop=True)
    for k, frame in enumerate(frames):
        gif.add(frame, 100 + 10 * k)
    gif.close()
    decoded, loop = frames_of(stream.getvalue())
    assert loop == 0 and gif.frames_written == len(decoded) == len(frames) - 1
    expected = [k for k in range(len(frames)) if k != 4]
    for (picture, duration), k in zip(decoded, expected):
        assert np.array_equal(picture, colours[frames[k]])
        assert duration == (100 + 10 * k) + (140 if k == 3 else 0)


def test_a_still_single_frame_plays_once():
    stream = io.BytesIO()
    gif = GifStream(stream, (4, 3), bytes(range(6)) + bytes(3), 2, loop=False)
    gif.add(np.ones((3, 4), np.uint8), 2000)
    gif.close()
    decoded, loop = frames_of(stream.getvalue())
    assert loop is None and len(decoded) == 1 and decoded[0][1] == 2000
    assert (decoded[0][0] == (3, 4, 5)).all()
