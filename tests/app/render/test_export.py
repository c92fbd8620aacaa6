"""Lecture export: GIFs and PNG frames drawn headless, read back with Pillow.

Expected pixels come from a textbook Bresenham written here, not from the
code under test; colours are probed at cell centres, where neither grid
lines nor outlines reach.
"""
import io
import json
import os
import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

from algorithms.core import registry
from app import cli
from app.render import export as ex
from app.render.frame import FrameMarks, compose_frame, frame_marks, primitive_mask
from app.render.compose import PALETTE, Overlay, compose
from app.model.scene import Scene, load, save
from tests.support import ROOT
from tests.support.bresenham import bresenham_pixels

P, Q = (1, 1), (12, 6)
GRID = (14, 8)


def rgb(color):
    value = int(color.lstrip("#"), 16)
    return ((value >> 16) & 255, (value >> 8) & 255, value & 255)


@pytest.fixture
def line_scene(tmp_path):
    path = tmp_path / "line.json"
    save(Scene(algorithm="line-bresenham", points=[list(P), list(Q)], width=GRID[0],
               height=GRID[1], title="A line",
               bookmarks=[{"name": "third", "step": 3}, {"name": "late", "step": 9}]), path)
    return path


def line_run(origin="bottom-left"):
    return Scene(algorithm="line-bresenham", points=[list(P), list(Q)], width=GRID[0],
                 height=GRID[1], origin=origin,
                 bookmarks=[{"name": "third", "step": 3}, {"name": "late", "step": 9}])


def steps_of(scene) -> int:
    return len(ex.record(scene))


def gif_frames(path):
    """Every frame of a GIF as RGB arrays, and each frame's info."""
    frames, infos = [], []
    with Image.open(path) as image:
        for k in range(image.n_frames):
            image.seek(k)
            frames.append(np.asarray(image.convert("RGB")))
            infos.append(dict(image.info))
    return frames, infos


def gif_blocks(data: bytes):
    """The GIF's global-table flag and, per image, its local-table flag."""
    flags = data[10]
    pos = 13 + (3 * (2 << (flags & 7)) if flags & 0x80 else 0)
    local = []
    while data[pos] != 0x3B:
        if data[pos] == 0x21:
            pos += 2
            while data[pos]:
                pos += data[pos] + 1
            pos += 1
        else:
            assert data[pos] == 0x2C
            image_flags = data[pos + 9]
            local.append(bool(image_flags & 0x80))
            pos += 10 + (3 * (2 << (image_flags & 7)) if image_flags & 0x80 else 0) + 1
            while data[pos]:
                pos += data[pos] + 1
            pos += 1
    return bool(flags & 0x80), local


