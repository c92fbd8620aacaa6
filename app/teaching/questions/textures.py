"""Question templates of the textures family: the mip level a pixel reads.

Each variant draws a counter-clockwise triangle on the 1/2 px grid with
texture coordinates (quarters) per vertex and w = 1, so the mapping is
affine and its derivatives are the same at every pixel; it runs the real
textured traversal with mip-mapping (filter mip-nearest: OpenGL's
LINEAR_MIPMAP_NEAREST) and reads the level, and the derivatives, rho and
lambda it was chosen from, from the frame of the asked pixel.
"""
from __future__ import annotations

import math
import random
from fractions import Fraction

from algorithms.core.steps import PLOT, Vars

from app.teaching.questions import triangle_draws as draws
from app.teaching.questions.model import NUMERICAL, Answer, Template, Worked

ALGORITHM = "triangle-texture"
TEXTURE = "checker:8"   # 64 x 64 texels, levels 0 .. 6
OPTIONS = {"texture": TEXTURE, "filter": "mip-nearest", "perspective": True, "w": (1.0,) * 3}
MARGIN = 0.05           # lambda stays this far from a level's bounds L +- 1/2
UV_STEPS = 8            # u, v in 0, 1/4, ..., 2


def _draw_uv(rng) -> tuple:
    while True:
        uv = [Fraction(rng.randint(0, UV_STEPS), 4) for _ in range(6)]
        corners = [(uv[0], uv[1]), (uv[2], uv[3]), (uv[4], uv[5])]
        if draws.area2(*corners) != 0:  # a mapping that stretches the texture both ways
            return tuple(float(v) for v in uv)


def _clear(step, top) -> bool:
    """The level is not at a bound of lambda (or capped at the top): by hand,
    rounding could not change it."""
    lam = step.values["lambda"]
    level = int(step.values["level"])
    bounds = [level - 0.5, level + 0.5] if level > 0 else [0.5]
    return level < top and all(abs(lam - b) >= MARGIN for b in bounds)


def _scene_input(scene):
    points, grid = draws.scene_triangles(scene, MIP_LEVEL)
    options = {name: value for name, value in scene.options.items()
               if name in ("uv", "w", "texture", "perspective", "wrap")}
    options["filter"] = "mip-nearest"
    return points[:3], grid, options


def _mip_level(seed, scene=None):
    rng = random.Random(seed)
    for _ in range(draws.ATTEMPTS):
        if scene is None:
            points, grid = draws.draw_triangle(rng), draws.GRID
            options = {**OPTIONS, "uv": _draw_uv(rng)}
        else:
            points, grid, options = _scene_input(scene)
        trace = draws.run(ALGORITHM, points, options, grid)
        setup = [record.values for _, record in trace.records_of(Vars)
                 if "levels" in record.values][0]
        top = setup["levels"] - 1
        covered = [step for step in _covered(trace) if _clear(step, top)]
        if covered or scene is not None:
            break
    if not covered:
        raise ValueError("no covered pixel of the scene has a mip level clear of a tie")
    step = covered[rng.randrange(len(covered))]
    level = int(step.values["level"])
    v = step.values
    uv = [setup[f"uv{k}"] for k in range(3)]
    ws = [setup[f"w{k}"] for k in range(3)]
    size = setup["size"]
    text = (f"A triangle has the vertices {draws.vertices_text(points)} with texture "
            f"coordinates (u, v) = " + ", ".join(f"({a:g}, {b:g})" for a, b in uv)
            + (f" and w = {', '.join(f'{w:g}' for w in ws)}" if len(set(ws)) > 1 else "")
            + f". The texture is {size} texels with a mip-map pyramid (level 0 is the full "
            f"texture, each level halves it, {setup['levels']} levels). {draws.CENTRE_TEXT} "
            f"The level of detail is lambda = log2(rho), rho the longer of the derivative "
            f"vectors (du/dx, dv/dx) and (du/dy, dv/dy) in texels; the nearest level is read "
            f"(level 0 when lambda <= 1/2, else ceil(lambda + 1/2) - 1). Which mip level does "
            f"pixel p = {step.pixel} read? Give the level as a whole number.")
    rows = (("du/dx", f"{v['du/dx']:.6g}"), ("dv/dx", f"{v['dv/dx']:.6g}"),
            ("du/dy", f"{v['du/dy']:.6g}"), ("dv/dy", f"{v['dv/dy']:.6g}"),
            ("rho", f"{v['rho']:.6g}"), ("lambda", f"{v['lambda']:.6g}"), ("level", str(level)))
    width, height = (int(part) for part in size.split(" x "))
    along_x = math.hypot(v["du/dx"] * width, v["dv/dx"] * height)
    along_y = math.hypot(v["du/dy"] * width, v["dv/dy"] * height)
    summary = (f"The planes of u and v through the vertices give du/dx = {v['du/dx']:.4g}, "
               f"dv/dx = {v['dv/dx']:.4g}, du/dy = {v['du/dy']:.4g}, dv/dy = {v['dv/dy']:.4g}; "
               f"in texels (x {width}, x {height}) the x vector is {along_x:.4g} long and the y "
               f"vector {along_y:.4g}, so rho = {v['rho']:.4g}, lambda = log2(rho) = "
               f"{v['lambda']:.4g} and the level is {level}.")
    worked = Worked(("quantity", "value at p"), rows, summary)
    answer = Answer(NUMERICAL, level, str(level))
    picture_scene = draws.make_scene(ALGORITHM, points, options, grid, "Mip level")
    return draws.question(MIP_LEVEL, seed, "Mip level at a pixel", text, answer, worked,
                          picture_scene)


def _covered(trace):
    for i in range(len(trace)):
        step = trace.step(i)
        if step.record is None and step.kind == PLOT and "level" in step.values:
            yield step


MIP_LEVEL = Template("texture-mip-level", "textures", "Texture: the mip level pixel p reads",
                     (ALGORITHM,), _mip_level)

TEMPLATES = (MIP_LEVEL,)
