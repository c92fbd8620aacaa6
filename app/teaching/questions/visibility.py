"""Question templates of the visibility family: which triangle the z-buffer
shows at a pixel, and whether the painter's order fails on a scene.

Each variant draws two or three counter-clockwise triangles on the 1/2 px
grid with a depth per vertex (tenths, smaller is nearer), runs the real
z-buffer or painter's algorithm and reads the answer from its frames and
tables: the fragments at the pixel with their depths and verdicts, or the
painter's disagreement with the z-buffer.
"""
from __future__ import annotations

import random
from collections import defaultdict

from algorithms.core.steps import PLOT, Table, Vars

from app.teaching.questions import triangle_draws as draws
from app.teaching.questions.model import CHOICE, Answer, Template, Worked

MIN_GAP = 0.02      # fragments' depths at the asked pixel differ by at least this much
MIN_AREA2 = 16      # larger triangles than the triangle family's, so that they overlap
NEAR = "Depth z is interpolated barycentrically at the pixel centre; smaller z is nearer."


def _draw(rng, count):
    """``count`` triangles and a depth (a tenth in 0.1 .. 0.9) per vertex."""
    points = [p for _ in range(count) for p in draws.draw_triangle(rng, min_area2=MIN_AREA2)]
    return points, tuple(rng.randint(1, 9) / 10 for _ in points)


