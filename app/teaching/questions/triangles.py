"""Question templates of the triangle family: edge values, barycentric
weights, the top-left rule and perspective-correct interpolation at a pixel.

Each variant draws a counter-clockwise triangle on the 1/2 px grid
(triangle_draws.py), runs the real traversal and reads the answer from the
frame of the chosen pixel: the edge values, the weights and the verdict are
the run's own. Edge k joins P(k+1) to P(k+2), as the triangle family
defines it (algorithms/triangles/__init__.py).
"""
from __future__ import annotations

import random
from fractions import Fraction

from algorithms.core import registry
from algorithms.core.steps import PLOT, Table, Vars

from app.model.exact import lattice_weights
from app.teaching.questions import triangle_draws as draws
from app.teaching.questions.model import CHOICE, NUMERICAL, SHORT, Answer, Template, Worked

TRAVERSALS = ("triangle-bbox", "triangle-scan", "triangle-incremental", "triangle-halfplane",
              "triangle-barycentric", "triangle-pineda")
CENTRE = draws.CENTRE_TEXT
EDGES = "Edge e_k joins P(k+1) to P(k+2): e_k(x, y) = (x_j - x_i)(y - y_i) - (y_j - y_i)(x - x_i)."
PERSPECTIVE_W = (1, 2, 4)  # w per vertex: 1/w stays a short decimal


# ------------------------------------------------------------- inputs
def _run(template, rng, scene, options=None, carried=()):
    """(trace, grid, options) of a triangle drawn from ``rng``, or of the first
    triangle of ``scene`` with its options named in ``carried``."""
    options = dict(options or {})
    if scene is None:
        points, grid = draws.draw_triangle(rng), draws.GRID
    else:
        points, grid = draws.scene_triangles(scene, template)
        points = points[:3]
        options.update({name: tuple(scene.options[name])[:3] for name in carried
                        if len(scene.options.get(name) or ()) >= 3})
        if draws.area2(*points) < 0:  # counter-clockwise, as the run would draw it
            points = [points[0], points[2], points[1]]
            options.update({name: (v[0], v[2], v[1]) for name, v in options.items()
                            if name in carried})
    return draws.run(template.algorithms[0], points, options, grid), grid, options


def _setup(trace):
    """The run's triangle: (vertices in the order drawn, 2A, the edges table rows)."""
    values = trace.records_of(Vars)[0][1].values
    edges = [record for _, record in trace.records_of(Table) if record.name == "edges"]
    if not edges or not values.get("2A"):
        raise ValueError("the scene's first triangle has no area once snapped to 1/256 px")
    vertices = [tuple(draws.exact(c) for c in values[f"P{k}"]) for k in range(3)]
    return vertices, draws.exact(values["2A"]), edges[0].rows


def _frames(trace, want=None):
    """Pixel frames of the run (the first triangle's), filtered by ``want``."""
    lines = [step for step in (trace.step(i) for i in range(len(trace)))
             if step.record is None and step.pixel is not None and "e0" in step.values]
    return [step for step in lines if want is None or want(step)]


def _pick(rng, frames):
    if not frames:
        raise ValueError("no pixel of the scene suits this question")
    return frames[rng.randrange(len(frames))]


def _centre(pixel):
    return (Fraction(2 * pixel[0] + 1, 2), Fraction(2 * pixel[1] + 1, 2))


def _edge_sum(k, vertices, pixel, value) -> str:
    """e_k at the pixel's centre with the numbers put in (the value is the run's)."""
    (xi, yi), (xj, yj) = vertices[(k + 1) % 3], vertices[(k + 2) % 3]
    x, y = _centre(pixel)
    t = draws.decimal_text
    return (f"e{k} = ({t(xj)} - {t(xi)})({t(y)} - {t(yi)}) - ({t(yj)} - {t(yi)})({t(x)} - {t(xi)})"
            f" = {t(value)}")


def _scene(template, trace, grid, options, seed, label):
    vertices = [tuple(c) for c in _setup(trace)[0]]
    return draws.make_scene(template.algorithms[0], vertices, options, grid,
                            f"{label}")


