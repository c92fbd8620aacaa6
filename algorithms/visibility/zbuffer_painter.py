"""The visibility family: the z-buffer and the painter's algorithm.

Both draw k triangles (3k points) with a depth per vertex (``z``, one per
point, or three shared by every triangle; smaller is nearer). A triangle
covers the pixels whose centres it covers under the fill rule, exactly as
the triangle family decides it (vertices snapped to 1/256 px, integer edge
functions); those pixels are its *fragments*.

A fragment's depth is the barycentric interpolation of the vertex depths at
the pixel centre, z = alpha z0 + beta z1 + gamma z2 with alpha = e0 / 2A
and so on, computed exactly (fractions) from the integer edge values and
rounded once to float64, so two runs, or two triangles in one plane, never
disagree by rounding.

z-buffer. The depth buffer starts at ``clear_depth`` (1.0: far) in every
pixel; a fragment passes when z < ZB[x, y] (``depth_test=less``) or
z <= ZB[x, y] (``less-equal``); a passing fragment writes its colour and
its depth. Frames: one per fragment, a PLOT frame when it passes and a
VISIT frame when it fails, with the values z (the fragment's depth), zb
(the depth stored before the test) and rgb (its colour). ``Start`` names z
as ``depth_value``, so the replayed Raster carries the depth buffer at any
step (NaN where no fragment has been stored yet: the clear value;
``depth_view`` fills it in).

Painter's algorithm. The triangles are sorted by a key of their vertex
depths (``sort``: mean, min or max z), farthest first, and drawn in that
order with no depth test: every fragment is a PLOT frame, the last one
drawn wins. The final step compares the picture with the z-buffer's
(depth test less, no far limit, so only the order matters) and lists the
pixels whose colours differ: the count ``disagree``, and the table
``disagreement``. It fails on triangles that pierce each other
(``intersecting_scene``) and on triangles that overlap in a cycle
(``cyclic_scene``): no order of whole triangles is right there.

Colours: ``colors`` with one colour per point (or three shared) shades
each fragment by its barycentric weights (Gouraud); without them every
triangle takes a colour of its own from a fixed palette.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms import triangles
from algorithms.triangles import ops_sum
from algorithms.core.code import Code
from algorithms.triangles.interpolate import mix, per_vertex, unpack
from algorithms.core.registry import AlgorithmSpec, Inputs, Option, Oracle
from algorithms.core.steps import PER_ROW, PLOT, VISIT, Note, Start, Table, Vars
from algorithms.core.trace import checkpoint

NAN = math.nan
TESTS = ("less", "less-equal")
SORT_KEYS = ("mean", "min", "max")
PALETTE = ("#e03131", "#1971c2", "#2f9e44", "#f08c00", "#9c36b5", "#0c8599", "#e8590c",
           "#5c940d")
MAX_TABLE_ROWS = 200

TRIANGLES = Inputs(3, integer=False, names=("P0", "P1", "P2"), multiple=True)
Z = Option("z", "numbers", (), "a depth per point (or three shared by every triangle); "
           "smaller is nearer. Without it every vertex lies at 0.5")
COLORS = Option("colors", "colors", (), "a colour #rrggbb per point (or three shared), "
                "interpolated over each triangle; without it each triangle has a colour "
                "of its own")
FILL_RULE = triangles.FILL_RULE
DEPTH_TEST = Option("depth_test", "choice", "less", "a fragment passes when z < ZB (less) "
                    "or z <= ZB (less-equal)", choices=TESTS)
CLEAR_DEPTH = Option("clear_depth", "float", 1.0, "the depth every pixel starts with (far)",
                     minimum=-1e300, maximum=1e300)
SORT = Option("sort", "choice", "mean", "the depth that places a triangle in the drawing "
              "order: the mean, the smallest or the largest of its vertex depths",
              choices=SORT_KEYS)


# ============================================================ fragments
class Scene:
    """Triangles of a run, snapped and counter-clockwise, with depths and colours."""

    def __init__(self, points, options, grid):
        full = {"subpixel_bits": 8, "cull": False, "fill_rule": options.get("fill_rule",
                                                                              "top-left")}
        self.setups = triangles.prepare(points, full)
        count = len(points)
        z = per_vertex(options, "z", count)
        self.z_given = z is not None
        self.z = [float(v) for v in z] if z is not None else [0.5] * count
        colors = per_vertex(options, "colors", count)
        self.colors = [unpack(c) for c in colors] if colors else None
        self.width, self.height = int(grid[0]), int(grid[1])

    def color_of(self, number: int) -> str:
        return PALETTE[number % len(PALETTE)]

    def fragments(self, setup):
        """(i, j, z, packed colour) of every pixel the triangle covers, row by row."""
        tri = setup.tri
        edges = triangles.Edges(tri, "fixed")
        total = sum(tri.at(0, 0))  # e0 + e1 + e2 is the same at every point: 2 S^2 * 2A
        zs = [Fraction(self.z[k]) for k in tri.order]
        colors = None if self.colors is None else [self.colors[k] for k in tri.order]
        flat = int(self.color_of(setup.number)[1:], 16)
        i_lo, i_hi, j_lo, j_hi = tri.box()
        i_lo, i_hi = max(i_lo, 0), min(i_hi, self.width - 1)
        j_lo, j_hi = max(j_lo, 0), min(j_hi, self.height - 1)
        for j in range(j_lo, j_hi + 1):
            checkpoint()  # a row can be 4096 pixels of work no frame separates (the final images)
            for i in range(i_lo, i_hi + 1):
                es = tri.at(i, j)
                covered, _ = edges.test(es)
                if not covered:
                    continue
                z = float((es[0] * zs[0] + es[1] * zs[1] + es[2] * zs[2]) / total)
                if colors is None:
                    color = flat
                else:
                    color = mix([e / total for e in es], colors)
                yield i, j, z, color

    def drawn(self):
        return [s for s in self.setups if s.tri is not None]


def passes(z: float, stored: float, test: str) -> bool:
    return z < stored if test == "less" else z <= stored


def zbuffer_image(points, options, grid, clear: float | None = None):
    """The z-buffer's final (colour, depth, triangle) arrays, (H, W) each.

    Colour -1, depth ``clear`` and triangle -1 where no fragment passed.
    """
    options = {**_defaults(ZBUFFER_OPTIONS), **options}
    scene = Scene(points, options, grid)
    clear = options["clear_depth"] if clear is None else clear
    test = options["depth_test"]
    # Zeroed buffers (colour and triangle plus one) cost nothing until
    # written; the passes over the whole buffers go a block of rows at a
    # time, so a cancel is heard between blocks (a whole pass over 16M
    # pixels took up to 400 ms).
    color = np.zeros((scene.height, scene.width), np.int64)
    depth = np.zeros((scene.height, scene.width))
    owner = np.zeros((scene.height, scene.width), np.int64)
    for setup in scene.drawn():
        for i, j, z, c in scene.fragments(setup):
            if passes(z, depth[j, i] if owner[j, i] else clear, test):
                color[j, i], depth[j, i], owner[j, i] = c + 1, z, setup.number + 1
    for rows in row_blocks(scene.height):
        depth[rows][owner[rows] == 0] = clear
        color[rows] -= 1
        owner[rows] -= 1
    return color, depth, owner


def row_blocks(height: int, rows: int = 64):
    """Slices of a few rows each, covering 0 .. height, with a checkpoint
    before each: whole-buffer passes on a big grid are done block by block."""
    for top in range(0, height, rows):
        checkpoint()
        yield slice(top, min(top + rows, height))


def painter_order(scene: Scene, key: str) -> list:
    """The drawn triangles, farthest first (ties keep the input order)."""
    def depth_key(setup):
        zs = [scene.z[k] for k in setup.tri.order]
        return {"mean": math.fsum(zs) / 3, "min": min(zs), "max": max(zs)}[key]
    return sorted(scene.drawn(), key=lambda s: -depth_key(s)), depth_key


def painter_image(points, options, grid):
    """The painter's final (colour, triangle) arrays, (H, W) each; -1 where nothing is drawn."""
    options = {**_defaults(PAINTER_OPTIONS), **options}
    scene = Scene(points, options, grid)
    color = np.full((scene.height, scene.width), -1, np.int64)
    owner = np.full((scene.height, scene.width), -1, np.int64)
    order, _ = painter_order(scene, options["sort"])
    for setup in order:
        for i, j, _, c in scene.fragments(setup):
            color[j, i], owner[j, i] = c, setup.number
    return color, owner


