"""Line templates: Bresenham's decision variable, the pixel at a step and
the NE steps; the first step where the DDA in float32 and in float64 part.

Drawn Bresenham variants lie in octant 1 (0 < dy < dx) on a 16x12 grid,
with no tie (d = 0) at any decision; a given scene may be in any octant
(the run maps it to octant 1) and may have ties (the run breaks them as
the notes do: d <= 0 chooses E). Step k is the k-th time round the loop;
P is plotted at step 0.
"""
from __future__ import annotations

from algorithms.core.trace import DEFAULT_STEP_CAP

from app.model import runs
from app.model.scene import Scene
from app.teaching.questions import common
from app.teaching.questions.model import NUMERICAL, Answer, Template, Worked

GRID = (16, 12)
BRESENHAM = "line-bresenham"
KEYS = ("pixel", "choice", "d", "d after")
RULE = ("d_0 = 2dy - dx; at each step, if d <= 0 choose E (x += 1; d += 2dy), else NE "
        "(x += 1, y += 1; d += 2(dy - dx)); in another octant the run maps P and Q into "
        "octant 1 first and maps each pixel back")


def _segment_text(scene) -> str:
    (x0, y0), (x1, y1) = scene.points
    return f"P = ({x0}, {y0}), Q = ({x1}, {y1})"


def _draw_segment(rng):
    dx = rng.randint(5, 10)
    dy = rng.randint(1, dx - 1)
    x0, y0 = rng.randint(0, GRID[0] - 1 - dx), rng.randint(0, GRID[1] - 1 - dy)
    return Scene(algorithm=BRESENHAM, points=((x0, y0), (x0 + dx, y0 + dy)),
                 width=GRID[0], height=GRID[1])


def _decisions(trace) -> list[int]:
    """The trace steps that decide E or NE, in order: step k is the k-th."""
    return [i for i in range(len(trace)) if trace.step(i).branch]


def _no_tie(scene) -> bool:
    trace = common.trace_of(scene)
    return all(trace.step(i).values["d"] != 0 for i in _decisions(trace))


def _bresenham(name, seed, scene):
    """The scene (drawn unless given), its trace, its decision steps and the Random."""
    if scene is None:
        scene, rng = common.drawn(seed, _draw_segment, _no_tie)
    else:
        import random
        common.suited(name, (BRESENHAM,), scene)
        rng = random.Random(seed)
    trace = common.trace_of(scene)
    decisions = _decisions(trace)
    if len(decisions) < 2:
        raise ValueError(f"{name}: the line takes {len(decisions)} step(s); it needs 2 or more")
    return scene, trace, decisions, rng


def _worked(trace, decisions, upto: int, summary: str) -> Worked:
    """The steps 1 .. upto as (k, pixel, choice, d, d after)."""
    rows = common.step_rows(trace, decisions[:upto], KEYS)
    return Worked(("k",) + KEYS, tuple((str(k + 1),) + row for k, row in enumerate(rows)),
                  summary)


def decision_after_step(seed: int, scene=None):
    name = "line-bresenham-d"
    scene, trace, decisions, rng = _bresenham(name, seed, scene)
    k = rng.randint(1, len(decisions) - 1)
    d = int(trace.step(decisions[k]).values["d"])  # the d step k+1 tests: d after step k
    text = (f"Bresenham's line from {_segment_text(scene)} ({RULE}). P is plotted at step 0. "
            f"What is d after step {k} (d_{k}, the value step {k + 1} tests)? Answer with "
            "an integer.")
    worked = _worked(trace, decisions, k, f"d after step {k} is {d}.")
    return common.question(name, seed, f"Bresenham: d after step {k}", text,
                           Answer(NUMERICAL, d, str(d)), worked, scene)


def pixel_at_step(seed: int, scene=None):
    name = "line-bresenham-pixel"
    scene, trace, decisions, rng = _bresenham(name, seed, scene)
    k = rng.randint(1, len(decisions) - 1)
    pixel = trace.step(decisions[k - 1]).pixel
    text = (f"Bresenham's line from {_segment_text(scene)} ({RULE}). P is plotted at step 0. "
            f"Which pixel is plotted at step {k}? Answer as (x, y).")
    worked = _worked(trace, decisions, k, f"Step {k} plots {common.pixel_text(pixel)}.")
    answer = common.short(common.pixel_text(pixel), f"({pixel[0]},{pixel[1]})",
                          f"{pixel[0]},{pixel[1]}", f"{pixel[0]}, {pixel[1]}")
    return common.question(name, seed, f"Bresenham: the pixel of step {k}", text, answer,
                           worked, scene)


