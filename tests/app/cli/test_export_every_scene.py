"""Every shipped scene exports with the default options, into a file a
slide can hold: a bounded number of frames, a frame no larger than a frame
may be, one line saying what was chosen."""
import pytest
from PIL import Image

from algorithms.core import registry

from app.model.scene import load
from app.render import units
from app.render.export import MAX_SIDE, ExportSettings, FrameRenderer, chosen_frames, record
from tests.support import ROOT

SCENES = sorted((ROOT / "resources" / "scenes").glob("*.json"))


def test_the_default_choice_of_every_scene_fits_a_slide():
    assert len(SCENES) >= 17
    for path in SCENES:
        scene = load(path)
        trace = record(scene)
        steps, said = chosen_frames(scene, trace, ExportSettings())
        assert 2 <= len(steps) <= units.AUTO_FRAMES or len(steps) == len(trace), path.name
        if said.startswith("one frame per animation frame"):
            # An animation (aa-temporal) shows each of its frames once it is complete.
            frames = registry.get(scene.algorithm).resolve(scene.options)["frames"]
            assert len(steps) == frames and steps[-1] < len(trace), path.name
        else:
            assert steps[0] == 0 and steps[-1] == len(trace) - 1, path.name
        assert steps == sorted(set(steps)), path.name
        assert f"{len(steps):,} frames for {len(trace):,} steps" in said
        width, height = FrameRenderer(scene, ExportSettings(), trace).size
        assert width <= MAX_SIDE and height <= MAX_SIDE, path.name


def test_every_shipped_scene_exports_from_the_command_line(run_cli, tmp_path, monkeypatch):
    # The automatic choice with a bound of 6 frames instead of 240, so that
    # the 17 exports take seconds: the same code chooses, draws and writes.
    monkeypatch.setattr(units, "AUTO_FRAMES", 6)
    for path in SCENES:
        gif = tmp_path / f"{path.stem}.gif"
        code, out, err = run_cli("export", path, "--gif", gif)
        assert code == 0 and err == "", (path.name, err)
        assert "one frame per" in out and "px per cell" in out
        with Image.open(gif) as image:
            assert image.n_frames <= 6 and max(image.size) <= MAX_SIDE
        assert gif.stat().st_size < 8 * 2 ** 20


@pytest.mark.parametrize("unit", ["step", "decision", "pixel", "scanline", "primitive"])
def test_each_unit_ends_its_frames_where_the_trace_says(unit):
    # Worked out here from the trace's own columns, step by step.
    scene = load(ROOT / "resources" / "scenes" / "triangle-fan-32.json")
    trace = record(scene)
    frames = units.unit_ends(trace, unit, 0, len(trace)).tolist()
    writes = [i for i in range(len(trace)) if trace.step(i).writes
              or (trace.step(i).record is not None and hasattr(trace.step(i).record, "x_start")
                  and trace.code[trace.step(i).line].kind == "plot")]
    if unit == "step":
        expected = list(range(len(trace)))
    elif unit == "decision":
        expected = [i for i in range(len(trace)) if trace.step(i).branch]
    elif unit == "pixel":
        expected = writes
    elif unit == "scanline":
        rows = [trace.step(i).pixel[1] for i in writes]
        expected = [i for k, i in enumerate(writes) if k + 1 == len(writes) or rows[k + 1] != rows[k]]
    else:
        starts = [i for i in range(len(trace)) if "triangle" in getattr(trace.step(i).record,
                                                                        "values", {})]
        expected = [i - 1 for i in starts if i > 0]
        assert len(starts) == 32
    assert frames == sorted({0, len(trace) - 1, *expected})