def depth_view(raster, clear: float = 1.0) -> np.ndarray:
    """The depth buffer of a replayed raster, with ``clear`` where nothing was stored."""
    if raster.depth is None:
        return np.full((raster.height, raster.width), float(clear))
    return np.where(np.isnan(raster.depth), float(clear), raster.depth)


def _defaults(options):
    return {option.name: option.default for option in options}


# ============================================================ z-buffer
# ------------------------------------------------- operation counts
# CodeLine.ops of the two visibility algorithms. Edge values are integers
# (vertices snapped to 1/256 px), so their additions count as int_add; the
# depth and the colour are interpolated from them. Conventions:
# * Line "triangle" runs once per triangle (its Vars record): snapping and 2A as in
#   the triangle family (8 mul, 6 round, 5 int_add, 2 compare), the three
#   edges' a, b, c (6 mul, 9 int_add) and the clamped bounding box (4
#   ceil/floor divisions with their 4 mul and 8 int_add, 8 + 4 compares).
# * Every fragment is one frame and carries its whole walk: the loop step
#   and test (1 int_add, 1 compare), e_k at the centre (6 mul, 6 int_add),
#   the three sign tests in full (3 compare, 1 pixel tested). Box pixels
#   the triangle does not cover yield no frame and are not counted, so
#   pixels_tested counts fragments only.
# * Gouraud colour (option colors): the weights e_k / 2A (3 div), per
#   channel alpha c0 + beta c1 + gamma c2 (3 mul, 2 float_add) and a round.
WALK_OPS = {"int_add": 7, "mul": 6, "compare": 4, "pixels_tested": 1}
TRIANGLE_OPS = {"mul": 18, "round": 6, "int_add": 22, "compare": 14, "div": 4}
# z = (e0 z0 + e1 z1 + e2 z2) / 2A, exactly, then one rounding to float64.
DEPTH_OPS = {"mul": 3, "float_add": 2, "div": 1}