# ------------------------------------------------------------ templates
def _edge_values(seed, scene=None):
    rng = random.Random(seed)
    trace, grid, options = _run(EDGE_VALUES, rng, scene)
    vertices, _, rows = _setup(trace)
    step = _pick(rng, _frames(trace))
    es = [draws.exact(step.values[f"e{k}"]) for k in range(3)]
    canonical, also = draws.spellings(es, draws.decimal_text)
    text = (f"A triangle has the vertices {draws.vertices_text(vertices)}. {CENTRE} {EDGES} "
            f"Give e0, e1, e2 at the centre of pixel p = {step.pixel}, exactly, as "
            f"\"(e0, e1, e2)\" (decimals or fractions).")
    worked = Worked(("edge", "from -> to", "a", "b", "c", "e at p"),
                    tuple(row[:5] + (draws.decimal_text(e),) for row, e in zip(rows, es)),
                    "; ".join(_edge_sum(k, vertices, step.pixel, es[k]) for k in range(3)) + ".")
    return draws.question(EDGE_VALUES, seed, "Edge values at a pixel", text,
                          Answer(SHORT, canonical, canonical, also=also), worked,
                          _scene(EDGE_VALUES, trace, grid, options, seed, "Edge values"))


def _weights(seed, scene=None):
    rng = random.Random(seed)
    trace, grid, options = _run(BARYCENTRIC, rng, scene)
    vertices, twice, _ = _setup(trace)
    step = _pick(rng, _frames(trace, lambda s: s.kind == PLOT))
    exact = lattice_weights(trace.variables_at(step.index), step.pixel)
    if not exact:
        raise ValueError("the scene's vertices are not on the 1/256 px grid: no exact weights")
    weights = [exact[name] for name in ("alpha", "beta", "gamma")]
    canonical, also = draws.spellings(weights)
    es = [draws.exact(step.values[f"e{k}"]) for k in range(3)]
    text = (f"A triangle has the vertices {draws.vertices_text(vertices)}. {CENTRE} Give the "
            f"barycentric weights (alpha, beta, gamma) of P0, P1, P2 at the centre of pixel "
            f"p = {step.pixel} as exact fractions in lowest terms, \"(alpha, beta, gamma)\".")
    rows = tuple((name, draws.decimal_text(e), draws.decimal_text(twice), draws.fraction_text(w))
                 for name, e, w in zip(("alpha", "beta", "gamma"), es, weights))
    summary = "; ".join(f"{name} = e{k} / 2A = {draws.decimal_text(e)} / "
                        f"{draws.decimal_text(twice)} = {draws.fraction_text(w)}"
                        for k, (name, e, w) in enumerate(zip(("alpha", "beta", "gamma"), es,
                                                             weights)))
    worked = Worked(("weight", "e_k at p", "2A", "e_k / 2A"), rows,
                    summary + "; they add up to 1.")
    return draws.question(BARYCENTRIC, seed, "Barycentric weights at a pixel", text,
                          Answer(SHORT, canonical, canonical, also=also), worked,
                          _scene(BARYCENTRIC, trace, grid, options, seed, "Barycentric weights"))


def _tie(step) -> bool:
    return step.values.get("tie", 0) == 1


def _top_left(seed, scene=None):
    rng = random.Random(seed)
    on_edge = rng.random() < 0.6  # the rule decides only for centres on an edge
    want = _tie if on_edge else (lambda step: not _tie(step))
    for _ in range(draws.ATTEMPTS):
        trace, grid, options = _run(TOP_LEFT, rng, scene, {"fill_rule": "top-left"})
        candidates = _frames(trace, want)
        if candidates or scene is not None:
            break
    if not candidates:  # a given scene without a centre on an edge: any pixel
        candidates = _frames(trace)
    step = _pick(rng, candidates)
    vertices, _, rows = _setup(trace)
    filled = step.kind == PLOT
    es = [draws.exact(step.values[f"e{k}"]) for k in range(3)]
    text = (f"A triangle has the vertices {draws.vertices_text(vertices)} (counter-clockwise). "
            f"{CENTRE} {EDGES} A centre exactly on an edge follows the top-left rule (y up): it "
            f"counts on a left edge or a bottom horizontal edge. Is pixel p = {step.pixel} filled?")
    worked_rows = tuple(row[:2] + (row[5], draws.decimal_text(e)) for row, e in zip(rows, es))
    verdict = "filled" if filled else "not filled"
    worked = Worked(("edge", "from -> to", "side", "e at p"), worked_rows,
                    "; ".join(_edge_sum(k, vertices, step.pixel, es[k]) for k in range(3))
                    + f". {_reason(step, es, rows)}; so p is {verdict}.")
    answer = Answer(CHOICE, 0 if filled else 1, "yes" if filled else "no", choices=("yes", "no"))
    return draws.question(TOP_LEFT, seed, "Top-left rule at a pixel", text, answer, worked,
                          _scene(TOP_LEFT, trace, grid, options, seed, "Top-left rule"))


