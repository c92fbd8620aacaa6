"""Flashes as WCAG 2.3.1 counts them (app/render/flashes.py), on frames made
here with known flashes, and on the exported frames of the aa-temporal scenes
(the wagon wheel's temporal aliasing and the motion-blur scenes) at their
default speed and at the fastest the export allows: never more than three a
second, the fast ones slowed to what is safe (app/render/flash_guard.py)."""
import numpy as np
import pytest

from algorithms.core import registry
from algorithms.core.steps import Vars
from app.model import shipped
from app.model.scene import Scene, load
from app.render import flash_guard, flashes
from app.render import export as ex
from app.render.settings import MAX_FPS, chosen_frames

SIDE = 300
BLACK, WHITE = (0, 0, 0), (255, 255, 255)


def frame(colour=BLACK, square=0, inside=WHITE, background=None):
    """A SIDE x SIDE frame of ``background`` (``colour`` when None) with a
    centred ``square``-pixel square of ``inside``; or all ``colour``."""
    image = np.empty((SIDE, SIDE, 3), np.uint8)
    image[:] = colour if background is None else background
    if square:
        lo = (SIDE - square) // 2
        image[lo:lo + square, lo:lo + square] = inside
    return image


def alternating(first, second, fps, seconds=3):
    """Frames swapping between two pictures at every frame, fps frames a second."""
    count = round(fps * seconds)
    return [first if k % 2 == 0 else second for k in range(count)], [1000 / fps] * count


def rate(frames, durations, loop=False):
    return flashes.flash_rate(frames, durations, loop).per_second


def test_a_whole_frame_black_white_at_5_hz_flashes_5_times_a_second():
    assert rate(*alternating(frame(BLACK), frame(WHITE), fps=10)) == 5


@pytest.mark.parametrize("fps, expected", [(4, 2), (7, 3), (8, 4), (20, 10)])
def test_the_count_follows_the_frame_rate(fps, expected):
    assert rate(*alternating(frame(BLACK), frame(WHITE), fps=fps)) == expected


# WCAG's field: 341 x 256 of a 1024 x 768 screen; a quarter of it flashing
# counts. In a 300 x 300 frame the field is 100 x 100 and a quarter 2500 px.
@pytest.mark.parametrize("square, counts", [(20, False), (45, False), (55, True), (150, True)])
def test_only_a_large_area_counts(square, counts):
    still = frame(BLACK)
    lit = frame(BLACK, square=square)
    assert rate(*alternating(still, lit, fps=10)) == (5 if counts else 0)


def test_small_changes_and_changes_among_bright_colours_are_not_flashes():
    grey = frame((118, 118, 118))        # relative luminance 0.181
    lighter = frame((128, 128, 128))     # 0.216: less than 0.1 apart
    assert rate(*alternating(grey, lighter, fps=10)) == 0
    bright = frame((237, 237, 237))      # 0.846: the darker is above 0.80
    assert rate(*alternating(bright, frame(WHITE), fps=10)) == 0
    red, green = frame((255, 0, 0)), frame((0, 255, 0))   # 0.213 and 0.715
    assert rate(*alternating(red, green, fps=10)) == 5


def test_a_slow_fade_is_one_change_not_many():
    ramp = [frame((v, v, v)) for v in range(0, 256, 15)]   # steps of less than 0.1 each
    frames = ramp + ramp[::-1]
    assert rate(frames, [1000 / 50] * len(frames)) == 1


def test_a_loop_counts_its_turn_back_to_the_first_frame():
    frames, durations = [frame(BLACK), frame(WHITE)], [100, 100]
    assert rate(frames, durations, loop=False) == 0
    assert rate(frames, durations, loop=True) == 5
    assert rate(frames, [100, 2100], loop=True) <= 1   # a long hold on the last frame


TEMPORAL = {
    "wagon wheel (temporal aliasing)": Scene(algorithm="aa-temporal", points=((16, 12),),
                                             width=32, height=24),
    "aa-motion-blur-jittered": load(shipped.scene_path("aa-motion-blur-jittered")),
    "aa-temporal-accumulation": load(shipped.scene_path("aa-temporal-accumulation")),
}


def measured(scene, settings):
    trace = ex.record(scene)
    settings = settings.for_grid(trace.width, trace.height)
    steps = chosen_frames(scene, trace, settings)[0]
    return flash_guard.measure(ex.FrameRenderer(scene, settings, trace), steps, settings)


@pytest.mark.parametrize("name", TEMPORAL)
def test_the_temporal_scenes_flash_at_most_3_times_a_second_at_their_default_speed(name):
    settings = ex.ExportSettings()
    assert measured(TEMPORAL[name], settings).per_second <= 3
    assert flash_guard.flash_safe(TEMPORAL[name], settings)[0] == settings   # left as asked


@pytest.mark.parametrize("hold", [2.0, 0.0])
@pytest.mark.parametrize("name", TEMPORAL)
def test_at_the_fastest_speed_they_are_slowed_where_they_would_flash(name, hold):
    scene, asked = TEMPORAL[name], ex.ExportSettings(fps=MAX_FPS, hold=hold)
    at_once = measured(scene, asked)
    settings, _, note = flash_guard.flash_safe(scene, asked)
    assert measured(scene, settings).per_second <= 3
    if at_once.per_second > 3:
        assert settings.fps == 7 and note.startswith(f"slowed from 50 to 7 frames a second: "
                                                     f"at 50 the animation would flash "
                                                     f"{at_once.per_second} times a second")
    else:
        assert (settings, note) == (asked, "")


def test_the_export_line_says_it_was_slowed(tmp_path, run_cli):
    gif = tmp_path / "blur.gif"
    status, out, err = run_cli("export", "aa-temporal-accumulation", "--gif", gif,
                               "--fps", "50", "--hold", "0")
    assert status == 0 and err == ""
    assert "slowed from 50 to 7 frames a second" in out and out.count("\n") == 1
    from PIL import Image
    with Image.open(gif) as image:
        assert image.info["duration"] >= 140   # 1/7 s, in ms (GIF's hundredths)


def picture_steps(trace):
    """The steps showing the empty grid and each complete animation frame,
    read from the records: frame k begins at the Vars record naming it and is
    complete one step before frame k + 1 begins, the last one step before the
    closing record."""
    starts = [index for index, record in trace.records_of(Vars) if "frame" in record.values]
    return [0] + [start - 1 for start in starts[1:]] + [len(trace) - 2]


@pytest.mark.parametrize("name", TEMPORAL)
def test_playback_is_capped_at_7_pictures_a_second(name):
    scene = TEMPORAL[name]
    trace = ex.record(scene)
    steps = picture_steps(trace)
    fewest = min(b - a for a, b in zip(steps, steps[1:]))
    cap = flashes.playback_cap(registry.get("aa-temporal"), trace)
    assert cap == 7 * fewest
    # At the cap, no second of play holds more than 7 changes of picture.
    window = cap  # steps in one second
    assert all(sum(start < s <= start + window for s in steps) <= 7 for start in range(len(trace)))


def test_a_run_without_animation_frames_has_no_playback_cap():
    scene = load(shipped.scene_path("demo-bresenham"))
    assert flashes.playback_cap(registry.get(scene.algorithm), ex.record(scene)) is None