def _shade_ops(options) -> dict:
    if not options.get("colors"):
        return {}  # the triangle's palette colour: nothing computed per fragment
    return {"div": 3, "mul": 9, "float_add": 6, "round": 3}


def zbuffer_code(points, options) -> Code:
    test = "<" if options.get("depth_test", "less") == "less" else "<="
    # A fragment interpolates its depth and tests it against ZB (1 compare),
    # passing or not; only a passing one writes colour and depth.
    fragment = ops_sum(WALK_OPS, DEPTH_OPS, {"compare": 1}, _shade_ops(options))
    code = Code()
    code.add("clear", f"ZB[x, y] = {options.get('clear_depth', 1.0):g} for every pixel (far);  "
                      "CB[x, y] = background")
    code.add("triangle", "for each triangle T, in input order:   (snap, make counter-clockwise)",
             ops=TRIANGLE_OPS)
    code.add("fragments", "    for each fragment (x, y) of T   (pixel centres T covers, fill "
                          "rule):")
    code.add("plot_pass", f"        z = alpha z0 + beta z1 + gamma z2;  if z {test} ZB[x, y]:  "
                     "CB[x, y] = colour;  ZB[x, y] = z", PLOT, "pass", ops=fragment)
    code.add("fail", f"        else (z {'>=' if test == '<' else '>'} ZB[x, y]): hidden, keep "
                     "CB and ZB", VISIT, "fail", ops=fragment)
    code.add("done", "done")
    return code


