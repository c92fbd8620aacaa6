"""pipeline: world triangles through view, projection, clipping, divide and viewport, then the
triangle family's rasterizer, a depth test and shading.

Input: 3k points, the world x and y of each vertex, with ``z`` its world
z; per vertex ``colors``, ``normals`` (x,y,z each; none: the face normal)
and ``uv``. Shading with one directional light (``light``: the direction
the light travels) and ambient 0.2:

    colour = base (0.2 + 0.8 max(0, N . L)),   L = -light / |light|;

flat: N the face normal and base the mean of the vertex colours, one
colour per triangle; Gouraud: the colour lit at each (clipped) vertex and
interpolated; Phong: N and base interpolated, N renormalized, lit per
pixel. Attributes are interpolated perspective-correctly (weights
b_k / w_k, normalized); depth linearly in the window (it is z_ndc, already
divided). With a texture, base is multiplied by the texel colour / 255.
"""
from __future__ import annotations

import math

import numpy as np

from algorithms import triangles
from algorithms.core.code import Code
from algorithms.core.errors import InputError
from algorithms.triangles.interpolate import pack, per_vertex, unpack
from algorithms.core.steps import PLOT, VISIT, Note, Start, Table, Vars
from algorithms.textures import texels
from algorithms.textures.sampling import Mapping, Sampler

from .space import PLANES, Camera, clip_polygon, distance, normalized, to_window

AMBIENT = 0.2
# Products of coordinates stay far inside the float range (and the window's).
WORLD_LIMIT = 1e6
SHADINGS = ("flat", "gouraud", "phong")
CLIPPINGS = ("all", "near", "none")
FRAGMENT_OPS = {"int_add": 7, "mul": 30, "compare": 5, "pixels_tested": 1, "float_add": 20,
                "div": 6, "round": 3, "sqrt": 1}


def pipeline_code(options) -> Code:
    code = Code()
    code.add("model", "for each triangle, each vertex k:  world_k = model p_k   (the points are "
                      "given in world coordinates: the model matrix is the identity)")
    code.add("view", "    eye_k = view (world_k - camera):  x_eye = side . d,  y_eye = up . d,  "
                     "z_eye = -forward . d", ops={"mul": 27, "float_add": 36})
    code.add("projection", "    clip_k = projection eye_k:  x_clip = f/aspect x_eye,  y_clip = "
                           "f y_eye,  z_clip = A z_eye + B,  w = -z_eye",
             ops={"mul": 21, "float_add": 9})
    planes = {"all": "near, far, left, right, bottom, top", "near": "the near plane",
              "none": "nothing (every w must be > 0)"}[options["clipping"]]
    code.add("clip", f"    clip against {planes}: inside when d >= 0, d = w + z (near), "
                     "w - z (far), w +- x, w +- y; a crossing edge gains a + t (b - a), "
                     "t = d_a / (d_a - d_b)")
    code.add("divide", "    each corner C_k:  x_ndc = x_clip / w,  y_ndc = y_clip / w,  "
                       "z_ndc = z_clip / w", ops={"div": 3})
    code.add("viewport", "    x_win = (x_ndc + 1) W/2,  y_win = (y_ndc + 1) H/2,  "
                         "depth = (z_ndc + 1)/2", ops={"mul": 3, "float_add": 3})
    code.add("fan", "    rasterize each triangle (C0, Ck, Ck+1) of the polygon: snap and set up "
                    "its edges (the triangle family's rasterizer)")
    shade = {"flat": "colour = the triangle's (face normal, mean colour)",
             "gouraud": "colour = sum b'_k colour_k (lit at the vertices)",
             "phong": "N = normalize(sum b'_k N_k); colour = base (0.2 + 0.8 max(0, N.L))"
             }[options["shading"]]
    code.add("plot_pass", "        each covered pixel: b_k = e_k / 2A;  b'_k = (b_k / w_k) / "
                          "sum;  depth = sum b_k depth_k;  if depth < ZB: "
             + shade + ("; times the texel at (u, v)" if _textured(options) else "")
             + ";  CB = colour;  ZB = depth", PLOT, "pass", ops=FRAGMENT_OPS)
    code.add("fail", "        else: hidden (depth >= ZB)", VISIT, "fail", ops=FRAGMENT_OPS)
    code.add("done", "done: the clip and window coordinates of every vertex are in the variables")
    return code


