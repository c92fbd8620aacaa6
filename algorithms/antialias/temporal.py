"""Temporal aliasing: a spinning wheel or a moving triangle over animation frames.

Each frame samples the scene at one instant (the wagon-wheel effect) or
averages it over the frame's exposure (motion blur).
"""
from __future__ import annotations

import math

import numpy as np

from algorithms.core.code import Code
from algorithms.triangles.interpolate import unpack
from algorithms.core.registry import InputError, Option
from algorithms.core.steps import PLOT, VISIT, Start, Vars
from algorithms.core.trace import checkpoint

from .shapes import INK, POSITION, UNIT, Shapes, ink_blend, ops_sum, test_ops
from .supersample import ACCUMULATION, lattice, sample_strata

NAN = math.nan

TEMPORAL_OPTIONS = (
    Option("primitive", "choice", "auto", "wheel (1 point: the centre) or triangle (3 points); "
           "auto picks by the number of points", choices=("auto", "wheel", "triangle")),
    Option("motion", "choice", "spin", "spin about the centre, or move along +x",
           choices=("spin", "move")),
    Option("mode", "choice", "instant", "instant: one sample time per frame; motion-blur: "
           "average over the frame's exposure", choices=("instant", "motion-blur")),
    Option("frames", "int", 12, "animation frames", minimum=1, maximum=240),
    Option("speed", "float", 80.0, "degrees per frame (spin) or px per frame (move)",
           minimum=-3600, maximum=3600),
    Option("time_samples", "int", 8, "instants averaged per frame with motion-blur",
           minimum=1, maximum=64),
    Option("shutter", "float", 1.0, "fraction of the frame interval the exposure lasts",
           minimum=0.01, maximum=1),
    Option("n", "int", 2, "spatial samples per pixel: n x n grid", minimum=1, maximum=8),
    Option("radius", "float", 9.0, "wheel radius in px", minimum=1, maximum=2048),
    Option("spokes", "int", 4, "number of spokes", minimum=1, maximum=32),
    Option("spoke_width", "float", 1.5, "spoke width in px", minimum=0.1, maximum=64),
    Option("phase", "float", 0.0, "angle of the first spoke at t = 0, degrees",
           minimum=-360, maximum=360),
    Option("times", "choice", "even", "motion-blur instants: even (the middle of each of the "
           "time_samples strata of the exposure) or jittered (a random instant in each)",
           choices=("even", "jittered")),
)


def _temporal_shapes(points, options, t: float) -> Shapes:
    """The primitive at time t (in frames), as shapes."""
    kind = _primitive(points, options)
    speed = options["speed"]
    if kind == "wheel":
        (cx, cy), = points
        angle = math.radians(options["phase"] + speed * t) if options["motion"] == "spin" \
            else math.radians(options["phase"])
        shift = speed * t if options["motion"] == "move" else 0.0
        spokes = []
        for k in range(options["spokes"]):
            a = angle + 2 * math.pi * k / options["spokes"]
            radius = options["radius"]
            spokes += [(cx + shift, cy),
                       (cx + shift + radius * math.cos(a), cy + radius * math.sin(a))]
        return Shapes(spokes, {"shape": "thick-line", "width": options["spoke_width"],
                               "caps": "butt"})
    if options["motion"] == "spin":
        cx = sum(p[0] for p in points) / 3
        cy = sum(p[1] for p in points) / 3
        a = math.radians(speed * t)
        c, s = math.cos(a), math.sin(a)
        moved = [(cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy))
                 for x, y in points]
    else:
        moved = [(x + speed * t, y) for x, y in points]
    return Shapes(moved, {"shape": "triangles"})


