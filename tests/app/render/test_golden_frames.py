"""Exported frames of shipped scenes against their stored golden frames
(see golden_frames.py). ``--update-golden`` rewrites the files instead; a
failed comparison writes a diff image and names it."""
import numpy as np
import pytest
from PIL import Image

from tests.support.golden_frames import (CELL_PIXELS, CHANGED, GAP, GOLDEN, GOLDEN_DIR,
                                         diff_image, golden_frames, write_golden)


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


@pytest.mark.parametrize("name", GOLDEN)
def test_exported_frames_match_the_golden_frames(name, request, tmp_path):
    now = golden_frames(name)
    if request.config.getoption("--update-golden"):
        pytest.skip(f"wrote {write_golden(name, now)}")
    with np.load(GOLDEN_DIR / f"{name}.npz") as stored:
        steps, expected = stored["steps"], stored["cells"]
    assert now["steps"].tolist() == steps.tolist(), (
        f"{name}: the run now has other steps than when its golden frames were made "
        f"({now['steps'].tolist()} against {steps.tolist()})")
    assert now["cells"].shape == expected.shape
    if not np.array_equal(now["cells"], expected):
        picture = diff_image(expected, now["cells"], tmp_path / f"{name}-diff.png")
        pytest.fail(f"{name}: {differences(steps, expected, now['cells'])}\n"
                    f"Expected | now | changed cells: {picture}\n"
                    "If the change is intended, run pytest with --update-golden.")


def test_every_golden_scene_has_its_file_and_no_other():
    assert sorted(p.stem for p in GOLDEN_DIR.glob("*.npz")) == sorted(GOLDEN)


def test_a_changed_cell_is_named():
    expected = np.zeros((1, 2, 3, 3), np.uint8)
    got = expected.copy()
    got[0, 1, 2] = (255, 0, 0)
    assert differences([7], expected, got) == "1 cells differ:\n  step 7 cell (2, 1): #000000 -> #ff0000"


def test_the_diff_image_shows_expected_now_and_the_changed_cell(tmp_path):
    expected = np.zeros((1, 2, 3, 3), np.uint8)
    got = expected.copy()
    got[0, 1, 2] = (255, 0, 0)  # cell (2, 1): the top row, drawn y upwards
    picture = np.asarray(Image.open(diff_image(expected, got, tmp_path / "d.png")))
    width = 3 * CELL_PIXELS
    assert picture.shape[0] == 2 * CELL_PIXELS
    panels = [picture[:, k * (width + GAP):k * (width + GAP) + width] for k in range(3)]
    top_right = (CELL_PIXELS // 2, 2 * CELL_PIXELS + CELL_PIXELS // 2)
    assert (panels[0] == 0).all()
    assert tuple(panels[1][top_right]) == (255, 0, 0) and panels[1].sum() == 255 * CELL_PIXELS ** 2
    changed = (panels[2] == CHANGED).all(axis=2)
    assert changed.sum() == CELL_PIXELS ** 2 and changed[top_right]