def zbuffer(points, options, grid):
    scene = Scene(points, options, grid)
    test = options["depth_test"]
    clear = float(options["clear_depth"])
    at = zbuffer_code(points, options).at
    constants = {"clear_depth": clear, "depth_test": test, "fill_rule": options["fill_rule"],
                 "triangles": len(scene.setups)}
    yield Start(line=at["clear"], values=("z", "zb", "rgb"), constants=constants,
                pixel_value="rgb", depth_value="z")
    if not scene.z_given:
        yield Note(line=at["clear"], text="No z given: every vertex lies at depth 0.5, so the "
                                          "first triangle drawn over a pixel keeps it.")
    # Zeroed buffers cost nothing until written (the system hands out zero
    # pages lazily): filling 16M depths with ``clear`` before the first
    # frame took 100-200 ms no cancel could interrupt. A pixel not yet
    # written holds ``clear``.
    depth = np.zeros((scene.height, scene.width))
    fragments = passed = overdraw = 0
    written = np.zeros((scene.height, scene.width), bool)
    pass_line, fail_line = at["plot_pass"], at["fail"]
    for setup in scene.setups:
        yield from _triangle_vars(scene, setup, at["triangle"])
        if setup.tri is None:
            continue
        for i, j, z, color in scene.fragments(setup):
            fragments += 1
            stored = depth[j, i] if written[j, i] else clear
            if passes(z, stored, test):
                passed += 1
                overdraw += bool(written[j, i])
                written[j, i] = True
                depth[j, i] = z
                yield (pass_line, i, j, z, float(stored), float(color))
            else:
                yield (fail_line, i, j, z, float(stored), float(color))
    yield Vars(line=at["done"], values={"fragments": fragments, "passed": passed,
                                        "failed": fragments - passed, "overwritten": overdraw,
                                        "visible": int(written.sum())})


def _triangle_vars(scene, setup, line):
    values = {"triangle": setup.number + 1}
    order = setup.tri.order if setup.tri is not None else tuple(range(3 * setup.number,
                                                                      3 * setup.number + 3))
    for k, index in enumerate(order):
        values[f"P{k}"] = (setup.tri.px(k) if setup.tri is not None
                           else tuple(v / 256 for v in setup.snapped[k]))
        values[f"z{k}"] = scene.z[index]
    if scene.colors is None:
        values["colour"] = scene.color_of(setup.number)
    yield Vars(line=line, values=values)
    if setup.tri is None:
        yield Note(line=line,
                   text=f"Triangle {setup.number + 1} has no area once snapped: no fragments.")


def explain_depth(trace, i):
    step = trace.step(i)
    if "z" not in step.values or step.pixel is None:
        return []
    z, stored = step.values["z"], step.values.get("zb", NAN)
    variables = trace.variables_at(i)
    rows = [("fragment colour", f"#{int(step.values['rgb']):06x}")] if "rgb" in step.values \
        else []
    if "zb" in step.values:
        test = variables.get("depth_test", "less")
        sign = "<" if test == "less" else "<="
        verdict = "passes: colour and depth written" if step.kind == PLOT else \
            "fails: the stored fragment is nearer"
        rows.append(("depth test", f"{z!r} {sign} {stored!r}?  {verdict}"))
    return rows


# ============================================================ painter
def painter_code(points, options) -> Code:
    key = options.get("sort", "mean")
    # Line "sort": the key of every triangle, one row of its drawing-order table
    # (mean: 2 float_add and a division; min or max: 2 compares); the sort's
    # comparisons are not counted. Fragments carry the walk and the colour
    # but no depth: the depth the shared fragment walk also yields is shown,
    # not used. Line "compare" checks the result against a z-buffer run: analysis,
    # not part of the algorithm, so not counted.
    key_ops = {"float_add": 2, "div": 1} if key == "mean" else {"compare": 2}
    code = Code()
    code.add("sort", f"key(T) = the {key} of T's vertex depths;  sort the triangles by key, "
                     "largest (farthest) first", per={PER_ROW: key_ops})
    code.add("triangle", "for each triangle T in that order (back to front):", ops=TRIANGLE_OPS)
    code.add("plot_paint", "    for each fragment (x, y) of T:  CB[x, y] = colour   (no depth test: "
                      "the last triangle drawn wins)", PLOT,
             ops=ops_sum(WALK_OPS, _shade_ops(options)))
    code.add("compare", "compare with the z-buffer: disagree = pixels whose colours differ")
    code.add("done", "done")
    return code