def _primitive(points, options) -> str:
    kind = options.get("primitive", "auto")
    if kind == "auto":
        if len(points) not in (1, 3):
            raise InputError(f"aa-temporal: expected 1 point (a wheel's centre) or 3 (a "
                             f"triangle), got {len(points)}")
        kind = "wheel" if len(points) == 1 else "triangle"
    expected = 1 if kind == "wheel" else 3
    if len(points) != expected:
        raise InputError(f"primitive {kind}: expected {expected} point"
                         f"{'' if expected == 1 else 's'}"
                         f"{' (the centre)' if kind == 'wheel' else ''}, got {len(points)}")
    return kind


def time_samples(options, frame: int) -> list[float]:
    """The instants (in frames) a frame's image averages."""
    if options["mode"] == "instant":
        return [float(frame)]
    count, shutter = options["time_samples"], options["shutter"]
    if options.get("times", "even") == "jittered":
        # One random instant per stratum, the same for every run of the frame.
        offsets = np.random.default_rng([frame, count]).random(count).tolist()
        return [frame + shutter * (s + u) / count for s, u in enumerate(offsets)]
    return [frame + shutter * (s + 0.5) / count for s in range(count)]


# Samples tested at once: a frame's image is made in bands of rows of about
# this many samples (over all its instants), so that a large grid with n = 8
# never needs gigabytes and a run can stop between two bands.
SAMPLES_PER_BAND = 1 << 20
# Samples tested in one call, between two checks for a cancel (a call over
# 2^16 samples of a 32-spoke wheel takes a few tens of milliseconds at most).
SAMPLES_PER_TEST = 1 << 16


def _setup(points, options, grid):
    options = {**{o.name: o.default for o in TEMPORAL_OPTIONS}, **options}
    points = [tuple(map(float, p)) for p in points]
    xs = np.arange(int(grid[0]), dtype=np.int64)
    kx, ky, big = sample_strata("grid", options["n"], 0, 0, xs)
    return options, points, (lattice(kx[0], big), lattice(ky[0], big))