def steps_choosing_ne(seed: int, scene=None):
    name = "line-bresenham-ne"
    scene, trace, decisions, _ = _bresenham(name, seed, scene)
    chosen = [k + 1 for k, i in enumerate(decisions) if trace.step(i).branch == "NE"]
    text = (f"Bresenham's line from {_segment_text(scene)} ({RULE}). P is plotted at step 0; "
            f"the loop runs steps 1 .. {len(decisions)}. Which steps choose NE? Answer with "
            "the step numbers in increasing order, separated by spaces (e.g. 2 4 5), or "
            "none.")
    canonical = " ".join(map(str, chosen)) or "none"
    worked = _worked(trace, decisions, len(decisions),
                     f"NE at steps {canonical}." if chosen else "No step chooses NE.")
    answer = common.short(canonical, ",".join(map(str, chosen)) or "none",
                          ", ".join(map(str, chosen)) or "none")
    return common.question(name, seed, "Bresenham: the NE steps", text, answer, worked, scene)


# ------------------------------------------------------------ DDA precision
DDA = "line-dda"
DDA_GRID = 600  # long lines far from the origin, where float32's error reaches half a pixel


def _dda_pixels(scene, dtype: str):
    options = {**scene.options, "dtype": dtype}
    trace = runs.record(scene.spec, scene.points, scene.spec.resolve(options), scene.grid,
                        DEFAULT_STEP_CAP)
    return trace, [trace.step(i) for i in range(len(trace)) if trace.step(i).writes]


def _first_difference(scene):
    """(k, float32 run, float64 run, float32 steps, float64 steps), k None if they agree."""
    t32, s32 = _dda_pixels(scene, "float32")
    t64, s64 = _dda_pixels(scene, "float64")
    k = next((k for k, (a, b) in enumerate(zip(s32, s64)) if a.pixel != b.pixel), None)
    return k, t32, t64, s32, s64


def _draw_long_segment(rng):
    x0, y0 = rng.randint(100, 300), rng.randint(100, 300)
    length = rng.randint(150, DDA_GRID - 1 - max(x0, y0))
    rise = rng.randint(1, length - 1)
    p, q = (x0, y0), (x0 + length, y0 + rise)
    if rng.random() < 0.5:  # a steep line: x and y swap parts
        p, q = (y0, x0), (y0 + rise, x0 + length)
    return Scene(algorithm=DDA, points=(p, q), width=DDA_GRID, height=DDA_GRID)


def dda_precision(seed: int, scene=None):
    name = "line-dda-precision"
    if scene is None:
        scene, _ = common.drawn(seed, _draw_long_segment,
                                lambda s: _first_difference(s)[0] is not None)
    else:
        common.suited(name, (DDA,), scene)
    k, t32, t64, s32, s64 = _first_difference(scene)
    if k is None:
        raise ValueError(f"{name}: the float32 and float64 runs of this line plot the same pixels")
    (x0, y0), (x1, y1) = scene.points
    text = (f"The DDA draws the line from {_segment_text(scene)}: steps = max(|dx|, |dy|), "
            "x_inc = dx / steps, y_inc = dy / steps; x and y start at P and at each step add "
            "x_inc and y_inc and plot (round(x), round(y)), round(v) = floor(v + 1/2). Run it "
            "once with float32 accumulators and once with float64. P is plotted at step 0. At "
            "which step do the two runs first plot different pixels? Answer with the step "
            "number.")
    rows = []
    for j in range(max(0, k - 3), k + 1):
        a, b = s32[j], s64[j]
        rows.append((str(j), f"{a.values['x']:.9g}", f"{a.values['y']:.9g}",
                     common.pixel_text(a.pixel), f"{b.values['x']:.17g}",
                     f"{b.values['y']:.17g}", common.pixel_text(b.pixel)))
    summary = (f"At step {k} float32 plots {common.pixel_text(s32[k].pixel)} and float64 "
               f"{common.pixel_text(s64[k].pixel)}; every step before agrees.")
    worked = Worked(("step", "x (float32)", "y (float32)", "pixel (float32)", "x (float64)",
                     "y (float64)", "pixel (float64)"), tuple(rows), summary)
    return common.question(name, seed, "DDA: float32 against float64", text,
                           Answer(NUMERICAL, k, str(k)), worked, scene)


TEMPLATES = (
    Template("line-bresenham-d", "lines", "Bresenham: the decision variable d after step k",
             (BRESENHAM,), decision_after_step),
    Template("line-bresenham-pixel", "lines", "Bresenham: the pixel plotted at step k",
             (BRESENHAM,), pixel_at_step),
    Template("line-bresenham-ne", "lines", "Bresenham: which steps choose NE",
             (BRESENHAM,), steps_choosing_ne),
    Template("line-dda-precision", "lines",
             "DDA: the first step where float32 and float64 plot different pixels",
             (DDA,), dda_precision),
)