def _reason(step, es, rows) -> str:
    """Why the centre is in or out, from the run's verdict and edges table."""
    if _tie(step):
        parts = []
        for k in (k for k in range(3) if es[k] == 0):
            side, rule = rows[k][5].split(" (")
            kept = "keeps" if rule.startswith("kept") else "leaves out"
            parts.append(f"e{k} = 0: the centre lies on e{k}, a {side} edge, which the "
                         f"top-left rule {kept}")
        return ", and ".join(parts)
    if step.kind == PLOT:
        return "Every edge value is positive: the centre is inside"
    return ", ".join(f"e{k} = {draws.decimal_text(es[k])} < 0" for k in range(3)
                     if es[k] < 0) + ": the centre is outside"


def _perspective(seed, scene=None):
    rng = random.Random(seed)
    options = {}
    if scene is None:
        w = [rng.choice(PERSPECTIVE_W) for _ in range(3)]
        while len(set(w)) == 1:
            w[rng.randrange(3)] = rng.choice(PERSPECTIVE_W)
        options = {"w": tuple(float(v) for v in w),
                   "s": tuple(float(rng.randint(0, 12)) for _ in range(3))}
    elif scene.options.get("near", 0) > 0 or scene.options.get("perspective") is False:
        raise ValueError("the scene clips at the near plane or interpolates affinely")
    trace, grid, options = _run(PERSPECTIVE, rng, scene, options, carried=("w", "s"))
    vertices, _, _ = _setup(trace)
    step = _pick(rng, _frames(trace, lambda s: s.kind == PLOT))
    variables = trace.variables_at(step.index)
    ws = [1 / variables[f"1/w{k}"] for k in range(3)]
    ss = _vertex_s(trace, options)
    value = _recorded_fraction(step.values["s_persp"])
    weights = lattice_weights(variables, step.pixel)
    text = (f"A triangle has the vertices {draws.vertices_text(vertices)}, with w = "
            f"{', '.join(f'{v:g}' for v in ws)} and the attribute s = "
            f"{', '.join(f'{v:g}' for v in ss)} at P0, P1, P2. {CENTRE} Give the "
            f"perspective-correct value of s at the centre of pixel p = {step.pixel} "
            f"(interpolate s/w and 1/w with the screen-space barycentric weights, then divide), "
            f"as a decimal to 3 places.")
    names = ("alpha", "beta", "gamma")
    rows = tuple((f"P{k}", draws.fraction_text(weights[names[k]]) if weights else
                  f"{step.values[names[k]]:.6g}", f"{ws[k]:g}", f"{ss[k]:g}") for k in range(3))
    summary = (f"s/w = {step.values['s/w']:.6g} and 1/w = {step.values['1/w']:.6g} at the centre "
               f"(each alpha q0 + beta q1 + gamma q2); s = (s/w) / (1/w) = "
               f"{draws.fraction_text(value)} = {float(value):.3f} (affine, without the divide: "
               f"{step.values['s_affine']:.4g}).")
    worked = Worked(("vertex", "weight at p", "w", "s"), rows, summary)
    answer = Answer(NUMERICAL, value, f"{float(value):.3f}", tolerance=0.001)
    return draws.question(PERSPECTIVE, seed, "Perspective-correct value at a pixel", text,
                          answer, worked, _scene(PERSPECTIVE, trace, grid, options, seed,
                                                 "Perspective-correct value"))


def _vertex_s(trace, options) -> list[float]:
    resolved = registry.get("triangle-perspective").resolve(options)
    s = list(resolved["s"])
    return s[:3] if len(s) >= 3 else s * 3


def _recorded_fraction(value: float) -> Fraction:
    """The exact rational a recorded float stands for: inputs on the 1/2 px grid
    with w in 1, 2, 4 give a denominator far below 10^6, so the nearest such
    fraction is the value the run rounded."""
    found = Fraction(value).limit_denominator(10 ** 6)
    if abs(float(found) - value) > 1e-12 * max(1.0, abs(value)):
        raise ValueError("the value at this pixel has no short exact form")
    return found


EDGE_VALUES = Template("triangle-edge-values", "triangles", "Triangle: the edge values e0, e1, e2 at pixel p",
                       TRAVERSALS, _edge_values)
BARYCENTRIC = Template("triangle-barycentric-weights", "triangles",
                       "Triangle: the barycentric weights at pixel p (exact fractions)",
                       ("triangle-barycentric",) + TRAVERSALS[:-2], _weights)
TOP_LEFT = Template("triangle-top-left", "triangles",
                    "Triangle: is pixel p filled under the top-left rule (yes/no)", TRAVERSALS, _top_left)
PERSPECTIVE = Template("triangle-perspective-value", "triangles",
                       "Triangle: the perspective-correct value of an attribute at pixel p",
                       ("triangle-perspective",), _perspective)

TEMPLATES = (EDGE_VALUES, BARYCENTRIC, TOP_LEFT, PERSPECTIVE)