def painter(points, options, grid):
    scene = Scene(points, options, grid)
    key = options["sort"]
    order, depth_key = painter_order(scene, key)
    at = painter_code(points, options).at
    constants = {"sort": key, "fill_rule": options["fill_rule"], "triangles": len(scene.setups)}
    yield Start(line=at["sort"], values=("z", "key", "rgb"), constants=constants,
                pixel_value="rgb")
    rows = tuple((rank + 1, s.number + 1, depth_key(s), *(scene.z[k] for k in s.tri.order))
                 for rank, s in enumerate(order))
    yield Table(line=at["sort"], name="drawing order",
                columns=("rank", "triangle", f"{key} z", "z0", "z1", "z2"), rows=rows)
    # Colour and triangle are stored plus one in zeroed buffers, which cost
    # nothing until written (filling them with -1 before the first frame
    # took over 100 ms no cancel could interrupt); 0 means nothing drawn.
    color = np.zeros((scene.height, scene.width), np.int64)
    owner = np.zeros((scene.height, scene.width), np.int64)
    paint_line = at["plot_paint"]
    for setup in order:
        yield from _triangle_vars(scene, setup, at["triangle"])
        k = depth_key(setup)
        for i, j, z, c in scene.fragments(setup):
            color[j, i], owner[j, i] = c + 1, setup.number + 1
            yield (paint_line, i, j, z, k, float(c))
    for rows in row_blocks(scene.height):
        color[rows] -= 1
        owner[rows] -= 1
    reference, _, ref_owner = zbuffer_image(points, {**options, "depth_test": "less"}, grid,
                                            clear=math.inf)
    differ, wrong, drawn = _disagreement(color, owner, reference, ref_owner)
    rows = tuple((int(x), int(y), _owner_text(owner[y, x]), _color_text(color[y, x]),
                  _owner_text(ref_owner[y, x]), _color_text(reference[y, x]))
                 for y, x in differ[:MAX_TABLE_ROWS])
    yield Table(line=at["compare"], name="disagreement",
                columns=("x", "y", "painter: triangle", "painter: colour", "z-buffer: triangle",
                         "z-buffer: colour"), rows=rows)
    if len(differ) > MAX_TABLE_ROWS:
        yield Note(line=at["compare"],
                   text=f"The table lists the first {MAX_TABLE_ROWS} of {len(differ)} pixels.")
    yield Vars(line=at["compare"], values={"disagree": int(len(differ)), "wrong_triangle": wrong,
                                           "drawn": drawn})
    if len(differ):
        yield Note(line=at["done"], text=f"{len(differ)} pixels differ from the z-buffer: no "
                                         "drawing order of whole triangles is right for this "
                                         "scene.")


def _disagreement(color, owner, reference, ref_owner):
    """(pixels (y, x) whose colours differ, in row order; how many have
    another triangle; how many are drawn), a block of rows at a time."""
    differ, wrong, drawn = [], 0, 0
    for rows in row_blocks(color.shape[0]):
        found = np.argwhere(color[rows] != reference[rows])
        found[:, 0] += rows.start
        differ.append(found)
        wrong += int((owner[rows] != ref_owner[rows]).sum())
        drawn += int((color[rows] >= 0).sum())
    return (np.concatenate(differ) if differ else np.zeros((0, 2), np.int64)), wrong, drawn


def _owner_text(number) -> str:
    return "-" if number < 0 else str(int(number) + 1)


def _color_text(color) -> str:
    return "background" if color < 0 else f"#{int(color):06x}"


def explain_painter(trace, i):
    step = trace.step(i)
    rows = []
    if "rgb" in step.values:
        rows.append(("fragment colour", f"#{int(step.values['rgb']):06x}"))
    if "key" in step.values:
        rows.append(("order", f"drawn by its key {step.values['key']!r}; later triangles "
                              "paint over earlier ones whatever their depth"))
    return rows


# ============================================================ scenes
def intersecting_scene() -> dict:
    """Two triangles that pierce each other: each is in front over part of the other."""
    points = [(2.0, 3.0), (29.0, 11.0), (3.0, 21.0),
              (30.0, 3.0), (29.0, 21.0), (2.0, 12.0)]
    z = [0.1, 0.9, 0.1,
         0.1, 0.1, 0.9]
    colors = ["#e03131"] * 3 + ["#1971c2"] * 3
    return {"algorithm": "painter", "points": points, "grid": (32, 24),
            "options": {"z": tuple(z), "colors": tuple(colors), "sort": "mean"}}