def _scene_input(template, scene):
    points, grid = draws.scene_triangles(scene, template)
    points = points[:len(points) - len(points) % 3]
    z = scene.options.get("z") or ()
    if len(z) not in (3, len(points)):
        raise ValueError(f"template {template.name} needs a scene with a depth z per vertex")
    z = tuple(z) if len(z) == len(points) else tuple(z) * (len(points) // 3)
    return points, z, grid


def _triangle_of(trace, step) -> int:
    """The number (1, 2, ...) of the triangle whose fragment ``step`` is."""
    return trace.last_of(Vars, at=step.index)[1].values["triangle"]


def _fragments(trace) -> dict:
    """pixel -> [(triangle, step)] of every fragment the run drew, in drawing order."""
    found = defaultdict(list)
    for i in range(len(trace)):
        step = trace.step(i)
        if step.record is None and step.pixel is not None and "z" in step.values:
            found[step.pixel].append((_triangle_of(trace, step), step))
    return found


def _separated(fragments) -> bool:
    """Two or more triangles at the pixel, their depths well apart."""
    zs = sorted(step.values["z"] for _, step in fragments)
    return len(zs) >= 2 and all(b - a >= MIN_GAP for a, b in zip(zs, zs[1:]))


def _scene_text(points, z) -> str:
    parts = []
    for n in range(len(points) // 3):
        corners = ", ".join(f"{draws.point_text(p)} z = {z[3 * n + k]:g}"
                            for k, p in enumerate(points[3 * n:3 * n + 3]))
        parts.append(f"T{n + 1}: {corners}")
    return "; ".join(parts)


# -------------------------------------------------------------- z-buffer
def _visible(seed, scene=None):
    rng = random.Random(seed)
    for _ in range(draws.ATTEMPTS):
        if scene is None:
            points, z = _draw(rng, rng.choice((2, 3)))
            grid = draws.GRID
        else:
            points, z, grid = _scene_input(VISIBLE, scene)
        trace = draws.run("zbuffer", points, {"z": z}, grid)
        pixels = sorted(p for p, f in _fragments(trace).items() if _separated(f))
        if pixels or scene is not None:
            break
    if not pixels:
        raise ValueError("no pixel of the scene is covered by two triangles at clearly "
                         "different depths")
    pixel = pixels[rng.randrange(len(pixels))]
    fragments = _fragments(trace)[pixel]
    winner = [number for number, step in fragments if step.kind == PLOT][-1]
    names = tuple(f"T{n + 1}" for n in range(len(points) // 3))
    text = (f"A z-buffer (cleared to depth 1, a fragment passes when z < ZB) draws the "
            f"triangles in the order T1, T2, ...: {_scene_text(points, z)}. {NEAR} "
            f"{draws.CENTRE_TEXT} Which triangle is visible at pixel p = {pixel}?")
    rows = tuple((names[number - 1], f"{step.values['z']:.4g}", f"{step.values['zb']:.4g}",
                  "pass: written" if step.kind == PLOT else "fail: hidden")
                 for number, step in fragments)
    order = sorted(fragments, key=lambda item: item[1].values["z"])
    summary = ("The fragments at p, in drawing order, with z = alpha z0 + beta z1 + gamma z2: "
               + ", ".join(f"{names[n - 1]} z = {s.values['z']:.4g}" for n, s in fragments)
               + f". The nearest is {names[order[0][0] - 1]}, so {names[winner - 1]} is visible.")
    worked = Worked(("triangle", "z at p", "ZB before", "depth test"), rows, summary)
    answer = Answer(CHOICE, winner - 1, names[winner - 1], choices=names)
    picture_scene = draws.make_scene("zbuffer", points, {"z": z}, grid,
                                     "Visible triangle")
    return draws.question(VISIBLE, seed, "Visible triangle at a pixel", text, answer, worked,
                          picture_scene)


# --------------------------------------------------------------- painter
def _table(trace, name):
    return [record for _, record in trace.records_of(Table) if record.name == name][0]


def _painter_ties(trace) -> bool:
    """Equal sort keys, or two triangles at one depth at a pixel: the answer
    would rest on a tie rule, which this question is not about."""
    keys = [row[2] for row in _table(trace, "drawing order").rows]
    if len(set(keys)) < len(keys):
        return True
    for fragments in _fragments(trace).values():
        zs = sorted(step.values["z"] for _, step in fragments)
        if any(b - a < 1e-9 for a, b in zip(zs, zs[1:])):
            return True
    return False


def _painter(seed, scene=None):
    rng = random.Random(seed)
    want = rng.random() < 0.5  # both answers, about as often
    for _ in range(draws.ATTEMPTS):
        if scene is None:
            points, z = _draw(rng, 2)
            grid = draws.GRID
        else:
            points, z, grid = _scene_input(PAINTER, scene)
        trace = draws.run("painter", points, {"z": z, "sort": "mean"}, grid)
        fails = trace.final_variables()["disagree"] > 0
        if scene is not None or (fails == want and not _painter_ties(trace)):
            break
    order = _table(trace, "drawing order")
    differ = _table(trace, "disagreement").rows
    names = [f"T{row[1]}" for row in order.rows]
    text = (f"Triangles with a depth z per vertex: {_scene_text(points, z)}. {NEAR} The "
            f"painter's algorithm sorts whole triangles by the mean of their vertex depths, "
            f"farthest (largest) first, and draws them in that order with no depth test. "
            f"{draws.CENTRE_TEXT} Does the painter's order fail here, that is, does some pixel "
            f"show another triangle than a z-buffer (z < ZB) would?")
    rows = tuple((str(row[0]), f"T{row[1]}", f"{row[2]:.4g}",
                  " ".join(f"{v:g}" for v in row[3:])) for row in order.rows)
    if differ:
        x, y, painted, _, nearest, _ = differ[0]
        because = (f"it fails at {len(differ)} pixel(s), e.g. ({x}, {y}): the painter leaves "
                   f"T{painted} on top where T{nearest} is nearer")
    else:
        because = "every pixel shows the nearest triangle covering it: the order is right"
    summary = (f"Mean depths give the order {' then '.join(names)} (back to front); "
               f"compared with the z-buffer, {because}.")
    worked = Worked(("rank", "triangle", "mean z", "z0 z1 z2"), rows, summary)
    answer = Answer(CHOICE, 0 if differ else 1, "yes" if differ else "no",
                    choices=("yes", "no"))
    picture_scene = draws.make_scene("painter", points, {"z": z, "sort": "mean"}, grid,
                                     "Painter's order")
    return draws.question(PAINTER, seed, "Painter's order", text, answer, worked, picture_scene)


VISIBLE = Template("zbuffer-visible", "visibility", "Z-buffer: which triangle is visible at pixel p",
                   ("zbuffer", "painter"), _visible)
PAINTER = Template("painter-fails", "visibility", "Painter's algorithm: does its order fail here (yes/no)",
                   ("painter", "zbuffer"), _painter)

TEMPLATES = (VISIBLE, PAINTER)
