"""Circle templates: the pixels of the second octant and the decision
variable after k steps of the midpoint circle (the integer start 1 - R or
the fraction start 5/4 - R).

Drawn variants have radius 3 .. 7 on a 16x12 grid holding the second
octant (and the whole circle up to radius 5). The
second octant is the arc from (xc, yc + R) down to the diagonal x = y,
the one the loop computes before mirroring. Step k is the k-th time round
the loop (one E or SE decision); d_0 is the start.
"""
from __future__ import annotations

import random

from app.model.scene import Scene
from app.teaching.questions import common
from app.teaching.questions.model import NUMERICAL, Answer, Template, Worked

GRID = (16, 12)
MIDPOINT = "circle-midpoint"
KEYS = ("pixel", "choice", "d", "d after", "x", "y")
STARTS = {"integer": "d_0 = 1 - R", "fraction": "d_0 = 5/4 - R"}


def _rule(start: str) -> str:
    return (f"{STARTS[start]}; x = 0, y = R; while y > x: if d < 0 choose E (d += 2x + 3; "
            "x += 1), else SE (d += 2(x - y) + 5; x += 1; y -= 1), with x and y before the "
            "step in the update; a step that makes x > y plots nothing and ends the loop")


def _draw(rng):
    r = rng.randint(3, 7)
    # The second octant lies on the grid; the rest of a large circle may not.
    centre = (rng.randint(min(r, GRID[0] - 1 - r), GRID[0] - 1 - r),
              rng.randint(min(r, GRID[1] - 1 - r), GRID[1] - 1 - r))
    start = rng.choice(sorted(STARTS))
    return Scene(algorithm=MIDPOINT, points=(centre,), options={"radius": r, "start": start},
                 width=GRID[0], height=GRID[1])


def _circle(name: str, seed: int, scene):
    if scene is None:
        scene, rng = common.drawn(seed, _draw, lambda s: True)
    else:
        common.suited(name, (MIDPOINT,), scene)
        rng = random.Random(seed)
    trace = common.trace_of(scene)
    decisions = [i for i in range(len(trace)) if trace.step(i).branch]
    return scene, trace, decisions, rng


def _options(scene) -> dict:
    """The scene's options, defaults filled in."""
    return scene.spec.resolve(scene.options)


def _inputs(scene) -> str:
    (xc, yc), = scene.points
    return f"centre C = ({xc}, {yc}), radius R = {_options(scene)['radius']}"


def _worked(trace, decisions, upto: int, summary: str) -> Worked:
    rows = common.step_rows(trace, decisions[:upto], KEYS)
    return Worked(("k",) + KEYS, tuple((str(k + 1),) + row for k, row in enumerate(rows)),
                  summary)


def second_octant(seed: int, scene=None):
    name = "circle-octant-pixels"
    scene, trace, decisions, _ = _circle(name, seed, scene)
    (xc, yc), = scene.points
    # Each plot of the loop's own offset (x, y): the pixel (xc + x, yc + y).
    pixels = []
    for i in range(len(trace)):
        step = trace.step(i)
        if step.writes and "x" in step.values and step.pixel == (
                xc + int(step.values["x"]), yc + int(step.values["y"])):
            pixels.append(step.pixel)
    pixels = list(dict.fromkeys(pixels))
    options = _options(scene)
    text = (f"The midpoint circle with {_inputs(scene)} ({_rule(options['start'])}). "
            f"Which pixels does it plot in the second octant, from ({xc}, {yc + options['radius']}) "
            "to the diagonal x = y, before mirroring? Answer with the pixels in the order "
            "plotted, as (x, y) separated by spaces.")
    canonical = " ".join(map(common.pixel_text, pixels))
    compact = " ".join(f"({x},{y})" for x, y in pixels)
    worked = _worked(trace, decisions, len(decisions),
                     f"The second octant holds {len(pixels)} pixels: {canonical}.")
    return common.question(name, seed, "Midpoint circle: the second octant", text,
                           common.short(canonical, compact, compact.replace(" ", ""),
                                        canonical.replace(") (", "), (")),
                           worked, scene)


def decision_after_steps(seed: int, scene=None):
    name = "circle-midpoint-d"
    scene, trace, decisions, rng = _circle(name, seed, scene)
    if len(decisions) < 2:
        raise ValueError(f"{name}: the circle's loop takes {len(decisions)} step(s); "
                         "it needs 2 or more")
    k = rng.randint(1, len(decisions) - 1)
    d = common.exact(trace.step(decisions[k]).values["d"])  # tested at step k + 1
    text = (f"The midpoint circle with {_inputs(scene)} ({_rule(_options(scene)['start'])}). "
            f"What is d after {k} step(s) (d_{k}, the value step {k + 1} tests)? Answer with "
            "an exact number (an integer, or a fraction p/q).")
    shown = common.fraction_text(d)
    worked = _worked(trace, decisions, k, f"d after step {k} is {shown}.")
    return common.question(name, seed, f"Midpoint circle: d after step {k}", text,
                           Answer(NUMERICAL, d, shown), worked, scene)


TEMPLATES = (
    Template("circle-octant-pixels", "circles", "Midpoint circle: the pixels of the second octant",
             (MIDPOINT,), second_octant),
    Template("circle-midpoint-d", "circles",
             "Midpoint circle: d after k steps (integer or 5/4 start)", (MIDPOINT,),
             decision_after_steps),
)
