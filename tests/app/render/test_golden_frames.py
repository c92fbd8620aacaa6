"""Exported frames of shipped scenes against their stored golden frames
(see golden_frames.py; regenerated only by ``python scripts/make_golden.py``)."""
import numpy as np
import pytest

from tests.support.golden_frames import GOLDEN, GOLDEN_DIR, golden_frames


def hex_colour(rgb) -> str:
    return "#%02x%02x%02x" % tuple(int(v) for v in rgb)


def differences(steps, expected, got, limit: int = 12) -> str:
    """The cells that differ, as "step s (x, y): expected -> got" lines."""
    lines = []
    for k, step in enumerate(steps):
        ys, xs = np.nonzero((expected[k] != got[k]).any(axis=2))
        lines += [f"step {step} cell ({x}, {y}): {hex_colour(expected[k][y, x])} -> "
                  f"{hex_colour(got[k][y, x])}" for x, y in zip(xs, ys)]
    shown = "\n  ".join(lines[:limit])
    more = f"\n  ... and {len(lines) - limit} more" if len(lines) > limit else ""
    return f"{len(lines)} cells differ:\n  {shown}{more}"


def test_every_golden_scene_has_its_file_and_no_other():
    assert sorted(p.stem for p in GOLDEN_DIR.glob("*.npz")) == sorted(GOLDEN)


@pytest.mark.parametrize("name", GOLDEN)
def test_exported_frames_match_the_golden_frames(name):
    with np.load(GOLDEN_DIR / f"{name}.npz") as stored:
        steps, expected = stored["steps"], stored["cells"]
    now = golden_frames(name)
    assert now["steps"].tolist() == steps.tolist(), (
        f"{name}: the run now has other steps than when its golden frames were made "
        f"({now['steps'].tolist()} against {steps.tolist()})")
    assert now["cells"].shape == expected.shape
    if not np.array_equal(now["cells"], expected):
        pytest.fail(f"{name}: {differences(steps, expected, now['cells'])}\n"
                    "If the change is intended, run `python scripts/make_golden.py`.")


def test_a_changed_cell_is_named():
    expected = np.zeros((1, 2, 3, 3), np.uint8)
    got = expected.copy()
    got[0, 1, 2] = (255, 0, 0)
    assert differences([7], expected, got) == "1 cells differ:\n  step 7 cell (2, 1): #000000 -> #ff0000"