def frame_bands(points, options, grid, frame: int):
    """Image ``frame`` of the animation as (first row, coverage rows) bands, top
    to bottom, each made only when asked for."""
    options, points, offsets = _setup(points, options, grid)
    width, height = int(grid[0]), int(grid[1])
    instants = time_samples(options, frame)
    shapes = [_temporal_shapes(points, options, t) for t in instants]
    per_row = max(1, width * len(offsets[0]) * len(instants))
    band = max(1, SAMPLES_PER_BAND // per_row)
    for top in range(0, height, band):
        checkpoint()  # bands the shapes miss test nothing but still cost time
        hits = np.zeros((min(band, height - top), width), np.int64)
        for shape in shapes:
            _add_hits(hits, top, shape, offsets, height)
        yield top, hits / (len(instants) * options["n"] ** 2)


def iter_temporal_frames(points, options, grid):
    """Image k of the animation, coverage (H, W) float64, for k = 0 .. frames - 1,
    each computed only when asked for."""
    frames = {**{o.name: o.default for o in TEMPORAL_OPTIONS}, **options}["frames"]
    for frame in range(frames):
        image = np.zeros((int(grid[1]), int(grid[0])))
        for top, rows in frame_bands(points, options, grid, frame):
            image[top:top + len(rows)] = rows
        yield image


def _add_hits(hits: np.ndarray, top: int, shapes: Shapes, offsets, height: int) -> None:
    """Add to hits (rows top .. top + len(hits) of the grid) the number of each
    pixel's samples inside the shapes."""
    width = hits.shape[1]
    x0, y0, x1, y1 = shapes.window((width, height))
    y0, y1 = max(y0, top), min(y1, top + len(hits))
    if x1 <= x0 or y1 <= y0:
        return
    ox, oy = offsets
    # The window is tested a piece at a time with a checkpoint between: one
    # call over a whole band took up to 380 ms no cancel could interrupt.
    # Hits are whole counts per pixel, so the pieces add up to the same image.
    per_pixel = len(ox)
    rows_at_once = max(1, SAMPLES_PER_TEST // (per_pixel * (x1 - x0)))
    cols_at_once = max(1, SAMPLES_PER_TEST // per_pixel)
    for r0 in range(y0, y1, rows_at_once):
        r1 = min(r0 + rows_at_once, y1)
        for c0 in range(x0, x1, cols_at_once):
            checkpoint()
            c1 = min(c0 + cols_at_once, x1)
            hits[r0 - top:r1 - top, c0:c1] += _inside_counts(shapes, offsets, c0, c1, r0, r1)


def _inside_counts(shapes: Shapes, offsets, x0, x1, y0, y1) -> np.ndarray:
    """Per pixel of columns x0..x1, rows y0..y1: how many of its samples are inside."""
    ox, oy = offsets
    cols = np.arange(x0, x1, dtype=np.int64)
    rows = np.arange(y0, y1, dtype=np.int64)
    sx = cols[None, :, None] * UNIT + ox[None, None, :]
    sy = rows[:, None, None] * UNIT + oy[None, None, :]
    sx, sy = np.broadcast_arrays(sx, sy)
    return (shapes.owners(sx, sy) >= 0).sum(axis=2)


def temporal_frames(points, options, grid) -> list[np.ndarray]:
    """All the images of the animation at once (for tests and small runs)."""
    return list(iter_temporal_frames(points, options, grid))


def apparent_speed(points, options) -> float:
    """The motion the frames seem to show, per frame: the speed folded into one period."""
    if options["motion"] == "move":
        return float(options["speed"])
    period = 360.0 / options["spokes"] if _primitive(points, options) == "wheel" else 360.0
    return float((options["speed"] + period / 2) % period - period / 2)


def temporal_code(points, options) -> Code:
    blur = options.get("mode", "instant") == "motion-blur"
    within = "u_s" if options.get("times", "even") == "jittered" else "1/2"
    sample = (f"average over {options.get('time_samples', 8)} instants t = k + shutter "
              f"(s + {within}) / {options.get('time_samples', 8)}"
              + ("  (u_s random in [0, 1): jittered)" if within == "u_s" else "")
              if blur else "one instant t = k")
    # Every pixel frame of line "plot_pixels" stands for the pixel's n^2 samples at each
    # of the frame's instants, each tested against every shape (the images
    # come from the vectorised kernel, which tests them all), at its
    # position (POSITION) and summed (1 int_add); then one division. Pixels
    # the primitive's window reaches but that show nothing in this frame or
    # the last yield no frame and are not counted, nor is moving the
    # primitive to each instant (line "frames": per instant, not per pixel).
    # With motion blur the samples are counted on line "accumulate" instead,
    # one frame per pixel and instant, and a pixel frame only divides.
    instants = options.get("time_samples", 8) if blur else 1
    per_pixel = 0 if blur else instants * options.get("n", 2) ** 2
    shape_test = {}
    try:
        shape_test = test_ops(_temporal_shapes(
            [tuple(map(float, p)) for p in points],
            {**{o.name: o.default for o in TEMPORAL_OPTIONS}, **options}, 0.0))[1]
    except (InputError, ValueError, TypeError, KeyError):
        pass
    one = ops_sum({"samples": 1, "int_add": 1}, POSITION, shape_test)
    pixel = ops_sum(one, times=per_pixel) | {"div": 1}
    pixel = ops_sum(pixel, {"compare": 2, "pixels_tested": 1})
    code = Code()
    code.add("setup", "setup: the primitive, its motion per frame, the n x n samples of a pixel")
    code.add("frames", f"for each animation frame k:  {sample}"
                       + ("  (clear the accumulation buffer)" if blur else ""))
    if blur:
        code.add("accumulate", "    for each instant t, each pixel the primitive reaches at t:  "
                               "accumulation buffer += its n^2 samples inside at t", VISIT,
                 ops=ops_sum(one, times=options.get("n", 2) ** 2))
    summed = "the accumulation buffer" if blur else "(samples inside, over all instants)"
    code.add("plot_pixels", "    for each pixel (x, y) the primitive reaches in any frame:  "
                            f"coverage = {summed} / (instants * n^2);  write it", PLOT, ops=pixel)
    code.add("done", "done")
    return code


def _accumulate(points, options, grid, frame: int, line: int):
    """Motion blur through the accumulation buffer: each instant of the
    frame adds, per pixel, its samples inside the primitive at that instant.
    Yields a frame per pixel an instant reaches, with the buffer's value
    there (samples so far / (instants * n^2)); returns the frame's image."""
    options, points, offsets = _setup(points, options, grid)
    width, height = int(grid[0]), int(grid[1])
    instants = time_samples(options, frame)
    total = len(instants) * options["n"] ** 2
    buffer = np.zeros((height, width), np.int64)
    for t in instants:
        hits = np.zeros((height, width), np.int64)
        _add_hits(hits, 0, _temporal_shapes(points, options, t), offsets, height)
        buffer += hits
        for y, x in np.argwhere(hits > 0):
            yield (line, int(x), int(y), float(frame), NAN, NAN, float(buffer[y, x] / total))
    return buffer / total


def temporal(points, options, grid):
    kind = _primitive(points, options)
    apparent = apparent_speed(points, options)
    at = temporal_code(points, options).at
    blur = options["mode"] == "motion-blur"
    constants = {"primitive": kind, "motion": options["motion"], "mode": options["mode"],
                 "frames": options["frames"], "speed": options["speed"], "apparent speed":
                 apparent}
    yield Start(line=at["setup"], values=("frame", "coverage", "rgb") + (("accum",) * blur),
                constants=constants, pixel_value="coverage", color_value="rgb", replaces=True,
                buffer_value="accum" if blur else None, buffer_name=ACCUMULATION if blur else "")
    # Each frame's image is made band by band when the run reaches it, so the
    # step cap and a cancel stop the work: the pixels written are those that
    # show something in this frame or the last, in row order.
    previous = np.zeros((int(grid[1]), int(grid[0])))
    ink = unpack(INK)
    for k in range(options["frames"]):
        instants = time_samples(options, k)
        values = {"frame": k, "t": f"{instants[0]:g} .. {instants[-1]:g}" if len(instants) > 1
                  else instants[0]}
        if options["motion"] == "spin":
            values["angle"] = options["speed"] * instants[0] % 360
        if blur:
            values["cleared"] = ACCUMULATION
        yield Vars(line=at["frames"], values=values)
        # (np.zeros, not zeros_like: that one writes every zero at once, 100 ms at 4096^2)
        image = np.zeros(previous.shape)
        bands = frame_bands(points, options, grid, k)
        if blur:
            bands = [(0, (yield from _accumulate(points, options, grid, k, at["accumulate"])))]
        for top, rows in bands:
            image[top:top + len(rows)] = rows
            shown = (rows > 0) | (previous[top:top + len(rows)] > 0)
            for y, x in np.argwhere(shown):
                value = float(rows[y, x])
                yield (at["plot_pixels"], int(x), int(y) + top, float(k), value,
                       float(ink_blend(ink, value))) + (NAN,) * blur
        previous = image
    yield Vars(line=at["done"], values={"frames": options["frames"], "apparent speed": apparent})


def animation_frame_steps(spec, trace) -> list[int]:
    """The step at which each animation frame of an ``aa-temporal`` run is
    complete (its image fully written), in order; [] for other runs.

    Frame k starts with a Vars record naming ``frame`` k; the step before
    the next frame's record (or before the closing record) shows image k
    with frame k's variables.
    """
    if spec.name != "aa-temporal" or trace.start is None:
        return []
    starts = [index for index, record in trace.records_of(Vars) if "frame" in record.values]
    ends = [start - 1 for start in starts[1:]] + [len(trace) - 2]
    return [max(end, start) for start, end in zip(starts, ends)]