def _textured(options) -> bool:
    return options.get("texture", "none") != "none"


class World:
    """The run's vertices with their attributes, checked."""

    def __init__(self, points, options):
        count = len(points)
        z = per_vertex(options, "z", count) or [0.0] * count
        self.positions = [[float(x), float(y), float(zk)] for (x, y), zk in zip(points, z)]
        for n, p in enumerate(self.positions):
            if not all(abs(v) <= WORLD_LIMIT for v in p):
                raise InputError(f"point {n + 1}: world coordinates must lie within "
                                 f"+-{WORLD_LIMIT:g}")
        colors = per_vertex(options, "colors", count)
        self.colors = [list(unpack(c)) for c in colors] if colors else [[200.0] * 3] * count
        self.normals = _triples(options, "normals", count)
        flat = options.get("uv") or ()
        if flat and len(flat) not in (2 * count, 6):
            raise InputError(f"option uv: give u,v per point ({2 * count} numbers), "
                             f"not {len(flat)}")
        self.uv = [(flat[(2 * k) % len(flat)], flat[(2 * k + 1) % len(flat)]) if flat
                   else (0.0, 0.0) for k in range(count)]
        self.has_uv = bool(flat) or _textured(options)
        self.light = normalized([-v for v in _light(options)])
        self.texture = None
        if _textured(options):
            self.texture = Sampler(texels.load(options["texture"]), options["filter"], "repeat")

    def face_normal(self, n):
        a, b, c = self.positions[3 * n:3 * n + 3]
        u = [q - p for p, q in zip(a, b)]
        v = [q - p for p, q in zip(a, c)]
        cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        return normalized(cross) if any(cross) else [0.0, 0.0, 1.0]

    def shade(self, base, normal):
        lit = AMBIENT + (1 - AMBIENT) * max(0.0, sum(p * q for p, q in zip(normal, self.light)))
        return [c * lit for c in base]


def _triples(options, name, count):
    flat = options.get(name) or ()
    if not flat:
        return None
    if len(flat) not in (3 * count, 9):
        raise InputError(f"option {name}: give x,y,z per point ({3 * count} numbers), "
                         f"not {len(flat)}")
    return [normalized([flat[(3 * k + n) % len(flat)] for n in range(3)]) for k in range(count)]


def _light(options):
    light = options.get("light") or ()
    if len(light) != 3:
        raise InputError("option light: give the direction x,y,z (three numbers)")
    return light