def cyclic_scene() -> dict:
    """Three long triangles overlapping in a cycle: A over B, B over C, C over A.

    Each lies along one side of a larger triangle, wide and far (z = 0.9)
    at its tail, narrow and near (z = 0.1) at its head, and its head
    crosses the tail of the next one: so each triangle is in front of the
    next and behind the previous one.
    """
    points = [(6.5, 9.8), (7.0, 1.9), (27.0, 7.2),      # A: tail at the left, head at the right
              (22.3, 2.8), (28.4, 7.9), (13.2, 20.2),   # B: tail at the right, head at the top
              (19.5, 18.0), (12.3, 21.6), (7.8, 3.6)]   # C: tail at the top, head at the left
    z = [0.9, 0.9, 0.1] * 3
    colors = ["#e03131"] * 3 + ["#2f9e44"] * 3 + ["#1971c2"] * 3
    return {"algorithm": "painter", "points": points, "grid": (32, 24),
            "options": {"z": tuple(z), "colors": tuple(colors), "sort": "mean"}}


def separate_scene() -> dict:
    """Three triangles that do not overlap: the painter and the z-buffer agree."""
    points = [(1.0, 1.0), (9.0, 2.0), (4.0, 9.0),
              (12.0, 2.0), (20.0, 1.0), (16.0, 10.0),
              (23.0, 3.0), (31.0, 8.0), (25.0, 20.0)]
    z = [0.3, 0.5, 0.4, 0.8, 0.7, 0.6, 0.2, 0.2, 0.9]
    return {"algorithm": "painter", "points": points, "grid": (32, 24),
            "options": {"z": tuple(z), "sort": "mean"}}


SCENES = {"painter-intersecting": intersecting_scene, "painter-cyclic": cyclic_scene,
          "painter-separate": separate_scene}



# `run --json`'s fragments: the z and colour of each fragment written.
FRAGMENTS = (("triangle", "@triangle"), ("z", "z"), ("color", "rgb"))
ZBUFFER_OPTIONS = (Z, COLORS, DEPTH_TEST, CLEAR_DEPTH, FILL_RULE)
PAINTER_OPTIONS = (Z, COLORS, SORT, FILL_RULE)

ZBUFFER = AlgorithmSpec(
    name="zbuffer", title="Z-buffer", family="visibility",
    summary="keep, per pixel, the nearest fragment: z < ZB[x, y] writes colour and depth",
    inputs=TRIANGLES, options=ZBUFFER_OPTIONS,
    code=lambda points, options: tuple(zbuffer_code(points, options).lines), generator=zbuffer,
    notes=("Depths are interpolated barycentrically at the pixel centre, exactly, then "
           "rounded once to float64.",
           "Fragments that fail the depth test are shown but write nothing; the depth "
           "buffer view shows ZB at any step.",
           "Triangles may come in any order, intersect or overlap in a cycle: the "
           "z-buffer is right in every case."),
    explain=explain_depth, uses_grid=True, fragments=FRAGMENTS,
    oracle=Oracle(
        "exact",
        "Per pixel, the colour of the nearest triangle covering its centre and its depth rounded "
        "once, from exact barycentric depths in Fractions written in the test, for both depth "
        "tests.",
        ("algorithms/visibility/test_visibility.py",)),
)

PAINTER = AlgorithmSpec(
    name="painter", title="Painter's algorithm", family="visibility",
    summary="sort triangles by depth and draw them back to front",
    inputs=TRIANGLES, options=PAINTER_OPTIONS,
    code=lambda points, options: tuple(painter_code(points, options).lines), generator=painter,
    notes=("No depth buffer: whatever is drawn last over a pixel stays.",
           "Whole triangles cannot be ordered when they pierce each other or overlap in "
           "a cycle; the last step counts the pixels where the result differs from the "
           "z-buffer's.",),
    explain=explain_painter, uses_grid=True, fragments=FRAGMENTS,
    oracle=Oracle(
        "exact",
        "Each pixel shows the last triangle, in the order the key sorts (farthest first, ties in "
        "input order), whose exact coverage holds it; vertex colours mixed by exact barycentric "
        "weights, within half a level. Written in the test, on the catalogue and random scenes.",
        ("algorithms/visibility/test_visibility_reference.py",
         "algorithms/visibility/test_visibility.py")),
)

# The module's algorithms, in the order they are listed.
SPECS = (ZBUFFER, PAINTER)
