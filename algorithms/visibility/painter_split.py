"""The painter's algorithm made right by splitting: a BSP tree.

Triangles that pierce each other or overlap in a cycle have no correct
drawing order as whole triangles (algorithms/visibility/zbuffer_painter.py's ``painter``
counts how wrong each order is). Here each triangle's plane splits the
triangles that cross it, so that every piece lies wholly on one side of
every plane above it in a binary space partition; walking the tree from
the far side of each plane to the near side (the viewer looks along +z:
smaller z is nearer) gives an order that is right for every pixel. The
splits are the cost: counted, with the pieces they make.

Planes and splits are exact (fractions of the vertex coordinates and
depths); the pieces are then drawn as the visibility family draws a
triangle (vertices snapped to 1/256 px, top-left rule), each in its source
triangle's colour.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms.visibility import zbuffer_painter as visibility  # its names are read when a run starts: it may still be loading now
from algorithms.core.code import Code, listing
from algorithms.triangles.interpolate import per_vertex
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import PLOT, Note, Start, Table, Vars
from algorithms.triangles.edges import TRIANGLES

Z = Option("z", "numbers", (), "a depth per point (or three shared by every triangle); "
           "smaller is nearer")

MAX_PIECES = 4096  # a BSP can cut n triangles into O(n^2) pieces or more


def plane_of(tri):
    """(n, d) with n . v + d = 0 on the triangle's plane (n = (b - a) x (c - a))."""
    a, b, c = tri
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return n, -sum(n[k] * a[k] for k in range(3))


def side(plane, v) -> Fraction:
    n, d = plane
    return n[0] * v[0] + n[1] * v[1] + n[2] * v[2] + d


def split(tri, plane):
    """(front pieces, back pieces) of a triangle cut by the plane, as triangles."""
    front, back = [], []
    for k in range(3):
        p, q = tri[k], tri[(k + 1) % 3]
        sp, sq = side(plane, p), side(plane, q)
        if sp >= 0:
            front.append(p)
        if sp <= 0:
            back.append(p)
        if (sp > 0 and sq < 0) or (sp < 0 and sq > 0):
            t = sp / (sp - sq)
            cut = tuple(p[k] + t * (q[k] - p[k]) for k in range(3))
            front.append(cut)
            back.append(cut)
    return _fan(front), _fan(back)


def _fan(polygon):
    return [(polygon[0], polygon[k], polygon[k + 1]) for k in range(1, len(polygon) - 1)]


class Bsp:
    """The tree's pieces in drawing order, and the splits that made them."""

    def __init__(self, pieces):
        self.splits = self.classified = 0
        self.events = []  # (source, by, pieces made) per split
        self.order = []   # (triangle (3 points), source) far to near
        self._walk(self._build(pieces))

    def _build(self, pieces):
        if not pieces:
            return None
        if len(pieces) + self.splits > MAX_PIECES:
            raise OverflowError
        (root, source), rest = pieces[0], pieces[1:]
        plane = plane_of(root)
        front, back, here = [], [], [(root, source)]
        for tri, owner in rest:
            self.classified += 1
            sides = [side(plane, v) for v in tri]
            if all(s >= 0 for s in sides) and any(s > 0 for s in sides):
                front.append((tri, owner))
            elif all(s <= 0 for s in sides) and any(s < 0 for s in sides):
                back.append((tri, owner))
            elif all(s == 0 for s in sides):
                here.append((tri, owner))
            else:
                ahead, behind = split(tri, plane)
                self.splits += 1
                self.events.append((owner, source, len(ahead) + len(behind)))
                front += [(t, owner) for t in ahead]
                back += [(t, owner) for t in behind]
        return plane, here, self._build(front), self._build(back)

    def _walk(self, node):
        if node is None:
            return
        (n, _), here, front, back = node
        # The viewer is at z = -infinity: on the front side when n_z < 0.
        near, far = (front, back) if n[2] < 0 else (back, front)
        self._walk(far)
        # Triangles in one plane: the first given is drawn last, so that it wins
        # where they overlap, as the z-buffer's strict depth test keeps the first.
        self.order += here[::-1]
        self._walk(near)


# Operation counts: a triangle classified against a plane evaluates n . v + d
# at its three vertices (3 mul and 3 additions each) and tests the signs; a
# cut finds two crossing points (a division and a lerp of 3 coordinates
# each); each piece is set up and walked as the painter sets up and walks a
# triangle (visibility.TRIANGLE_OPS, WALK_OPS). Building a node's plane (a
# cross product) is counted on its first classification's line.
CLASSIFY_OPS = {"mul": 9, "float_add": 9, "compare": 6}
CUT_OPS = {"div": 2, "mul": 6, "float_add": 12}


