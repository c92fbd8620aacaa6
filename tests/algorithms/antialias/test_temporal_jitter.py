"""Jittered time samples for motion blur, beside the even ones."""
import numpy as np
import pytest

from algorithms.antialias.temporal import TEMPORAL_OPTIONS, temporal_frames, time_samples

DEFAULTS = {o.name: o.default for o in TEMPORAL_OPTIONS}
TRIANGLE = ((3.0, 4.0), (9.0, 3.0), (5.0, 11.0))
GRID = (24, 14)


def options(**given):
    return {**DEFAULTS, "primitive": "triangle", "motion": "move", "mode": "motion-blur",
            "speed": 5.0, "frames": 3, "time_samples": 6, "shutter": 0.75, **given}


@pytest.mark.parametrize("frame", [0, 1, 7])
def test_one_jittered_instant_in_each_stratum_of_the_exposure(frame):
    even = time_samples(options(), frame)
    jittered = time_samples(options(times="jittered"), frame)
    width = 0.75 / 6
    for s, (e, j) in enumerate(zip(even, jittered)):
        assert e == pytest.approx(frame + width * (s + 0.5))
        assert frame + width * s <= j < frame + width * (s + 1)
    assert jittered != even
    assert jittered == time_samples(options(times="jittered"), frame)  # repeatable


def instant_image(t):
    """The triangle moved speed * t along +x, sampled at one instant (frame 0)."""
    moved = tuple((x + 5.0 * t, y) for x, y in TRIANGLE)
    return temporal_frames(moved, options(mode="instant", frames=1), GRID)[0]


@pytest.mark.parametrize("times", ["even", "jittered"])
def test_a_blurred_frame_is_the_mean_of_its_instants(times):
    frames = temporal_frames(TRIANGLE, options(times=times), GRID)
    for k, image in enumerate(frames):
        instants = time_samples(options(times=times), k)
        expected = np.mean([instant_image(t) for t in instants], axis=0)
        assert np.allclose(image, expected, atol=1e-12)


def test_jitter_trades_banding_for_noise():
    # Even instants copy the triangle at fixed spacings (bands); jittered ones
    # at irregular spacings: the two frames differ, with the same ink in total
    # to within the triangle's area times one stratum's motion.
    even = temporal_frames(TRIANGLE, options(), GRID)[1]
    jittered = temporal_frames(TRIANGLE, options(times="jittered"), GRID)[1]
    assert not np.allclose(even, jittered)
    assert abs(even.sum() - jittered.sum()) < 1.0