def pipeline(points, options, grid):
    width, height = int(grid[0]), int(grid[1])
    world = World(points, options)
    for name in ("eye", "target"):
        if not all(abs(v) <= WORLD_LIMIT for v in options[name]):
            raise InputError(f"option {name}: coordinates must lie within +-{WORLD_LIMIT:g}")
    camera = Camera(options["eye"], options["target"], options["fov"], options["near"],
                    options["far"], width / height)
    at = pipeline_code(options).at
    # u and v are columns only when the scene has them (uv or a texture).
    uv = ("u", "v") if world.has_uv else ()
    yield Start(line=at["model"], values=("depth", "zb", "w", *uv, "rgb"),
                constants={"shading": options["shading"], "clipping": options["clipping"],
                           "triangles": len(points) // 3}, pixel_value="rgb", depth_value="depth")
    state = {"color": np.full((height, width), -1.0), "depth": np.full((height, width), np.inf),
             "clip": [], "window": [], "fragments": 0, "passed": 0}
    planes = {"all": PLANES, "near": ("near",), "none": ()}[options["clipping"]]
    for n in range(len(points) // 3):
        yield from _triangle(n, world, camera, planes, options, state, at, (width, height))
    yield Vars(line=at["done"], values={"clip": tuple(state["clip"]),
                                        "window": tuple(state["window"]),
                                        "fragments": state["fragments"],
                                        "passed": state["passed"]})


def _triangle(n, world, camera, planes, options, state, at, grid):
    corners = []
    eyes = []
    for k in range(3):
        index = 3 * n + k
        eye = camera.to_eye(world.positions[index])
        clip = camera.to_clip(eye)
        normal = world.normals[index] if world.normals else world.face_normal(n)
        color = world.colors[index]
        lit = world.shade(color, normal)
        eyes.append(eye)
        corners.append([*clip, *color, *normal, *world.uv[index], *lit])
        state["clip"].append(tuple(clip))
    triangle = {"triangle": n + 1}
    yield Vars(line=at["model"], values=triangle | _named(
        ("x_world", "y_world", "z_world"), world.positions[3 * n:3 * n + 3]))
    yield Vars(line=at["view"], values=_named(("x_eye", "y_eye", "z_eye"), eyes))
    yield Vars(line=at["projection"], values=_named(("x_clip", "y_clip", "z_clip", "w"),
                                                     [c[:4] for c in corners]))
    if not planes and any(not c[3] > 0 for c in corners):
        raise InputError(f"triangle {n + 1} has a vertex with w <= 0 (at or behind the eye): "
                         "set clipping to near or all")
    polygon, report = clip_polygon(corners, planes)
    if planes:
        yield Table(line=at["clip"], name="clipping", columns=CLIP_COLUMNS,
                    rows=clip_rows(corners, planes, report))
    if len(polygon) < 3:
        yield Note(line=at["clip"], text=f"Triangle {n + 1} lies outside the view volume: "
                                         "nothing is left to draw.")
        return
    yield Vars(line=at["divide"], values={"corners": len(polygon)} | _named(
        ("x_ndc", "y_ndc", "z_ndc"), [[float(v / c[3]) for v in c[:3]] for c in polygon])
        | {f"w_C{k}": float(c[3]) for k, c in enumerate(polygon)})
    windows = [to_window(c, *grid) for c in polygon]
    state["window"] += [tuple(float(v) for v in p) for p in windows]
    yield Vars(line=at["viewport"], values=_named(("x_win", "y_win", "depth"), windows))
    face = (world.colors[3 * n:3 * n + 3], world.face_normal(n))
    for k in range(1, len(polygon) - 1):
        fan = [polygon[0], polygon[k], polygon[k + 1]]
        corners = [windows[0], windows[k], windows[k + 1]]
        yield Vars(line=at["fan"], values={"fan triangle": f"C0 C{k} C{k + 1}"}
                   | {f"Q{m}": (round(float(c[0]), 6), round(float(c[1]), 6))
                      for m, c in enumerate(corners)}
                   | {f"H{m}": tuple(float(v) for v in c[:4])
                      for m, c in enumerate((polygon[0], polygon[k], polygon[k + 1]))})
        yield from _fragments(fan, corners, face, world, options, state, at)


CLIP_COLUMNS = ("plane", "inside when", "vertices in", "out", "corners after")
INSIDE = {"near": "-w <= z", "far": "z <= w", "left": "-w <= x", "right": "x <= w",
          "bottom": "-w <= y", "top": "y <= w"}


def clip_rows(vertices, planes, report) -> tuple:
    """Per plane: its inequality, how many of the triangle's vertices pass it and how many do
    not, and the corners the polygon has after the cut (a dash once nothing is left)."""
    after = {plane: left for plane, _, left in report}
    rows = []
    for plane in planes:
        inside = sum(1 for v in vertices if distance(plane, v) >= 0)
        rows.append((plane, INSIDE[plane], inside, len(vertices) - inside,
                     after.get(plane, "-")))
    return tuple(rows)


def _named(names, rows) -> dict:
    """Short variables per vertex: x_eye0, y_eye0, z_eye0, x_eye1, ..."""
    return {f"{name}{k}": float(v) for k, row in enumerate(rows) for name, v in zip(names, row)}


def _fragments(fan, windows, face, world, options, state, at):
    setups = triangles.prepare([(p[0], p[1]) for p in windows],
                               {"subpixel_bits": 8, "fill_rule": "top-left", "cull": False})
    setup = setups[0]
    if setup.tri is None:
        return
    tri = setup.tri
    order = tri.order
    corner = [fan[k] for k in order]
    depth = [float(windows[k][2]) for k in order]
    w = [float(c[3]) for c in corner]
    flat = world.shade([sum(c[n] for c in face[0]) / 3 for n in range(3)], face[1])
    mapping = None
    if world.texture is not None:
        mapping = Mapping([tri.px(k) for k in range(3)], [(c[10], c[11]) for c in corner], w)
    edges = triangles.Edges(tri, "fixed")
    total = sum(tri.at(0, 0))
    height, width = state["depth"].shape
    i_lo, i_hi, j_lo, j_hi = tri.box()
    for j in range(max(j_lo, 0), min(j_hi, height - 1) + 1):
        for i in range(max(i_lo, 0), min(i_hi, width - 1) + 1):
            es = tri.at(i, j)
            if not edges.test(es)[0]:
                continue
            b = [e / total for e in es]
            q = [bk / wk for bk, wk in zip(b, w)]
            bp = [qk / sum(q) for qk in q]
            z = sum(bk * dk for bk, dk in zip(b, depth))
            state["fragments"] += 1
            stored = state["depth"][j, i]
            zb = float(stored) if math.isfinite(stored) else math.nan
            uv = (sum(p * c[10] for p, c in zip(bp, corner)),
                  sum(p * c[11] for p, c in zip(bp, corner))) if world.has_uv else ()
            if not z < stored:
                yield (at["fail"], i, j, z, zb, 1 / sum(q), *uv, math.nan)
                continue
            color = _shade(options["shading"], bp, corner, flat, world)
            if mapping is not None:
                texel = world.texture.sample(mapping, i, j).color
                color = [c * t / 255 for c, t in zip(color, texel)]
            state["passed"] += 1
            state["depth"][j, i] = z
            yield (at["plot_pass"], i, j, z, zb, 1 / sum(q), *uv, float(pack(color)))


def _shade(shading, bp, corner, flat, world):
    if shading == "flat":
        return flat
    if shading == "gouraud":
        return [sum(p * c[12 + n] for p, c in zip(bp, corner)) for n in range(3)]
    base = [sum(p * c[4 + n] for p, c in zip(bp, corner)) for n in range(3)]
    normal = [sum(p * c[7 + n] for p, c in zip(bp, corner)) for n in range(3)]
    length = math.sqrt(sum(v * v for v in normal))
    normal = [v / length for v in normal] if length > 0 else normal
    return world.shade(base, normal)


def explain(trace, i):
    """A fragment's way back through the stages: its weights, and its clip, NDC and window
    coordinates from the fan triangle's corners."""
    step = trace.step(i)
    if step.pixel is None or "depth" not in step.values:
        return []
    var = trace.variables_at(i)
    try:
        corners = [var[f"Q{m}"] for m in range(3)]
        clips = [var[f"H{m}"] for m in range(3)]
    except KeyError:
        return []
    x, y = step.pixel[0] + 0.5, step.pixel[1] + 0.5
    (x0, y0), (x1, y1), (x2, y2) = corners
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    if area == 0:
        return []
    b0 = ((x1 - x) * (y2 - y) - (x2 - x) * (y1 - y)) / area
    b1 = ((x2 - x) * (y0 - y) - (x0 - x) * (y2 - y)) / area
    b = (b0, b1, 1 - b0 - b1)
    q = [bk / c[3] for bk, c in zip(b, clips)]
    bp = [qk / sum(q) for qk in q]
    clip = [sum(p * c[n] for p, c in zip(bp, clips)) for n in range(4)]
    ndc = [v / clip[3] for v in clip[:3]]
    text = lambda values: "(" + ", ".join(f"{v:.4g}" for v in values) + ")"  # noqa: E731
    return [("window weights b", text(b)), ("perspective weights b'", text(bp)),
            ("clip (sum b' H_k)", text(clip)), ("ndc (clip / w)", text(ndc)),
            ("window", text(((ndc[0] + 1) * trace.width / 2, (ndc[1] + 1) * trace.height / 2,
                             (ndc[2] + 1) / 2)))]