def cell(image, x, y, scale, height, y_down=False):
    row = (y if y_down else height - 1 - y) * scale + scale // 2
    return tuple(int(v) for v in image[row, x * scale + scale // 2])


# ----------------------------------------------------------------- the GIF
def test_gif_frames_sizes_durations_and_pixels(tmp_path):
    run = line_run()
    settings = ex.ExportSettings(fps=5, hold=1.5, scale=8, caption=True, panel="none",
                                 primitive=False)
    target = tmp_path / "line.gif"
    result = ex.export(run, settings, gif=target)
    frames, infos = gif_frames(target)
    steps = steps_of(run)
    assert result.frames == len(frames) == steps
    caption = result.size[1] - GRID[1] * 8
    assert caption > 0
    assert frames[0].shape == (GRID[1] * 8 + caption, GRID[0] * 8, 3)
    # 1000 / 5 = 200 ms a frame; the last one held 1.5 s longer.
    assert [info["duration"] for info in infos] == [200] * (steps - 1) + [1700]
    assert infos[0]["loop"] == 0
    line = set(bresenham_pixels(P, Q))
    ink, background = rgb(PALETTE.ink), rgb(PALETTE.background)
    # Step 0 is the set-up: nothing written yet.
    for x in range(GRID[0]):
        for y in range(GRID[1]):
            assert cell(frames[0], x, y, 8, GRID[1]) == background
            expected = ink if (x, y) in line else background
            assert cell(frames[-1], x, y, 8, GRID[1]) == expected, (x, y)


def test_play_once_has_no_loop_and_one_palette(tmp_path):
    target = tmp_path / "once.gif"
    ex.export(line_run(), ex.ExportSettings(scale=4, loop=False), gif=target)
    with Image.open(target) as image:
        assert "loop" not in image.info
    has_global, local = gif_blocks(target.read_bytes())
    assert has_global and len(local) == steps_of(line_run()) and not any(local)


def test_durations_keep_time_at_any_rate():
    for fps in (1, 3, 7, 24, 30, 33.3, 50, 0.1):
        durations = ex.frame_durations(200, fps)
        assert all(d % 10 == 0 and abs(d - 1000 / fps) <= 10 for d in durations), fps
        assert abs(sum(durations) - 200 * 1000 / fps) <= 5
    assert ex.frame_durations(3, 30, hold=2) == [30, 40, 2030]
    assert ex.frame_durations(0, 10) == []


def test_range_by_steps_and_bookmarks(tmp_path):
    run = line_run()
    target = tmp_path / "part.gif"
    result = ex.export(run, ex.ExportSettings(first=2, last=5, scale=4), gif=target)
    assert result.frames == 4 == len(gif_frames(target)[0])
    result = ex.export(run, ex.ExportSettings(first="third", last="late", scale=4), gif=target)
    assert result.frames == 7
    assert ex.frame_range(run, ex.record(run), "late") == range(9, steps_of(run))


@pytest.mark.parametrize("settings, words", [
    (dict(fps=0), "frames per second"),
    (dict(fps=51), "frames per second"),
    (dict(fps=float("nan")), "finite"),
    (dict(scale=0), "scale"),
    (dict(scale=65), "scale"),
    (dict(scale=2.5), "scale"),
    (dict(hold=-1), "hold"),
    (dict(panel="side"), "panel"),
    (dict(theme="pink"), "theme"),
    (dict(first=99), "0 .. "),
    (dict(first=-1), "0 .. "),
    (dict(first=5, last=2), "before it starts"),
    (dict(first="nowhere"), "bookmark"),
])
def test_bad_settings_say_what(tmp_path, settings, words):
    target = tmp_path / "bad.gif"
    with pytest.raises(ex.ExportError, match=words):
        ex.export(line_run(), ex.ExportSettings(**settings), gif=target)
    assert not target.exists()
    assert list(tmp_path.iterdir()) == []


def test_frame_size_is_capped(tmp_path):
    run = Scene(algorithm="line-bresenham", points=[[0, 0], [3, 1]], width=600, height=20)
    with pytest.raises(ex.ExportError, match="4096"):
        ex.export(run, ex.ExportSettings(scale=8), gif=tmp_path / "wide.gif")
    assert list(tmp_path.iterdir()) == []


def test_unwritable_places_are_named(tmp_path):
    with pytest.raises(ex.ExportError, match="does not exist"):
        ex.export(line_run(), gif=tmp_path / "missing" / "x.gif")
    with pytest.raises(ex.ExportError, match="folder, not a file"):
        ex.export(line_run(), gif=tmp_path)
    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(ex.ExportError, match="not a folder"):
        ex.export(line_run(), frames_dir=blocker)
    if os.geteuid() != 0:
        locked = tmp_path / "locked"
        locked.mkdir(mode=0o500)
        with pytest.raises(ex.ExportError, match="not writable"):
            ex.export(line_run(), gif=locked / "x.gif")


def test_cancel_leaves_the_old_file_and_no_temporary(tmp_path):
    target = tmp_path / "kept.gif"
    target.write_bytes(b"the old animation")
    seen = []

    def progress(done, total):
        seen.append(done)

    with pytest.raises(ex.ExportCancelled):
        ex.export(line_run(), ex.ExportSettings(scale=4), gif=target,
                  frames_dir=tmp_path / "frames", progress=progress,
                  cancelled=lambda: len(seen) >= 3)
    assert seen == [1, 2, 3]
    assert target.read_bytes() == b"the old animation"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["kept.gif"]


def test_a_failure_while_drawing_leaves_nothing(tmp_path, monkeypatch):
    calls = []
    original = ex.FrameRenderer.image

    def failing(self, index):
        calls.append(index)
        if len(calls) > 4:
            raise OSError(28, "No space left on device")
        return original(self, index)

    monkeypatch.setattr(ex.FrameRenderer, "image", failing)
    with pytest.raises(ex.ExportError, match="No space left"):
        ex.export(line_run(), ex.ExportSettings(scale=4), gif=tmp_path / "x.gif")
    assert list(tmp_path.iterdir()) == []


def test_identical_frames_are_joined_with_their_time(tmp_path):
    # Without caption and highlights the set-up steps look the same: Pillow
    # writes them as one frame, as long as all of them together.
    target = tmp_path / "joined.gif"
    result = ex.export(line_run(), ex.ExportSettings(scale=4, fps=10, hold=0, caption=False,
                                                     highlight=False, panel="none"), gif=target)
    frames, infos = gif_frames(target)
    assert len(frames) < result.frames
    assert sum(info["duration"] for info in infos) == sum(result.durations)


# ------------------------------------------------------------------ frames
def test_png_frames_beside_the_gif(tmp_path):
    run = line_run(origin="top-left")
    folder = tmp_path / "frames"
    settings = ex.ExportSettings(scale=6, panel="code", primitive=False)
    result = ex.export(run, settings, gif=tmp_path / "a.gif", frames_dir=folder)
    names = sorted(p.name for p in folder.iterdir() if p.name != ex.MANIFEST)
    assert names == [f"frame_{k:04d}.png" for k in range(steps_of(run))]
    assert (folder / ex.MANIFEST).is_file()
    renderer = ex.FrameRenderer(run, settings)
    assert result.size == (GRID[0] * 6 + renderer.panel_width,
                           max(GRID[1] * 6, renderer.body_height) + renderer.caption_height)
    last = np.asarray(Image.open(folder / names[-1]).convert("RGB"))
    assert last.shape[:2] == result.size[::-1]
    # Origin top-left: row 0 of the grid is at the top of the picture.
    for x, y in bresenham_pixels(P, Q):
        assert cell(last, x, y, 6, GRID[1], y_down=True) == rgb(PALETTE.ink)
    assert cell(last, 0, 7, 6, GRID[1], y_down=True) == rgb(PALETTE.background)
    # The GIF's frames are the same pictures.
    frames, _ = gif_frames(tmp_path / "a.gif")
    for k in (0, 5, len(frames) - 1):
        png = np.asarray(Image.open(folder / names[k]).convert("RGB"))
        assert np.array_equal(png, frames[k])


def test_a_shorter_export_replaces_the_frames_of_a_longer_one(tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    (folder / "notes.txt").write_text("keep me")
    ex.export(line_run(), ex.ExportSettings(scale=2), frames_dir=folder)
    ex.export(line_run(), ex.ExportSettings(scale=2, first=0, last=2), frames_dir=folder)
    assert sorted(p.name for p in folder.iterdir()) == [
        ".rasterlab-frames.json", "frame_0000.png", "frame_0001.png", "frame_0002.png",
        "notes.txt"]


# ------------------------------------------------------------ what's drawn
def test_burn_in_choices_change_what_is_drawn():
    run = line_run()
    base = dict(scale=8, caption=False, panel="none")
    middle = 6
    plain = ex.FrameRenderer(run, ex.ExportSettings(**base, primitive=False, highlight=False,
                                                    grid_lines=False)).rgb(middle)
    full = ex.FrameRenderer(run, ex.ExportSettings(**base)).rgb(middle)
    colours = {tuple(c) for c in full.reshape(-1, 3)}
    assert {rgb(PALETTE.primitive), rgb(PALETTE.current), rgb(PALETTE.grid)} <= colours
    bare = {tuple(c) for c in plain.reshape(-1, 3)}
    assert bare == {rgb(PALETTE.ink), rgb(PALETTE.background)}


def test_dark_theme_and_the_side_panels():
    run = line_run()
    dark = ex.FrameRenderer(run, ex.ExportSettings(scale=8, theme="dark", panel="both"))
    image = dark.rgb(steps_of(run) - 1)
    assert cell(image, 0, 0, 8, GRID[1]) == rgb(ex.DARK.palette.background)
    assert cell(image, P[0], P[1], 8, GRID[1]) == rgb(ex.DARK.palette.ink)
    panel = image[:dark.body_height, GRID[0] * 8 + 2:]
    assert rgb(ex.DARK.panel) in {tuple(c) for c in panel.reshape(-1, 3)}
    for kind in ("code", "variables", "both"):
        renderer = ex.FrameRenderer(run, ex.ExportSettings(scale=8, panel=kind))
        assert renderer.size[0] == GRID[0] * 8 + renderer.panel_width


def test_the_code_panel_marks_the_current_line():
    run = line_run()
    renderer = ex.FrameRenderer(run, ex.ExportSettings(scale=8, panel="code", caption=False))
    marked = rgb(ex.LIGHT.current_line)
    rows_per_line = [len(rows) for rows in renderer._text.wrapped]
    for index in (1, 4, 5):
        image = renderer.rgb(index)
        panel = image[:, GRID[0] * 8 + 2:]
        rows = np.flatnonzero((panel == marked).all(axis=2).any(axis=1))
        line = renderer.trace.step(index).line
        text = renderer._text
        # The panel is as tall as the grid and scrolls: the current line is
        # marked whole, below the title, on the rows the line takes.
        assert renderer.body_height == max(GRID[1] * 8, text.code_height)
        assert rows.min() >= text.pad + text.line
        assert rows.max() - rows.min() + 1 == text.line * rows_per_line[line]
        assert rows.max() < text.code_height
        assert (rows.min() - text.pad) % text.line == 0


def test_run_colours_are_in_the_palette():
    scene = Scene(algorithm="flood-fill", points=[[[2, 2], [17, 3], [10, 14]]], width=20,
                  height=16)
    renderer = ex.FrameRenderer(scene, ex.ExportSettings(scale=4, panel="none", caption=False,
                                                         primitive=False))
    palette = {tuple(c) for c in renderer.colours.rgb}
    assert {rgb("#c0392b"), rgb("#2e86de")} <= palette
    trace = renderer.trace
    image = renderer.rgb(len(trace) - 1)
    final = trace.raster_at(len(trace) - 1)
    ys, xs = np.nonzero((final.counts == 1) & (final.colors >= 0))
    for x, y in list(zip(xs, ys))[:50]:
        value = int(final.colors[y, x])
        assert cell(image, x, y, 4, 16) == ((value >> 16) & 255, (value >> 8) & 255, value & 255)


def test_palette_lookup_takes_the_nearest_colour():
    colours = ex.ColourIndex([(0, 0, 0), (255, 255, 255), (200, 0, 0)])
    pixels = np.array([[[0, 0, 0, 255], [250, 250, 250, 255], [190, 10, 5, 255]]], np.uint8)
    assert colours.indices(pixels).tolist() == [[0, 1, 2]]
    assert colours.transparent == 3 and len(colours.palette_bytes()) == 12


def test_a_run_with_many_colours_gets_a_reduced_palette():
    class Start:
        pixel_value = "rgb"

    class ManyColours:
        start = Start()

        def pixel_values(self):
            return np.arange(0, 0xFFFFFF, 4099, dtype=np.float64)  # about 4,000 colours

    colours = ex.build_palette(ex.LIGHT, ManyColours())
    assert len(colours) == 253
    theme = {rgb(c) for c in (PALETTE.background, PALETTE.ink, PALETTE.primitive)}
    assert theme <= {tuple(c) for c in colours.rgb}
    pixel = np.array([[[255, 0, 0, 255]]], np.uint8)
    index = colours.indices(pixel)[0, 0]
    assert np.abs(colours.rgb[index].astype(int) - [255, 0, 0]).sum() < 120


@pytest.mark.parametrize("scene", [
    Scene(algorithm="polygon-scanline", points=[[[3, 4], [30, 6], [24, 28], [5, 20]]],
          width=32, height=32),
    Scene(algorithm="triangle-bbox", points=[[1.5, 2.25], [20.5, 4.75], [9.25, 18.5],
                                             [14, 20], [22, 3], [23, 21]], width=24, height=24),
    Scene(algorithm="flood-fill", points=[[[2, 2], [17, 3], [10, 14]]], width=20, height=16,
          origin="top-left"),
    Scene(algorithm="circle-midpoint", points=[[12, 10]], options={"radius": 7}, width=24,
          height=20),
])
@pytest.mark.parametrize("scale", [1, 2, 5])
def test_redrawing_only_what_changed_gives_the_same_frames(scene, scale):
    settings = ex.ExportSettings(scale=scale, caption=False, panel="none")
    quick = ex.FrameRenderer(scene, settings)
    whole = ex.FrameRenderer(scene, settings, quick.trace, incremental=False)
    count = len(quick.trace)
    order = list(range(min(count, 80))) + [count - 1, 3, count // 2, 1, count - 2]
    for index in order:
        assert np.array_equal(quick.render(index), whole.render(index)), index


@pytest.mark.parametrize("scene", [
    Scene(algorithm="flood-fill", points=[[[2, 2], [17, 3], [10, 14]]], width=20, height=16),
    Scene(algorithm="flood-fill", points=[[[2, 2], [17, 3], [10, 14]]], width=20, height=16,
          options={"order": "span"}),
    Scene(algorithm="polygon-scanline", points=[[[3, 4], [30, 6], [24, 28], [5, 20]]],
          width=32, height=32),
    Scene(algorithm="line-dda", points=[[0, 0], [19, 7]], width=20, height=8),
])
def test_frames_in_order_replay_as_the_trace_does(scene):
    trace = ex.record(scene)
    states = ex._States(trace)
    for index in range(len(trace)):
        state, written = states.at(index)
        expected = trace.raster_at(index)
        assert np.array_equal(state.raster.counts, expected.counts), index
        if expected.colors is not None:
            assert np.array_equal(state.raster.colors, expected.colors), index
        assert (written is None) == (index == 0)


def test_frames_are_drawn_by_compose():
    """One path, one current cell: compose_frame is render.compose itself."""
    renderer = ex.FrameRenderer(line_run())
    paths, trace = renderer.paths, renderer.trace
    for index in (2, 5, len(trace) - 1):
        state = trace.state_at(index)
        marks = frame_marks(state, paths)
        ours = compose_frame(state.raster, marks, PALETTE, 8, True)
        overlay = Overlay(current=state.pixel, candidates=state.candidates,
                          primitive=paths[0][0], closed=paths[0][1])
        assert np.array_equal(ours, compose(state.raster, overlay, PALETTE, 8, True))
    assert primitive_mask(*GRID, paths, PALETTE, 8).any()
    assert primitive_mask(*GRID, paths, PALETTE, 2) is None
    assert FrameMarks().outline_overlays()[0].current is None


# -------------------------------------------------------------------- CLI
def test_cli_exports_gif_and_frames(run_cli, line_scene, tmp_path):
    gif, folder = tmp_path / "out.gif", tmp_path / "frames"
    code, out, err = run_cli("export", str(line_scene), "--gif", str(gif), "--frames-dir",
                             str(folder), "--fps", "10", "--scale", "5", "--from", "third",
                             "--to", "8", "--hold", "0", "--no-caption", "--panel", "none",
                             "--theme", "dark", "--once", "--no-grid", "--no-primitive",
                             "--no-highlight")
    assert code == 0 and err == ""
    assert "6 frames" in out
    frames, infos = gif_frames(gif)
    assert len(frames) <= 6 and "loop" not in infos[0]
    assert frames[0].shape == (GRID[1] * 5, GRID[0] * 5, 3)
    assert len(list(folder.glob("frame_*.png"))) == 6
    assert {tuple(c) for c in frames[-1].reshape(-1, 3)} == {
        rgb(ex.DARK.palette.ink), rgb(ex.DARK.palette.background)}


@pytest.mark.parametrize("args, words", [
    ([], "export needs an output: --gif, --frames-dir, --mp4, --webm, --svg-dir, --pdf or --html"),
    (["--gif", "{tmp}/x.gif", "--fps", "0"], "--fps"),
    (["--gif", "{tmp}/x.gif", "--fps", "1e9"], "--fps"),
    (["--gif", "{tmp}/x.gif", "--fps", "inf"], "--fps"),
    (["--gif", "{tmp}/x.gif", "--scale", "0"], "--scale"),
    (["--gif", "{tmp}/x.gif", "--scale", "65"], "--scale"),
    (["--gif", "{tmp}/x.gif", "--scale", "two"], "--scale"),
    (["--gif", "{tmp}/x.gif", "--hold", "-2"], "--hold"),
    (["--gif", "{tmp}/x.gif", "--from", "99"], "--from 99"),
    (["--gif", "{tmp}/x.gif", "--to", "nowhere"], "--to"),
    (["--gif", "{tmp}/x.gif", "--panel", "left"], "--panel"),
    (["--gif", "{tmp}/x.gif", "--theme", "pink"], "--theme"),
    (["--gif", "{tmp}/no/such/folder/x.gif"], "does not exist"),
    (["--gif", "/proc/rasterlab-export.gif"], "cannot write"),
])
def test_cli_bad_input_exits_2_with_one_line(run_cli, line_scene, tmp_path, args, words):
    args = [a.replace("{tmp}", str(tmp_path)) for a in args]
    code, out, err = run_cli("export", str(line_scene), *args)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("rasterlab: ") and words in err
    assert "Traceback" not in err
    assert not any(p.suffix in (".gif", ".tmp") for p in tmp_path.rglob("*"))


def test_cli_refuses_frames_too_large(run_cli, tmp_path):
    wide = tmp_path / "wide.json"
    save(Scene(algorithm="line-bresenham", points=[[0, 0], [5, 2]], width=300, height=10), wide)
    code, out, err = run_cli("export", str(wide), "--gif", str(tmp_path / "x.gif"),
                             "--scale", "16")
    assert code == 2 and err.count("\n") == 1 and "4096" in err
    assert not (tmp_path / "x.gif").exists()


def test_cli_bad_scene_files(run_cli, tmp_path):
    broken = tmp_path / "broken.json"
    broken.write_text('{"version": 1, "grid": ')
    for scene in (str(broken), str(tmp_path / "missing.json")):
        code, out, err = run_cli("export", scene, "--gif", str(tmp_path / "x.gif"))
        assert code == 2 and err.count("\n") == 1
    wrong = tmp_path / "wrong.json"
    wrong.write_text(json.dumps({"version": 1, "grid": {"width": 8, "height": 8},
                                 "algorithm": "no-such", "primitives": []}))
    code, _, err = run_cli("export", str(wrong), "--gif", str(tmp_path / "x.gif"))
    assert code == 2 and "algorithm" in err
    assert not (tmp_path / "x.gif").exists()


def test_progress_bar_only_on_a_terminal():
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    quiet = cli._ProgressBar(io.StringIO())
    assert not quiet.active
    screen = Terminal()
    bar = cli._ProgressBar(screen)
    assert bar.active
    bar.show(3, 10)
    bar.show(10, 10)
    bar.clear()
    text = screen.getvalue()
    assert "3/10 frames" in text and "10/10 frames, writing" in text and text.endswith("\033[K")


def test_the_command_runs_headless(line_scene, tmp_path):
    """The real command in a fresh process: no display, nothing on stderr."""
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY",
                                                           "QT_QPA_PLATFORM")}
    gif = tmp_path / "slide.gif"
    done = subprocess.run([sys.executable, "-m", "rasterlab", "export", str(line_scene), "--gif",
                           str(gif), "--scale", "4"], cwd=ROOT, env=env, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    with Image.open(gif) as image:
        assert image.n_frames == len(registry.get("line-bresenham").record(
            [P, Q], {}, grid=GRID))


def test_the_shipped_example_gif_is_small_and_matches_its_scene():
    example = ROOT / "resources" / "example-bresenham.gif"
    assert example.stat().st_size < 400 * 1024
    renderer = ex.FrameRenderer(load(ROOT / "resources" / "scenes" / "demo-bresenham.json"))
    with Image.open(example) as image:
        assert image.n_frames == len(renderer.trace) and image.info.get("loop") == 0
        assert image.size == renderer.size


# ---------------------------------------------------------------- writers
def test_every_writer_gets_the_same_frames(tmp_path):
    null = ex.NullWriter()
    result = ex.export(line_run(), ex.ExportSettings(scale=4), frames_dir=tmp_path / "frames",
                       writers=[null])
    assert null.finished and not null.aborted
    assert null.size == result.size and len(null.frames) == result.frames == steps_of(line_run())
    for k in (0, result.frames - 1):
        png = np.asarray(Image.open(tmp_path / "frames" / f"frame_{k:04d}.png").convert("RGB"))
        assert np.array_equal(png, np.asarray(null.frames[k].convert("RGB")))


def test_a_failing_writer_aborts_the_others(tmp_path):
    class Full(ex.NullWriter):
        def grab_frame(self, image):
            if len(self.frames) == 2:
                raise OSError(28, "No space left on device")
            super().grab_frame(image)

    null = ex.NullWriter()
    with pytest.raises(ex.ExportError, match="No space left"):
        ex.export(line_run(), ex.ExportSettings(scale=4), gif=tmp_path / "x.gif",
                  writers=[null, Full()])
    assert null.aborted and not null.finished
    assert list(tmp_path.iterdir()) == []


def test_export_loads_no_qt():
    """Export draws its text with Pillow: the command never imports Qt."""
    code = ("import sys, tempfile, os\n"
            "from app import cli\n"
            "out = os.path.join(tempfile.mkdtemp(), 'x.gif')\n"
            "assert cli.main(['export', 'resources/scenes/circle-radius-1.json', '--gif', out,"
            " '--scale', '4']) == 0\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] in"
            " ('PySide6', 'pyqtgraph', 'shiboken6', 'widgets')))\n")
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().splitlines()[-1] == "[]"


def test_cells_that_differ_from_a_compared_run_are_outlined():
    settings = ex.ExportSettings(scale=8, caption=False, panel="none", primitive=False)
    plain = ex.FrameRenderer(line_run(), settings)
    marked = ex.FrameRenderer(line_run(), settings, plain.trace, differences=np.array([[5, 6]]))
    difference = rgb(PALETTE.difference)

    def outlined(renderer, x, y):
        top = (GRID[1] - 1 - y) * 8
        block = renderer.rgb(3)[top:top + 8, x * 8:x * 8 + 8]
        return difference in {tuple(c) for c in block.reshape(-1, 3)}

    assert outlined(marked, 5, 6) and not outlined(marked, 6, 5) and not outlined(plain, 5, 6)