def split_code(points, options) -> Code:
    code = Code()
    code.add("build", "build a BSP tree: take a triangle's plane n . v + d = 0 (v = (x, y, z))")
    code.add("classify", "    put each other triangle in front of it (n . v + d >= 0 at every "
                         "corner), behind it (<= 0), or, when it crosses,", ops=CLASSIFY_OPS)
    code.add("split", "        cut it along the plane into 3 triangles, the pieces going to "
                      "their sides", ops=CUT_OPS)
    code.add("order", "walk the tree: at each plane draw the far side first, then the plane's "
                      "own triangles, then the near side (the viewer looks along +z)")
    code.add("piece", "for each piece in that order:", ops=visibility.TRIANGLE_OPS)
    code.add("plot_paint", "    paint its pixels in its triangle's colour (no depth test)",
             PLOT, ops=visibility.WALK_OPS)
    code.add("compare", "compare with the z-buffer's picture")
    code.add("done", "done")
    return code


def painter_split(points, options, grid):
    at = split_code(points, options).at
    yield Start(line=at["build"], values=("z", "piece", "rgb"),
                constants={"triangles": len(points) // 3}, pixel_value="rgb")
    z = per_vertex(options, "z", len(points))
    z = [0.5] * len(points) if z is None else list(z)
    solid = [(tuple((Fraction(points[3 * t + k][0]), Fraction(points[3 * t + k][1]),
                     Fraction(z[3 * t + k])) for k in range(3)), t)
             for t in range(len(points) // 3)]
    solid = [(tri, t) for tri, t in solid if any(plane_of(tri)[0])]
    try:
        bsp = Bsp(solid)
    except OverflowError:
        from algorithms.core.errors import InputError
        raise InputError(f"the BSP tree would cut these triangles into more than "
                         f"{MAX_PIECES} pieces") from None
    for k in range(bsp.classified):
        yield Vars(line=at["classify"], values={"classified": k + 1})
    for k, (owner, by, made) in enumerate(bsp.events):
        yield Vars(line=at["split"], values={"splits": k + 1})
        yield Note(line=at["split"], text=f"triangle {owner + 1} crosses the plane of triangle "
                                          f"{by + 1}: cut into {made} pieces")
    yield Table(line=at["order"], name="drawing order",
                columns=("rank", "triangle", "z0", "z1", "z2"),
                rows=tuple((rank + 1, owner + 1, *(float(v[2]) for v in tri))
                           for rank, (tri, owner) in enumerate(bsp.order[:200])))
    color = np.full((int(grid[1]), int(grid[0])), -1, np.int64)
    yield from _paint(bsp.order, grid, color, at)
    reference, _, _ = visibility.zbuffer_image(points, {"z": tuple(z), "depth_test": "less"},
                                               grid, clear=math.inf)
    disagree = int((color != reference).sum())
    yield Vars(line=at["compare"], values={"splits": bsp.splits, "pieces": len(bsp.order),
                                           "disagree": disagree})


def _paint(order, grid, color, at):
    flat = [(float(v[0]), float(v[1])) for tri, _ in order for v in tri]
    depths = tuple(float(v[2]) for tri, _ in order for v in tri)
    scene = visibility.Scene(flat, {"z": depths, "fill_rule": "top-left"}, grid)
    line = at["plot_paint"]
    for setup in scene.drawn():
        owner = order[setup.number][1]
        yield Vars(line=at["piece"], values={"piece": setup.number + 1, "triangle": owner + 1})
        palette = visibility.PALETTE
        packed = int(palette[owner % len(palette)][1:], 16)
        for i, j, depth, _ in scene.fragments(setup):
            color[j, i] = packed
            yield (line, i, j, depth, float(setup.number + 1), float(packed))


PAINTER_SPLIT = AlgorithmSpec(
    name="painter-split",
    title="Painter's algorithm with splitting (BSP)",
    family="visibility",
    summary="split the triangles that cross each other's planes, then paint far to near",
    inputs=TRIANGLES,
    options=(Z,),
    code=listing(split_code),
    generator=painter_split,
    uses_grid=True,
    notes=("Whole triangles that pierce each other or overlap in a cycle have no right order; "
           "cut along the planes they cross, their pieces do. splits counts the cuts and "
           "pieces what is drawn: the price of a right order.",
           "disagree counts the pixels unlike the z-buffer's: 0 but for pixel centres within "
           "a rounding of the line where two triangles meet, or of an edge a cut ends on (the "
           "pieces' corners snap to 1/256 px)."),
    oracle=Oracle(
        "exact",
        "Where the nearest triangle is clear (not within 1/256 px of an edge, nor 1/50 in depth of "
        "another), the colour of the triangle nearest the viewer, from exact plane depths in "
        "Fractions written in the test.",
        ("algorithms/visibility/test_painter_split.py",)),
)

# The module's algorithms, in the order they are listed.
SPECS = (PAINTER_SPLIT,)
